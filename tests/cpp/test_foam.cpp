// The OpenFOAM polyMesh reader on small cases whose answers are counted by hand, written the ways
// OpenFOAM writes them (tests/data/formats/foam: hex2_ascii by hand, hex2_binary and hex2_gzip by
// OpenFOAM's foamFormatConvert from it), and the ways a user names a case.
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

// Two unit hexahedra side by side along x: 3 x 2 x 2 = 12 points; 11 faces (the one between the
// cells, then 5 boundary faces of each cell); 20 edges (8 along x, 6 along y, 6 along z); both
// cells hexahedra, face 0 owned by cell 0 and neighboured by cell 1.
void expect_hex2(const Mesh& m) {
  EXPECT_EQ(m.num_vertices(), 12u);
  EXPECT_EQ(m.num_faces(), 11u);
  EXPECT_EQ(m.num_edges(), 20u);
  ASSERT_EQ(m.num_cells(), 2u);
  EXPECT_TRUE(m.is_hex(0) && m.is_hex(1));
  EXPECT_EQ(std::count(m.face_boundary.begin(), m.face_boundary.end(), 1), 10);
}

TEST(Foam, TwoHexahedraInAsciiBinaryAndGzip) {
  for (const char* name : {"hex2_ascii", "hex2_binary", "hex2_gzip"}) {
    SCOPED_TRACE(name);
    const MeshInput in = read_input(foam_case(name));
    // Owned faces as written, the neighbour's reversed: cell 0 lists faces 0-5, cell 1 face 0
    // reversed (2*0+1) and faces 6-10.
    ASSERT_EQ(in.cells.rows(), 2u);
    EXPECT_EQ(std::vector<int32_t>(in.cells[0].begin(), in.cells[0].end()), (std::vector<int32_t>{0, 2, 4, 6, 8, 10}));
    EXPECT_EQ(std::vector<int32_t>(in.cells[1].begin(), in.cells[1].end()), (std::vector<int32_t>{1, 12, 14, 16, 18, 20}));
    EXPECT_EQ(in.binary, std::string(name) == "hex2_binary");
    expect_hex2(build_mesh(in));
  }
}

TEST(Foam, ACaseIsItsFolderItsFoamFileItsPolyMeshOrItsOwnerFile) {
  const std::string c = foam_case("hex2_ascii");
  for (const std::string& p : {c, c + "/hex2_ascii.foam", c + "/constant", c + "/constant/polyMesh",
                                c + "/constant/polyMesh/owner", foam_case("hex2_gzip") + "/constant/polyMesh/owner.gz"}) {
    SCOPED_TRACE(p);
    EXPECT_EQ(format_from_path(p), Format::Foam);
    expect_hex2(load_mesh(p));
  }
  EXPECT_EQ(format_from_name("openfoam"), Format::Foam);
}

// snappyHexMesh without -overwrite writes its meshes into time folders: the newest one is read
// (here 2/, binary), not constant/ (ASCII) nor the older 0.5/ (broken).
TEST(Foam, TheNewestTimeFolderWithAPolyMeshWins) {
  const fs::path dir = fs::temp_directory_path() / ("hbc_foam_times_" + std::to_string(::getpid()));
  fs::create_directories(dir / "constant");
  fs::create_directories(dir / "0.5" / "polyMesh");
  fs::create_directories(dir / "10");  // a time folder without a mesh
  fs::create_directories(dir / "2");
  fs::copy(foam_case("hex2_ascii") + "/constant/polyMesh", dir / "constant" / "polyMesh");
  fs::copy(foam_case("hex2_binary") + "/constant/polyMesh", dir / "2" / "polyMesh");
  std::ofstream(dir / "0.5" / "polyMesh" / "owner") << "broken";
  EXPECT_EQ(fs::path(foam_mesh_dir(dir.string())), dir / "2" / "polyMesh");
  const MeshInput in = read_input(dir.string());
  EXPECT_TRUE(in.binary);
  expect_hex2(build_mesh(in));
  fs::remove_all(dir);
}

