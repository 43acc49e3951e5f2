#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/base_complex.hpp"
#include "hbc/singularity_graph.hpp"
#include "hbc/sheets.hpp"
#include "json.hpp"

namespace hbc::cli {

int cmd_analyze(const Args& args_in) {
  Args args = args_in;
  const bool json = take_flag(args, "--json");
  const Format format = take_format(args);
  if (args.size() != 1) throw std::invalid_argument("usage: hbc analyze FILE [--json] [--format F]");
  double t_load = 0;
  const Mesh m = load_for_cli(args[0], format, &t_load);
  auto t0 = std::chrono::steady_clock::now();
  SingularityGraph g = singularity_graph(m);
  auto t1 = std::chrono::steady_clock::now();
  BaseComplex bc = base_complex(m, g);
  auto t2 = std::chrono::steady_clock::now();
  SheetDomain dom = sheet_domain(m, bc, take_flag(args, "--mesh-level") ? SheetLevel::Mesh : SheetLevel::Complex);
  Sheets sh = extract_sheets(m, dom);
  auto t3 = std::chrono::steady_clock::now();
  int32_t big = largest_self_intersecting(sh);
  Subsheets sub;
  if (big >= 0) sub = decompose_sheet(dom, sh, big);
  for (size_t i = 0; i < sh.size(); ++i)
    if (sh.classes[i].type3) {
      Subsheets x = decompose_sheet(dom, sh, static_cast<int32_t>(i));
      { std::fprintf(stderr, "sheet %zu: cells %d units %d curves %d edges %d type %s subsheets %zu:", i, sh.sheet_cells.count(i), sh.sheet_units.count(i), sh.sheet_curves.count(i), sh.sheet_edges.count(i), sheet_type_name(sh.classes[i].type), x.size()); for (size_t q = 0; q < x.size(); ++q) std::fprintf(stderr, " %d/%d%s", x.curves.count(q), x.units.count(q), sheet_type_name(x.classes[q].type)); std::fprintf(stderr, "\n"); }
    }
  const size_t nc = m.num_cells();
  JsonWriter w;
  w.begin()
      .num("cells", static_cast<int64_t>(nc))
      .real("hex_ratio", nc ? double(m.num_hex_cells()) / double(nc) : 0.0)
      .num("singular_edges", static_cast<int64_t>(g.num_singular_edges()))
      .num("singularities", static_cast<int64_t>(g.num_singularities()))
      .num("pseudo_singular_edges", static_cast<int64_t>(g.pseudo_singular_edges.size()))
      .num("non_manifold_edges", static_cast<int64_t>(g.non_manifold_edges.size()))
      .num("singular_vertices", static_cast<int64_t>(g.singular_vertices.size()))
      .num("components", static_cast<int64_t>(bc.num_components()))
      .num("hex_components", static_cast<int64_t>(bc.num_hex_components()))
      .num("non_hex_components", static_cast<int64_t>(bc.num_non_hex_components()))
      .num("patches", static_cast<int64_t>(bc.num_patches()))
      .num("curves", static_cast<int64_t>(bc.num_curves()))
      .num("corners", static_cast<int64_t>(bc.corners.size()))
      .num("self_adjacent_faces", static_cast<int64_t>(bc.self_adjacent_faces.size()))
      .num("sheets", static_cast<int64_t>(sh.size()))
      .num("sheets_perfect", static_cast<int64_t>(sh.count(SheetType::Perfect)))
      .num("sheets_type1", static_cast<int64_t>(sh.count(SheetType::Type1)))
      .num("sheets_type2", static_cast<int64_t>(sh.count(SheetType::Type2)))
      .num("sheets_type3", static_cast<int64_t>(sh.count(SheetType::Type3)))
      .num("subsheets_of_largest_self_intersecting", static_cast<int64_t>(sub.size()))
      .begin("timings")
      .real("load", t_load)
      .real("singularity_graph", std::chrono::duration<double>(t1 - t0).count())
      .real("base_complex", std::chrono::duration<double>(t2 - t1).count())
      .real("sheets", std::chrono::duration<double>(t3 - t2).count())
      .end()
      .end();
  (void)json;
  std::printf("%s\n", w.text().c_str());
  return 0;
}

}  // namespace hbc::cli
