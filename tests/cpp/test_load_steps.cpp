// The steps of build_mesh on hand-built cells, the fast MEDIT section parser against the token
// scanner, and parallel loads against single-threaded ones (every array of the Mesh).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "hbc/generate.hpp"
#include "mesh/mesh_steps.hpp"
#include "parallel/parallel.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using namespace mesh_steps;

const Threads kOne{1, 1};

// A MeshInput from vertex positions and cells given as lists of face loops (each cell its own
// copy of a shared face, as .HYBRID files do; flips all 0).
MeshInput soup(std::vector<double> points, const std::vector<std::vector<std::vector<int32_t>>>& cells) {
  MeshInput in;
  in.source = "hand.mesh";
  in.points = std::move(points);
  for (const auto& cell : cells) {
    for (const auto& loop : cell) {
      in.cells.items.push_back(static_cast<int32_t>(2 * in.faces.rows()));
      in.faces.push_row(loop.begin(), loop.end());
    }
    in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
  }
  return in;
}

// Unit cube on vertices base..base+7 (bottom 0-3 counter-clockwise from above, top 4-7 above
// them), faces outward.
std::vector<std::vector<int32_t>> cube(int32_t b) {
  return {{b + 0, b + 3, b + 2, b + 1}, {b + 4, b + 5, b + 6, b + 7}, {b + 0, b + 1, b + 5, b + 4},
          {b + 1, b + 2, b + 6, b + 5}, {b + 2, b + 3, b + 7, b + 6}, {b + 3, b + 0, b + 4, b + 7}};
}
void add_square(std::vector<double>& p, double x, double y, double z) {
  for (auto [dx, dy] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) p.insert(p.end(), {x + dx, y + dy, z});
}

// The steps up to and including check_cells, as build_mesh runs them.
struct Built {
  MeshInput in;
  Mesh m;
  EdgeFaceCounts counts;
  CellCheck cells;
};
Built through_check(MeshInput in) {
  Built b{std::move(in), {}, {}, {}};
  validate_input(b.in, kOne);
  b.m.points = b.in.points;
  b.counts = build_edges(b.m, merge_faces(b.in, b.m, kOne), kOne);
  b.cells = check_cells(b.m, b.in, kOne);
  return b;
}

double signed_volume(const Mesh& m, size_t c) {
  double vol = 0;
  for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) {
    auto loop = m.face_verts[m.cell_faces.items[i]];
    std::vector<int32_t> l(loop.begin(), loop.end());
    if (m.cell_face_flip[i]) std::reverse(l.begin(), l.end());
    const double* p0 = &m.points[3 * l[0]];
    for (size_t t = 1; t + 1 < l.size(); ++t) {
      const double *p1 = &m.points[3 * l[t]], *p2 = &m.points[3 * l[t + 1]];
      vol += p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) - p0[1] * (p1[0] * p2[2] - p1[2] * p2[0]) +
             p0[2] * (p1[0] * p2[1] - p1[1] * p2[0]);
    }
  }
  return vol / 6;
}

// Two unit cubes stacked along z: vertices 0-3 at z=0, 4-7 at z=1, 8-11 at z=top.
MeshInput stacked_cubes(double top) {
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 1);
  add_square(p, 0, 0, top);
  auto upper = cube(4);
  // The upper cube's bottom face is the lower cube's top face, listed as the upper cube sees it.
  return soup(p, {cube(0), upper});
}

// Cube 0 at the origin and cube 1 (vertices 8-15) moved by (x, y, z), some of cube 1's vertices
// glued onto cube 0's ((from, to) pairs), built single-threaded.
Mesh two_cubes(double x, double y, double z, const std::vector<std::pair<int32_t, int32_t>>& glue) {
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 1);
  add_square(p, x, y, z);
  add_square(p, x, y, z + 1);
  MeshInput in = soup(p, {cube(0), cube(8)});
  for (auto& v : in.faces.items)
    for (auto [from, to] : glue)
      if (v == from) v = to;
  return build_mesh(std::move(in), kOne);
}

