// hbc compare FILES... -o DIR [--names A,B,...] [--figures] [-j N] [--format F] [--threads T]
// [--skip-invalid]: the structural metrics of several meshes side by side (docs/compare.md). Each
// mesh is measured by a child process (the hidden `hbc compare-one FILE` with the reading options,
// N at a time, as in `hbc table`), so that a file that fails (bad input, crash, out of memory)
// fails only its own column. This process writes metrics.json,
// metrics.csv and metrics.tex itself; report.html (plots, definitions, Blender panels) is written
// by the Python package (`python -m hbc.report DIR`), which needs matplotlib: when it cannot run,
// the three tables are still there and the exit status says what is missing.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/cell_quality.hpp"
#include "hbc/metrics.hpp"
#include "hbc/version.hpp"
#include "hbc/json.hpp"
#include "metrics_json.hpp"
#include "run_children.hpp"
#include "hbc/report.hpp"

namespace hbc::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// ---- the child: one mesh ------------------------------------------------------------------

// Scaled Jacobian histograms per cell type, with the bins of QualitySummary (20 bins of 0.1 over
// [-1, 1]; below -1 to the first, 1.0 to the last), for the report's per-type histograms.
Json sj_histograms(const Mesh& mesh, const Threads& threads) {
  const std::vector<double> sj = scaled_jacobians(mesh, threads);
  std::vector<std::vector<int64_t>> bins(5, std::vector<int64_t>(20, 0));
  std::vector<int64_t> count(5, 0);
  for (size_t c = 0; c < sj.size(); ++c) {
    const int t = static_cast<int>(mesh.cell_type[c]);
    const double v = std::isfinite(sj[c]) ? sj[c] : -1.0;
    const int b = std::clamp(static_cast<int>(std::floor((v + 1.0) / 0.1 + 1e-9)), 0, 19);
    ++bins[t][b];
    ++count[t];
  }
  Json by_type = Json::object();
  for (int t = 0; t < 5; ++t)
    if (count[t] > 0) by_type[cell_type_name(static_cast<CellType>(t))] = bins[t];
  return by_type;
}

// `hbc metrics --json`'s object (the same analysis options: no wireframe, the authors' subsheet
// rule) beside the per-type scaled Jacobian histograms, and with --skip-invalid what was dropped
// (as `hbc analyze --json` says it), as one JSON document on stdout.
void run_compare_one(const InputArgs& input) {
  const AnalysisOptions opt = analysis_options(input, {{"wireframe", false}});
  double t_load = 0;
  std::vector<DroppedCell> dropped;
  const Mesh mesh = load_for_cli(input, &t_load, &dropped);
  const auto t0 = Clock::now();
  const Analysis analysis = analyze(mesh, opt);
  const auto t1 = Clock::now();
  const Metrics m = compute_metrics(mesh, analysis, input.load_threads());
  const auto t2 = Clock::now();
  const Json timings = {{"load", t_load},
                        {"analysis", std::chrono::duration<double>(t1 - t0).count()},
                        {"metrics", std::chrono::duration<double>(t2 - t1).count()}};
  Json out = {{"metrics", metrics_json(input.file, m, timings)},
              {"scaled_jacobian_by_type", sj_histograms(mesh, input.load_threads())}};
  add_dropped_json(out, input.skip_invalid, dropped);
  write_output(json_text(out), std::nullopt);
}

// ---- the parent: many meshes --------------------------------------------------------------

struct Column {
  std::string name, file;
  Json metrics;         // the child's "metrics" (null when it failed)
  Json sj_by_type;      // the child's "scaled_jacobian_by_type"
  Json dropped;         // the child's "dropped" (--skip-invalid; null without it or when it failed)
  std::string error;    // empty when the child succeeded
  double seconds = 0;
};

// Fills a column from its child's result.
void finish_child(const ChildResult& r, Column& c) {
  c.seconds = r.seconds;
  if (!r.started) {
    c.error = "could not start the measurement";
    return;
  }
  if (!r.succeeded()) {
    c.error = r.failure("failed (exit status " + std::to_string(r.exit_code) + ")");
    return;
  }
  try {
    Json doc = Json::parse(r.out);
    c.metrics = std::move(doc.at("metrics"));
    c.sj_by_type = std::move(doc.at("scaled_jacobian_by_type"));
    if (doc.contains("dropped")) c.dropped = std::move(doc.at("dropped"));
  } catch (const std::exception& e) {
    c.error = std::string("unreadable result: ") + e.what();
  }
}

void report_progress(size_t done, size_t total, const Column& c) {
  if (c.error.empty())
    std::fprintf(stderr, "hbc compare: [%zu/%zu] %s: %.2f s\n", done, total, c.name.c_str(), c.seconds);
  else
    std::fprintf(stderr, "hbc compare: [%zu/%zu] %s: FAILED: %s\n", done, total, c.name.c_str(), c.error.c_str());
}

