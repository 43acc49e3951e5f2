// Decomposed OpenFOAM cases joined without reconstructPar, on hex2 (two unit hexahedra along x,
// tests/data/formats/foam/hex2_ascii) split by decomposePar into one cell per processor
// (make_foam_cases.sh): hex2_decomposed (ASCII, constant/polyMesh kept), hex2_decomposed_binary
// and hex2_decomposed_gzip (processor folders only). What decomposePar wrote, by hand:
//   processor0: cell 0; faces 4(0 4 6 2) 4(0 1 5 4) 4(2 6 7 3) 4(0 2 3 1) 4(4 5 7 6) | 4(1 3 7 5)
//               (five walls, then the processor patch procBoundary0to1), all owned by local cell 0;
//               pointProcAddressing (0 1 3 4 6 7 9 10), faceProcAddressing (2 3 4 5 6 1),
//               cellProcAddressing (0)
//   processor1: cell 1; faces 4(1 3 7 5) ... | 4(0 4 6 2) (procBoundary1to0);
//               pointProcAddressing (1 2 4 5 7 8 10 11), faceProcAddressing (7 8 9 10 11 -1),
//               cellProcAddressing (1)
// So global face 0, hex2's internal face 4(1 4 10 7), is processor0's local face 5 as written
// (+1) and processor1's local face 5 reversed (-1: 4(0 4 6 2) -> points (1 7 10 4), face 0 with its
// first point kept and the rest reversed). Joined, cell 0 lists 2*0 (owner of face 0) and faces
// 1..5 as written (2, 4, 6, 8, 10); cell 1 lists 2*0+1 (face 0 reversed) and faces 6..10.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

namespace fs = std::filesystem;

std::string foam_case(const std::string& name) { return std::string(HBC_FORMATS_DIR) + "/foam/" + name; }

std::vector<int32_t> row(const Csr<int32_t>& c, size_t r) { return {c[r].begin(), c[r].end()}; }

void expect_same_input(const MeshInput& a, const MeshInput& b) {
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.cells, b.cells);
}

TEST(FoamDecomposed, JoinedIsTheMeshDecomposeParSplitInEveryWriting) {
  const MeshInput whole = read_input(foam_case("hex2_ascii"));
  for (const std::string& path : {foam_case("hex2_decomposed") + "/processor*", foam_case("hex2_decomposed_binary"),
                                  foam_case("hex2_decomposed_gzip") + "/hex2_decomposed_gzip.foam"}) {
    SCOPED_TRACE(path);
    const MeshInput in = read_input(path);
    expect_same_input(in, whole);
    EXPECT_EQ(row(in.cells, 0), (std::vector<int32_t>{0, 2, 4, 6, 8, 10}));
    EXPECT_EQ(row(in.cells, 1), (std::vector<int32_t>{1, 12, 14, 16, 18, 20}));
    EXPECT_EQ(row(in.faces, 0), (std::vector<int32_t>{1, 4, 10, 7}));
    ASSERT_FALSE(in.warnings.empty());
    EXPECT_NE(in.warnings[0].find("decomposed case: 2 processor folders"), std::string::npos) << in.warnings[0];
    const Mesh m = build_mesh(in);
    EXPECT_EQ(m.num_cells(), 2u);
    EXPECT_EQ(m.num_faces(), 11u);  // face 0 once, not once per processor
    EXPECT_EQ(std::count(m.face_boundary.begin(), m.face_boundary.end(), 1), 10);
  }
}

// constant/polyMesh first when the case has it; `case/processor*` asks for the processors.
TEST(FoamDecomposed, TheReconstructedMeshComesFirstUnlessAskedForTheProcessors) {
  const std::string c = foam_case("hex2_decomposed");
  EXPECT_EQ(foam_decomposed_case(c), "");
  EXPECT_EQ(foam_decomposed_case(c + "/hex2_decomposed.foam"), "");
  EXPECT_EQ(foam_decomposed_case(c + "/processor*"), c);
  EXPECT_EQ(foam_decomposed_case(foam_case("hex2_decomposed_binary")), foam_case("hex2_decomposed_binary"));
  EXPECT_EQ(foam_decomposed_case(c + "/processor0"), "");  // one processor is a case of its own
  EXPECT_EQ(format_from_path(c + "/processor*"), Format::Foam);
  EXPECT_TRUE(read_input(c).warnings.empty());
  EXPECT_EQ(read_input(c + "/processor1").cells.rows(), 1u);
}

TEST(FoamDecomposed, SameForAnyThreadCount) {
  const std::string c = foam_case("hex2_decomposed_gzip");
  const MeshInput one = read_foam_decomposed(c, {1, 1});
  const MeshInput two = read_foam_decomposed(c, {2, 1});
  expect_same_input(one, two);
  EXPECT_EQ(build_mesh(one, {1, 1}), build_mesh(two, {2, 1}));
}

// The processors' files in memory, to break one at a time.
struct Processors {
  std::vector<std::string> text[2];  // points faces owner neighbour pointPA facePA cellPA boundary
  Processors() {
    const char* names[] = {"points", "faces", "owner", "neighbour", "pointProcAddressing", "faceProcAddressing",
                           "cellProcAddressing", "boundary"};
    for (int p = 0; p < 2; ++p)
      for (const char* n : names)
        text[p].push_back(read_file_bytes(foam_case("hex2_decomposed") + "/processor" + std::to_string(p) + "/constant/polyMesh/" + n));
  }
  std::vector<FoamProcessorFiles> files(int n = 2) const {
    std::vector<FoamProcessorFiles> out;
    for (int p = 0; p < n; ++p) {
      const auto& t = text[p];
      const std::string d = "p" + std::to_string(p) + "/";
      out.push_back({{t[0], t[1], t[2], t[3], d + "points", d + "faces", d + "owner", d + "neighbour"}, t[4], t[5], t[6],
                     d + "pointProcAddressing", d + "faceProcAddressing", d + "cellProcAddressing", t[7], d + "boundary"});
    }
    return out;
  }
};

