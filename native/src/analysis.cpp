#include "hbc/analysis.hpp"

#include <chrono>

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

SheetStage sheet_stage(const Mesh& mesh, const BaseComplex& complex, const AnalysisOptions& opt, Timings& timings) {
  auto t = std::chrono::steady_clock::now();
  SheetStage st;
  st.domain = sheet_domain(mesh, complex, opt.sheet_level, LoadOptions{opt.threads});
  st.sheets = extract_sheets(mesh, st.domain, LoadOptions{opt.threads});
  st.largest_self_intersecting = largest_self_intersecting(st.sheets);
  timings.sheets = since(t);
  if (opt.subsheets) {
    t = std::chrono::steady_clock::now();
    st.subsheets.emplace();
    for (size_t s = 0; s < st.sheets.size(); ++s)
      if (st.sheets.classes[s].type3) st.subsheets->push_back(decompose_sheet(st.domain, st.sheets, static_cast<int32_t>(s)));
    timings.subsheets = since(t);
  }
  return st;
}

WireframeStage wireframe_stage(const Mesh& mesh, const BaseComplex& complex, const AnalysisOptions& opt) {
  WireframeStage st;
  st.view = opt.wireframe_level == Level::Complex ? complex_from_base(mesh, complex) : complex_from_mesh(mesh);
  st.wireframe = vsg_wireframe(st.view, opt.wireframe_options, LoadOptions{opt.threads});
  return st;
}

}  // namespace

Analysis analyze(const Mesh& mesh, const AnalysisOptions& opt) {
  Analysis a;
  auto t = std::chrono::steady_clock::now();
  a.graph = singularity_graph(mesh);
  a.timings.singularity_graph = since(t);

  t = std::chrono::steady_clock::now();
  a.complex = base_complex(mesh, a.graph, LoadOptions{opt.threads});
  a.timings.base_complex = since(t);

  if (opt.sheets) a.sheet_stage = sheet_stage(mesh, a.complex, opt, a.timings);
  if (opt.wireframe) {
    t = std::chrono::steady_clock::now();
    a.wireframe_stage = wireframe_stage(mesh, a.complex, opt);
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

// Frees the base complex arrays that neither sheet_domain nor the statistics read (about half of
// it on a mesh cut into many components). Kept: the components, their kinds, cells, adjacency and
// curves, the curves themselves, the patches' curves, the separation faces, the corners' count and
// the self-adjacent faces.
void keep_for_sheets(BaseComplex& bc) {
  release(bc.edge_complex);
  release(bc.vert_corner);
  release(bc.face_patch);
  release(bc.patch_faces.items);  // the row count (num_patches) stays
  release(bc.patch_components);
  release(bc.patch_corners);
  release(bc.edge_curve);
  release(bc.component_patches);
  release(bc.component_corners);
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

StatsRun analyze_stats(const Mesh& mesh, const AnalysisOptions& opt) {
  StatsRun run;
  Stats& s = run.stats;
  BaseComplex bc;
  {
    auto t = std::chrono::steady_clock::now();
    const SingularityGraph graph = singularity_graph(mesh);
    s.timings.singularity_graph = since(t);
    graph_stats(mesh, graph, s);
    t = std::chrono::steady_clock::now();
    bc = base_complex(mesh, graph, LoadOptions{opt.threads});
    s.timings.base_complex = since(t);
    complex_stats(bc, s);
  }
  if (opt.wireframe) {
    const auto t = std::chrono::steady_clock::now();
    WireframeStage st;
    st.view = opt.wireframe_level == Level::Complex ? complex_from_base(mesh, bc) : complex_from_mesh(mesh);
    if (opt.sheets) keep_for_sheets(bc);
    st.wireframe = vsg_wireframe(st.view, opt.wireframe_options, LoadOptions{opt.threads});
    s.timings.vsg_wireframe = since(t);
    wireframe_stats(st.wireframe, s);
  }
  if (opt.sheets) {
    const SheetStage st = sheet_stage(mesh, bc, opt, s.timings);
    sheet_stats(st, s);
    if (st.subsheets)
      for (const Subsheets& x : *st.subsheets)
        run.subsheet_counts.push_back({x.sheet, st.sheets.sheet_blocks.count(static_cast<size_t>(x.sheet)),
                                       static_cast<int64_t>(x.size())});
  }
  return run;
}

}  // namespace hbc
