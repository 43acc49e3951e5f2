// What hbc compare writes (hbc/comparison.hpp), the writers the command and hbc.compare() share:
// the columns' names, one measured and one failed column in metrics.json, .csv and .tex. Equality
// with the command's and Python's files on real meshes: tests/python/test_compare.py.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "hbc/comparison.hpp"
#include "hbc/generate.hpp"

namespace hbc {
namespace {

TEST(Comparison, ColumnNamesAreTheFileNamesMadeUnique) {
  // Two files of one name in two folders stay two columns: the second is "x.mesh (2)".
  auto cols = comparison_columns({"a/x.mesh", "b/x.mesh", "c/y.mesh"}, {});
  ASSERT_EQ(cols.size(), 3u);
  EXPECT_EQ(cols[0].name, "x.mesh");
  EXPECT_EQ(cols[1].name, "x.mesh (2)");
  EXPECT_EQ(cols[2].name, "y.mesh");
  EXPECT_EQ(cols[1].file, "b/x.mesh");
  cols = comparison_columns({"p", "q", "r"}, {"A", "A", "A"});
  EXPECT_EQ(cols[1].name, "A (2)");
  EXPECT_EQ(cols[2].name, "A (3)");
  try {
    comparison_columns({"p", "q", "r"}, {"A"});
    FAIL() << "one name for three files was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--names gives 1 names for 3 files");
  }
}

// A 2×2×2 grid (8 hexes, 27 vertices) measured, beside a column that failed to load.
std::vector<ComparisonColumn> grid_and_failure() {
  const Mesh grid = build_mesh(generate_grid(2, 2, 2));
  std::vector<ComparisonColumn> cols = comparison_columns({"grid.mesh", "b_c.mesh"}, {"grid", "b_c"});
  set_measurement(cols[0], json_text(comparison_measurement(grid, "grid.mesh", 1, 0.0, false, {})));
  cols[1].error = "b_c.mesh:4: expected 3 vertices";
  return cols;
}

TEST(Comparison, TablesOfAMeasuredAndAFailedColumn) {
  const auto cols = grid_and_failure();
  ASSERT_TRUE(cols[0].error.empty()) << cols[0].error;
  const Json j = comparison_json(cols, false);
  EXPECT_EQ(j["values"]["census.cells"], Json::parse("[8, null]"));
  EXPECT_EQ(j["errors"], Json::parse(R"({"b_c": "b_c.mesh:4: expected 3 vertices"})"));
  EXPECT_TRUE(j["metrics"][1].is_null() && j["scaled_jacobian_histograms"]["by_type"][1].is_null());
  // Every cell of a unit grid has scaled Jacobian 1: the last bin, [0.9, 1], holds all 8 hexes.
  EXPECT_EQ(j["scaled_jacobian_histograms"]["by_type"][0]["hex"][19], 8);
  EXPECT_FALSE(j["meshes"][0].contains("dropped"));  // only with skip_invalid

  // CSV: name, mesh, one column per metric, then one per deprecated key of a metric (metric_aliases,
  // docs/concepts.md's retired words), error; the failed row's metrics are empty fields.
  const std::string csv = comparison_csv(cols);
  size_t aliased = 0;
  for (const MetricAlias& a : metric_aliases()) aliased += metric_index(a.group, a.key) >= 0;
  EXPECT_GT(aliased, 0u);
  const size_t header_end = csv.find('\n'), row1_end = csv.find('\n', header_end + 1);
  const std::string failed_row = csv.substr(row1_end + 1);
  EXPECT_EQ(failed_row, "b_c,b_c.mesh" + std::string(metric_fields().size() + aliased, ',') + ",b_c.mesh:4: expected 3 vertices\n");
  EXPECT_EQ(csv.substr(header_end + 1, 15), "grid,grid.mesh,");

  // TeX: the failed column says "failed" on every metric row, its error is a note, names escaped.
  const std::string tex = comparison_tex(cols);
  EXPECT_NE(tex.find("Metric & Unit & grid & b\\_c \\\\"), std::string::npos);
  EXPECT_NE(tex.find("{\\footnotesize b\\_c: b\\_c.mesh:4: expected 3 vertices}"), std::string::npos);
  size_t failed = 0;
  for (size_t at = tex.find("& failed"); at != std::string::npos; at = tex.find("& failed", at + 1)) ++failed;
  EXPECT_EQ(failed, metric_fields().size());
}

TEST(Comparison, AnUnreadableMeasurementFailsItsColumn) {
  ComparisonColumn c;
  set_measurement(c, "{\"metrics\": {}}");  // no scaled_jacobian_by_type
  EXPECT_EQ(c.error.rfind("unreadable result: ", 0), 0u) << c.error;
  EXPECT_TRUE(c.metrics.is_null());
  ComparisonColumn d;
  set_measurement(d, "not JSON");
  EXPECT_EQ(d.error.rfind("unreadable result: ", 0), 0u) << d.error;
}

}  // namespace
}  // namespace hbc