TEST(LoadSteps, MergeFacesJoinsCopiesInOrderOfFirstUse) {
  // 2 cubes x 6 face copies; the shared square is listed by both: 11 faces, numbered as the cells
  // name them, the second copy seen reversed against the first (stored) loop.
  MeshInput in = stacked_cubes(2);
  in.faces.push_row(std::vector<int32_t>{0, 1, 2});  // used by no cell: dropped
  Mesh m;
  m.points = in.points;
  (void)merge_faces(in, m, kOne);  // the ranks matter to build_edges only
  ASSERT_EQ(m.num_faces(), 11u);
  EXPECT_EQ(m.dropped_faces, 1);
  std::vector<int32_t> first_cell(m.cell_faces[0].begin(), m.cell_faces[0].end());
  EXPECT_EQ(first_cell, (std::vector<int32_t>{0, 1, 2, 3, 4, 5}));
  // Upper cube's bottom loop {4,7,6,5} is the lower cube's top {4,5,6,7} (face 1) reversed.
  EXPECT_EQ(m.cell_faces[1][0], 1);
  EXPECT_EQ(m.cell_face_flip[6], 1);
  EXPECT_EQ(m.cell_face_flip[0], 0);
  EXPECT_EQ(m.face_cells[1], (std::array<int32_t, 2>{0, 1}));
  EXPECT_EQ(m.face_cells[0], (std::array<int32_t, 2>{0, -1}));
}

TEST(LoadSteps, MergeFacesRejectsAFaceInThreeCells) {
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 1);
  MeshInput in = soup(p, {cube(0), cube(0), cube(0)});
  Mesh m;
  m.points = in.points;
  EXPECT_THROW((void)merge_faces(in, m, kOne), InputError);
}

TEST(LoadSteps, EdgesAreNumberedAlongTheLoops) {
  // One cube: 12 edges; the first face (0 3 2 1) gives edges 0-3, 3-2, 2-1, 1-0 as 0..3.
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 1);
  Built b = through_check(soup(p, {cube(0)}));
  ASSERT_EQ(b.m.num_edges(), 12u);
  EXPECT_EQ(b.m.edge_verts[0], (std::array<int32_t, 2>{0, 3}));
  EXPECT_EQ(b.m.edge_verts[1], (std::array<int32_t, 2>{2, 3}));
  EXPECT_EQ(b.m.edge_verts[3], (std::array<int32_t, 2>{0, 1}));
  // Face 2 (0 1 5 4) starts with edge 0-1, edge 3.
  EXPECT_EQ(b.m.face_edges(2)[0], 3);
  const std::vector<int32_t> ce = test::cell_edge_ids(b.m, 0);
  EXPECT_EQ(ce.size(), 12u);
  EXPECT_TRUE(std::is_sorted(ce.begin(), ce.end()));
  // Every edge of a lone cube is in two faces, both on the boundary; the lowest face starts it.
  for (size_t e = 0; e < 12; ++e) {
    EXPECT_EQ(b.counts[e].faces, 2) << "edge " << e;
    EXPECT_EQ(b.counts[e].boundary_faces, 2) << "edge " << e;
  }
  EXPECT_EQ(b.m.fan_start[3], 0) << "edge 0-1 is in faces 0 and 2";
  EXPECT_EQ(b.m.cell_type[0], CellType::Hex);
  EXPECT_FALSE(b.cells.faces_shared_twice);
}

TEST(LoadSteps, AnOpenCellIsRejectedNamingItsEdge) {
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 1);
  auto open = cube(0);
  open.pop_back();  // the face 3 0 4 7 missing: edges 0-3, 0-4, 3-7, 4-7 in one face only
  try {
    through_check(soup(p, {open}));
    FAIL() << "an open cell was accepted";
  } catch (const InputError& e) {
    // The lowest such edge: 0-3 is edge 0.
    EXPECT_NE(std::string(e.what()).find("a closed cell"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("edge (0 3) in 1"), std::string::npos) << e.what();
  }
}

TEST(LoadSteps, OrientationKeepsATangledCellInverted) {
  // The upper cube's top at z = 0.5, below its bottom at z = 1: it is tangled (volume -0.5)
  // while fitting its neighbour face to face. Its group has volume 1 - 0.5 > 0, so the lower
  // cube stays positive and the tangled one keeps its negative volume, instead of being turned
  // against its neighbour.
  MeshInput in = stacked_cubes(0.5);
  validate_input(in, kOne);
  Mesh m;
  m.points = in.points;
  build_edges(m, merge_faces(in, m, kOne), kOne);
  // Scramble what the file said: the orientation steps must not depend on it.
  for (auto& f : m.cell_face_flip) f ^= 1;
  CellCheck cells = check_cells(m, in, kOne);
  orient_groups(m, cells.volume, kOne);
  EXPECT_DOUBLE_EQ(signed_volume(m, 0), 1.0);
  EXPECT_DOUBLE_EQ(signed_volume(m, 1), -0.5);
  // The shared face (1) is seen in opposite directions by the two cells.
  EXPECT_NE(m.cell_face_flip[1], m.cell_face_flip[6]);
}

