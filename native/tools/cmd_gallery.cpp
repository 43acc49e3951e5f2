// hbc gallery DIR|FILES... -o SITE/ [--tags CSV] [-j N] [--dask ADDRESS] [--json-progress] ...: a
// browsable static site of a collection of meshes (docs/gallery.md). The site, its cache, the
// thumbnails (headless Chromium) and the work on a cluster are the Python package's (hbc.gallery),
// so this command runs `PYTHON -m hbc._gallery ARGS...` with the Python the report uses
// (locate.hpp: report_python) and exits with its status: every argument, --help included, is its.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "locate.hpp"
#include "run_children.hpp"

namespace hbc::cli {
namespace {

[[noreturn]] void run_gallery(const std::vector<std::string>& args) {
  const ReportPython py = report_python();
  std::vector<std::string> argv_s = {py.python, "-m", "hbc._gallery"};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<std::string> set_env;
  if (!py.package_dir.empty()) {
    const char* old = std::getenv("PYTHONPATH");
    set_env.push_back("PYTHONPATH=" + py.package_dir + (old && *old ? ":" + std::string(old) : std::string()));
  }
  const int rc = run_child(argv_s, set_env);
  if (rc == 127)
    std::fprintf(stderr, "hbc: error: hbc gallery needs Python with the hbc package: %s could not be started "
                         "(set HBC_PYTHON)\n", py.python.c_str());
  std::fflush(stdout);
  // The Python side's status is the command's (0 all measured, 1 some failed, 2 bad arguments).
  std::exit(rc);
}

}  // namespace

void add_gallery(CLI::App& app) {
  auto args = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand(
      "gallery", "a browsable static site of a collection of meshes: index.html, a viewer, a page per model "
                 "(docs/gallery.md; `hbc gallery --help` for its options)");
  cmd->prefix_command();
  cmd->set_help_flag();
  cmd->callback([cmd, args] { run_gallery(cmd->remaining()); });
}

}  // namespace hbc::cli
