// The validator (check_input) and the skip_invalid load on hand-written files with one defect of
// each class, whose reports are derived below (docs/check.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hbc/check.hpp"
#include "hbc/io.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

// tests/data/check/defects.HYBRID: 34 vertices (lines 2-35), 32 faces (lines 36-67), 10 cells (cell
// c's face line 68 + 2c). A grid of unit cubes x 0..3 (vertex x + 4y + 8z), then:
//   cell 0  hex A (x 0..1)                     cell 5  pyramid on the face A|B (face 1), apex 16
//   cell 1  hex B (x 1..2)                     cell 6  A again (same faces)
//   cell 2  one face (face 4): few, open       cell 7  a tet far away
//   cell 3  faces 15 (2 corners) and 0         cell 8  a tet with vertex 25 in two faces: (3,3,4,4)
//   cell 4  C (x 2..3) without its x=3 face    cell 9  a tet with vertices 30, 31 in two faces: four quads
// (25, 30 and 31 are moved off the straight edge between their neighbours, so the faces fold)
// vertex 32 sits on vertex 0 and no cell uses it; vertex 33 is used by none.
// Alone, cells 2, 3, 4 are refused (2: few_faces first, 3: degenerate_faces, 4: open_cells). Face 1
// is then in cells 0, 1, 5 and 6: 6 repeats 0's vertices and goes first (duplicate_cells); of 0, 1
// and 5, the third (5) goes (shared_faces). Kept: 0, 1, 7, 8, 9. Cells 8 and 9 have a vertex in 2
// faces off the edge (not_simple); 7, 8, 9 are three pieces apart from cell 0's; vertices 3 7 11 15 (C's far
// side), 16 (the apex), 32, 33 are in no kept cell.
std::string defects_file() { return std::string(HBC_FORMATS_DIR) + "/../check/defects.HYBRID"; }

std::vector<int64_t> ids(const DefectClass& d) {
  std::vector<int64_t> out;
  for (const DefectItem& it : d.first) out.push_back(it.id);
  return out;
}

TEST(Check, EveryClassOfTheHandWrittenFile) {
  const CheckReport r = check_file(defects_file());
  EXPECT_EQ(r.cells, 10);
  EXPECT_EQ(r.vertices, 34);
  EXPECT_FALSE(r.clean());
  using V = std::vector<int64_t>;
  EXPECT_EQ(ids(r[Defect::BadIndex]), V{});
  EXPECT_EQ(ids(r[Defect::DegenerateFaces]), V{15});
  EXPECT_EQ(r[Defect::DegenerateFaces].first[0].loc.line, 51);
  EXPECT_EQ(ids(r[Defect::FewFaces]), (V{2, 3}));
  EXPECT_EQ(r[Defect::FewFaces].first[0].loc.line, 72);
  EXPECT_EQ(ids(r[Defect::FaceTwice]), V{});
  EXPECT_EQ(ids(r[Defect::OpenCells]), (V{2, 4}));
  EXPECT_EQ(r[Defect::OpenCells].first[1].loc.line, 76);
  EXPECT_EQ(ids(r[Defect::SharedFaces]), V{5});
  EXPECT_EQ(ids(r[Defect::DuplicateCells]), V{6});
  EXPECT_EQ(ids(r[Defect::NotSimple]), (V{8, 9}));
  EXPECT_EQ(r[Defect::NotSimple].first[1].loc.line, 86);
  EXPECT_EQ(ids(r[Defect::Inverted]), V{});
  EXPECT_EQ(ids(r[Defect::ZeroVolume]), V{});
  EXPECT_EQ(ids(r[Defect::CoincidentVertices]), V{32});
  EXPECT_EQ(r[Defect::CoincidentVertices].first[0].loc.line, 34);
  EXPECT_EQ(ids(r[Defect::UnusedVertices]), (V{3, 7, 11, 15, 16, 32, 33}));
  EXPECT_EQ(ids(r[Defect::DisconnectedPieces]), (V{7, 8, 9}));
  // Of these, a skip_invalid load drops face 15 and cells 2 to 6 (RefusedWithoutTheOptionAndLoadedWithIt):
  // both few-face cells (2 is open, 3 uses face 15), both open cells, cells 5 and 6.
  EXPECT_EQ(r[Defect::DegenerateFaces].dropped, 1);
  EXPECT_EQ(r[Defect::FewFaces].dropped, 2);
  EXPECT_EQ(r[Defect::OpenCells].dropped, 2);
  EXPECT_EQ(r[Defect::SharedFaces].dropped, 1);
  EXPECT_EQ(r[Defect::DuplicateCells].dropped, 1);
  for (Defect d : {Defect::BadIndex, Defect::FaceTwice, Defect::NotSimple, Defect::Inverted, Defect::ZeroVolume,
                   Defect::CoincidentVertices, Defect::UnusedVertices, Defect::DisconnectedPieces})
    EXPECT_EQ(r[d].dropped, 0) << defect_key(d);
  std::vector<DroppedCell> loaded;
  load_mesh_skipping_invalid(defects_file(), loaded);
  EXPECT_EQ(r.dropped, loaded);
}