TEST(Foam, AFolderThatIsNoCaseIsNamedInTheError) {
  const std::string dir = HBC_FORMATS_DIR;  // a folder of mesh files, no polyMesh
  try {
    load_mesh(dir);
    FAIL() << "accepted a folder without a mesh";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir);
    EXPECT_NE(e.detail().find("OpenFOAM case"), std::string::npos) << e.what();
  }
  // Read as another format, a folder is still an InputError, not an allocation of its "size".
  EXPECT_THROW(load_mesh(dir, Format::Medit), InputError);
  const test::CliRun r = test::run_cli("info '" + dir + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + ": expected a mesh file or an OpenFOAM case"), std::string::npos) << r.err;
}

// A one-hexahedron case from memory, with the liberties the format allows: no header (ASCII), a
// uniform owner list "6{0}", an empty neighbour list, and comments of both kinds.
TEST(Foam, UniformListsCommentsAndNoHeader) {
  const std::string points = "8 ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) /* top */ (0 0 1) (1 0 1) (1 1 1) (0 1 1) )";
  const std::string faces = "// outward\n6(4(0 3 2 1) 4(4 5 6 7) 4(0 1 5 4) 4(1 2 6 5) 4(2 3 7 6) 4(3 0 4 7))";
  const Mesh m = build_mesh(read_foam({points, faces, "6{0}", "0()", "p", "f", "o", "n"}));
  ASSERT_EQ(m.num_cells(), 1u);
  EXPECT_TRUE(m.is_hex(0));
  EXPECT_EQ(m.num_edges(), 12u);
}

// Older OpenFOAM versions pad neighbour with -1 up to the number of faces: the same mesh.
TEST(Foam, NeighbourPaddedWithMinusOne) {
  const std::string dir = foam_case("hex2_ascii") + "/constant/polyMesh/";
  const std::string points = read_file_bytes(dir + "points"), faces = read_file_bytes(dir + "faces"),
                    owner = read_file_bytes(dir + "owner");
  const std::string padded = "11(1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1)";
  expect_hex2(build_mesh(read_foam({points, faces, owner, padded, "p", "f", "o", "n"})));
  EXPECT_THROW(read_foam({points, faces, owner, "3(1 -1 1)", "p", "f", "o", "n"}), InputError);
}

// Binary with 64-bit labels and big-endian numbers (arch "MSB;label=64;scalar=64"): hex2 again.
std::string big_endian_list(const std::vector<int64_t>& v) {
  std::string out = std::to_string(v.size()) + "\n(";
  for (int64_t x : v)
    for (int k = 7; k >= 0; --k) out += static_cast<char>((static_cast<uint64_t>(x) >> (8 * k)) & 0xff);
  return out + ")\n";
}

TEST(Foam, BinaryBigEndianWith64BitLabels) {
  const std::string header = "FoamFile { format binary; class %; arch \"MSB;label=64;scalar=64\"; }\n";
  auto with_class = [&](const std::string& cls) { std::string h = header; return h.replace(h.find('%'), 1, cls); };
  std::vector<int64_t> coords;  // doubles' bits, big-endian like the labels
  const int xyz[12][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {0, 1, 1}, {1, 1, 1}, {2, 1, 1}};
  for (const auto& p : xyz)
    for (int a : p) {
      const double d = a;
      int64_t bits;
      std::memcpy(&bits, &d, 8);
      coords.push_back(bits);
    }
  std::string points = big_endian_list(coords);
  points.replace(0, 2, "12");  // 36 doubles, 3 a point: 12 points
  const std::vector<int64_t> loops = {1, 4, 10, 7, 0, 6, 9, 3, 0, 1, 7, 6, 3, 9, 10, 4, 0, 3, 4, 1, 6, 7, 10, 9,
                                      2, 5, 11, 8, 1, 2, 8, 7, 4, 10, 11, 5, 1, 4, 5, 2, 7, 8, 11, 10};
  std::vector<int64_t> offsets;
  for (int64_t i = 0; i <= 11; ++i) offsets.push_back(4 * i);
  const std::string faces = with_class("faceCompactList") + big_endian_list(offsets) + big_endian_list(loops);
  const Mesh m = build_mesh(read_foam({with_class("vectorField") + points, faces,
                                       with_class("labelList") + big_endian_list({0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1}),
                                       with_class("labelList") + big_endian_list({1}), "p", "f", "o", "n"}));
  expect_hex2(m);
  EXPECT_DOUBLE_EQ(m.points[3 * 11], 2.0);
}

}  // namespace
}  // namespace hbc
