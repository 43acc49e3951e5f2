#include "test_support.hpp"

namespace hbc {
namespace {

// Two unit cubes sharing the face x = 1, written as MEDIT text.
const char* kTwoCubes =
    "MeshVersionFormatted 1\nDimension 3\nVertices\n12\n"
    "0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n1 1 1 0\n0 1 1 0\n"
    "2 0 0 0\n2 1 0 0\n2 0 1 0\n2 1 1 0\n"
    "Hexahedra\n2\n1 2 3 4 5 6 7 8 0\n2 9 10 3 6 11 12 7 0\nEnd\n";

TEST(MeshCore, TwoCubesTopology) {
  Mesh m = build_mesh(read_medit(kTwoCubes, "two_cubes.mesh"));
  EXPECT_EQ(m.num_vertices(), 12u);
  EXPECT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.num_faces(), 11u);
  EXPECT_EQ(m.num_edges(), 20u);
  EXPECT_EQ(m.num_hex_cells(), 2u);
  int interior = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) interior += !m.face_boundary[f];
  EXPECT_EQ(interior, 1);
  for (size_t e = 0; e < m.num_edges(); ++e) {
    EXPECT_TRUE(m.edge_fan_ok(e));
    const EdgeFan fan = test::fan_of(m, e);
    EXPECT_EQ(fan.faces.size(), fan.cells.size() + 1) << "boundary fan is a path";
    EXPECT_EQ(m.edge_valence(e), static_cast<int32_t>(fan.cells.size()));
  }
  for (size_t v = 0; v < m.num_vertices(); ++v) EXPECT_FALSE(m.vert_non_manifold[v]);
}

TEST(MeshCore, DegenerateHexIsPrism) {
  // A prism written as a hexahedron with ids 3=4 and 7=8 repeated.
  const char* text =
      "MeshVersionFormatted 1\nDimension\n3\nVertices\n6\n"
      "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n0 1 1 0\n"
      "Hexahedra\n1\n1 2 3 3 4 5 6 6 0\n";
  Mesh m = build_mesh(read_medit(text, "prism.mesh"));
  ASSERT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.cell_type[0], CellType::Prism);
  EXPECT_EQ(m.num_faces(), 5u);
  EXPECT_EQ(m.num_edges(), 9u);
}

TEST(MeshCore, FaceInThreeCellsIsRejected) {
  const char* text =
      "3 1 3\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n1 1\n1 1\n1 1\n";
  try {
    build_mesh(read_hedra(text, "three.hedra"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "three.hedra");
    EXPECT_GE(e.loc().line, 5);
  }
}

}  // namespace
}  // namespace hbc
