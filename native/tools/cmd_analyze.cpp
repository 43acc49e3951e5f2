#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/base_complex.hpp"
#include "hbc/singularity_graph.hpp"
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
      .begin("timings")
      .real("load", t_load)
      .real("singularity_graph", std::chrono::duration<double>(t1 - t0).count())
      .real("base_complex", std::chrono::duration<double>(t2 - t1).count())
      .end()
      .end();
  (void)json;
  std::printf("%s\n", w.text().c_str());
  return 0;
}

}  // namespace hbc::cli
