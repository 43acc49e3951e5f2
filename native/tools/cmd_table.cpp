// hbc table FILES|DIRS [--csv|--md|--latex] [-j N] [--format F] [--threads T] [--skip-invalid]:
// the paper's Table 1 for many meshes. Each mesh is analyzed by a child `hbc analyze --csv`
// process with the reading options, N at a time, so that one mesh that fails (bad file, crash,
// out of memory) is reported in its row and never stops the others.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/schema.hpp"
#include "run_children.hpp"
#include "hbc/report.hpp"

namespace hbc::cli {
namespace {

namespace fs = std::filesystem;

struct Row {
  std::string file;
  std::map<std::string, std::string> values;  // CSV header -> value
  std::string error;                          // empty when the analysis succeeded
};

bool supported(const fs::path& p) {
  try {
    format_from_path(p.string());
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<std::string> collect(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const std::string& in : inputs) {
    const fs::path p(in);
    if (fs::is_directory(p)) {
      std::vector<std::string> found;
      for (const auto& e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file() && supported(e.path())) found.push_back(e.path().string());
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.push_back(in);
    }
  }
  return files;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream ss(line);
  while (std::getline(ss, cur, sep)) out.push_back(cur);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

// Fills a row from its child's `hbc analyze --csv`.
void finish(const ChildResult& c, Row& r) {
  if (!c.started) {
    r.error = "could not start the analysis";
    return;
  }
  if (!c.succeeded()) {
    r.error = c.failure("failed");
    return;
  }
  std::istringstream ss(c.out);
  std::string header;
  std::getline(ss, header);
  std::string line{std::istreambuf_iterator<char>(ss), {}};  // a quoted name may hold a line break
  if (!line.empty() && line.back() == '\n') line.pop_back();
  // The first field is the mesh's name, quoted when it holds a comma; the values after it never
  // do, so they are read from the end.
  const auto keys = split(header, ','), vals = split(line, ',');
  if (vals.size() < keys.size()) {
    r.error = "the analysis printed no row of " + std::to_string(keys.size()) + " fields";
    return;
  }
  const size_t shift = vals.size() - keys.size();
  for (size_t i = 1; i < keys.size(); ++i) r.values[keys[i]] = vals[i + shift];
}

// A Table 1 cell from a row's CSV values: times in milliseconds, everything else as printed.
std::string cell(const Row& r, const Table1Column& c) {
  const std::string key = (c.timing ? "t_" : "") + std::string(c.field->key);
  auto it = r.values.find(key);
  if (it == r.values.end()) return "";
  if (c.timing) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", std::stod(it->second) * 1e3);
    return buf;
  }
  return it->second;
}

// The Markdown head of a column: the paper's symbol, times marked as milliseconds.
std::string title(const Table1Column& c) { return std::string(c.field->notation) + (c.timing ? " ms" : ""); }

std::string name_of(const std::string& file) { return fs::path(file).filename().string(); }

struct TableArgs {
  InputArgs reading;  // --format, --threads, --skip-invalid for every child (its file unused)
  std::vector<std::string> inputs;
  bool csv = false, md = false, latex = false;
  int jobs = 2;
};

void run_table(const TableArgs& args) {
  const bool csv = args.csv, latex = args.latex;
  const int jobs = args.jobs;
  const std::vector<std::string> files = collect(args.inputs);
  if (files.empty()) throw std::invalid_argument("no mesh files found in the given paths");

  std::vector<Row> rows(files.size());
  for (size_t i = 0; i < files.size(); ++i) rows[i].file = files[i];
  ChildRuns runs;
  runs.count = files.size();
  runs.jobs = jobs;
  runs.temp_name = "hbc-table";
  runs.args = [&](size_t i) {
    std::vector<std::string> a = {"analyze", files[i], "--csv"};
    for (std::string& o : reading_args(args.reading)) a.push_back(std::move(o));
    return a;
  };
  run_children(runs, [&](size_t i, const ChildResult& c) {
    std::fputs(c.warnings().c_str(), stderr);  // what --skip-invalid dropped, faces in no cell, ...
    finish(c, rows[i]);
  });

  int failures = 0;
  for (const Row& r : rows) failures += !r.error.empty();
  if (csv) {
    std::printf("%s,error\n", stats_csv_header().c_str());
    const auto keys = split(stats_csv_header(), ',');
    for (const Row& r : rows) {
      std::string line = csv_quoted(r.file);
      for (size_t i = 1; i < keys.size(); ++i) {
        auto it = r.values.find(keys[i]);
        line += "," + (it == r.values.end() ? std::string() : it->second);
      }
      std::printf("%s,%s\n", line.c_str(), csv_quoted(r.error).c_str());
    }
  } else if (latex) {
    std::printf("\\begin{tabular}{c|cc|cc|cccc|c|ccccc}\nModels");
    for (const Table1Column& c : table1_columns()) std::printf(" & %s", std::string(c.field->latex).c_str());
    std::printf(" \\\\ \\hline\n");
    for (const Row& r : rows) {
      std::string n = name_of(r.file);
      for (size_t p = 0; (p = n.find('_', p)) != std::string::npos; p += 2) n.insert(p, "\\");
      std::printf("%s", n.c_str());
      if (!r.error.empty()) std::printf(" & \\multicolumn{%zu}{l}{failed}", table1_columns().size());
      else
        for (const Table1Column& c : table1_columns()) std::printf(" & %s", cell(r, c).c_str());
      std::printf(" \\\\\n");
    }
    std::printf("\\end{tabular}\n");
  } else {
    std::printf("| mesh |");
    for (const Table1Column& c : table1_columns()) std::printf(" %s |", title(c).c_str());
    std::printf("\n|---|");
    for (size_t i = 0; i < table1_columns().size(); ++i) std::printf("---:|");
    std::printf("\n");
    for (const Row& r : rows) {
      std::printf("| %s |", name_of(r.file).c_str());
      if (!r.error.empty()) {
        std::printf(" failed: %s |", r.error.c_str());
        for (size_t i = 1; i < table1_columns().size(); ++i) std::printf(" |");
      } else {
        for (const Table1Column& c : table1_columns()) std::printf(" %s |", cell(r, c).c_str());
      }
      std::printf("\n");
    }
  }
  if (failures) std::fprintf(stderr, "hbc: %d of %zu mesh(es) failed (see their rows)\n", failures, rows.size());
}

}  // namespace

void add_table(CLI::App& app) {
  auto args = std::make_shared<TableArgs>();
  CLI::App* cmd = app.add_subcommand("table", "Table 1 for many meshes (one process each)");
  cmd->add_option("FILES", args->inputs, "mesh files, or folders searched for them")->required();
  auto* csv = cmd->add_flag("--csv", args->csv, "CSV with an error column");
  auto* md = cmd->add_flag("--md", args->md, "Markdown (the default)");
  auto* latex = cmd->add_flag("--latex", args->latex, "LaTeX tabular");
  csv->excludes(md)->excludes(latex);
  md->excludes(latex);
  cmd->add_option("-j", args->jobs, "meshes analyzed at once")->check(CLI::Range(1, 256))->capture_default_str();
  add_reading_options(*cmd, args->reading);
  cmd->callback([args] { run_table(*args); });
}

}  // namespace hbc::cli
