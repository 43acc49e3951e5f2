// hbc: the structure analyser for hex-dominant meshes, command-line front end.
#include <cstdio>
#include <exception>
#include <iostream>
#include <stdexcept>

#include "commands.hpp"

namespace {

const char* kUsage =
    "usage: hbc COMMAND [options]\n"
    "commands:\n"
    "  info FILE [--json] [--format F]            counts of the mesh (SPEC §5 keys)\n"
    "  analyze FILE [--json] [--csv] [--format F] hybrid singularity graph and base complex\n"
    "  sheets FILE [--json] [--level complex|mesh] sheets with type flags, sizes, subsheets\n"
    "  table FILES|DIRS [--csv|--md|--latex] [-j N] Table 1 for many meshes (one process each)\n"
    "  quality FILE [--json] [--format F]         scaled Jacobian, edge ratio per cell type (Verdict)\n"
    "  generate KIND [options] -o FILE            synthetic meshes with known structure\n"
    "  export-surface FILE -o OUT.obj|.ply|.off [--what boundary|patches|components|sheets] [--sheet N]\n"
    "                                             surfaces with per-face ids, through OpenMesh\n"
    "  export-vtu FILE -o OUT.vtu [--sheet N] [--level complex|mesh] [--ascii]\n"
    "                                             cells with block/sheet ids for ParaView (+ OUT_graph.vtu)\n"
    "  wireframe FILE [--level complex|mesh] [--rho R] [--sheet N] [--json|--obj] [-o OUT]\n"
    "                                             VSG wireframe (SPEC §4)\n"
    "formats: ovm, ovmb, mesh, hybrid, hedra, msh, vtk, vtu (chosen by extension unless --format is given)\n"
    "--threads N: threads for reading a mesh (default: HBC_THREADS, else every core)\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace hbc::cli;
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 1;
  }
  const std::string cmd = argv[1];
  Args args(argv + 2, argv + argc);
  try {
    if (cmd == "info") return cmd_info(args);
    if (cmd == "analyze") return cmd_analyze(args);
    if (cmd == "wireframe") return cmd_wireframe(args);
    if (cmd == "sheets") return cmd_sheets(args);
    if (cmd == "table") return cmd_table(args);
    if (cmd == "quality") return cmd_quality(args);
    if (cmd == "generate") return cmd_generate(args);
    if (cmd == "export-surface") return cmd_export_surface(args);
    if (cmd == "export-vtu") return cmd_export_vtu(args);
    if (cmd == "-h" || cmd == "--help" || cmd == "help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    std::fprintf(stderr, "hbc: unknown command '%s'\n%s", cmd.c_str(), kUsage);
    return 1;
  } catch (const hbc::InputError& e) {
    std::fprintf(stderr, "hbc: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "hbc: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "hbc: error: out of memory\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hbc: error: %s\n", e.what());
    return 2;
  }
}
