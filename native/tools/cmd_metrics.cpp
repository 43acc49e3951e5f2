// hbc metrics FILE [--json|--csv]: structural complexity metrics of a hex-dominant mesh
// (hbc/metrics.hpp; every metric defined in docs/metrics.md). Keys, labels and units come from
// metric_fields(), so the text, JSON and CSV outputs and the Python binding cannot drift apart.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "hbc/comparison.hpp"
#include "hbc/metrics.hpp"
#include "hbc/json.hpp"
#include "hbc/report.hpp"

namespace hbc::cli {
namespace {

struct MetricsArgs {
  InputArgs input;
  bool json = false, csv = false, no_quality = false;
  std::string subsheets = "layers";
};

void run_metrics(const MetricsArgs& args) {
  // No metric reads the wireframe.
  const AnalysisOptions opt = analysis_options(args.input, {{"wireframe", false}, {"subsheet_rule", args.subsheets}});
  double t_load = 0;
  const Mesh mesh = load_for_cli(args.input, &t_load);
  const auto t0 = std::chrono::steady_clock::now();
  const Analysis analysis = analyze(mesh, opt);
  const auto t1 = std::chrono::steady_clock::now();
  MetricsOptions mo;
  mo.quality = !args.no_quality;
  const Metrics m = compute_metrics(mesh, analysis, args.input.load_threads(), mo);
  const auto t2 = std::chrono::steady_clock::now();
  // The load, the analysis (its stages as in `hbc analyze`, without the wireframe) and the metrics.
  const Json timings = {{"load", t_load},
                        {"analysis", std::chrono::duration<double>(t1 - t0).count()},
                        {"metrics", std::chrono::duration<double>(t2 - t1).count()}};
  const auto fields = metric_fields();
  const std::string& file = args.input.file;
  if (args.json) {
    write_output(json_text(metrics_json(file, m, timings)), std::nullopt);
  } else if (args.csv) {
    std::string head = "mesh", row = csv_quoted(file);
    for (size_t i = 0; i < fields.size(); ++i) {
      head.append(",").append(fields[i].group).append(".").append(fields[i].key);
      row.append(",").append(number_text(m.values[i]));
    }
    // The deprecated columns last, so a reader of the old names finds them and the others keep their place.
    for (const MetricAlias& a : metric_aliases()) {
      const int i = metric_index(a.group, a.key);
      if (i < 0) continue;  // a distribution, not a CSV column
      head.append(",").append(a.group).append(".").append(a.old_key);
      row.append(",").append(number_text(m.values[static_cast<size_t>(i)]));
    }
    std::printf("%s\n%s\n", head.c_str(), row.c_str());
  } else {
    std::printf("%s\n", file.c_str());
    std::string_view group;
    for (size_t i = 0; i < fields.size(); ++i) {
      if (fields[i].group != group) {
        group = fields[i].group;
        std::printf("%.*s\n", static_cast<int>(group.size()), group.data());
      }
      const std::string v = number_text(m.values[i]);
      std::printf("  %-40.*s %14s  %.*s\n", static_cast<int>(fields[i].label.size()), fields[i].label.data(),
                  v.empty() ? "-" : v.c_str(), static_cast<int>(fields[i].unit.size()), fields[i].unit.data());
    }
  }
}

}  // namespace

void add_metrics(CLI::App& app) {
  auto args = std::make_shared<MetricsArgs>();
  CLI::App* cmd = add_mesh_command(app, "metrics",
                                   "structural complexity metrics: census, singular structure, base complex, sheets, "
                                   "non-hex clustering, quality beside structure (docs/metrics.md)",
                                   args->input, args->json, "print the metrics as JSON, grouped, with distributions");
  cmd->add_flag("--csv", args->csv, "print one CSV header (group.key) and row")->excludes("--json");
  cmd->add_flag("--no-quality", args->no_quality,
                "skip the quality group (the scaled Jacobian of every cell, most of the metrics' time): its values are null");
  cmd->add_option("--subsheets", args->subsheets,
                  "decomposition of self-intersecting sheets: layers (the paper's authors' rule) or fewest")
      ->check(CLI::IsMember({"layers", "fewest"}))
      ->capture_default_str();
  cmd->callback([args] { run_metrics(*args); });
}

}  // namespace hbc::cli
