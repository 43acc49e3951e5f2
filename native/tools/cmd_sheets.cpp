// hbc sheets FILE [--json] [--level complex|mesh]: every sheet with its type flags and sizes,
// and the subsheets of each self-intersecting sheet.
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "json.hpp"

namespace hbc::cli {
namespace {

void write_class(JsonWriter& w, const SheetClass& k) {
  w.str("type", sheet_type_name(k.type))
      .num("type1", k.type1)
      .num("type2", k.type2)
      .num("type3", k.type3)
      .num("unmatched_vertices", static_cast<int64_t>(k.unmatched_vertices.size()))
      .num("shared_vertices", static_cast<int64_t>(k.shared_vertices.size()))
      .num("self_parallel_curves", static_cast<int64_t>(k.self_parallel_curves.size()))
      .num("self_intersecting_blocks", static_cast<int64_t>(k.self_intersecting_units.size()));
}

}  // namespace

int cmd_sheets(const Args& args_in) {
  Args args = args_in;
  const bool json = take_flag(args, "--json");
  AnalysisOptions opt;
  opt.wireframe = false;
  if (auto level = take_option(args, "--level")) {
    if (*level == "mesh") opt.sheet_level = Level::Mesh;
    else if (*level != "complex") throw std::invalid_argument("--level takes complex or mesh");
  }
  const Format format = take_format(args);
  if (args.size() != 1) throw std::invalid_argument("usage: hbc sheets FILE [--json] [--level complex|mesh] [--format F]");
  const Mesh m = load_for_cli(args[0], format);
  const Analysis a = analyze(m, opt);
  const Sheets& sh = a.sheets;
  if (json) {
    JsonWriter w;
    w.begin().str("file", args[0]).str("level", opt.sheet_level == Level::Mesh ? "mesh" : "complex");
    w.num("largest_self_intersecting", a.largest_self_intersecting);
    w.begin("sheets");
    for (size_t s = 0; s < sh.size(); ++s) {
      w.begin(std::to_string(s).c_str())
          .num("blocks", sh.sheet_units.count(s))
          .num("cells", sh.sheet_cells.count(s))
          .num("curves", sh.sheet_curves.count(s))
          .num("edges", sh.sheet_edges.count(s))
          .num("non_hex_cells", sh.sheet_non_hex_cells.count(s));
      write_class(w, sh.classes[s]);
      if (const Subsheets* x = a.subsheets_of(static_cast<int32_t>(s))) {
        w.begin("subsheets");
        for (size_t i = 0; i < x->size(); ++i) {
          w.begin(std::to_string(i).c_str())
              .num("blocks", x->units.count(i))
              .num("cells", x->cells.count(i))
              .num("curves", x->curves.count(i));
          write_class(w, x->classes[i]);
          w.end();
        }
        w.end();
      }
      w.end();
    }
    w.end().end();
    std::printf("%s\n", w.text().c_str());
    return 0;
  }
  std::printf("%s: %zu sheets (%zu perfect, %zu type 1, %zu type 2, %zu type 3)\n", args[0].c_str(), sh.size(),
              sh.count(SheetType::Perfect), sh.count(SheetType::Type1), sh.count(SheetType::Type2),
              sh.count(SheetType::Type3));
  std::printf("%5s %-8s %5s %5s %7s %7s %7s %9s %9s\n", "sheet", "type", "t1t2t3", "", "blocks", "cells", "curves",
              "non-hex", "unmatched");
  for (size_t s = 0; s < sh.size(); ++s) {
    const SheetClass& k = sh.classes[s];
    std::printf("%5zu %-8s   %d%d%d %5s %7d %7d %7d %9d %9zu\n", s, sheet_type_name(k.type), k.type1, k.type2, k.type3,
                "", sh.sheet_units.count(s), sh.sheet_cells.count(s), sh.sheet_curves.count(s),
                sh.sheet_non_hex_cells.count(s), k.unmatched_vertices.size());
    if (const Subsheets* x = a.subsheets_of(static_cast<int32_t>(s)))
      for (size_t i = 0; i < x->size(); ++i)
        std::printf("      subsheet %-3zu %-8s blocks %d cells %d curves %d\n", i, sheet_type_name(x->classes[i].type),
                    x->units.count(i), x->cells.count(i), x->curves.count(i));
  }
  return 0;
}

}  // namespace hbc::cli