TEST(LoadSteps, OrientationTurnsAnInsideOutGroup) {
  // A single cube with every loop inward comes out with volume +1.
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 1);
  auto inward = cube(0);
  for (auto& l : inward) std::reverse(l.begin(), l.end());
  Built b = through_check(soup(p, {inward}));
  orient_groups(b.m, b.cells.volume, kOne);
  EXPECT_DOUBLE_EQ(signed_volume(b.m, 0), 1.0);
}

TEST(LoadSteps, EdgeFansRunThroughTheCellsInOrder) {
  // Two stacked cubes: the edge 4-5 between them has faces (2: front of the lower cube,
  // 1: shared, 6+2: front of the upper) and the cells 0, 1 between them; a boundary path.
  Built b = through_check(stacked_cubes(2));
  orient_groups(b.m, b.cells.volume, kOne);
  mark_boundary(b.m, kOne);
  edge_fans(b.m, b.counts, b.cells, kOne);
  const int32_t e45 = test::edge_between(b.m, 4, 5);
  ASSERT_GE(e45, 0);
  EXPECT_TRUE(b.m.edge_fan_ok(e45));
  EXPECT_EQ(b.m.edge_valence(e45), 2);
  const EdgeFan fan = test::fan_of(b.m, e45);
  ASSERT_EQ(fan.faces.size(), 3u);
  EXPECT_EQ(fan.faces[1], 1) << "the shared face lies between the two cells";
  EXPECT_EQ(fan.cells, (std::vector<int32_t>{0, 1}));
  EXPECT_TRUE(b.m.face_boundary[fan.faces[0]] && b.m.face_boundary[fan.faces[2]]);
  EXPECT_EQ(fan.faces[0], b.m.fan_start[e45]) << "the walk starts at the lowest boundary face";
}

TEST(LoadSteps, EveryBoundaryEdgeStartsItsFanAtItsLowestBoundaryFace) {
  // count_edge_faces finds the face of an edge's first boundary corner by searching the face
  // offsets from an estimate; here the lowest boundary face at each edge is found by a plain scan
  // over the faces in order (edges whose fan is not a path keep a row of odd_fan_faces instead).
  // The meshes mix face sizes (prisms, polyhedra of up to a dozen sides), where the estimate
  // misses, and include all-quad ones (armadillo), where it is exact.
  for (const char* rel : test::kVariedMeshes) {
    SCOPED_TRACE(rel);
    HBC_REQUIRE_DATA(rel);
    for (int threads : {1, 2}) {
      const Mesh m = load_mesh(test::data_path(rel), Format::Auto, Threads{threads, 64});
      std::vector<int32_t> lowest(m.num_edges(), -1);
      for (size_t f = 0; f < m.num_faces(); ++f)
        if (m.face_cells[f][1] < 0)
          for (int32_t e : m.face_edges(f))
            if (lowest[static_cast<size_t>(e)] < 0) lowest[static_cast<size_t>(e)] = static_cast<int32_t>(f);
      size_t boundary_edges = 0;
      for (size_t e = 0; e < m.num_edges(); ++e) {
        if (lowest[e] < 0 || !m.edge_fan_ok(e)) continue;
        ++boundary_edges;
        ASSERT_EQ(m.fan_start[e], lowest[e]) << "edge " << e << ", " << threads << " thread(s)";
      }
      EXPECT_GT(boundary_edges, 0u);
    }
  }
}

TEST(LoadSteps, TwoCubesOnOneEdgeHaveNoCyclicFan) {
  // Cubes 0 and 1 meet along the edge 2-6 only (the second one diagonally above the first's
  // corner): four boundary faces around it, two paths, so no cyclic order, and the ends of that
  // edge are non-manifold (their cells touch across no face).
  const Mesh m = two_cubes(1, 1, 0, {{8, 2}, {12, 6}});  // glue (1,1,0) and (1,1,1)
  const int32_t e = test::edge_between(m, 2, 6);
  ASSERT_GE(e, 0);
  EXPECT_FALSE(m.edge_fan_ok(e));
  EXPECT_EQ(m.edge_valence(e), 2);
  const EdgeFan fan = test::fan_of(m, e);
  EXPECT_EQ(fan.faces.size(), 4u);
  EXPECT_TRUE(std::is_sorted(fan.faces.begin(), fan.faces.end()));
  EXPECT_EQ(fan.cells, (std::vector<int32_t>{0, 1}));
  for (size_t v = 0; v < m.num_vertices(); ++v)
    EXPECT_EQ(m.vert_non_manifold[v] != 0, v == 2 || v == 6) << "vertex " << v;
}

