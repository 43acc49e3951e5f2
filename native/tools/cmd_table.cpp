// hbc table FILES|DIRS [--csv|--md|--latex] [-j N]: the paper's Table 1 for many meshes. Each
// mesh is analyzed by a child `hbc analyze --csv` process, N at a time, so that one mesh that
// fails (bad file, crash, out of memory) is reported in its row and never stops the others.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/schema.hpp"
#include "stats_format.hpp"

extern char** environ;

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

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

struct Job {
  pid_t pid;
  size_t row;
  std::string out, err;
};

Job start(const std::string& self, const std::string& file, size_t row, const std::string& tmp) {
  Job j{0, row, tmp + "/" + std::to_string(row) + ".out", tmp + "/" + std::to_string(row) + ".err"};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, j.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, j.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> argv_s = {self, "analyze", file, "--csv"};
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  if (posix_spawn(&j.pid, self.c_str(), &fa, nullptr, argv.data(), environ) != 0) j.pid = -1;
  posix_spawn_file_actions_destroy(&fa);
  return j;
}

void finish(const Job& j, int status, Row& r) {
  const std::string out = slurp(j.out), err = slurp(j.err);
  std::remove(j.out.c_str());
  std::remove(j.err.c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string msg = err;
    // Keep the error line itself; warnings before it are not the reason.
    const auto at = msg.rfind("error: ");
    if (at != std::string::npos) msg = msg.substr(at + 7);
    while (!msg.empty() && (msg.back() == '\n' || msg.back() == '\r')) msg.pop_back();
    if (WIFSIGNALED(status)) msg = "crashed (signal " + std::to_string(WTERMSIG(status)) + ")";
    r.error = msg.empty() ? "failed" : msg;
    return;
  }
  std::istringstream ss(out);
  std::string header, line;
  std::getline(ss, header);
  std::getline(ss, line);
  const auto keys = split(header, ','), vals = split(line, ',');
  for (size_t i = 0; i < keys.size() && i < vals.size(); ++i) r.values[keys[i]] = vals[i];
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
  std::vector<std::string> inputs;
  bool csv = false, md = false, latex = false;
  int jobs = 2;
};

void run_table(const TableArgs& args) {
  const bool csv = args.csv, latex = args.latex;
  const int jobs = args.jobs;
  const std::vector<std::string> files = collect(args.inputs);
  if (files.empty()) throw std::invalid_argument("no mesh files found in the given paths");

  const std::string self = fs::read_symlink("/proc/self/exe").string();
  char tmpl[] = "/tmp/hbc-table-XXXXXX";
  if (!mkdtemp(tmpl)) throw std::runtime_error("cannot create a temporary folder");
  const std::string tmp = tmpl;
  std::vector<Row> rows(files.size());
  std::vector<Job> running;
  size_t next = 0;
  while (next < files.size() || !running.empty()) {
    while (next < files.size() && static_cast<int>(running.size()) < jobs) {
      rows[next].file = files[next];
      Job j = start(self, files[next], next, tmp);
      if (j.pid < 0) rows[next].error = "could not start the analysis";
      else running.push_back(j);
      ++next;
    }
    if (running.empty()) continue;
    int status = 0;
    const pid_t done = waitpid(-1, &status, 0);
    auto it = std::find_if(running.begin(), running.end(), [&](const Job& j) { return j.pid == done; });
    if (it == running.end()) continue;
    finish(*it, status, rows[it->row]);
    running.erase(it);
  }
  fs::remove_all(tmp);

  int failures = 0;
  for (const Row& r : rows) failures += !r.error.empty();
  if (csv) {
    std::printf("%s,error\n", stats_csv_header().c_str());
    const auto keys = split(stats_csv_header(), ',');
    for (const Row& r : rows) {
      std::string line = r.file;
      for (size_t i = 1; i < keys.size(); ++i) {
        auto it = r.values.find(keys[i]);
        line += "," + (it == r.values.end() ? std::string() : it->second);
      }
      std::string err = r.error;
      std::replace(err.begin(), err.end(), ',', ';');
      std::printf("%s,%s\n", line.c_str(), err.c_str());
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
  cmd->callback([args] { run_table(*args); });
}

}  // namespace hbc::cli
