// hbc export-vtu FILE -o OUT.vtu [--sheet N] [--level complex|mesh] [--ascii]: the mesh with its
// analysis as cell and point data for ParaView, and the singularity graph in OUT_graph.vtu
// (vtu_export.hpp lists the arrays).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "hbc/vtu_export.hpp"

namespace hbc::cli {
namespace {

struct ExportVtuArgs {
  InputArgs input;
  std::string out;
  std::optional<int32_t> sheet;
  std::string level = "complex";
  bool ascii = false;
};

void run_export_vtu(const ExportVtuArgs& args) {
  VtuExportOptions vo;
  vo.ascii = args.ascii;
  vo.sheet = args.sheet;
  const AnalysisOptions opt = analysis_options(args.input, {{"wireframe", false}, {"level", args.level}});
  const Mesh mesh = load_for_cli(args.input);
  const Analysis a = analyze(mesh, opt);
  check_sheet_option(a, args.sheet);
  export_vtu(mesh, a, args.out, vo);
  std::printf("wrote %s: %zu cells, %zu components; %s: %zu singularity-graph edges\n", args.out.c_str(),
              mesh.num_cells(), a.complex.component_cells.rows(), vtu_graph_path(args.out).c_str(),
              a.graph.num_singular_edges() + a.graph.pseudo_singular_edges.size() + a.graph.non_manifold_edges.size());
}

}  // namespace

void add_export_vtu(CLI::App& app) {
  auto args = std::make_shared<ExportVtuArgs>();
  CLI::App* cmd = add_export_command(app, "export-vtu", "cells with component and sheet ids for ParaView (+ OUT_graph.vtu)",
                                     args->input, args->out, "the .vtu file to write");
  add_sheet_option(*cmd, args->sheet, "also write in_sheet and the subsheets of this sheet");
  add_level(*cmd, args->level, "level of the sheets");
  cmd->add_flag("--ascii", args->ascii, "text arrays instead of zlib-compressed base64");
  cmd->callback([args] { run_export_vtu(*args); });
}

}  // namespace hbc::cli