TEST(LoadSteps, CellsSharingTwoFacesAreWalked) {
  // A cube split by a bent wall into two cells that share both halves of the wall (two faces
  // with the same two cells): the fans along the wall's middle edge hold two-face cycles, which
  // only a walk can tell from one cycle, and check_cells says so.
  // Vertices: the cube's 8 corners, then the wall's middle line at x = 0.5 bent to y = 0.7.
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 1);
  p.insert(p.end(), {0.5, 0, 0, 0.5, 1, 0, 0.5, 1, 1, 0.5, 0, 1, 0.6, 0.5, 0, 0.6, 0.5, 1});
  // 8..11: the wall's outline (front bottom, back bottom, back top, front top); 12, 13: its bend.
  const std::vector<std::vector<int32_t>> left = {
      {0, 8, 12, 9, 3}, {4, 7, 10, 13, 11}, {0, 4, 11, 8}, {3, 9, 10, 7}, {0, 3, 7, 4},
      {8, 11, 13, 12}, {12, 13, 10, 9}};
  std::vector<std::vector<int32_t>> right = {
      {8, 1, 2, 9, 12}, {11, 13, 10, 6, 5}, {8, 11, 5, 1}, {9, 2, 6, 10}, {1, 5, 6, 2},
      {8, 12, 13, 11}, {12, 9, 10, 13}};
  const Mesh m = build_mesh(soup(p, {left, right}), kOne);
  EXPECT_EQ(m.num_cells(), 2u);
  const int32_t bend = test::edge_between(m, 12, 13);
  ASSERT_GE(bend, 0);
  EXPECT_TRUE(m.edge_fan_ok(bend));
  EXPECT_EQ(m.edge_valence(bend), 2);
  EXPECT_EQ(test::fan_of(m, bend).faces.size(), 2u);
  for (size_t v = 0; v < m.num_vertices(); ++v) EXPECT_FALSE(m.vert_non_manifold[v]) << "vertex " << v;
}

TEST(LoadSteps, CellTypesFromFacesAndVertices) {
  // A tet, a hex, and a triangular bipyramid (6 triangles, 5 vertices): a polyhedron, as it
  // matches no named type (prisms and pyramids: test_mesh_core's degenerate hexahedra).
  const char* text =
      "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n"
      "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 -1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";
  Mesh tet = build_mesh(read_medit(text, "tet.mesh"), kOne);
  EXPECT_EQ(tet.cell_type[0], CellType::Tet);
  std::vector<double> p = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1};
  Built b = through_check(soup(p, {{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 4}, {2, 1, 4}, {1, 0, 4}}}));
  EXPECT_EQ(b.m.cell_type[0], CellType::Polyhedron);
  EXPECT_FALSE(b.m.vert_non_manifold[0]);
  Mesh two = build_mesh(stacked_cubes(2), kOne);
  EXPECT_EQ(two.cell_type[0], CellType::Hex);
}

TEST(LoadSteps, APinchedVertexIsNonManifold) {
  // Two cubes meeting at vertex 6 of the first only (the second cube's vertex 0 there): the
  // cells around it are not face connected.
  // Vertex 8 (the corner (1,1,1) of the second cube) glued onto vertex 6.
  const Mesh m = two_cubes(1, 1, 1, {{8, 6}});
  for (size_t v = 0; v < m.num_vertices(); ++v)
    EXPECT_EQ(m.vert_non_manifold[v] != 0, v == 6) << "vertex " << v;
}

TEST(LoadSteps, ACellPinchedAtAVertexKeepsItManifold) {
  // One polyhedron made of two pyramids glued apex to apex (vertex 8), as one cell: its faces at
  // the apex form two cycles, but the cells around the apex (just this one) are one group, so
  // the vertex is not split apart as two cells meeting there would be.
  std::vector<double> p;
  add_square(p, 0, 0, 0);
  add_square(p, 0, 0, 2);
  p.insert(p.end(), {0.5, 0.5, 1});
  const std::vector<std::vector<int32_t>> hourglass = {
      {0, 3, 2, 1}, {0, 1, 8}, {1, 2, 8}, {2, 3, 8}, {3, 0, 8},
      {4, 5, 6, 7}, {5, 4, 8}, {6, 5, 8}, {7, 6, 8}, {4, 7, 8}};
  Built b = through_check(soup(p, {hourglass}));
  EXPECT_EQ(b.cells.pinched, (std::vector<int32_t>{8}));
  const Mesh m = build_mesh(soup(p, {hourglass}), kOne);
  EXPECT_EQ(m.cell_type[0], CellType::Polyhedron);
  EXPECT_FALSE(m.vert_non_manifold[8]);
}