// Runs one child per column with the reading options, `jobs` at a time, and fills each column
// from its child; the children's warnings (what --skip-invalid dropped) go to our stderr.
void measure(std::vector<Column>& cols, int jobs, const InputArgs& reading) {
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
    report_progress(++done, cols.size(), cols[i]);
  });
}

// ---- the outputs --------------------------------------------------------------------------

// The value of group.key in a column (NaN when the column failed or the value is null).
double value_of(const Column& c, const MetricField& f) {
  if (!c.error.empty()) return std::nan("");
  const Json& g = c.metrics.at(std::string(f.group));
  const Json& v = g.at(std::string(f.key));
  return v.is_number() ? v.get<double>() : std::nan("");
}

Json field_json(const MetricField& f) {
  return {{"key", std::string(f.group) + "." + std::string(f.key)}, {"group", std::string(f.group)},
          {"label", std::string(f.label)}, {"unit", std::string(f.unit)}, {"meaning", std::string(f.meaning)},
          {"refinement", refinement_name(f.refinement)}};
}

Json comparison_json(const std::vector<Column>& cols, bool skip_invalid) {
  Json j = {{"hbc_version", version()}};
  Json& meshes = j["meshes"] = Json::array();
  for (const Column& c : cols) {
    meshes.push_back({{"name", c.name}, {"file", c.file}, {"error", c.error.empty() ? Json() : Json(c.error)}});
    if (skip_invalid) meshes.back()["dropped"] = c.dropped;
  }
  Json& fields = j["fields"] = Json::array();
  Json& values = j["values"] = Json::object();
  for (const MetricField& f : metric_fields()) {
    fields.push_back(field_json(f));
    Json& row = values[std::string(f.group) + "." + std::string(f.key)] = Json::array();
    for (const Column& c : cols) {
      // The child's own JSON number (integer or double), so values equal `hbc metrics --json`.
      if (c.error.empty()) row.push_back(c.metrics.at(std::string(f.group)).at(std::string(f.key)));
      else row.push_back(nullptr);
    }
  }
  Json& per_mesh = j["metrics"] = Json::array();
  for (const Column& c : cols) per_mesh.push_back(c.error.empty() ? c.metrics : Json());
  Json& sj = j["scaled_jacobian_histograms"];
  sj["bin_edges"] = Json::array();
  for (int i = 0; i <= 20; ++i) sj["bin_edges"].push_back(std::round((-1.0 + 0.1 * i) * 10) / 10);
  sj["by_type"] = Json::array();
  for (const Column& c : cols) sj["by_type"].push_back(c.error.empty() ? c.sj_by_type : Json());
  Json& errors = j["errors"] = Json::object();
  for (const Column& c : cols)
    if (!c.error.empty()) errors[c.name] = c.error;
  return j;
}

// One row per mesh with `hbc metrics --csv`'s columns (group.key, the same number format), its
// name first and its error last.
std::string comparison_csv(const std::vector<Column>& cols) {
  std::string out = "name,mesh";
  for (const MetricField& f : metric_fields()) out.append(",").append(f.group).append(".").append(f.key);
  out += ",error\n";
  for (const Column& c : cols) {
    out += csv_quoted(c.name) + "," + csv_quoted(c.file);
    for (const MetricField& f : metric_fields()) out += "," + number_text(value_of(c, f));
    out += "," + csv_quoted(c.error) + "\n";
  }
  return out;
}

std::string latex_escaped(const std::string& s) {
  std::string o;
  for (char ch : s) {
    switch (ch) {
      case '\\': o += "\\textbackslash{}"; break;
      case '~': o += "\\textasciitilde{}"; break;
      case '^': o += "\\textasciicircum{}"; break;
      case '&': case '%': case '$': case '#': case '_': case '{': case '}': o += '\\'; o += ch; break;
      default: o += ch;
    }
  }
  return o;
}

// A cell of the LaTeX table: counts as integers with thin-space thousands, ratios with 3 decimals.
std::string latex_number(double v, const MetricField& f) {
  if (!std::isfinite(v)) return "--";
  char buf[48];
  if (f.unit == "ratio" || v != std::floor(v)) {
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.0f", std::fabs(v));
  std::string digits = buf, o;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) o += "\\,";
    o += digits[i];
  }
  return (v < 0 ? "-" : "") + o;
}

constexpr const char* kGroupTitles[][2] = {{"census", "Census"},
                                           {"singular", "Singular structure"},
                                           {"complex", "Hybrid base complex"},
                                           {"sheets", "Sheets"},
                                           {"non_hex", "Non-hex clustering"},
                                           {"quality", "Quality beside structure"},
                                           {"summary", "Summary"}};

std::string group_title(std::string_view g) {
  for (const auto& t : kGroupTitles)
    if (g == t[0]) return t[1];
  return std::string(g);
}

