// Replays every input kept in tests/fuzz/regressions/<harness>/ through the code path of that
// libFuzzer harness (tests/fuzz/fuzz_targets.hpp): each must be rejected with InputError or
// accepted with the invariants the harness checks; any other exception fails the test naming the
// file, and a crash or sanitizer report (scripts/check/asan_ubsan.sh) fails the suite.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../fuzz/fuzz_targets.hpp"
#include "hbc/wireframe_style.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

namespace fs = std::filesystem;

// From the build, not __FILE__: a compiler cache that rewrites paths relative to the build folder
// (ccache's base_dir) makes __FILE__ relative, and the sanitizer runs start from the source root.
fs::path regressions_dir() { return fs::path(HBC_FUZZ_REGRESSIONS_DIR); }

// The harnesses replayed here, one per folder under regressions/: a reader per format, and
// load + analyze.
const std::map<std::string, Format> kReaderHarnesses = {
    {"ovm", Format::Ovm},       {"ovmb", Format::Ovmb}, {"medit", Format::Medit}, {"hybrid", Format::Hybrid},
    {"hedra", Format::Hedra},   {"msh", Format::Msh},   {"vtk", Format::Vtk},     {"vtu", Format::Vtu},
    {"foam", Format::Foam},     {"su2", Format::Su2},   {"ugrid", Format::Ugrid}, {"fluent", Format::Fluent},
    {"abaqus", Format::Abaqus}, {"nastran", Format::Nastran}, {"lsdyna", Format::LsDyna}};
const std::string kAnalyzeHarness = "analyze";
const std::string kFoamDecomposedHarness = "foam_decomposed";