TEST(LoadSteps, ElementCellsGiveTheMeshOfTheirFaceSoup) {
  // Element cells (corners, faces from the templates) and the same cells as a face soup take
  // different paths through merge_faces and check_cells; every array must come out the same.
  for (const char* rel : {"hybrid-base-complex/twistcube_s.mesh", "cinolib/rockerarm.mesh"}) {
    SCOPED_TRACE(rel);
    HBC_REQUIRE_DATA(rel);
    const MeshInput in = read_input(test::data_path(rel));
    ASSERT_FALSE(in.cell_shape.empty());
    test::expect_same_mesh(build_mesh(in, kOne), build_mesh(with_face_soup(in), kOne));
  }
  // Hexahedra listed inside out (negative volume) are turned like any soup.
  MeshInput grid = with_face_soup(generate_grid(3, 3, 3));
  MeshInput flipped = read_medit(medit_text(build_mesh(grid, kOne)), "grid.mesh", kOne);
  for (size_t c = 0; c < flipped.cells.rows(); ++c) {
    auto row = flipped.cells.row(c);
    std::swap(row[1], row[3]), std::swap(row[5], row[7]);  // mirror each hexahedron
  }
  test::expect_same_mesh(build_mesh(flipped, kOne), build_mesh(with_face_soup(flipped), kOne));
}

// --- parser fast path ----------------------------------------------------------------------

std::string grid_text(int n) { return medit_text(build_mesh(generate_grid(n, n, n), kOne)); }

void expect_same_input(const MeshInput& a, const MeshInput& b) {
  test::expect_same_cells(a, b);
  EXPECT_EQ(a.vertex_loc, b.vertex_loc);
  EXPECT_EQ(a.cell_loc, b.cell_loc);
}

TEST(LoadParse, FastSectionsEqualTheTokenScanner) {
  // A comment after each count keeps the fast path off (the rest of the count's line is not
  // blank) without moving any line: both readings must agree on every value and line.
  const std::string fast = grid_text(12);
  std::string slow = fast;
  for (const char* kw : {"Vertices\n", "Hexahedra\n"}) {
    const size_t at = slow.find('\n', slow.find(kw) + std::strlen(kw));
    slow.insert(at, " # slow path");
  }
  ASSERT_NE(slow, fast);
  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    const Threads par{threads, 64};
    expect_same_input(read_medit(fast, "fast.mesh", par), read_medit(slow, "slow.mesh", par));
  }
}

TEST(LoadParse, IntegersOfEveryWidthReadAsTheTokenScannerReadsThem) {
  // The fast path sums up to 9 digits itself and hands longer numbers (leading zeros here) to
  // from_chars; negative reference numbers and 10-digit ids must come out as the scanner reads them.
  std::string text = grid_text(4);
  const size_t hex = text.find("Hexahedra\n");
  size_t at = text.find('\n', text.find('\n', hex) + 1) + 1;
  for (int line = 0; at < text.size() && text[at] != 'E'; ++line) {
    if (line % 2 == 0) text.insert(at, "000000000");  // the first id gets 10 or more digits
    const size_t ref = text.rfind(' ', text.find('\n', at));
    if (line % 3 == 0) text.replace(ref + 1, text.find('\n', at) - ref - 1, "-123456789012");
    at = text.find('\n', at) + 1;
  }
  std::string slow = text;
  const size_t count_end = slow.find('\n', slow.find("Hexahedra\n") + std::strlen("Hexahedra\n"));
  slow.insert(count_end, " # slow path");
  for (int threads : {1, 2}) {
    SCOPED_TRACE(threads);
    const Threads par{threads, 16};
    expect_same_input(read_medit(text, "fast.mesh", par), read_medit(slow, "slow.mesh", par));
  }
  test::expect_same_mesh(build_mesh(read_medit(text, "fast.mesh", kOne), kOne),
                         build_mesh(read_medit(grid_text(4), "plain.mesh", kOne), kOne));
}

TEST(LoadParse, FastPathReportsTheLineOfABadIndex) {
  // Vertex id 9999 on the second hexahedron line of a 2x2x2 grid: 27 vertices on lines 5-31,
  // "Hexahedra" on 32, the count on 33, the second hexahedron on line 35.
  std::string text = grid_text(2);
  const size_t hex = text.find("Hexahedra\n");
  const size_t second = text.find('\n', text.find('\n', text.find('\n', hex) + 1) + 1) + 1;
  text.replace(second, text.find(' ', second) - second, "9999");
  try {
    read_medit(text, "bad.mesh", kOne);
    FAIL() << "accepted an id out of range";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":35"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("found 9999"), std::string::npos) << e.what();
  }
}

