// hbc info FILE [--json]: the counts of a mesh (keys in docs/concepts.md, "The mesh").
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "hbc/report.hpp"

namespace hbc::cli {
namespace {

struct InfoArgs {
  InputArgs input;
  bool json = false;
};

void run_info(const InfoArgs& args) {
  const Mesh m = load_for_cli(args.input);
  if (args.json) {
    write_output(json_text(mesh_info_json(m, args.input.file)), std::nullopt);
    return;
  }
  const MeshCounts c = mesh_counts(m);
  const auto n = [&](size_t t) { return static_cast<long long>(c.cell_types[t]); };
  std::printf("file            %s\n", args.input.file.c_str());
  std::printf("vertices        %zu\nedges           %zu\nfaces           %zu\n", m.num_vertices(), m.num_edges(), m.num_faces());
  std::printf("cells           %lld (hex %lld, tet %lld, prism %lld, pyramid %lld, polyhedron %lld)\n",
              static_cast<long long>(m.num_cells()), n(0), n(1), n(2), n(3), n(4));
  std::printf("hex ratio       %.4f\n", c.hex_ratio);
  std::printf("boundary faces  %lld\nnon-manifold v. %lld\n", static_cast<long long>(c.boundary_faces),
              static_cast<long long>(c.non_manifold_vertices));
  std::printf("dropped         %lld face(s), %lld edge(s)\n", static_cast<long long>(m.dropped_faces), static_cast<long long>(m.dropped_edges));
}

}  // namespace

void add_info(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = add_mesh_command(app, "info", "counts of the mesh: vertices, edges, faces, cells by type, boundary faces", args->input, args->json);
  cmd->callback([args] { run_info(*args); });
}

}  // namespace hbc::cli