std::optional<Format> format_of_harness(const std::string& h) {
  const auto it = kReaderHarnesses.find(h);
  if (it == kReaderHarnesses.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> reader_harness_names() {
  std::vector<std::string> names;
  for (const auto& [name, format] : kReaderHarnesses) names.push_back(name);
  return names;
}

std::string file_bytes(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Sorted so that the order (and a failure's position) is the same on every machine.
std::vector<fs::path> inputs_of(const std::string& harness) {
  std::vector<fs::path> files;
  const fs::path dir = regressions_dir() / harness;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

struct Outcome {
  int accepted = 0, rejected = 0;
};

// A harness without kept inputs fails: a replay of nothing would pass having checked nothing.
template <class Run>
Outcome replay(const std::string& harness, Run&& run) {
  Outcome o;
  const std::vector<fs::path> inputs = inputs_of(harness);
  if (inputs.empty()) ADD_FAILURE() << "no regression inputs under " << regressions_dir() / harness;
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    try {
      const bool accepted = run(file_bytes(p));
      (accepted ? o.accepted : o.rejected) += 1;
      // bounds_*: a tiny file declaring huge counts or valences; it must be refused (before it
      // could allocate for them, which the sanitized run would report as an allocation failure).
      if (p.filename().string().rfind("bounds_", 0) == 0) {
        EXPECT_FALSE(accepted) << p;
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << p << ": only InputError may escape, got: " << e.what();
    }
  }
  return o;
}

class ReaderRegressions : public ::testing::TestWithParam<std::string> {};

TEST_P(ReaderRegressions, OnlyInputErrorOrAMesh) {
  const std::string h = GetParam();
  const std::optional<Format> format = format_of_harness(h);
  ASSERT_TRUE(format) << "no reader harness named " << h;
  const Outcome o = replay(h, [&](const std::string& b) { return fuzz::read_and_build(*format, b); });
  RecordProperty("accepted", o.accepted);
  RecordProperty("rejected", o.rejected);
}

INSTANTIATE_TEST_SUITE_P(Fuzz, ReaderRegressions, ::testing::ValuesIn(reader_harness_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(FuzzRegressions, AnalyzeOnlyInputErrorOrAnAnalysis) {
  replay(kAnalyzeHarness, [](const std::string& b) { return fuzz::load_and_analyze(b); });
}

TEST(FuzzRegressions, FoamDecomposedOnlyInputErrorOrAMesh) {
  const Outcome o = replay(kFoamDecomposedHarness, [](const std::string& b) { return fuzz::join_and_build(b); });
  EXPECT_GT(o.accepted, 0);  // the decomposed hex2 is a mesh: the path can accept
  EXPECT_GT(o.rejected, 0);
}

// The folder is where the harnesses' findings are kept: every folder in it must be a harness
// replayed above (a folder of a new or misspelt harness would otherwise never be replayed), and
// every harness must have its folder.
TEST(FuzzRegressions, FoldersAreTheReplayedHarnesses) {
  ASSERT_TRUE(fs::is_directory(regressions_dir())) << regressions_dir();
  for (const auto& e : fs::directory_iterator(regressions_dir()))
    if (e.is_directory()) {
      const std::string name = e.path().filename().string();
      EXPECT_TRUE(name == kAnalyzeHarness || name == kFoamDecomposedHarness || format_of_harness(name))
          << "no harness replays " << e.path();
    }
  for (const std::string& h : reader_harness_names()) EXPECT_TRUE(fs::is_directory(regressions_dir() / h)) << h;
  EXPECT_TRUE(fs::is_directory(regressions_dir() / kAnalyzeHarness));
  EXPECT_TRUE(fs::is_directory(regressions_dir() / kFoamDecomposedHarness));
  EXPECT_FALSE(format_of_harness("no-such-harness"));
}

// The harness code path itself must tell the outcomes apart, or the replays above prove nothing.
TEST(FuzzRegressions, HarnessPathSeesAcceptAndReject) {
  const std::string tet =
      "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
      "Tetrahedra\n1\n1 2 3 4 0\nEnd\n";
  EXPECT_TRUE(fuzz::read_and_build(Format::Medit, tet));
  EXPECT_FALSE(fuzz::read_and_build(Format::Medit, tet.substr(0, tet.size() - 12)));
  EXPECT_TRUE(fuzz::load_and_analyze(std::string(1, '\x02') + tet));
  EXPECT_FALSE(fuzz::load_and_analyze(std::string(1, '\x00') + tet));  // MEDIT text read as OVM
  EXPECT_FALSE(fuzz::load_and_analyze(""));
}

// Resource bounds on valid but extreme meshes (found by hand, not by the fuzzers, whose inputs are
// too small to reach them): k tets in a fan around one edge, so that about 2k faces, 2k edges and
// 2k wireframe edges meet at each end of that edge.
MeshInput tet_fan(int k) {
  MeshInput in;
  in.source = "fan";
  for (double z : {0.0, 1.0}) in.points.insert(in.points.end(), {0.0, 0.0, z});
  for (int i = 0; i < k; ++i) {
    const double a = 2 * std::numbers::pi * i / k;
    in.points.insert(in.points.end(), {std::cos(a), std::sin(a), 0.5});
  }
  for (int i = 0; i < k; ++i) {
    const int32_t r = 2 + i, s = 2 + (i + 1) % k;
    const int32_t f0 = static_cast<int32_t>(in.faces.rows());
    for (std::array<int32_t, 3> t : {std::array<int32_t, 3>{0, 1, r}, {0, s, 1}, {0, r, s}, {1, s, r}})
      in.faces.push_row(t.begin(), t.end());
    for (int32_t f = f0; f < f0 + 4; ++f) in.cells.items.push_back(2 * f);
    in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
  }
  return in;
}

// CPU seconds this thread spent in f(), the least of three runs: the thread's own clock does not
// count what other processes take from the machine.
template <class F>
double thread_seconds(F&& f) {
  double best = 1e300;
  for (int run = 0; run < 3; ++run) {
    timespec t0{}, t1{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
    f();
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
    best = std::min(best, static_cast<double>(t1.tv_sec - t0.tv_sec) + 1e-9 * static_cast<double>(t1.tv_nsec - t0.tv_nsec));
  }
  return best;
}

// Work that grows linearly grows 4x from k to 4k, a quadratic one 16x. The bound leaves room for
// n log n, caches and timer noise, and holds whatever the machine's speed or load (or a
// sanitizer's slowdown, which both sizes share).
constexpr double kLinearGrowthBound = 8.0;

// build_mesh filed faces and edges under their lowest vertex only, so every lookup at the fan's
// axis scanned all of them (k = 20000: 10 s; a 8 MB file would take a quarter of an hour). One
// thread, so that the thread's clock sees all the work.
TEST(ResourceBounds, TetFanBuildMesh) {
  const Threads one{1, 4096};
  const Mesh m = build_mesh(tet_fan(20000), one);
  EXPECT_EQ(m.num_cells(), 20000u);
  EXPECT_EQ(m.num_faces(), 60000u);
  EXPECT_EQ(m.num_edges(), 60001u);
  EXPECT_EQ(m.edge_valence(0), 20000);  // the axis (the first edge of the first face)
  const double small = thread_seconds([&] { build_mesh(tet_fan(5000), one); });
  const double large = thread_seconds([&] { build_mesh(tet_fan(20000), one); });
  EXPECT_LT(large, kLinearGrowthBound * small) << "quadratic again? 5000 tets: " << small << " s, 20000: " << large << " s";
}

// The wireframe colouring listed every pair of wires sharing a point (k = 10^4: 2.1 GB, 128 s);
// it must stay linear in memory and time.
TEST(ResourceBounds, TetFanAnalyze) {
  const Mesh m = build_mesh(tet_fan(4000));
  const Analysis a = analyze(m);
  ASSERT_TRUE(a.wireframe_stage);
  EXPECT_EQ(a.wireframe_stage->wireframe.vsg_edges, 4000 + 1);  // the axis and the k spokes at its ends
  EXPECT_EQ(wireframe_style(a.wireframe_stage->view, a.wireframe_stage->wireframe).color.size(),
            a.wireframe_stage->wireframe.size());
  // One thread, so that the thread's clock sees all the work (with a pool it sees the share this
  // thread happened to take, which varied with the machine's load).
  AnalysisOptions one;
  one.threads = 1;
  const Mesh small_mesh = build_mesh(tet_fan(1000));
  const double small = thread_seconds([&] { analyze(small_mesh, one); });
  const double large = thread_seconds([&] { analyze(m, one); });
  EXPECT_LT(large, kLinearGrowthBound * small) << "quadratic again? 1000 tets: " << small << " s, 4000: " << large << " s";
}

}  // namespace
}  // namespace hbc
