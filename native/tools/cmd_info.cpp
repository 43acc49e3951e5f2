// hbc info FILE [--json]: the counts of a mesh (keys in docs/concepts.md, "The mesh").
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "json.hpp"

namespace hbc::cli {
namespace {

struct InfoArgs {
  InputArgs input;
  bool json = false;
};

void run_info(const InfoArgs& args) {
  const Mesh m = load_for_cli(args.input);
  int64_t types[5] = {0, 0, 0, 0, 0};
  for (CellType t : m.cell_type) ++types[static_cast<int>(t)];
  int64_t boundary_faces = 0, non_manifold = 0;
  for (uint8_t b : m.face_boundary) boundary_faces += b;
  for (uint8_t b : m.vert_non_manifold) non_manifold += b;
  const int64_t nc = static_cast<int64_t>(m.num_cells());
  const double hex_ratio = nc ? static_cast<double>(types[0]) / static_cast<double>(nc) : 0.0;
  const char* file = args.input.file.c_str();

  if (args.json) {
    Json cell_types;
    for (int t = 0; t < 5; ++t) cell_types[cell_type_name(static_cast<CellType>(t))] = types[t];
    const Json j = {{"file", args.input.file},
                    {"vertices", m.num_vertices()},
                    {"edges", m.num_edges()},
                    {"faces", m.num_faces()},
                    {"cells", nc},
                    {"hex_cells", types[0]},
                    {"hex_ratio", hex_ratio},
                    {"cell_types", cell_types},
                    {"boundary_faces", boundary_faces},
                    {"non_manifold_vertices", non_manifold},
                    {"dropped_faces", m.dropped_faces},
                    {"dropped_edges", m.dropped_edges}};
    write_output(json_text(j), std::nullopt);
    return;
  }
  std::printf("file            %s\n", file);
  std::printf("vertices        %zu\nedges           %zu\nfaces           %zu\n", m.num_vertices(), m.num_edges(), m.num_faces());
  std::printf("cells           %lld (hex %lld, tet %lld, prism %lld, pyramid %lld, polyhedron %lld)\n",
              static_cast<long long>(nc), static_cast<long long>(types[0]), static_cast<long long>(types[1]),
              static_cast<long long>(types[2]), static_cast<long long>(types[3]), static_cast<long long>(types[4]));
  std::printf("hex ratio       %.4f\n", hex_ratio);
  std::printf("boundary faces  %lld\nnon-manifold v. %lld\n", static_cast<long long>(boundary_faces), static_cast<long long>(non_manifold));
  std::printf("dropped         %lld face(s), %lld edge(s)\n", static_cast<long long>(m.dropped_faces), static_cast<long long>(m.dropped_edges));
}

}  // namespace

void add_info(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = add_mesh_command(app, "info", "counts of the mesh: vertices, edges, faces, cells by type, boundary faces", args->input, args->json);
  cmd->callback([args] { run_info(*args); });
}

}  // namespace hbc::cli
