// hbc quality: Verdict's scaled Jacobian and edge ratio (cell_quality.hpp) summarised per cell type.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "hbc/cell_quality.hpp"
#include "json.hpp"

namespace hbc::cli {

namespace {

// count, min, mean, max and the histogram into the open JSON object (plus `inverted`, the
// negative values, for the scaled Jacobian).
void write_stats(JsonWriter& w, const MeasureStats& s, bool inverted) {
  w.num("count", s.count).real("min", s.min, 9).real("mean", s.mean, 9).real("max", s.max, 9);
  if (inverted) w.num("inverted", s.negative);
  w.array("histogram", s.histogram);
}

void write_measure(JsonWriter& w, const char* key, const std::vector<double>& edges, const MeasureStats& all,
                   const std::array<MeasureStats, 5>& per_type, bool inverted) {
  w.begin(key);
  write_stats(w, all, inverted);
  w.array("bin_edges", edges, 4);
  w.begin("per_type");
  for (size_t t = 0; t < 5; ++t) {
    w.begin(cell_type_name(static_cast<CellType>(t)));
    write_stats(w, per_type[t], inverted);
    w.end();
  }
  w.end().end();
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

}  // namespace

int cmd_quality(const Args& args_in) {
  Args args = args_in;
  const bool json = take_flag(args, "--json");
  const InputFormat format = take_format(args);
  if (args.size() != 1) throw std::invalid_argument("usage: hbc quality FILE [--json] [--format F]");
  const Mesh m = load_for_cli(args[0], format);
  const QualitySummary s = summarize_quality(m, cell_quality(m));
  if (json) {
    JsonWriter w;
    w.begin().str("file", args[0]).num("cells", s.scaled_jacobian.count).num("inverted", s.scaled_jacobian.negative);
    write_measure(w, "scaled_jacobian", s.sj_bin_edges, s.scaled_jacobian, s.sj_per_type, true);
    write_measure(w, "edge_ratio", s.er_bin_edges, s.edge_ratio, s.er_per_type, false);
    w.end();
    std::printf("%s\n", w.text().c_str());
  } else {
    std::printf("file            %s\ncells           %lld\ninverted        %lld (scaled Jacobian < 0)\n\n",
                args[0].c_str(), static_cast<long long>(s.scaled_jacobian.count),
                static_cast<long long>(s.scaled_jacobian.negative));
    print_measure("scaled Jacobian", s.sj_bin_edges, s.scaled_jacobian, s.sj_per_type);
    std::printf("\n");
    print_measure("edge ratio", s.er_bin_edges, s.edge_ratio, s.er_per_type);
  }
  return 0;
}

}  // namespace hbc::cli