// Replaces the list of an addressing file (everything from the count on) by `list`.
void set_list(std::string& file, const std::string& list) {
  const size_t header_end = file.find("\n}");
  const size_t at = file.find_first_of("0123456789", header_end);
  file.replace(at, file.find(')', at) + 1 - at, list);
}

InputError join_error(const Processors& p, int n = 2) {
  try {
    const auto files = p.files(n);
    join_foam_processors(files, "case");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "joined broken processors";
  return InputError("", {}, "");
}

TEST(FoamDecomposed, FromMemoryAsFromTheCase) {
  const Processors p;
  const auto files = p.files();
  expect_same_input(join_foam_processors(files, "case"), read_input(foam_case("hex2_ascii")));
}

TEST(FoamDecomposed, ALabelOutOfRangeIsNamedByFileAndLine) {
  Processors p;
  // The points together are 16 (8 + 8): an id of 99 cannot be one. On line 3 of the list.
  p.text[1][4] = "8\n(1 2 4 5\n7 8 10\n99)\n";
  InputError e = join_error(p);
  EXPECT_EQ(e.file(), "p1/pointProcAddressing");
  EXPECT_EQ(e.loc().line, 4);
  EXPECT_NE(e.detail().find("found 99"), std::string::npos) << e.what();
  // A face id 0 (faceProcAddressing is 1-based).
  p = Processors();
  p.text[0][5] = "6\n(2 3 4 5 6\n0)";
  e = join_error(p);
  EXPECT_EQ(e.file(), "p0/faceProcAddressing");
  EXPECT_EQ(e.loc().line, 3);
}

TEST(FoamDecomposed, CountsThatDoNotAddUpAreRefused) {
  Processors p;
  set_list(p.text[1][6], "1(0)");  // both processors claim cell 0
  EXPECT_NE(join_error(p).detail().find("found cell 0 twice"), std::string::npos);
  p = Processors();
  set_list(p.text[1][6], "1(2)");  // two cells in all: ids 0 and 1, not 2
  EXPECT_NE(join_error(p).detail().find("a cell id in [0, 1] (at most the processors' cells together), found 2"), std::string::npos);
  p = Processors();
  set_list(p.text[1][6], "2(1 2)");  // two labels for processor1's one cell
  const InputError e = join_error(p);
  EXPECT_EQ(e.file(), "p1/cellProcAddressing");
  EXPECT_NE(e.detail().find("expected 1 labels"), std::string::npos) << e.what();
  p = Processors();
  set_list(p.text[1][5], "6(7 8 9 10 11 1)");  // face 0 as written on both sides
  EXPECT_NE(join_error(p).detail().find("each face once on each side"), std::string::npos);
}

// Without processor1, processor0's patch procBoundary0to1 names a processor that is not there;
// with processor1's side of face 0 moved to face 11 (a face of its own), face 0 has no twin.
TEST(FoamDecomposed, AMissingProcessorOrTwinIsNamed) {
  Processors p;
  InputError e = join_error(p, 1);
  EXPECT_EQ(e.file(), "p0/boundary");
  EXPECT_NE(e.detail().find("processor1 that patch procBoundary0to1 faces"), std::string::npos) << e.what();
  set_list(p.text[1][5], "6(7 8 9 10 11 12)");
  e = join_error(p);
  EXPECT_EQ(e.file(), "p0/boundary");
  EXPECT_GT(e.loc().line, 0);
  EXPECT_NE(e.detail().find("face 0 of patch procBoundary0to1 (local face 5) on processor1 too, found it on no other processor"),
            std::string::npos)
      << e.what();
}

TEST(FoamDecomposed, AFolderWithAGapInItsProcessorsIsNamed) {
  const fs::path dir = fs::temp_directory_path() / ("hbc_foam_gap_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::copy(foam_case("hex2_decomposed_binary") + "/processor0", dir / "processor0", fs::copy_options::recursive);
  fs::copy(foam_case("hex2_decomposed_binary") + "/processor1", dir / "processor2", fs::copy_options::recursive);
  try {
    read_input(dir.string());
    ADD_FAILURE() << "read a case without processor1";
  } catch (const InputError& e) {
    EXPECT_NE(e.detail().find("found processor2 but no processor1"), std::string::npos) << e.what();
  }
  fs::rename(dir / "processor2", dir / "processor1");
  fs::remove(dir / "processor1" / "constant" / "polyMesh" / "cellProcAddressing");
  try {
    read_input(dir.string());
    ADD_FAILURE() << "read a processor without its addressing";
  } catch (const InputError& e) {
    EXPECT_NE(e.detail().find("decomposePar's addressing file cellProcAddressing"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(FoamDecomposed, TheCliSaysItJoinedTheProcessors) {
  const test::CliRun r = test::run_cli("info '" + foam_case("hex2_decomposed_binary") + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("hbc: warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("decomposed case: 2 processor folders joined"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("cells           2"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace hbc