// --- parallel loads --------------------------------------------------------------------------

using test::expect_same_mesh;

TEST(LoadParallel, EveryArrayEqualsTheSingleThreadedLoad) {
  // A grain of 64 splits even the small meshes into many ranges per step, so range boundaries
  // fall inside every kind of element; 3 threads on 2 cores still run the ranges concurrently.
  for (const char* rel : test::kVariedMeshes) {
    SCOPED_TRACE(rel);
    HBC_REQUIRE_DATA(rel);
    const Mesh one = load_mesh(test::data_path(rel), Format::Auto, Threads{1, 64});
    for (int threads : {2, 3}) test::expect_same(one, load_mesh(test::data_path(rel), Format::Auto, Threads{threads, 64}), "the mesh");
  }
  // The all-singleton worst case: a grid with about 1 % of its cells split into pyramids.
  std::vector<std::array<int, 3>> split;
  for (int i = 0; i < 12 * 12 * 12; i += 97) split.push_back({i % 12, i / 12 % 12, i / 144});
  const Mesh one = build_mesh(generate_split(12, 12, 12, SplitKind::Pyramids, split), Threads{1, 64});
  test::expect_same(one, build_mesh(generate_split(12, 12, 12, SplitKind::Pyramids, split), Threads{2, 64}), "the mesh");
}

// `in` with vertex v renumbered p[v]: points moved, face loops and element corners mapped.
MeshInput with_vertices_renumbered(MeshInput in, const std::vector<int32_t>& p) {
  std::vector<double> points(in.points.size());
  for (size_t v = 0; v < p.size(); ++v)
    for (size_t k = 0; k < 3; ++k) points[3 * static_cast<size_t>(p[v]) + k] = in.points[3 * v + k];
  in.points = std::move(points);
  for (int32_t& v : in.faces.items) v = p[static_cast<size_t>(v)];
  for (size_t c = 0; c < in.cells.rows(); ++c)
    if (in.shape(c) != CellShape::Faces)
      for (int32_t i = in.cells.offsets[c]; i < in.cells.offsets[c + 1]; ++i) in.cells.items[static_cast<size_t>(i)] = p[static_cast<size_t>(in.cells.items[static_cast<size_t>(i)])];
  for (auto& e : in.declared_edges) e = {p[static_cast<size_t>(e[0])], p[static_cast<size_t>(e[1])]};
  in.vertex_loc.clear();  // the locations no longer follow the vertex order
  return in;
}

TEST(LoadParallel, FacesAndEdgesDoNotDependOnTheVertexNumbering) {
  // Faces are numbered by first use (slot order) and edges along the loops (corner order); the
  // grouping that finds equal faces and edges ranks the vertices by first use, which a random
  // renumbering scatters. Every face, edge and cell array must come out the same, and every
  // vertex array the same under the renumbering, for 1 and 2 threads.
  std::vector<std::pair<std::string, MeshInput>> inputs;
  for (const char* rel : test::kVariedMeshes) {
    HBC_REQUIRE_DATA(rel);
    inputs.emplace_back(rel, read_input(test::data_path(rel)));
  }
  std::vector<std::array<int, 3>> split;
  for (int i = 0; i < 12 * 12 * 12; i += 97) split.push_back({i % 12, i / 12 % 12, i / 144});
  inputs.emplace_back("split grid", generate_split(12, 12, 12, SplitKind::Pyramids, split));
  std::mt19937 rng(11);
  for (auto& [name, in] : inputs) {
    SCOPED_TRACE(name);
    const Mesh a = build_mesh(in, kOne);
    std::vector<int32_t> p(a.num_vertices());
    std::iota(p.begin(), p.end(), 0);
    std::shuffle(p.begin(), p.end(), rng);
    for (int threads : {1, 2}) {
      const Mesh b = build_mesh(with_vertices_renumbered(in, p), Threads{threads, 64});
      EXPECT_EQ(a.face_verts.offsets, b.face_verts.offsets);
      std::vector<int32_t> loops = a.face_verts.items;
      for (int32_t& v : loops) v = p[static_cast<size_t>(v)];
      EXPECT_EQ(loops, b.face_verts.items);
      auto edges = a.edge_verts;
      for (auto& e : edges) e = {std::min(p[static_cast<size_t>(e[0])], p[static_cast<size_t>(e[1])]), std::max(p[static_cast<size_t>(e[0])], p[static_cast<size_t>(e[1])])};
      EXPECT_EQ(edges, b.edge_verts);
#define HBC_SAME(x) EXPECT_EQ(a.x, b.x) << #x
      HBC_SAME(face_edge_ids); HBC_SAME(face_cells); HBC_SAME(cell_faces.offsets); HBC_SAME(cell_faces.items);
      HBC_SAME(cell_face_flip); HBC_SAME(fan_start); HBC_SAME(odd_fan_faces.offsets); HBC_SAME(odd_fan_faces.items);
      HBC_SAME(valence_small); HBC_SAME(edge_boundary); HBC_SAME(face_boundary); HBC_SAME(cell_type);
      HBC_SAME(dropped_faces); HBC_SAME(dropped_edges); HBC_SAME(warnings);
#undef HBC_SAME
      for (size_t v = 0; v < a.num_vertices(); ++v) {
        ASSERT_EQ(a.vert_boundary[v], b.vert_boundary[static_cast<size_t>(p[v])]) << "vertex " << v;
        ASSERT_EQ(a.vert_non_manifold[v], b.vert_non_manifold[static_cast<size_t>(p[v])]) << "vertex " << v;
      }
    }
  }
}

