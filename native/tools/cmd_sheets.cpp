// hbc sheets FILE [--json] [--level complex|mesh] [--subsheets layers|fewest]: every sheet with its
// type flags and sizes, and the subsheets of each self-intersecting sheet.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <limits>
#include <memory>

#include "commands.hpp"
#include "hbc/analysis.hpp"
#include "hbc/json.hpp"

namespace hbc::cli {
namespace {

struct SheetsArgs {
  InputArgs input;
  bool json = false;
  std::string level = "complex";
  std::string subsheets = "layers";
  int64_t search_steps = SubsheetOptions{}.node_budget;
};

// The classification of a sheet or subsheet, added to its object after its sizes.
void add_class(Json& j, const SheetClass& k) {
  j["type"] = sheet_type_name(k.type);
  j["type1"] = k.type1;
  j["type2"] = k.type2;
  j["type3"] = k.type3;
  j["unmatched_vertices"] = k.unmatched_vertices.size();
  j["shared_vertices"] = k.shared_vertices.size();
  j["self_parallel_curves"] = k.self_parallel_curves.size();
  j["self_intersecting_blocks"] = k.self_intersecting_blocks.size();
}

// Fewest: the bound that proves the count (or the gap to it) and the time the search took.
void add_bound(Json& j, const Subsheets& x, double seconds) {
  if (x.rule != SubsheetRule::Fewest) return;
  j["subsheets_lower_bound"] = x.lower_bound;
  j["subsheets_proven"] = x.proven;
  j["seconds_subsheets"] = seconds;
}

Json sheets_json(const std::string& file, Level level, SubsheetRule rule, const SheetStage& st) {
  const Sheets& sh = st.sheets;
  Json sheets = Json::object();
  for (size_t s = 0; s < sh.size(); ++s) {
    Json j = {{"blocks", sh.sheet_blocks.count(s)},
              {"cells", sh.sheet_cells.count(s)},
              {"curves", sh.sheet_curves.count(s)},
              {"edges", sh.sheet_edges.count(s)},
              {"non_hex_cells", sh.sheet_non_hex_cells.count(s)}};
    add_class(j, sh.classes[s]);
    if (const Subsheets* x = st.subsheets_of(static_cast<int32_t>(s))) {
      Json& subs = j["subsheets"] = Json::object();
      for (size_t i = 0; i < x->size(); ++i) {
        Json& sub = subs[std::to_string(i)] = {{"blocks", x->blocks.count(i)}, {"cells", x->cells.count(i)}, {"curves", x->curves.count(i)}};
        add_class(sub, x->classes[i]);
      }
      add_bound(j, *x, st.subsheet_seconds[static_cast<size_t>(x - st.subsheets->data())]);
    }
    sheets[std::to_string(s)] = std::move(j);
  }
  return {{"file", file},
          {"level", level_name(level)},
          {"subsheet_rule", subsheet_rule_name(rule)},
          {"largest_self_intersecting", st.largest_self_intersecting.value_or(-1)},
          {"sheets", std::move(sheets)}};
}

void print_sheets_table(const std::string& file, const SheetStage& st) {
  const Sheets& sh = st.sheets;
  std::printf("%s: %zu sheets (%zu perfect, %zu type 1, %zu type 2, %zu type 3)\n", file.c_str(), sh.size(),
              sh.count(SheetType::Perfect), sh.count(SheetType::Type1), sh.count(SheetType::Type2),
              sh.count(SheetType::Type3));
  std::printf("%5s %-8s %5s %5s %7s %7s %7s %9s %9s\n", "sheet", "type", "t1t2t3", "", "blocks", "cells", "curves",
              "non-hex", "unmatched");
  for (size_t s = 0; s < sh.size(); ++s) {
    const SheetClass& k = sh.classes[s];
    std::printf("%5zu %-8s   %d%d%d %5s %7d %7d %7d %9d %9zu\n", s, sheet_type_name(k.type), k.type1, k.type2, k.type3,
                "", sh.sheet_blocks.count(s), sh.sheet_cells.count(s), sh.sheet_curves.count(s),
                sh.sheet_non_hex_cells.count(s), k.unmatched_vertices.size());
    if (const Subsheets* x = st.subsheets_of(static_cast<int32_t>(s))) {
      for (size_t i = 0; i < x->size(); ++i)
        std::printf("      subsheet %-3zu %-8s blocks %d cells %d curves %d\n", i, sheet_type_name(x->classes[i].type),
                    x->blocks.count(i), x->cells.count(i), x->curves.count(i));
      if (x->rule == SubsheetRule::Fewest)
        std::printf("      fewest: %zu subsheets, lower bound %d (%s)\n", x->size(), x->lower_bound,
                    x->proven ? "proven minimal" : "search budget reached");
    }
  }
}

void run_sheets(const SheetsArgs& args) {
  const AnalysisOptions opt = analysis_options(args.input, {{"wireframe", false},
                                                            {"level", args.level},
                                                            {"subsheet_rule", args.subsheets},
                                                            {"search_steps", args.search_steps}});
  const Mesh m = load_for_cli(args.input);
  const Analysis a = analyze(m, opt);
  const SheetStage& st = *a.sheet_stage;  // opt.sheets is on
  if (args.json) write_output(json_text(sheets_json(args.input.file, opt.sheet_level, opt.subsheet_options.rule, st)), std::nullopt);
  else print_sheets_table(args.input.file, st);
}

}  // namespace

void add_sheets(CLI::App& app) {
  auto args = std::make_shared<SheetsArgs>();
  CLI::App* cmd =
      add_mesh_command(app, "sheets", "sheets with type flags, sizes and subsheets", args->input, args->json);
  add_level(*cmd, args->level, "level of the sheets");
  cmd->add_option("--subsheets", args->subsheets,
                  "decomposition of self-intersecting sheets: layers (the paper's authors' rule) or fewest "
                  "(the fewest subsheets, with a lower bound)")
      ->check(CLI::IsMember({"layers", "fewest"}))
      ->capture_default_str();
  cmd->add_option("--search-steps", args->search_steps, "--subsheets fewest: steps of the exact search per sheet")
      ->check(CLI::Range(int64_t{0}, std::numeric_limits<int64_t>::max()))
      ->capture_default_str();
  cmd->callback([args] { run_sheets(*args); });
}

}  // namespace hbc::cli
