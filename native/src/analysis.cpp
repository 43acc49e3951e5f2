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
  st.domain = sheet_domain(mesh, complex, opt.sheet_level);
  st.sheets = extract_sheets(mesh, st.domain);
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
  st.wireframe = vsg_wireframe(st.view, opt.wireframe_options);
  return st;
}

}  // namespace

Analysis analyze(const Mesh& mesh, const AnalysisOptions& opt) {
  Analysis a;
  auto t = std::chrono::steady_clock::now();
  a.graph = singularity_graph(mesh);
  a.timings.singularity_graph = since(t);

  t = std::chrono::steady_clock::now();
  a.complex = base_complex(mesh, a.graph);
  a.timings.base_complex = since(t);

  if (opt.sheets) a.sheet_stage = sheet_stage(mesh, a.complex, opt, a.timings);
  if (opt.wireframe) {
    t = std::chrono::steady_clock::now();
    a.wireframe_stage = wireframe_stage(mesh, a.complex, opt);
    a.timings.vsg_wireframe = since(t);
  }
  return a;
}

Stats compute_stats(const Mesh& m, const Analysis& a) {
  Stats s;
  s.cells = static_cast<int64_t>(m.num_cells());
  s.hex_cells = static_cast<int64_t>(m.num_hex_cells());
  s.hex_ratio = s.cells ? static_cast<double>(s.hex_cells) / static_cast<double>(s.cells) : 0.0;
  s.singular_edges = static_cast<int64_t>(a.graph.num_singular_edges());
  s.singularities = static_cast<int64_t>(a.graph.num_singularities());
  s.pseudo_singular_edges = static_cast<int64_t>(a.graph.pseudo_singular_edges.size());
  s.non_manifold_edges = static_cast<int64_t>(a.graph.non_manifold_edges.size());
  s.singular_vertices = static_cast<int64_t>(a.graph.singular_vertices.size());
  s.components = static_cast<int64_t>(a.complex.num_components());
  s.hex_components = static_cast<int64_t>(a.complex.num_hex_components());
  s.hex_component_ratio = s.components ? static_cast<double>(s.hex_components) / static_cast<double>(s.components) : 0.0;
  s.patches = static_cast<int64_t>(a.complex.num_patches());
  s.curves = static_cast<int64_t>(a.complex.num_curves());
  s.corners = static_cast<int64_t>(a.complex.corners.size());
  s.self_adjacent_faces = static_cast<int64_t>(a.complex.self_adjacent_faces.size());
  if (const auto& st = a.sheet_stage) {
    const Sheets& sh = st->sheets;
    s.sheets = static_cast<int64_t>(sh.size());
    s.sheets_perfect = static_cast<int64_t>(sh.count(SheetType::Perfect));
    s.sheets_type1 = static_cast<int64_t>(sh.count(SheetType::Type1));
    s.sheets_type2 = static_cast<int64_t>(sh.count(SheetType::Type2));
    s.sheets_type3 = static_cast<int64_t>(sh.count(SheetType::Type3));
    if (st->subsheets) {
      const Subsheets* big = st->largest_self_intersecting ? st->subsheets_of(*st->largest_self_intersecting) : nullptr;
      s.subsheets_of_largest_self_intersecting = big ? static_cast<int64_t>(big->size()) : 0;
    }
  }
  if (const auto& st = a.wireframe_stage) {
    const VsgWireframe& w = st->wireframe;
    s.vsg_edges = w.vsg_edges;
    s.wireframe_edges = w.wireframe_edges();
    s.wireframe_edges_simplified = w.wireframe_edges_simplified();
  }
  s.timings = a.timings;
  return s;
}

}  // namespace hbc
