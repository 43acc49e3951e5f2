// The structure commands end to end: `hbc analyze --json`, `hbc sheets --json` and `hbc table`
// on the Table 1 meshes, with one bad file among them.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "test_support.hpp"

namespace hbc {
namespace {

struct Output {
  int status;
  std::string text;
};

Output run(const std::string& args) {
  const std::string cmd = std::string(HBC_CLI) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int st = pclose(p);
  return {WEXITSTATUS(st), out};
}

// "key": integer pairs of a flat JSON object (enough for the CLI's own output).
int64_t json_int(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return -999;
  return std::stoll(json.substr(at + key.size() + 4));
}

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
  const Output o = run("analyze " + test::data_path("hybrid-base-complex/twistcube_s.mesh") + " --json");
  ASSERT_EQ(o.status, 0);
  for (const char* k : {"cells", "hex_ratio", "singular_edges", "singularities", "pseudo_singular_edges",
                        "non_manifold_edges", "singular_vertices", "components", "hex_components",
                        "hex_component_ratio", "sheets", "sheets_perfect", "sheets_type1", "sheets_type2",
                        "sheets_type3", "subsheets_of_largest_self_intersecting", "vsg_edges", "wireframe_edges",
                        "wireframe_edges_simplified", "timings", "load", "singularity_graph", "base_complex",
                        "subsheets", "vsg_wireframe"})
    EXPECT_NE(o.text.find(std::string("\"") + k + "\""), std::string::npos) << k;
  EXPECT_EQ(json_int(o.text, "components"), 1301);
  EXPECT_EQ(json_int(o.text, "subsheets_of_largest_self_intersecting"), 9);
}

TEST(CliStructure, SheetsListsEverySheet) {
  HBC_REQUIRE_DATA("hybrid-base-complex/teapot.hedra");
  const Output o = run("sheets " + test::data_path("hybrid-base-complex/teapot.hedra") + " --json");
  ASSERT_EQ(o.status, 0);
  size_t sheets = 0, subsheet_lists = 0;
  for (size_t p = 0; (p = o.text.find("\"blocks\"", p)) != std::string::npos; ++p) ++sheets;
  for (size_t p = 0; (p = o.text.find("\"subsheets\"", p)) != std::string::npos; ++p) ++subsheet_lists;
  EXPECT_EQ(subsheet_lists, 2u);          // the two self-intersecting sheets
  EXPECT_EQ(sheets, 23u + 6u + 3u);       // 23 sheets, their 6 + 3 subsheets
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
  const Output o = run(args);
  ASSERT_EQ(o.status, 0);
  std::istringstream ss(o.text);
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
    const std::string json = run("analyze " + test::data_path(m) + " --json").text;
    for (const char* k : {"cells", "components", "hex_components", "sheets", "sheets_type1", "sheets_type2",
                          "sheets_type3", "subsheets_of_largest_self_intersecting", "vsg_edges"}) {
      const size_t col = static_cast<size_t>(std::find(header.begin(), header.end(), k) - header.begin());
      ASSERT_LT(col, header.size()) << k;
      EXPECT_EQ(std::stoll(row[col]), json_int(json, k)) << m << " " << k;
    }
  }
  const auto& failed = rows[bad];
  EXPECT_NE(failed.back().find("broken.mesh"), std::string::npos) << failed.back();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hbc
