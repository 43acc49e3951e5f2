#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "stats_format.hpp"

namespace hbc::cli {

int cmd_analyze(const Args& args_in) {
  Args args = args_in;
  const bool json = take_flag(args, "--json");
  const bool csv = take_flag(args, "--csv");
  AnalysisOptions opt;
  if (take_flag(args, "--no-sheets")) opt.sheets = false;
  if (take_flag(args, "--no-wireframe")) opt.wireframe = false;
  if (auto rho = take_option(args, "--rho")) opt.wireframe_options.rho = std::stod(*rho);
  if (auto level = take_option(args, "--level")) {
    if (*level == "mesh") {
      opt.sheet_level = Level::Mesh;
      opt.wireframe_level = Level::Mesh;
    }
    else if (*level != "complex") throw std::invalid_argument("--level takes complex or mesh");
  }
  const Format format = take_format(args);
  if (args.size() != 1)
    throw std::invalid_argument("usage: hbc analyze FILE [--json] [--csv] [--level complex|mesh] [--rho R] [--no-sheets] [--no-wireframe] [--format F]");
  double t_load = 0;
  const Mesh m = load_for_cli(args[0], format, &t_load);
  Analysis a = analyze(m, opt);
  a.timings.load = t_load;
  const Stats s = compute_stats(m, a);
  if (json) {
    JsonWriter w;
    w.begin().str("file", args[0]);
    write_stats_json(w, s);
    w.end();
    std::printf("%s\n", w.text().c_str());
  } else if (csv) {
    std::printf("%s\n%s\n", stats_csv_header().c_str(), stats_csv_row(args[0], s).c_str());
  } else {
    std::printf("%s", stats_table(args[0], s).c_str());
    for (const Subsheets& x : a.subsheets)
      std::printf("  self-intersecting sheet %d (%d blocks): %zu subsheets\n", x.sheet,
                  a.sheets.sheet_units.count(static_cast<size_t>(x.sheet)), x.size());
  }
  return 0;
}

}  // namespace hbc::cli
