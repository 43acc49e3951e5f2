// The commands that read many meshes, one child each (`hbc table`, `hbc compare`), take the reading
// options of the one-mesh commands (--format, --threads, --skip-invalid) with the same help, and
// pass them to every child: a file with refused cells fails its row or column without
// --skip-invalid, with a message advising an option the command has, and is read with it as
// `hbc analyze --skip-invalid` / `hbc metrics --skip-invalid` read it.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using test::run_cli;

// tests/data/check/defects.HYBRID (derived in test_check.cpp): 10 cells, of which --skip-invalid
// drops 5 (cells 2 to 6) and keeps 5; without it every reading command refuses the file.
std::string defects_file() { return std::string(HBC_FORMATS_DIR) + "/../check/defects.HYBRID"; }

// The help line of `option` in `hbc CMD --help` (CLI11 prints one line per option).
std::string help_line(const std::string& cmd, const std::string& option) {
  const test::CliRun r = run_cli(cmd + " --help");
  std::istringstream ss(r.out);
  for (std::string line; std::getline(ss, line);)
    if (line.find("  " + option) != std::string::npos) return line;
  return "";
}

TEST(CliMany, TableAndCompareTakeTheReadingOptionsWithTheSameHelp) {
  for (const char* option : {"--format", "--threads", "--skip-invalid"}) {
    const std::string want = help_line("analyze", option);
    ASSERT_FALSE(want.empty()) << option;
    EXPECT_EQ(help_line("table", option), want) << option;
    EXPECT_EQ(help_line("compare", option), want) << option;
  }
}

class CliManyFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(dir_);
    // The same bytes under a name no format claims: only --format hybrid reads it.
    std::filesystem::copy_file(defects_file(), odd_, std::filesystem::copy_options::overwrite_existing);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  const std::filesystem::path dir_ = std::filesystem::temp_directory_path() / ("hbc_cli_many_" + std::to_string(::getpid()));
  const std::string odd_ = (dir_ / "defects.txt").string();
};

// The value of column `key` in the one data row of `hbc table --csv` output (header first), for
// a row whose fields hold no comma (not a failed row: its error is quoted).
std::string table_value(const std::string& csv, const std::string& key) {
  std::istringstream ss(csv);
  std::string header, row;
  std::getline(ss, header);
  std::getline(ss, row);
  std::vector<std::string> keys, vals;
  std::istringstream hs(header), rs(row);
  for (std::string f; std::getline(hs, f, ',');) keys.push_back(f);
  for (std::string f; std::getline(rs, f, ',');) vals.push_back(f);
  if (!row.empty() && row.back() == ',') vals.emplace_back();
  for (size_t i = 0; i < keys.size() && i < vals.size(); ++i)
    if (keys[i] == key) return vals[i];
  return "<no " + key + ">";
}

TEST_F(CliManyFiles, TableReadsABrokenFileWithSkipInvalid) {
  const std::string file = "'" + defects_file() + "'";
  // Without the option the row fails, and the advice names an option `hbc table` has.
  const test::CliRun refused = run_cli("table --csv " + file);
  ASSERT_EQ(refused.status, 0) << refused.err;
  EXPECT_NE(refused.out.find("--skip-invalid"), std::string::npos) << refused.out;
  EXPECT_EQ(table_value(refused.out, "cells"), "");
  // With it the row is `hbc analyze --skip-invalid`'s, and the child's warning says what went.
  const test::CliRun read = run_cli("table --csv " + file + " --skip-invalid --threads 1");
  ASSERT_EQ(read.status, 0) << read.err;
  const auto analyzed = run_cli("analyze " + file + " --skip-invalid --json").json();
  EXPECT_EQ(table_value(read.out, "cells"), std::to_string(analyzed["cells"].get<int64_t>()));
  EXPECT_EQ(table_value(read.out, "cells"), "5");
  EXPECT_EQ(table_value(read.out, "components"), std::to_string(analyzed["components"].get<int64_t>()));
  EXPECT_EQ(table_value(read.out, "error"), "");
  EXPECT_NE(read.err.find("5 cell(s) dropped"), std::string::npos) << read.err;
  // --format reaches the child: the .txt copy is read only with it.
  EXPECT_EQ(table_value(run_cli("table --csv '" + odd_ + "' --skip-invalid").out, "cells"), "");
  const test::CliRun as_hybrid = run_cli("table --csv '" + odd_ + "' --skip-invalid --format hybrid");
  EXPECT_EQ(table_value(as_hybrid.out, "cells"), "5") << as_hybrid.out << as_hybrid.err;
}

TEST_F(CliManyFiles, CompareReadsABrokenFileWithSkipInvalid) {
  const std::string file = "'" + defects_file() + "'";
  const std::string out = (dir_ / "out").string();
  // Without the option the column fails (exit 2), advising an option `hbc compare` has.
  const test::CliRun refused = run_cli("compare " + file + " -o '" + out + "' --no-report");
  EXPECT_EQ(refused.status, 2) << refused.err;
  auto j = nlohmann::json::parse(test::slurp(dir_ / "out" / "metrics.json"));
  const std::string error = j["meshes"][0]["error"].get<std::string>();
  EXPECT_NE(error.find("--skip-invalid"), std::string::npos) << error;
  EXPECT_FALSE(j["meshes"][0].contains("dropped"));  // without the option, metrics.json as before
  // With it (and --threads, --format reaching the child) the column is `hbc metrics --skip-invalid
  // --json`, and meshes[0].dropped is `hbc analyze --skip-invalid --json`'s "dropped".
  const test::CliRun read =
      run_cli("compare '" + odd_ + "' -o '" + out + "' --no-report --skip-invalid --threads 1 --format hybrid");
  ASSERT_EQ(read.status, 0) << read.err;
  EXPECT_NE(read.err.find("5 cell(s) dropped"), std::string::npos) << read.err;
  j = nlohmann::json::parse(test::slurp(dir_ / "out" / "metrics.json"));
  EXPECT_TRUE(j["meshes"][0]["error"].is_null());
  auto got = j["metrics"][0];
  auto want = run_cli("metrics " + file + " --skip-invalid --json").json();
  got.erase("timings");
  want.erase("timings");
  got.erase("file");
  want.erase("file");
  EXPECT_EQ(got, want);
  EXPECT_EQ(j["values"]["census.cells"][0], 5);
  EXPECT_EQ(j["meshes"][0]["dropped"], run_cli("analyze " + file + " --skip-invalid --json --no-wireframe").json()["dropped"]);
  // A value the option cannot take is rejected as the reading commands reject it.
  const test::CliRun bad = run_cli("compare " + file + " -o '" + out + "' --no-report --threads 0");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--threads"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace hbc