TEST(LoadParallel, APoolRunsEveryRangeOnceAndSplitsNestedCallsOnItsOwn) {
  // Many short steps in a row (as a load runs them), a range that splits its own work while the
  // pool is busy, and an exception: the same ranges and the same first error as without a pool.
  const detail::RunOptions run(Threads{3, 8});
  const Threads& par = run.get();
  ASSERT_NE(par.pool, nullptr);
  for (int step = 0; step < 200; ++step) {
    const size_t n = 1 + static_cast<size_t>(step) * 7 % 100;
    std::vector<int> hits(n, 0);
    detail::parallel_ranges(n, par, [&](size_t b, size_t e, int) {
      for (size_t i = b; i < e; ++i) ++hits[i];
      detail::parallel_ranges(e - b, par, [&](size_t nb, size_t ne, int) {
        for (size_t i = nb; i < ne; ++i) ++hits[b + i];
      });
    });
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 2), static_cast<std::ptrdiff_t>(n)) << "step " << step;
  }
  try {
    detail::parallel_ranges(100, par, [&](size_t b, size_t, int r) {
      if (r > 0) throw std::runtime_error("range " + std::to_string(r) + " from " + std::to_string(b));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "range 1 from 33");
  }
}

TEST(LoadParallel, APoolRunsMoreJobsThanItHasWorkersEachOnce) {
  // The calling thread and the one worker claim jobs until none is left, so a call may hand the
  // pool more jobs than threads; each job runs exactly once, and run() returns after all of them.
  detail::WorkerPool pool(1);
  for (int n : {1, 2, 5, 17})
    for (int call = 0; call < 50; ++call) {
      std::vector<std::atomic<int>> hits(static_cast<size_t>(n));
      ASSERT_TRUE(pool.run(n, [&](int i) { hits[static_cast<size_t>(i)].fetch_add(1); }));
      for (int i = 0; i < n; ++i) ASSERT_EQ(hits[static_cast<size_t>(i)].load(), 1) << "job " << i << " of " << n;
    }
}

TEST(LoadParallel, APoolWorkerTakesJobsWhetherPollingOrAsleep) {
  // Job 0 waits (up to 5 s) until job 1 has started, so with one worker job 1 must run on the
  // worker: the caller is held in job 0. Calls follow each other at once (the worker is still
  // polling) or after 5 ms (past kPoll's 200 µs: the worker sleeps and must be woken). Job 1
  // sometimes lasts 5 ms, so the caller too stops polling and sleeps until the worker wakes it;
  // without that wake-up run() would never return.
  detail::WorkerPool pool(1);
  for (int call = 0; call < 40; ++call) {
    if (call % 2 == 1) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::atomic<bool> started{false};
    bool met = false;
    ASSERT_TRUE(pool.run(2, [&](int i) {
      if (i == 1) {
        started = true;
        if (call % 4 >= 2) std::this_thread::sleep_for(std::chrono::milliseconds(5));
        return;
      }
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
      while (!started && std::chrono::steady_clock::now() < until) std::this_thread::yield();
      met = started;
    }));
    ASSERT_TRUE(met) << "call " << call << ": job 1 did not start on the worker while job 0 ran";
  }
}

