// hbc export-surface FILE -o OUT.obj|.ply|.off [--what boundary|patches|components|sheets]: a surface of mesh faces through
// OpenMesh. Each --what only chooses the face list and the ids that colour it (surface.hpp).
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "hbc/structure_surfaces.hpp"
#include "hbc/surface.hpp"

namespace hbc::cli {

int cmd_export_surface(const Args& args_in) {
  Args args = args_in;
  auto out = take_option(args, "-o");
  auto what = take_option(args, "--what");
  auto sheet = take_option(args, "--sheet");
  const InputFormat format = take_format(args);
  if (!out || args.size() != 1)
    throw std::invalid_argument("usage: hbc export-surface FILE -o OUT.obj|.ply|.off [--what boundary|patches|components|sheets] [--sheet N] [--format F]");
  const std::string kind = what.value_or("boundary");
  const Mesh mesh = load_for_cli(args[0], format);
  FaceSelection sel;
  if (kind == "boundary") {
    sel = boundary_selection(mesh);
  } else if (kind == "patches" || kind == "components" || kind == "sheets") {
    AnalysisOptions opt;
    opt.sheets = kind == "sheets";
    opt.subsheets = false;
    opt.wireframe = false;
    const Analysis a = analyze(mesh, opt);
    if (kind == "patches") sel = patch_selection(mesh, a.complex);
    else if (kind == "components") sel = component_selection(mesh, a.complex);
    else {
      const int32_t s = sheet ? std::stoi(*sheet) : -1;
      if (s >= static_cast<int32_t>(a.sheets.size()))
        throw std::invalid_argument("--sheet " + std::to_string(s) + ": the mesh has " + std::to_string(a.sheets.size()) + " sheets");
      sel = sheet_selection(mesh, a.sheets, s);
    }
  } else {
    throw std::invalid_argument("--what must be boundary, patches, components or sheets, got '" + kind + "'");
  }
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