// A booktabs table, one column per mesh, one row per metric grouped as in docs/metrics.md; a
// failed mesh's column shows "failed" and its error in the notes under the table.
std::string comparison_tex(const std::vector<Column>& cols) {
  const size_t ncol = 2 + cols.size();
  std::string o = "% hbc compare (hbc " + std::string(version()) + "): needs \\usepackage{booktabs}\n";
  o += "\\begin{table}[t]\n\\centering\n\\small\n\\begin{tabular}{ll" + std::string(cols.size(), 'r') + "}\n";
  o += "\\toprule\nMetric & Unit";
  for (const Column& c : cols) o += " & " + latex_escaped(c.name);
  o += " \\\\\n";
  std::string_view group;
  for (const MetricField& f : metric_fields()) {
    if (f.group != group) {
      group = f.group;
      o += "\\midrule\n\\multicolumn{" + std::to_string(ncol) + "}{l}{\\emph{" + group_title(group) + "}} \\\\\n";
    }
    o += latex_escaped(std::string(f.label)) + " & " + (f.unit == "ratio" ? std::string() : latex_escaped(std::string(f.unit)));
    for (const Column& c : cols) o += " & " + (c.error.empty() ? latex_number(value_of(c, f), f) : std::string("failed"));
    o += " \\\\\n";
  }
  o += "\\bottomrule\n";
  for (const Column& c : cols)
    if (!c.error.empty())
      o += "\\multicolumn{" + std::to_string(ncol) + "}{l}{\\footnotesize " + latex_escaped(c.name) +
           ": " + latex_escaped(c.error) + "} \\\\\n";
  o += "\\end{tabular}\n\\caption{Structural metrics (hbc compare; definitions in docs/metrics.md).}\n"
       "\\label{tab:hbc-compare}\n\\end{table}\n";
  return o;
}

// ---- the report -----------------------------------------------------------------------------

// The folder holding the hbc package next to this executable (the build tree's bin/../python),
// when there is one.
std::string package_dir_beside(const fs::path& exe) {
  const fs::path p = exe.parent_path().parent_path() / "python";
  return fs::exists(p / "hbc" / "report.py") ? p.string() : std::string();
}

// The Python a build tree's package was built for (its CMakeCache's Python_EXECUTABLE), when this
// executable is BUILD/bin/hbc: the one interpreter its compiled module surely imports in.
std::string build_python(const fs::path& exe) {
  std::ifstream cache(exe.parent_path().parent_path() / "CMakeCache.txt");
  for (std::string line; std::getline(cache, line);)
    if (line.rfind("Python_EXECUTABLE:", 0) == 0) return line.substr(line.find('=') + 1);
  return "";
}

// Runs `PYTHON -m hbc.report DIR [--figures]` (PYTHON: $HBC_PYTHON, else the build tree's, else
// python3 on PATH) with the package beside this executable first on PYTHONPATH; its messages go to
// our stderr. Returns its exit status (127 when it could not start).
int run_report(const std::string& dir, bool figures) {
  const fs::path exe = fs::read_symlink("/proc/self/exe");
  const char* py_env = std::getenv("HBC_PYTHON");
  const std::string pkg = package_dir_beside(exe);
  std::string python = py_env && *py_env ? py_env : pkg.empty() ? "" : build_python(exe);
  if (python.empty()) python = "python3";
  std::vector<std::string> argv_s = {python, "-m", "hbc.report", dir, "--cli", exe.string()};
  if (figures) argv_s.push_back("--figures");
  std::vector<std::string> set_env;
  if (!pkg.empty()) {
    const char* old = std::getenv("PYTHONPATH");
    set_env.push_back("PYTHONPATH=" + pkg + (old && *old ? ":" + std::string(old) : std::string()));
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

std::vector<Column> columns_of(const CompareArgs& args) {
  std::vector<std::string> names;
  if (!args.names.empty()) {
    std::stringstream ss(args.names);
    for (std::string n; std::getline(ss, n, ',');) names.push_back(n);
    if (names.size() != args.files.size())
      throw std::invalid_argument("--names gives " + std::to_string(names.size()) + " names for " +
                                  std::to_string(args.files.size()) + " files");
  }
  std::vector<Column> cols(args.files.size());
  std::set<std::string> seen;
  for (size_t i = 0; i < cols.size(); ++i) {
    cols[i].file = args.files[i];
    std::string n = names.empty() ? fs::path(args.files[i]).filename().string() : names[i];
    // Two files of one name (a.mesh in two folders) stay two columns.
    const std::string base = n;
    for (int k = 2; seen.count(n); ++k) n = base + " (" + std::to_string(k) + ")";
    seen.insert(n);
    cols[i].name = n;
  }
  return cols;
}

void run_compare(const CompareArgs& args) {
  std::vector<Column> cols = columns_of(args);
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
  for (const Column& c : cols) failures += !c.error.empty();
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
