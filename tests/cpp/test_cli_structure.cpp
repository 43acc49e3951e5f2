// The structure commands end to end: `hbc analyze --json`, `hbc sheets --json` and `hbc table`
// on the Table 1 meshes, with one bad file among them.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using test::run_cli;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream ss(line);
  while (std::getline(ss, cur, ',')) out.push_back(cur);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

TEST(CliStructure, AnalyzeJsonHasTheSpecKeys) {
  HBC_REQUIRE_DATA("hybrid-base-complex/twistcube_s.mesh");
  const test::CliRun o = run_cli("analyze " + test::data_path("hybrid-base-complex/twistcube_s.mesh") + " --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = o.json();
  for (const char* k : {"cells", "singular_edges", "singularities", "pseudo_singular_edges", "non_manifold_edges",
                        "singular_vertices", "components", "hex_components", "sheets", "sheets_perfect",
                        "sheets_type1", "sheets_type2", "sheets_type3", "subsheets_of_largest_self_intersecting",
                        "vsg_edges", "wireframe_edges", "wireframe_edges_simplified"})
    EXPECT_TRUE(j.contains(k) && j[k].is_number_integer()) << k;
  for (const char* k : {"hex_ratio", "hex_component_ratio"}) EXPECT_TRUE(j.contains(k) && j[k].is_number_float()) << k;
  ASSERT_TRUE(j.contains("timings"));
  for (const char* k : {"load", "singularity_graph", "base_complex", "sheets", "subsheets", "vsg_wireframe"})
    EXPECT_TRUE(j["timings"].contains(k) && j["timings"][k].get<double>() >= 0) << k;
  EXPECT_EQ(j["components"], 1301);
  EXPECT_EQ(j["subsheets_of_largest_self_intersecting"], 9);
}

TEST(CliStructure, SheetsListsEverySheet) {
  HBC_REQUIRE_DATA("hybrid-base-complex/teapot.hedra");
  const test::CliRun o = run_cli("sheets " + test::data_path("hybrid-base-complex/teapot.hedra") + " --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = o.json();
  EXPECT_EQ(j["level"], "complex");
  ASSERT_EQ(j["sheets"].size(), 23u);
  std::vector<size_t> subsheets;  // sizes of the subsheet lists, in sheet order
  for (const auto& [id, sheet] : j["sheets"].items()) {
    EXPECT_GT(sheet["blocks"].get<int>(), 0) << id;
    if (sheet.contains("subsheets")) subsheets.push_back(sheet["subsheets"].size());
  }
  std::sort(subsheets.begin(), subsheets.end());
  // The two self-intersecting sheets, by the authors' rule (the default; docs/validation.md).
  EXPECT_EQ(subsheets, (std::vector<size_t>{3, 4}));
  EXPECT_EQ(j["subsheet_rule"], "layers");
  const auto& largest = j["sheets"][std::to_string(j["largest_self_intersecting"].get<int>())];
  EXPECT_EQ(largest["subsheets"].size(), 4u);
}

// --subsheets fewest: every self-intersecting sheet gets its count's lower bound, never above it,
// and whether the two meet; no other sheet gets one.
TEST(CliStructure, SheetsFewestGivesABound) {
  HBC_REQUIRE_DATA("hybrid-base-complex/teapot.hedra");
  const test::CliRun o = run_cli("sheets " + test::data_path("hybrid-base-complex/teapot.hedra") +
                                 " --json --subsheets fewest --search-steps 1000");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = o.json();
  EXPECT_EQ(j["subsheet_rule"], "fewest");
  int bounded = 0;
  for (const auto& [id, sheet] : j["sheets"].items()) {
    ASSERT_EQ(sheet.contains("subsheets_lower_bound"), sheet["type3"].get<bool>()) << id;
    if (!sheet["type3"].get<bool>()) continue;
    ++bounded;
    const auto bound = sheet["subsheets_lower_bound"].get<size_t>();
    EXPECT_GE(bound, 2u) << id;  // a self-intersecting sheet has two curves meeting in a block
    EXPECT_LE(bound, sheet["subsheets"].size()) << id;
    EXPECT_EQ(sheet["subsheets_proven"].get<bool>(), bound == sheet["subsheets"].size()) << id;
  }
  EXPECT_EQ(bounded, 2);
  EXPECT_NE(run_cli("sheets " + test::data_path("hybrid-base-complex/teapot.hedra") + " --subsheets greedy").status, 0);
}

// The table equals each mesh's own `analyze --json`, and a bad file only fails its own row.
TEST(CliStructure, TableMatchesAnalyzeAndSurvivesABadFile) {
  HBC_REQUIRE_DATA("hybrid-base-complex/teapot.hedra");
  const auto dir = std::filesystem::temp_directory_path() / "hbc_table_test";
  std::filesystem::create_directories(dir);
  const std::string bad = (dir / "broken.mesh").string();
  std::ofstream(bad) << "MeshVersionFormatted 1\nDimension 3\nVertices\n2\n0 0 0 0\n";
  const std::vector<std::string> meshes = {"hybrid-base-complex/teapot.hedra", "hybrid-base-complex/twistcube_s.mesh",
                                           "hybrid-base-complex/cube_twist-comp.obj.HYBRID"};
  std::string args = "table --csv -j 2";
  for (const auto& m : meshes) args += " " + test::data_path(m);
  args += " " + bad;
  const test::CliRun o = run_cli(args);
  ASSERT_EQ(o.status, 0) << o.err;
  std::istringstream ss(o.out);
  std::string header_line, line;
  std::getline(ss, header_line);
  const auto header = split(header_line);
  std::map<std::string, std::vector<std::string>> rows;
  while (std::getline(ss, line)) rows[split(line)[0]] = split(line);
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& m : meshes) {
    const auto& row = rows[test::data_path(m)];
    ASSERT_EQ(row.size(), header.size());
    EXPECT_TRUE(row.back().empty()) << "error column of " << m;
    const auto json = run_cli("analyze " + test::data_path(m) + " --json").json();
    for (const char* k : {"cells", "components", "hex_components", "sheets", "sheets_type1", "sheets_type2",
                          "sheets_type3", "subsheets_of_largest_self_intersecting", "vsg_edges"}) {
      const size_t col = static_cast<size_t>(std::find(header.begin(), header.end(), k) - header.begin());
      ASSERT_LT(col, header.size()) << k;
      EXPECT_EQ(std::stoll(row[col]), json[k].get<int64_t>()) << m << " " << k;
    }
  }
  // The error is the last field, after as many fields as the header has before it; it names the
  // file, and it is quoted because the reader's message holds a comma (RFC 4180).
  const auto& failed = rows[bad];
  ASSERT_GE(failed.size(), header.size());
  std::string error;
  for (size_t i = header.size() - 1; i < failed.size(); ++i) error += (error.empty() ? "" : ",") + failed[i];
  EXPECT_NE(error.find("broken.mesh"), std::string::npos) << error;
  EXPECT_EQ(error.front(), '"') << error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hbc
