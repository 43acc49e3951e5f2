// hbc analyze FILE [--json|--csv]: the whole pipeline and the statistics of the paper's Table 1
// (docs/concepts.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <utility>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "hbc/report.hpp"
#include "hbc/wireframe_style.hpp"

namespace hbc::cli {
namespace {

struct AnalyzeArgs {
  InputArgs input;
  bool json = false, csv = false, no_sheets = false, no_wireframe = false;
  std::string level = "complex";
  double rho = WireframeStyleOptions{}.rho;  // checked, then unused (below)
  std::string subsheets = "layers";
};

void run_analyze(const AnalyzeArgs& args) {
  const AnalysisOptions opt = analysis_options(args.input, {{"sheets", !args.no_sheets},
                                                            {"wireframe", !args.no_wireframe},
                                                            {"level", args.level},
                                                            {"subsheet_rule", args.subsheets}});
  double t_load = 0;
  std::vector<DroppedCell> dropped;
  Mesh m = load_for_cli(args.input, &t_load, &dropped);
  // Only counts are printed: analyze_stats drops each stage once counted, and the mesh once only the
  // wireframe's view is still to be built, a lower peak at 10^7 cells.
  StatsRun run = analyze_stats(std::move(m), opt);
  run.stats.timings.load = t_load;
  const Stats& s = run.stats;
  const std::string& file = args.input.file;
  if (args.json) {
    Json j = {{"file", file}};
    add_stats_json(j, s);
    add_dropped_json(j, args.input.skip_invalid, dropped);
    write_output(json_text(j), std::nullopt);
  } else if (args.csv) {
    std::printf("%s\n%s\n", stats_csv_header().c_str(), stats_csv_row(file, s).c_str());
  } else {
    std::printf("%s", stats_table(file, s).c_str());
    for (const SubsheetCount& x : run.subsheet_counts)
      std::printf("  self-intersecting sheet %d (%d blocks): %lld subsheets\n", x.sheet, x.blocks,
                  static_cast<long long>(x.subsheets));
  }
}

}  // namespace

void add_analyze(CLI::App& app) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = add_mesh_command(app, "analyze", "hybrid singularity graph, base complex, sheets and VSG wireframe",
                                   args->input, args->json, "print the statistics (the paper's Table 1 and more) as JSON");
  cmd->add_flag("--csv", args->csv, "print them as one CSV header and row")->excludes("--json");
  add_level(*cmd, args->level, "level of sheets and wireframe");
  // rho only sets the wireframe's colour classes, which the analysis no longer computes (the render
  // layer's wireframe_style does, for what shows them): nothing here depends on it. It stays, range
  // checked, for the command lines that already pass it.
  cmd->add_option("--rho", args->rho, "colour-class threshold of the wireframe (presentation only: no count depends on it)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_flag("--no-sheets", args->no_sheets, "skip the sheet stages");
  cmd->add_option("--subsheets", args->subsheets,
                  "decomposition of self-intersecting sheets: layers (the paper's authors' rule) or fewest")
      ->check(CLI::IsMember({"layers", "fewest"}))
      ->capture_default_str();
  cmd->add_flag("--no-wireframe", args->no_wireframe, "skip the wireframe stage");
  cmd->callback([args] { run_analyze(*args); });
}

}  // namespace hbc::cli
