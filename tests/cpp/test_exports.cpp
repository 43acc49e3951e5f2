// The binding surface's one description (hbc/exports.hpp): the table's own consistency, and
// analyze_settings, the one reader of analyze's options that the CLI and both bindings use.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "hbc/exports.hpp"
#include "hbc/wireframe_style.hpp"

namespace hbc {
namespace {

TEST(Exports, EveryArrayIsDescribedOnceWithAKnownDimension) {
  std::set<std::string> symbols;
  for (const Dimension& d : dimensions()) EXPECT_TRUE(symbols.insert(std::string(d.symbol)).second) << d.symbol;
  std::set<std::string> names;
  for (const ExportedArray& a : exported_arrays()) {
    const std::string id = std::string(a.holder) + "." + std::string(a.name);
    EXPECT_TRUE(names.insert(id).second) << id << " twice";
    EXPECT_TRUE(symbols.count(std::string(a.rows))) << id << ": rows " << a.rows;
    EXPECT_NE(a.surfaces & kBoth, 0) << id << " is bound nowhere";
    EXPECT_FALSE(a.meaning.empty()) << id;
    EXPECT_TRUE(!a.csr || a.dtype == Dtype::Int32) << id << ": CSR items are int32";
    // A deprecated name is JavaScript's old one (Python never had it) and names a live entry.
    if (!a.deprecated.empty()) {
      EXPECT_EQ(a.surfaces, kJs) << id;
      const ExportedArray* now = find_exported_array(a.holder, a.deprecated);
      ASSERT_NE(now, nullptr) << id << " -> " << a.deprecated;
      EXPECT_TRUE(now->deprecated.empty() && (now->surfaces & kJs)) << id;
    }
  }
}

TEST(Exports, FindsCsrHalvesAndNothingElse) {
  EXPECT_EQ(find_exported_array("Analysis", "sheet_components_items"), find_exported_array("Analysis", "sheet_components"));
  EXPECT_NE(find_exported_array("Mesh", "face_vertices_offsets"), nullptr);
  EXPECT_EQ(find_exported_array("Mesh", "points_offsets"), nullptr);  // points is no CSR
  EXPECT_EQ(find_exported_array("Mesh", "sheet_type"), nullptr);      // another holder's
  EXPECT_EQ(find_exported_array("Analysis", "sheet_componentsx"), nullptr);
  EXPECT_EQ(numpy_shape_text(*find_exported_array("Mesh", "points")), "float32 (nv, 3)");
  EXPECT_EQ(numpy_shape_text(*find_exported_array("Mesh", "cell_faces")), "int32 (cell_faces_offsets[-1],)");
}

// The table's default texts are AnalyzeSettings{}'s values: each default, given explicitly, changes
// nothing. rho's default is the render layer's (WireframeStyleOptions), threads' is "none" (0).
TEST(Exports, DefaultsAreTheLibrarys) {
  const AnalyzeSettings d;
  EXPECT_EQ(d.rho, WireframeStyleOptions{}.rho);
  std::vector<OptionSetting> given;
  for (const AnalyzeOption& o : analyze_options()) {
    const std::string text(o.default_text);
    switch (o.type) {
      case OptionType::Bool: given.push_back({std::string(o.key), text == "true"}); break;
      case OptionType::Int:
        if (text != "none") given.push_back({std::string(o.key), int64_t{std::stoll(text)}});
        break;
      case OptionType::Real: given.push_back({std::string(o.key), std::stod(text)}); break;
      case OptionType::Choice: given.push_back({std::string(o.key), text}); break;
    }
  }
  EXPECT_EQ(given.size(), analyze_options().size() - 1);  // all but threads
  const AnalyzeSettings s = analyze_settings(given);
  EXPECT_EQ(s.rho, d.rho);
  const AnalysisOptions &a = s.options, &b = d.options;
  EXPECT_EQ(a.sheets, b.sheets);
  EXPECT_EQ(a.subsheets, b.subsheets);
  EXPECT_EQ(a.wireframe, b.wireframe);
  EXPECT_EQ(a.sheet_level, b.sheet_level);
  EXPECT_EQ(a.wireframe_level, b.wireframe_level);
  EXPECT_EQ(a.subsheet_options.rule, b.subsheet_options.rule);
  EXPECT_EQ(a.subsheet_options.node_budget, b.subsheet_options.node_budget);
  EXPECT_EQ(a.threads, b.threads);
}

TEST(Exports, EachOptionSetsItsField) {
  const std::vector<OptionSetting> kv = {{"rho", 0.25},          {"level", std::string("mesh")},
                                         {"wireframe", false},   {"threads", int64_t{3}},
                                         {"subsheet_rule", std::string("fewest")}, {"search_steps", 7.0}};
  const AnalyzeSettings s = analyze_settings(kv);
  EXPECT_EQ(s.rho, 0.25);
  EXPECT_EQ(s.options.sheet_level, Level::Mesh);
  EXPECT_EQ(s.options.wireframe_level, Level::Mesh);  // level sets both
  EXPECT_FALSE(s.options.wireframe);
  EXPECT_EQ(s.options.threads, 3);
  EXPECT_EQ(s.options.subsheet_options.rule, SubsheetRule::Fewest);
  EXPECT_EQ(s.options.subsheet_options.node_budget, 7);  // an integral double (JavaScript's numbers)
  EXPECT_TRUE(s.options.sheets && s.options.subsheets);
  // Subsheets need sheets: without them the subsheet stage is off, whatever it was asked.
  const std::vector<OptionSetting> off = {{"sheets", false}, {"subsheets", true}};
  EXPECT_FALSE(analyze_settings(off).options.subsheets);
  // Later settings win, and the defaults given are kept where nothing is set.
  AnalyzeSettings d;
  d.options.threads = 1;
  const std::vector<OptionSetting> twice = {{"rho", 0.1}, {"rho", 0.9}};
  const AnalyzeSettings t = analyze_settings(twice, d);
  EXPECT_EQ(t.rho, 0.9);
  EXPECT_EQ(t.options.threads, 1);
}

// Each error names the key, what it takes and what it got.
TEST(Exports, BadKeysAndValuesAreNamed) {
  const auto message = [](OptionSetting kv) -> std::string {
    try {
      analyze_settings(std::vector<OptionSetting>{std::move(kv)});
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_THROW(analyze_settings(std::vector<OptionSetting>{{"colour", true}}), UnknownOptionError);
  EXPECT_NE(message({"colour", true}).find("'colour'"), std::string::npos);
  EXPECT_EQ(message({"level", std::string("fine")}), "level must be one of 'complex', 'mesh', not 'fine'");
  EXPECT_EQ(message({"rho", 1.5}), "rho must be in [0, 1], not 1.5");
  EXPECT_EQ(message({"rho", std::string("high")}), "rho must be in [0, 1], not 'high'");
  EXPECT_EQ(message({"threads", int64_t{0}}), "threads must be an integer >= 1, not 0");
  EXPECT_EQ(message({"search_steps", 2.5}), "search_steps must be an integer >= 0, not 2.5");
  EXPECT_EQ(message({"sheets", int64_t{1}}), "sheets must be true or false, not 1");
  EXPECT_EQ(message({"subsheet_rule", std::string("greedy")}),
            "subsheet_rule must be one of 'layers', 'fewest', not 'greedy'");
}

}  // namespace
}  // namespace hbc
