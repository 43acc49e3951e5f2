// The command line itself (CLI11): help for every command, one version, typed options whose bad
// values exit 2 naming the option (as bad input does), and JSON that stays valid for any file name.
#include <filesystem>
#include <string>

#include "cli_support.hpp"
#include "hbc/generate.hpp"
#include "hbc/version.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using test::run_cli;

TEST(CliOptions, EveryCommandHasHelp) {
  for (const char* cmd : {"info", "analyze", "sheets", "table", "generate", "generate grid", "generate split",
                          "generate sector", "generate cylinder", "generate twisted-ring", "generate twisted-pair",
                          "export-surface", "wireframe", "export-vtu", "export-html", "quality", "metrics", "compare",
                          "check"}) {
    const test::CliRun r = run_cli(std::string(cmd) + " --help");
    EXPECT_EQ(r.status, 0) << cmd << ": " << r.err;
    // CLI11's help starts with the command's description and names the command in its usage line.
    EXPECT_NE(r.out.find("Usage: hbc " + std::string(cmd)), std::string::npos) << r.out;
  }
  const test::CliRun top = run_cli("--help");
  EXPECT_EQ(top.status, 0);
  for (const char* cmd : {"info", "analyze", "sheets", "table", "generate", "export-surface", "wireframe", "export-vtu",
                          "export-html", "quality", "metrics", "compare", "check"})
    EXPECT_NE(top.out.find(cmd), std::string::npos) << cmd;
  EXPECT_EQ(run_cli("").status, 1);         // no command
  EXPECT_EQ(run_cli("frobnicate").status, 1);
}

TEST(CliOptions, VersionIsTheLibrarys) {
  const test::CliRun r = run_cli("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, std::string("hbc ") + version() + "\n");
  EXPECT_EQ(std::string(version()), HBC_VERSION);
  EXPECT_EQ(std::string(version()), std::to_string(HBC_VERSION_MAJOR) + "." + std::to_string(HBC_VERSION_MINOR) +
                                        "." + std::to_string(HBC_VERSION_PATCH));
}

class CliBadValues : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(dir_);
    write_mesh(build_mesh(generate_sector(5, 1, 1)), mesh_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // Exit status 2 and a message naming `option`.
  void expect_rejected(const std::string& args, const std::string& option) {
    const test::CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const std::filesystem::path dir_ = std::filesystem::temp_directory_path() / ("hbc_cli_opt_" + std::to_string(::getpid()));
  const std::string mesh_ = (dir_ / "s.mesh").string();
};

TEST_F(CliBadValues, RangesAndChoices) {
  for (const char* cmd : {"wireframe", "analyze"}) {
    expect_rejected(std::string(cmd) + " '" + mesh_ + "' --rho abc", "--rho");
    expect_rejected(std::string(cmd) + " '" + mesh_ + "' --rho 7", "--rho");
    expect_rejected(std::string(cmd) + " '" + mesh_ + "' --rho -0.5", "--rho");
    expect_rejected(std::string(cmd) + " '" + mesh_ + "' --level coarse", "--level");
  }
  expect_rejected("wireframe '" + mesh_ + "' --sheet -3", "--sheet");
  expect_rejected("wireframe '" + mesh_ + "' --sheet x", "--sheet");
  expect_rejected("export-surface '" + mesh_ + "' -o '" + (dir_ / "o.obj").string() + "' --what sheets --sheet -3", "--sheet");
  expect_rejected("sheets '" + mesh_ + "' --format stl", "--format");
  expect_rejected("table '" + mesh_ + "' -j 0", "-j");
  // The twisted pair's middle line needs an even section.
  const std::string out = " -o '" + (dir_ / "p.ovm").string() + "'";
  expect_rejected("generate twisted-pair --section 5 --sections 12" + out, "--section");
  expect_rejected("generate twisted-pair --section 0 --sections 12" + out, "--section");
  expect_rejected("generate twisted-pair --section 4 --sections 2" + out, "--sections");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "p.ovm"));
  // The edges are right at the ends of the range.
  EXPECT_EQ(run_cli("wireframe '" + mesh_ + "' --rho 0").status, 0);
  EXPECT_EQ(run_cli("wireframe '" + mesh_ + "' --rho 1").status, 0);
}

TEST_F(CliBadValues, UsageErrorsExit1) {
  EXPECT_EQ(run_cli("info").status, 1);                                     // FILE missing
  EXPECT_EQ(run_cli("info '" + mesh_ + "' --no-such-option").status, 1);
  EXPECT_EQ(run_cli("info '" + mesh_ + "' '" + mesh_ + "'").status, 1);    // one FILE only
  EXPECT_EQ(run_cli("wireframe '" + mesh_ + "' --json --obj").status, 1);  // exclusive
  EXPECT_EQ(run_cli("analyze '" + mesh_ + "' --json --csv").status, 1);
}

// The file name is written as a JSON string: quotes, backslashes and control characters escaped.
TEST_F(CliBadValues, JsonEscapesTheFileName) {
  const std::string odd = (dir_ / "a \"quoted\" \\ name\tx.mesh").string();
  std::filesystem::copy_file(mesh_, odd);
  std::string quoted = "'";
  for (char c : odd) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  for (const char* cmd : {"info", "analyze", "sheets", "wireframe"}) {
    const test::CliRun r = run_cli(std::string(cmd) + " " + quoted + " --json");
    ASSERT_EQ(r.status, 0) << cmd << ": " << r.err;
    EXPECT_EQ(r.json()["file"], odd) << cmd;
  }
}

// A sector of valence 5 around one axis edge (one ring, one layer: 5 hex cells). The wireframe
// command and `analyze` run the same library stage, so their counts agree; every edge's arrays
// have one entry (three coordinates) per polyline vertex.
TEST_F(CliBadValues, WireframeJsonOfASector) {
  const test::CliRun r = run_cli("wireframe '" + mesh_ + "' --json --level mesh");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j["level"], "mesh");
  EXPECT_EQ(j["sheet"], -1);
  EXPECT_DOUBLE_EQ(j["rho"].get<double>(), 0.8);
  const auto stats = run_cli("analyze '" + mesh_ + "' --json --level mesh").json();
  EXPECT_EQ(j["vsg_edges"], stats["vsg_edges"]);
  EXPECT_EQ(j["wireframe_edges"], stats["wireframe_edges"]);
  EXPECT_EQ(j["edges"].size(), stats["wireframe_edges"].get<size_t>());
  ASSERT_GE(j["edges"].size(), 1u);
  for (const auto& e : j["edges"]) {
    const size_t n = e["vertices"].size();
    EXPECT_EQ(e["points"].size(), 3 * n);
    EXPECT_EQ(e["opacity"].size(), n);
  }
  const test::CliRun info = run_cli("info '" + mesh_ + "' --json");
  EXPECT_EQ(info.json()["cells"], 5);
  EXPECT_EQ(info.json()["cell_types"]["hex"], 5);
}

}  // namespace
}  // namespace hbc
