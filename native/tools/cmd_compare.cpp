// hbc compare FILES... -o DIR [--names A,B,...] [--figures] [-j N] [--format F] [--threads T]
// [--skip-invalid]: the structural metrics of several meshes side by side (docs/compare.md). Each
// mesh is measured by a child process (the hidden `hbc compare-one FILE` with the reading options,
// N at a time, as in `hbc table`), so that a file that fails (bad input, crash, out of memory)
// fails only its own column. This process writes metrics.json, metrics.csv and metrics.tex with
// the library's writers (hbc/comparison.hpp, which hbc.compare() in Python uses too); report.html
// (plots, definitions, Blender panels) is written by the Python package (`python -m hbc.report
// DIR`), which needs matplotlib: when it cannot run, the three tables are still there and the exit
// status says what is missing.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/comparison.hpp"
#include "hbc/json.hpp"
#include "locate.hpp"
#include "run_children.hpp"

namespace hbc::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// ---- the child: one mesh ------------------------------------------------------------------

// The library's measurement of one mesh (hbc/comparison.hpp) as one JSON document on stdout.
void run_compare_one(const InputArgs& input) {
  double t_load = 0;
  std::vector<DroppedCell> dropped;
  const Mesh mesh = load_for_cli(input, &t_load, &dropped);
  write_output(json_text(comparison_measurement(mesh, input.file, input.threads, t_load, input.skip_invalid, dropped)),
               std::nullopt);
}

// ---- the parent: many meshes --------------------------------------------------------------

// Fills a column from its child's result.
void finish_child(const ChildResult& r, ComparisonColumn& c) {
  if (!r.started)
    c.error = "could not start the measurement";
  else if (!r.succeeded())
    c.error = r.failure("failed (exit status " + std::to_string(r.exit_code) + ")");
  else
    set_measurement(c, r.out);
}

void report_progress(size_t done, size_t total, const ComparisonColumn& c, double seconds) {
  if (c.error.empty())
    std::fprintf(stderr, "hbc compare: [%zu/%zu] %s: %.2f s\n", done, total, c.name.c_str(), seconds);
  else
    std::fprintf(stderr, "hbc compare: [%zu/%zu] %s: FAILED: %s\n", done, total, c.name.c_str(), c.error.c_str());
}

// Runs one child per column with the reading options, `jobs` at a time, and fills each column
// from its child; the children's warnings (what --skip-invalid dropped) go to our stderr.
void measure(std::vector<ComparisonColumn>& cols, int jobs, const InputArgs& reading) {
  ChildRuns runs;
  runs.count = cols.size();
  runs.jobs = jobs;
  runs.temp_name = "hbc-compare";
  runs.args = [&](size_t i) {
    std::vector<std::string> a = {"compare-one", cols[i].file};
    for (std::string& o : reading_args(reading)) a.push_back(std::move(o));
    return a;
  };
  size_t done = 0;
  run_children(runs, [&](size_t i, const ChildResult& r) {
    std::fputs(r.warnings().c_str(), stderr);
    finish_child(r, cols[i]);
    report_progress(++done, cols.size(), cols[i], r.seconds);
  });
}

// ---- the report -----------------------------------------------------------------------------

// Runs `PYTHON -m hbc.report DIR [--figures]` with the Python and package locate.hpp finds; its
// messages go to our stderr. Returns its exit status (127 when it could not start).
int run_report(const std::string& dir, bool figures) {
  const ReportPython py = report_python();
  std::vector<std::string> argv_s = {py.python, "-m", "hbc.report", dir};
  if (figures) argv_s.push_back("--figures");
  std::vector<std::string> set_env;
  if (!py.package_dir.empty()) {
    const char* old = std::getenv("PYTHONPATH");
    set_env.push_back("PYTHONPATH=" + py.package_dir + (old && *old ? ":" + std::string(old) : std::string()));
  }
  return run_child(argv_s, set_env);
}

struct CompareArgs {
  InputArgs reading;  // --format, --threads, --skip-invalid for every child (its file unused)
  std::vector<std::string> files;
  std::string out, names;
  bool figures = false, no_report = false;
  int jobs = 2;
};

std::vector<ComparisonColumn> columns_of(const CompareArgs& args) {
  std::vector<std::string> names;
  if (!args.names.empty()) {
    std::stringstream ss(args.names);
    for (std::string n; std::getline(ss, n, ',');) names.push_back(n);
  }
  return comparison_columns(args.files, names);
}

void run_compare(const CompareArgs& args) {
  std::vector<ComparisonColumn> cols = columns_of(args);
  fs::create_directories(args.out);
  const auto t0 = Clock::now();
  measure(cols, args.jobs, args.reading);
  const fs::path dir(args.out);
  write_output(json_text(comparison_json(cols, args.reading.skip_invalid)), (dir / "metrics.json").string());
  write_output(comparison_csv(cols), (dir / "metrics.csv").string());
  write_output(comparison_tex(cols), (dir / "metrics.tex").string());
  std::fprintf(stderr, "hbc compare: %zu mesh(es) measured in %.2f s; wrote %s/metrics.{json,csv,tex}\n",
               cols.size(), std::chrono::duration<double>(Clock::now() - t0).count(), args.out.c_str());
  int failures = 0;
  for (const ComparisonColumn& c : cols) failures += !c.error.empty();
  std::string problem;
  if (!args.no_report) {
    const int rc = run_report(args.out, args.figures);
    if (rc == 127)
      problem = "report.html not written: no Python to run hbc.report (set HBC_PYTHON)";
    else if (rc != 0)
      problem = "report.html not written (hbc.report exit status " + std::to_string(rc) +
                "; see its message above; HBC_PYTHON names a Python with the hbc package and matplotlib); "
                "metrics.json, metrics.csv and metrics.tex are complete";
  }
  if (failures) {
    const std::string f = std::to_string(failures) + " of " + std::to_string(cols.size()) +
                          " mesh(es) failed (see their columns and the errors entry of metrics.json)";
    problem = problem.empty() ? f : f + "; " + problem;
  }
  if (!problem.empty()) throw std::runtime_error(problem);
}

}  // namespace

void add_compare(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "structural metrics of several meshes side by side: metrics.json/.csv/.tex and report.html "
                 "(docs/compare.md)");
  cmd->add_option("FILES", args->files, "mesh files, one column each")->required();
  cmd->add_option("-o,--out", args->out, "output folder (created)")->required();
  cmd->add_option("--names", args->names, "column names, comma-separated, one per file (default: file names)");
  cmd->add_flag("--figures", args->figures, "render the comparison panels in Blender into the report");
  cmd->add_flag("--no-report", args->no_report, "write only metrics.json/.csv/.tex (no Python)");
  cmd->add_option("-j", args->jobs, "meshes measured at once")->check(CLI::Range(1, 256))->capture_default_str();
  add_reading_options(*cmd, args->reading);
  cmd->callback([args] { run_compare(*args); });

  // The child of one column: hidden, its JSON is an internal format of hbc compare.
  auto input = std::make_shared<InputArgs>();
  CLI::App* one = app.add_subcommand("compare-one", "");
  one->group("");
  add_input(*one, *input);
  one->callback([input] { run_compare_one(*input); });
}

}  // namespace hbc::cli