TEST(Check, RefusedWithoutTheOptionAndLoadedWithIt) {
  try {
    load_mesh(defects_file());
    FAIL() << "loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--skip-invalid"), std::string::npos) << e.what();
  }
  std::vector<DroppedCell> dropped;
  const Mesh m = load_mesh_skipping_invalid(defects_file(), dropped);
  EXPECT_EQ(m.num_cells(), 5u);
  const std::vector<DroppedCell> want = {{2, Defect::FewFaces, SourceLoc::at_line(72)},
                                         {3, Defect::DegenerateFaces, SourceLoc::at_line(74)},
                                         {4, Defect::OpenCells, SourceLoc::at_line(76)},
                                         {5, Defect::SharedFaces, SourceLoc::at_line(78)},
                                         {6, Defect::DuplicateCells, SourceLoc::at_line(80)}};
  EXPECT_EQ(dropped, want);
  ASSERT_FALSE(m.warnings.empty());
  EXPECT_NE(m.warnings.back().find("5 cell(s) dropped"), std::string::npos) << m.warnings.back();
}

// A unit cube (cell 0, lines 23-24), a flat cell of three faces closing on themselves beside it
// (cell 1, lines 25-26: the quad 8 9 10 11 and the triangles 8 9 10 and 8 10 11, every edge in two
// of them) and a cell of that quad alone (cell 2, lines 27-28). Cells 1 and 2 have fewer than 4
// faces; cell 2 is also open, so a skip_invalid load drops it (reason few_faces, its first class)
// and keeps cell 1, which loads as the closed polyhedron it is (build_mesh takes it). The report
// says so: few_faces counts 2 cells of which 1 is dropped, and its dropped list is the load's.
// (Before, few_faces was a "refused" class and `hbc check` said all of them went: issue 62 saw
// 154 few-face cells announced on a published RHDM file where the load drops 10.)
const char* kFlatCell =
    "12 9 9\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n5 0 0\n6 0 0\n6 1 0\n5 1 0\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n4 8 9 10 11\n3 8 9 10\n3 8 10 11\n"
    "6 0 1 2 3 4 5\n6 0 0 0 0 0 0\n3 6 7 8\n3 0 0 0\n1 6\n1 0\n0\n0\n0\n";

TEST(Check, TheReportDropsWhatTheLoadDrops) {
  const MeshInput in = read_hybrid(kFlatCell, "flat.HYBRID");
  const CheckReport r = check_input(in);
  using V = std::vector<int64_t>;
  EXPECT_EQ(ids(r[Defect::FewFaces]), (V{1, 2}));
  EXPECT_EQ(r[Defect::FewFaces].dropped, 1);
  EXPECT_EQ(ids(r[Defect::OpenCells]), V{2});
  EXPECT_EQ(r[Defect::OpenCells].dropped, 1);
  EXPECT_FALSE(defect_refused(Defect::FewFaces));
  EXPECT_TRUE(defect_refused(Defect::OpenCells));
  std::vector<DroppedCell> loaded;
  const Mesh m = build_mesh_skipping_invalid(in, loaded);
  const std::vector<DroppedCell> want = {{2, Defect::FewFaces, SourceLoc::at_line(27)}};
  EXPECT_EQ(loaded, want);
  EXPECT_EQ(r.dropped, loaded);
  EXPECT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.cell_faces.count(1), 3u);  // the flat cell, kept whole
}

// Every shared mesh of the paper's data and of Robust Hex-Dominant Meshing (the folder where
// published RHDM files with few-face cells go): the report's dropped list is the load's.
TEST(Check, SharedMeshesReportWhatTheLoadDrops) {
  const std::string root = test::data_path("hybrid-base-complex");
  HBC_REQUIRE_DATA("hybrid-base-complex");
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    try {
      format_from_path(e.path().string());
    } catch (const std::exception&) {
      continue;  // not a mesh
    }
    const CheckReport r = check_file(e.path().string());
    std::vector<DroppedCell> loaded;
    const Mesh m = load_mesh_skipping_invalid(e.path().string(), loaded);
    EXPECT_EQ(r.dropped, loaded) << e.path();
    EXPECT_EQ(static_cast<int64_t>(m.num_cells()) + static_cast<int64_t>(loaded.size()), r.cells) << e.path();
    ++files;
  }
  EXPECT_GE(files, 4);
}

