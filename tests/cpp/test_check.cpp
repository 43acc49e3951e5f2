// The validator (check_input) and the skip_invalid load on hand-written files with one defect of
// each class, whose reports are derived below (docs/check.md).
#include <gtest/gtest.h>

#include <string>

#include "hbc/check.hpp"
#include "hbc/io.hpp"

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
