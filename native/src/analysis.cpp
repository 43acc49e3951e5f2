#include "hbc/analysis.hpp"

#include <chrono>

namespace hbc {
namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

const Subsheets* Analysis::subsheets_of(int32_t s) const {
  for (const Subsheets& x : subsheets)
    if (x.sheet == s) return &x;
  return nullptr;
}

Analysis analyze(const Mesh& mesh, const AnalysisOptions& opt) {
  Analysis a;
  auto t = std::chrono::steady_clock::now();
  a.graph = singularity_graph(mesh);
  a.timings.singularity_graph = since(t);

  t = std::chrono::steady_clock::now();
  a.complex = base_complex(mesh, a.graph);
  a.timings.base_complex = since(t);

  if (opt.sheets) {
    t = std::chrono::steady_clock::now();
    a.domain = sheet_domain(mesh, a.complex, opt.sheet_level);
    a.sheets = extract_sheets(mesh, a.domain);
    a.largest_self_intersecting = largest_self_intersecting(a.sheets);
    a.timings.sheets = since(t);
    a.has_sheets = true;
    if (opt.subsheets) {
      t = std::chrono::steady_clock::now();
      for (size_t s = 0; s < a.sheets.size(); ++s)
        if (a.sheets.classes[s].type3) a.subsheets.push_back(decompose_sheet(a.domain, a.sheets, static_cast<int32_t>(s)));
      a.timings.subsheets = since(t);
      a.has_subsheets = true;
    }
  }
  if (opt.wireframe) {
    t = std::chrono::steady_clock::now();
    a.wire_complex = opt.wireframe_level == Level::Complex ? complex_from_base(mesh, a.complex)
                                                                  : complex_from_mesh(mesh);
    a.wireframe = vsg_wireframe(a.wire_complex, opt.wireframe_options);
    a.timings.vsg_wireframe = since(t);
    a.has_wireframe = true;
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
  if (a.has_sheets) {
    s.sheets = static_cast<int64_t>(a.sheets.size());
    s.sheets_perfect = static_cast<int64_t>(a.sheets.count(SheetType::Perfect));
    s.sheets_type1 = static_cast<int64_t>(a.sheets.count(SheetType::Type1));
    s.sheets_type2 = static_cast<int64_t>(a.sheets.count(SheetType::Type2));
    s.sheets_type3 = static_cast<int64_t>(a.sheets.count(SheetType::Type3));
    const Subsheets* big = a.subsheets_of(a.largest_self_intersecting);
    if (a.has_subsheets) s.subsheets_of_largest_self_intersecting = big ? static_cast<int64_t>(big->size()) : 0;
  }
  if (a.has_wireframe) {
    s.vsg_edges = a.wireframe.vsg_edges;
    s.wireframe_edges = a.wireframe.wireframe_edges();
    s.wireframe_edges_simplified = a.wireframe.wireframe_edges_simplified();
  }
  s.timings = a.timings;
  return s;
}

}  // namespace hbc
