// hbc quality FILE [--json]: Verdict's scaled Jacobian and edge ratio (cell_quality.hpp) summarised
// per cell type.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "hbc/cell_quality.hpp"
#include "hbc/json.hpp"

namespace hbc::cli {
namespace {

struct QualityArgs {
  InputArgs input;
  bool json = false;
};

// count, min, mean, max and the histogram (plus `inverted`, the negative values, for the scaled
// Jacobian); a measure over no cell has null statistics.
Json stats_json(const MeasureStats& s, bool inverted) {
  Json j = {{"count", s.count}, {"min", s.min}, {"mean", s.mean}, {"max", s.max}};
  if (inverted) j["inverted"] = s.negative;
  j["histogram"] = s.histogram;
  return j;
}

Json measure_json(const std::vector<double>& edges, const MeasureStats& all, const std::array<MeasureStats, 5>& per_type,
                  bool inverted) {
  Json j = stats_json(all, inverted);
  j["bin_edges"] = edges;
  Json& types = j["per_type"] = Json::object();
  for (size_t t = 0; t < 5; ++t) types[cell_type_name(static_cast<CellType>(t))] = stats_json(per_type[t], inverted);
  return j;
}

void print_measure(const char* title, const std::vector<double>& edges, const MeasureStats& all,
                   const std::array<MeasureStats, 5>& per_type) {
  std::printf("%-16s %10s %10s %10s %10s\n", title, "count", "min", "mean", "max");
  auto row = [](const char* name, const MeasureStats& s) {
    if (s.count == 0) return;
    std::printf("  %-14s %10lld %10.4f %10.4f %10.4f\n", name, static_cast<long long>(s.count), s.min, s.mean, s.max);
  };
  row("all", all);
  for (size_t t = 0; t < 5; ++t) row(cell_type_name(static_cast<CellType>(t)), per_type[t]);
  std::printf("  histogram (all cells):\n");
  for (size_t i = 0; i < all.histogram.size(); ++i) {
    if (all.histogram[i] == 0) continue;
    std::printf("    [%7.2f, %7.2f%c %10lld\n", edges[i], edges[i + 1], i + 2 == edges.size() ? ']' : ')',
                static_cast<long long>(all.histogram[i]));
  }
}

void run_quality(const QualityArgs& args) {
  const Mesh m = load_for_cli(args.input);
  const QualitySummary s = summarize_quality(m, cell_quality(m));
  const std::string& file = args.input.file;
  if (args.json) {
    const Json j = {{"file", file},
                    {"cells", s.scaled_jacobian.count},
                    {"inverted", s.scaled_jacobian.negative},
                    {"scaled_jacobian", measure_json(s.sj_bin_edges, s.scaled_jacobian, s.sj_per_type, true)},
                    {"edge_ratio", measure_json(s.er_bin_edges, s.edge_ratio, s.er_per_type, false)}};
    write_output(json_text(j), std::nullopt);
    return;
  }
  std::printf("file            %s\ncells           %lld\ninverted        %lld (scaled Jacobian < 0)\n\n", file.c_str(),
              static_cast<long long>(s.scaled_jacobian.count), static_cast<long long>(s.scaled_jacobian.negative));
  print_measure("scaled Jacobian", s.sj_bin_edges, s.scaled_jacobian, s.sj_per_type);
  std::printf("\n");
  print_measure("edge ratio", s.er_bin_edges, s.edge_ratio, s.er_per_type);
}

}  // namespace

void add_quality(CLI::App& app) {
  auto args = std::make_shared<QualityArgs>();
  CLI::App* cmd = add_mesh_command(app, "quality", "scaled Jacobian and edge ratio per cell type, inverted cells",
                                   args->input, args->json);
  cmd->callback([args] { run_quality(*args); });
}

}  // namespace hbc::cli
