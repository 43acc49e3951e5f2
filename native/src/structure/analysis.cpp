#include "hbc/analysis.hpp"

#include <chrono>
#include <functional>
#include <optional>

#include "parallel/parallel.hpp"
#include "platform/memory.hpp"

namespace hbc {

const Subsheets* SheetStage::subsheets_of(int32_t s) const {
  if (!subsheets) return nullptr;
  for (const Subsheets& x : *subsheets)
    if (x.sheet == s) return &x;
  return nullptr;
}

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// `after_domain` runs once the domain is built (analyze_stats frees what only the domain read).
SheetStage sheet_stage(const Mesh& mesh, const BaseComplex& complex, const AnalysisOptions& opt, const Threads& par,
                       Timings& timings, const std::function<void()>& after_domain = {}) {
  auto t = std::chrono::steady_clock::now();
  SheetStage st;
  st.domain = sheet_domain(mesh, complex, opt.sheet_level, par);
  if (after_domain) after_domain();
  st.sheets = extract_sheets(mesh, st.domain, par);
  st.largest_self_intersecting = largest_self_intersecting(st.sheets);
  timings.sheets = since(t);
  if (opt.subsheets) {
    t = std::chrono::steady_clock::now();
    st.subsheets.emplace();
    for (size_t s = 0; s < st.sheets.size(); ++s)
      if (st.sheets.classes[s].type3) {
        const auto ts = std::chrono::steady_clock::now();
        st.subsheets->push_back(decompose_sheet(st.domain, st.sheets, static_cast<int32_t>(s), opt.subsheet_options));
        st.subsheet_seconds.push_back(since(ts));
      }
    timings.subsheets = since(t);
  }
  return st;
}

WireframeStage wireframe_stage(const Mesh& mesh, const BaseComplex& complex, const AnalysisOptions& opt,
                               const Threads& par) {
  WireframeStage st;
  st.view = opt.wireframe_level == Level::Complex ? complex_from_base(mesh, complex, par) : complex_from_mesh(mesh, par);
  st.wireframe = vsg_wireframe(st.view, opt.wireframe_options, par);
  return st;
}

}  // namespace

Analysis analyze(const Mesh& mesh, const AnalysisOptions& opt) {
  // One worker pool for all the stages, as for the load: no thread started per parallel pass
  // (some fifty per analysis, each a few milliseconds of work on a mesh of tens of thousands of
  // cells).
  const detail::RunOptions run(Threads{opt.threads});
  const Threads& par = run.get();
  Analysis a;
  auto t = std::chrono::steady_clock::now();
  a.graph = singularity_graph(mesh, par);
  a.timings.singularity_graph = since(t);

  t = std::chrono::steady_clock::now();
  a.complex = base_complex(mesh, a.graph, par);
  a.timings.base_complex = since(t);

  if (opt.sheets) a.sheet_stage = sheet_stage(mesh, a.complex, opt, par, a.timings);
  if (opt.wireframe) {
    t = std::chrono::steady_clock::now();
    a.wireframe_stage = wireframe_stage(mesh, a.complex, opt, par);
    a.timings.vsg_wireframe = since(t);
  }
  return a;
}

