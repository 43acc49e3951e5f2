// hbc export-surface FILE -o OUT.obj|.ply|.off [--what boundary|patches|components|sheets]: a surface of mesh faces through
// OpenMesh. Each --what only chooses the face list and the ids that colour it (surface.hpp).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "hbc/face_selection.hpp"
#include "hbc/surface.hpp"

namespace hbc::cli {
namespace {

struct ExportSurfaceArgs {
  InputArgs input;
  std::string out;
  std::string what = "boundary";
  std::optional<int32_t> sheet;
};

FaceSelection selection(const Mesh& mesh, const ExportSurfaceArgs& args) {
  if (args.what == "boundary") return boundary_selection(mesh);
  const AnalysisOptions opt =
      analysis_options(args.input, {{"sheets", args.what == "sheets"}, {"subsheets", false}, {"wireframe", false}});
  const Analysis a = analyze(mesh, opt);
  if (args.what == "patches") return patch_selection(mesh, a.complex);
  if (args.what == "components") return component_selection(mesh, a.complex);
  check_sheet_option(a, args.sheet);
  return sheet_selection(mesh, a.sheet_stage->sheets, args.sheet);
}

void run_export_surface(const ExportSurfaceArgs& args) {
  const Mesh mesh = load_for_cli(args.input);
  SurfaceStats stats;
  const SurfaceMesh surface = build_surface(mesh, selection(mesh, args), &stats);
  write_surface(surface, args.out);
  if (stats.unwelded_faces > 0)
    std::fprintf(stderr, "hbc: warning: %lld face(s) at non-manifold edges or vertices written unwelded\n",
                 static_cast<long long>(stats.unwelded_faces));
  std::printf("wrote %s: %lld faces, %zu vertices\n", args.out.c_str(), static_cast<long long>(stats.faces),
              surface.n_vertices());
}

}  // namespace

void add_export_surface(CLI::App& app) {
  auto args = std::make_shared<ExportSurfaceArgs>();
  CLI::App* cmd = add_export_command(app, "export-surface", "surfaces with per-face ids, through OpenMesh", args->input,
                                     args->out, "output surface, .obj, .ply or .off");
  cmd->add_option("--what", args->what, "which faces")
      ->check(CLI::IsMember({"boundary", "patches", "components", "sheets"}))
      ->capture_default_str();
  add_sheet_option(*cmd, args->sheet, "with --what sheets: that sheet only (default: all)");
  cmd->callback([args] { run_export_surface(*args); });
}

}  // namespace hbc::cli
