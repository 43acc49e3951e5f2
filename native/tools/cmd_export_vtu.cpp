// hbc export-vtu FILE -o OUT.vtu [--sheet N] [--level complex|mesh] [--ascii]: the mesh with its
// analysis as cell and point data for ParaView, and the singularity graph in OUT_graph.vtu
// (vtu_export.hpp lists the arrays).
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "hbc/vtu_export.hpp"

namespace hbc::cli {

int cmd_export_vtu(const Args& args_in) {
  Args args = args_in;
  auto out = take_option(args, "-o");
  auto sheet = take_option(args, "--sheet");
  auto level = take_option(args, "--level");
  VtuExportOptions vo;
  vo.ascii = take_flag(args, "--ascii");
  const InputFormat format = take_format(args);
  if (!out || args.size() != 1)
    throw std::invalid_argument("usage: hbc export-vtu FILE -o OUT.vtu [--sheet N] [--level complex|mesh] [--ascii] [--format F]");
  AnalysisOptions opt;
  opt.wireframe = false;
  if (level && *level == "mesh") opt.sheet_level = SheetLevel::Mesh;
  else if (level && *level != "complex") throw std::invalid_argument("--level takes complex or mesh");
  if (sheet) vo.sheet = std::stoi(*sheet);
  const Mesh mesh = load_for_cli(args[0], format);
  const Analysis a = analyze(mesh, opt);
  export_vtu(mesh, a, *out, vo);
  std::printf("wrote %s: %zu cells, %zu components; %s: %zu singularity-graph edges\n", out->c_str(), mesh.num_cells(),
              a.complex.component_cells.rows(), vtu_graph_path(*out).c_str(),
              a.graph.num_singular_edges() + a.graph.pseudo_singular_edges.size() + a.graph.non_manifold_edges.size());
  return 0;
}

}  // namespace hbc::cli