TEST(LoadParallel, ResizeTouchedKeepsTheOldEntriesAndFillsOnlyTheNewOnes) {
  // resize_with takes the plain resize for T() and resize(n, value) for any other value: both
  // must give what vector::resize(n, value) gives, the old entries kept, shrinking only cutting.
  const Threads par{2, 1};
  std::vector<std::array<int32_t, 2>> pairs{{7, 8}};
  detail::resize_touched(pairs, 3, par);
  EXPECT_EQ(pairs, (std::vector<std::array<int32_t, 2>>{{7, 8}, {0, 0}, {0, 0}}));
  detail::resize_touched(pairs, 5, par, std::array<int32_t, 2>{-1, -1});
  EXPECT_EQ(pairs, (std::vector<std::array<int32_t, 2>>{{7, 8}, {0, 0}, {0, 0}, {-1, -1}, {-1, -1}}));
  detail::resize_touched(pairs, 2, par, std::array<int32_t, 2>{5, 5});
  EXPECT_EQ(pairs, (std::vector<std::array<int32_t, 2>>{{7, 8}, {0, 0}}));
  // Past the size where touch_pages faults the pages in from both threads (4 MiB).
  std::vector<uint8_t> flags(3, 9);
  detail::resize_touched(flags, size_t{5} << 20, par, uint8_t{1});
  EXPECT_EQ(std::count(flags.begin(), flags.end(), uint8_t{9}), 3);
  EXPECT_EQ(std::count(flags.begin(), flags.end(), uint8_t{1}), (ptrdiff_t{5} << 20) - 3);
}

TEST(LoadParallel, WeightedRangesSplitByWeightAndPartedRowsFindRowsPastEmptyRanges) {
  const detail::RunOptions run(Threads{2, 8});
  // One unit of weight 1000, then 999 of weight 1 (prefix 0, 1000, 1001, ..., 1999), two ranges:
  // the first unit whose prefix reaches half the total (999.5 rounded down) is unit 1, so the
  // heavy unit is a range alone, where ranges of as many units would cut at 500.
  {
    const Threads& par = run.get();
    std::vector<int32_t> prefix(1001);
    for (size_t i = 1; i <= 1000; ++i) prefix[i] = 1000 + static_cast<int32_t>(i) - 1;
    ASSERT_EQ(detail::weighted_range_count(prefix, par), 2);
    std::vector<std::array<size_t, 2>> seen(2);
    detail::weighted_ranges(prefix, par, [&](size_t b, size_t e, int r) { seen[static_cast<size_t>(r)] = {b, e}; });
    EXPECT_EQ(seen[0], (std::array<size_t, 2>{0, 1}));
    EXPECT_EQ(seen[1], (std::array<size_t, 2>{1, 1000}));
  }
  // Weights 100, 0, 0 in three ranges: cuts at the first prefix reaching 33 and 66, both unit 1,
  // so the middle range is empty. Parted rows built over these ranges still find each row
  // (row r holds r), the empty part sharing its first row with the part after it.
  {
    const Threads par{3, 1};
    const std::vector<int32_t> prefix{0, 100, 100, 100};
    std::vector<std::array<size_t, 2>> seen(3);
    detail::weighted_ranges(prefix, par, [&](size_t b, size_t e, int r) { seen[static_cast<size_t>(r)] = {b, e}; });
    EXPECT_EQ(seen, (std::vector<std::array<size_t, 2>>{{0, 1}, {1, 1}, {1, 3}}));
    const auto rows = detail::weighted_parted_rows<int32_t, int>(
        prefix, par, [](size_t i, Csr<int32_t>& out, int&) { out.items.push_back(static_cast<int32_t>(i)); });
    ASSERT_EQ(rows.parts.size(), 3u);
    for (size_t r = 0; r < 3; ++r) {
      ASSERT_EQ(rows[r].size(), 1u) << "row " << r;
      EXPECT_EQ(rows[r][0], static_cast<int32_t>(r)) << "row " << r;
    }
  }
}

TEST(LoadParallel, ErrorsNameTheFirstBadCellForAnyThreadCount) {
  // Two open cells, far apart in the cell order: every thread count reports the first one.
  const MeshInput base = generate_grid(20, 20, 20);
  std::string first;
  for (int threads : {1, 2, 3}) {
    MeshInput in = base;
    // Cells 100 and 5000 lose their last face.
    Csr<int32_t> cells;
    for (size_t c = 0; c < in.cells.rows(); ++c) {
      auto row = in.cells[c];
      cells.push_row(row.begin(), row.end() - ((c == 100 || c == 5000) ? 1 : 0));
    }
    in.cells = cells;
    try {
      build_mesh(std::move(in), Threads{threads, 64});
      FAIL() << "open cells accepted";
    } catch (const InputError& e) {
      if (first.empty()) first = e.what();
      EXPECT_EQ(std::string(e.what()), first);
      EXPECT_NE(first.find("cell 100 "), std::string::npos) << first;
    }
  }
}

}  // namespace
}  // namespace hbc