// Three hexes along x between planes at x = 0, 2, 1, 3 (lines 5-20): the middle one runs from 2
// back to 1, volume -1 against its neighbours' +2 (inverted, line 32); a fourth hex (line 34) has
// all corners in the plane z = 0: volume 0, and a piece of its own.
const char* kTangled =
    "MeshVersionFormatted 2\nDimension 3\nVertices\n24\n"
    "0 0 0 0\n0 1 0 0\n0 1 1 0\n0 0 1 0\n"
    "2 0 0 0\n2 1 0 0\n2 1 1 0\n2 0 1 0\n"
    "1 0 0 0\n1 1 0 0\n1 1 1 0\n1 0 1 0\n"
    "3 0 0 0\n3 1 0 0\n3 1 1 0\n3 0 1 0\n"
    "10 0 0 0\n11 0 0 0\n11 1 0 0\n10 1 0 0\n10.25 0.25 0 0\n10.75 0.25 0 0\n10.75 0.75 0 0\n10.25 0.75 0 0\n"
    "Hexahedra\n4\n1 2 3 4 5 6 7 8 0\n5 6 7 8 9 10 11 12 0\n9 10 11 12 13 14 15 16 0\n17 18 19 20 21 22 23 24 0\nEnd\n";

TEST(Check, InvertedAndZeroVolume) {
  const CheckReport r = check_input(read_medit(kTangled, "tangled.mesh"));
  using V = std::vector<int64_t>;
  EXPECT_EQ(ids(r[Defect::Inverted]), V{1});
  EXPECT_EQ(r[Defect::Inverted].first[0].loc.line, 32);
  EXPECT_NEAR(r[Defect::Inverted].first[0].volume, -1.0, 1e-12);
  EXPECT_EQ(ids(r[Defect::ZeroVolume]), V{3});
  EXPECT_EQ(ids(r[Defect::DisconnectedPieces]), V{3});
  EXPECT_EQ(r[Defect::OpenCells].count + r[Defect::NotSimple].count + r[Defect::UnusedVertices].count, 0);
}

// A file build_mesh accepts gives no dropped cell and the very same mesh.
TEST(Check, CleanFilesLoadAsBefore) {
  for (const char* text : {kTangled}) {
    const MeshInput in = read_medit(text, "t.mesh");
    std::vector<DroppedCell> dropped;
    EXPECT_EQ(build_mesh_skipping_invalid(in, dropped), build_mesh(in));
    EXPECT_TRUE(dropped.empty());
  }
}

// A unit cube whose edge 0-1 carries vertex 8 at its middle (a hanging node, where snappyHexMesh
// refined a neighbour across that edge): the two faces at the edge are pentagons and vertex 8 is
// in only those two. V - E + F = 9 - 13 + 6 = 2 and 8 lies on the straight edge, so the cell is a
// true polyhedron: no defect. Moved 0.3 off the edge (1.5 0 0.3 after scaling: the faces fold by
// far more than 10 degrees) the same cell is not_simple.
std::string cube_with_corner_on_edge(const char* mid) {
  return std::string("9 6 3\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n0 0 2\n2 0 2\n2 2 2\n0 2 2\n") + mid +
         "\n5 0 8 1 5 4\n5 0 3 2 1 8\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n4 4 5 6 7\n6 0 1 2 3 4 5\n6 0 0 0 0 0 0\n0\n";
}

TEST(Check, ACornerOnAStraightEdgeIsNoDefect) {
  const std::string on = cube_with_corner_on_edge("1 0 0"), off = cube_with_corner_on_edge("1 0 0.3");
  const CheckReport r_on = check_input(read_hybrid(on, "on.HYBRID"));
  EXPECT_EQ(r_on[Defect::NotSimple].count, 0);
  EXPECT_EQ(r_on[Defect::OpenCells].count, 0);
  const CheckReport r_off = check_input(read_hybrid(off, "off.HYBRID"));
  EXPECT_EQ(r_off[Defect::NotSimple].count, 1);
}

}  // namespace
}  // namespace hbc