namespace {

void graph_stats(const Mesh& m, const SingularityGraph& g, Stats& s) {
  s.cells = static_cast<int64_t>(m.num_cells());
  s.hex_cells = static_cast<int64_t>(m.num_hex_cells());
  s.hex_ratio = s.cells ? static_cast<double>(s.hex_cells) / static_cast<double>(s.cells) : 0.0;
  s.singular_edges = static_cast<int64_t>(g.num_singular_edges());
  s.singularities = static_cast<int64_t>(g.num_singularities());
  s.pseudo_singular_edges = static_cast<int64_t>(g.pseudo_singular_edges.size());
  s.non_manifold_edges = static_cast<int64_t>(g.non_manifold_edges.size());
  s.singular_vertices = static_cast<int64_t>(g.singular_vertices.size());
}

void complex_stats(const BaseComplex& bc, Stats& s) {
  s.components = static_cast<int64_t>(bc.num_components());
  s.hex_components = static_cast<int64_t>(bc.num_hex_components());
  s.hex_component_ratio = s.components ? static_cast<double>(s.hex_components) / static_cast<double>(s.components) : 0.0;
  s.patches = static_cast<int64_t>(bc.num_patches());
  s.curves = static_cast<int64_t>(bc.num_curves());
  s.corners = static_cast<int64_t>(bc.corners.size());
  s.self_adjacent_faces = static_cast<int64_t>(bc.self_adjacent_faces.size());
}

void sheet_stats(const SheetStage& st, Stats& s) {
  const Sheets& sh = st.sheets;
  s.sheets = static_cast<int64_t>(sh.size());
  s.sheets_perfect = static_cast<int64_t>(sh.count(SheetType::Perfect));
  s.sheets_type1 = static_cast<int64_t>(sh.count(SheetType::Type1));
  s.sheets_type2 = static_cast<int64_t>(sh.count(SheetType::Type2));
  s.sheets_type3 = static_cast<int64_t>(sh.count(SheetType::Type3));
  if (st.subsheets) {
    const Subsheets* big = st.largest_self_intersecting ? st.subsheets_of(*st.largest_self_intersecting) : nullptr;
    s.subsheets_of_largest_self_intersecting = big ? static_cast<int64_t>(big->size()) : 0;
  }
}

void wireframe_stats(const VsgWireframe& w, Stats& s) {
  s.vsg_edges = w.vsg_edges;
  s.wireframe_edges = w.wireframe_edges();
  s.wireframe_edges_simplified = w.wireframe_edges_simplified();
}

template <class T>
void release(T& v) {
  v = T();  // clear() would keep the room
}

// The graph arrays base_complex does not read (it asks is_structural, the edge classes, only):
// dropped once counted, before the base complex is built next to the graph.
void keep_for_base_complex(SingularityGraph& g) {
  release(g.edge_irregular);
  release(g.chain_verts);
  release(g.chain_edges);
  release(g.edge_chain);
  release(g.pseudo_singular_edges);
  release(g.non_manifold_edges);
  release(g.singular_vertices);
  release(g.pseudo_singular_vertices);
  release(g.vert_pseudo_singular);
}

// analyze_stats frees each base complex array once the last of base_view_facts, sheet_domain and
// complex_from_base(bc, facts) that reads it is done. Read by none of them:
void drop_unread(BaseComplex& bc) {
  release(bc.edge_complex);
  release(bc.vert_corner);
  release(bc.edge_curve);
  release(bc.component_patches);
  release(bc.component_corners);
  release(bc.corners);
  release(bc.self_adjacent_faces);
}

// Read by base_view_facts only.
void drop_facts_only(BaseComplex& bc) {
  release(bc.face_patch);
  release(bc.patch_faces);
  release(bc.patch_corners);
}

// Read by base_view_facts and sheet_domain, not by the view built from the facts.
void drop_domain_only(BaseComplex& bc) {
  release(bc.face_separation);
  release(bc.cell_component);
  release(bc.component_cells);
  release(bc.component_adjacency);
  release(bc.curve_edges);
}

// Past the facts only the sheets read a given-up mesh: its topology and edge fans, none of these
// flags (test_stats_memory runs the sheets on a given-up mesh).
void keep_for_sheets(Mesh& m) {
  release(m.valence_small);
  release(m.edge_boundary);
  release(m.face_boundary);
  release(m.vert_non_manifold);
}

// The graph and the base complex, counted; only the base complex (all of it) is kept.
BaseComplex counted_base_complex(const Mesh& mesh, const Threads& par, Stats& s) {
  auto t = std::chrono::steady_clock::now();
  SingularityGraph graph = singularity_graph(mesh, par);
  s.timings.singularity_graph = since(t);
  graph_stats(mesh, graph, s);
  keep_for_base_complex(graph);
  t = std::chrono::steady_clock::now();
  BaseComplex bc = base_complex(mesh, graph, par);
  s.timings.base_complex = since(t);
  complex_stats(bc, s);
  return bc;
}

void counted_sheets(const Mesh& mesh, BaseComplex& bc, const AnalysisOptions& opt, const Threads& par, StatsRun& run) {
  const SheetStage st = sheet_stage(mesh, bc, opt, par, run.stats.timings, [&] {
    drop_domain_only(bc);
    detail::return_freed_memory();
  });
  sheet_stats(st, run.stats);
  if (st.subsheets)
    for (const Subsheets& x : *st.subsheets)
      run.subsheet_counts.push_back({x.sheet, st.sheets.sheet_blocks.count(static_cast<size_t>(x.sheet)),
                                     static_cast<int64_t>(x.size())});
}

// analyze_stats; `owned` is the mesh when the caller gave it up (freed before the view is built).
StatsRun stats_run(const Mesh& mesh, Mesh* owned, const AnalysisOptions& opt) {
  const detail::RunOptions threads(Threads{opt.threads});
  const Threads& par = threads.get();
  StatsRun run;
  Stats& s = run.stats;
  // Only complex_from_mesh, the mesh-level view, reads what the stages before it do not.
  const bool mesh_view = opt.wireframe && opt.wireframe_level == Level::Mesh;
  if (owned && !mesh_view) release_unanalyzed(*owned);
  BaseComplex bc = counted_base_complex(mesh, par, s);
  drop_unread(bc);
  // The complex-level view is built last, from the base complex alone, so that neither the mesh
  // nor the sheets are alive next to it; what it needs of the mesh is taken now (its time is the
  // wireframe's).
  std::optional<BaseViewFacts> facts;
  if (opt.wireframe && opt.wireframe_level == Level::Complex) {
    const auto t = std::chrono::steady_clock::now();
    facts = base_view_facts(mesh, bc, par);
    s.timings.vsg_wireframe = since(t);
  }
  drop_facts_only(bc);
  if (owned && !mesh_view) keep_for_sheets(*owned);
  detail::return_freed_memory();
  if (opt.sheets) counted_sheets(mesh, bc, opt, par, run);
  detail::return_freed_memory();
  if (!opt.wireframe) return run;
  const auto t = std::chrono::steady_clock::now();
  WireframeStage st;
  if (facts) {
    if (owned) release(*owned);
    st.view = complex_from_base(bc, *facts, par);
    facts.reset();
    release(bc);
  } else {
    release(bc);
    st.view = complex_from_mesh(mesh, par);
  }
  // The wireframe's presentation (opacity, ρ colours) is no part of the analysis: the render
  // layer styles a wireframe when a front end shows it (wireframe_style.hpp).
  st.wireframe = vsg_wireframe(st.view, opt.wireframe_options, par);
  s.timings.vsg_wireframe += since(t);
  wireframe_stats(st.wireframe, s);
  return run;
}

}  // namespace

Stats compute_stats(const Mesh& m, const Analysis& a) {
  Stats s;
  graph_stats(m, a.graph, s);
  complex_stats(a.complex, s);
  if (a.sheet_stage) sheet_stats(*a.sheet_stage, s);
  if (a.wireframe_stage) wireframe_stats(a.wireframe_stage->wireframe, s);
  s.timings = a.timings;
  return s;
}

StatsRun analyze_stats(const Mesh& mesh, const AnalysisOptions& opt) { return stats_run(mesh, nullptr, opt); }

StatsRun analyze_stats(Mesh&& mesh, const AnalysisOptions& opt) { return stats_run(mesh, &mesh, opt); }

}  // namespace hbc
