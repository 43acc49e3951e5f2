// hbc export-surface FILE -o OUT.obj|.ply|.off [--what boundary]: a surface of mesh faces through
// OpenMesh. Each --what only chooses the face list and the ids that colour it (surface.hpp).
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/surface.hpp"

namespace hbc::cli {

int cmd_export_surface(const Args& args_in) {
  Args args = args_in;
  auto out = take_option(args, "-o");
  auto what = take_option(args, "--what");
  const Format format = take_format(args);
  if (!out || args.size() != 1)
    throw std::invalid_argument("usage: hbc export-surface FILE -o OUT.obj|.ply|.off [--what boundary] [--format F]");
  const std::string kind = what.value_or("boundary");
  const Mesh mesh = load_for_cli(args[0], format);
  FaceSelection sel;
  if (kind == "boundary") sel = boundary_selection(mesh);
  else throw std::invalid_argument("--what must be boundary, got '" + kind + "'");
  SurfaceStats stats;
  const SurfaceMesh surface = build_surface(mesh, sel, &stats);
  write_surface(surface, *out);
  if (stats.unwelded_faces > 0)
    std::fprintf(stderr, "hbc: warning: %lld face(s) at non-manifold edges or vertices written unwelded\n",
                 static_cast<long long>(stats.unwelded_faces));
  std::printf("wrote %s: %lld faces, %zu vertices\n", out->c_str(), static_cast<long long>(stats.faces),
              surface.n_vertices());
  return 0;
}

}  // namespace hbc::cli
