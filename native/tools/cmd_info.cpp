#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "json.hpp"

namespace hbc::cli {

int cmd_info(const Args& args_in) {
  Args args = args_in;
  const bool json = take_flag(args, "--json");
  const InputFormat format = take_format(args);
  if (args.size() != 1) throw std::invalid_argument("usage: hbc info FILE [--json] [--format F]");
  const Mesh m = load_for_cli(args[0], format);

  int64_t types[5] = {0, 0, 0, 0, 0};
  for (CellType t : m.cell_type) ++types[static_cast<int>(t)];
  int64_t boundary_faces = 0, non_manifold = 0;
  for (uint8_t b : m.face_boundary) boundary_faces += b;
  for (uint8_t b : m.vert_non_manifold) non_manifold += b;
  const int64_t nc = static_cast<int64_t>(m.num_cells());
  const double hex_ratio = nc ? static_cast<double>(types[0]) / static_cast<double>(nc) : 0.0;

  if (json) {
    JsonWriter w;
    w.begin()
        .str("file", args[0])
        .num("vertices", static_cast<int64_t>(m.num_vertices()))
        .num("edges", static_cast<int64_t>(m.num_edges()))
        .num("faces", static_cast<int64_t>(m.num_faces()))
        .num("cells", nc)
        .num("hex_cells", types[0])
        .real("hex_ratio", hex_ratio)
        .begin("cell_types");
    for (int t = 0; t < 5; ++t) w.num(cell_type_name(static_cast<CellType>(t)), types[t]);
    w.end()
        .num("boundary_faces", boundary_faces)
        .num("non_manifold_vertices", non_manifold)
        .num("dropped_faces", m.dropped_faces)
        .num("dropped_edges", m.dropped_edges)
        .end();
    std::printf("%s\n", w.text().c_str());
  } else {
    std::printf("file            %s\n", args[0].c_str());
    std::printf("vertices        %zu\nedges           %zu\nfaces           %zu\n", m.num_vertices(), m.num_edges(), m.num_faces());
    std::printf("cells           %lld (hex %lld, tet %lld, prism %lld, pyramid %lld, polyhedron %lld)\n",
                static_cast<long long>(nc), static_cast<long long>(types[0]), static_cast<long long>(types[1]),
                static_cast<long long>(types[2]), static_cast<long long>(types[3]), static_cast<long long>(types[4]));
    std::printf("hex ratio       %.4f\n", hex_ratio);
    std::printf("boundary faces  %lld\nnon-manifold v. %lld\n", static_cast<long long>(boundary_faces), static_cast<long long>(non_manifold));
    std::printf("dropped         %lld face(s), %lld edge(s)\n", static_cast<long long>(m.dropped_faces), static_cast<long long>(m.dropped_edges));
  }
  return 0;
}

}  // namespace hbc::cli
