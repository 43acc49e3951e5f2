// Synthetic meshes: counts derived by hand (in the comments), edge valences, orientation,
// determinism. Every mesh here goes through build_mesh, which checks conformity.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <cmath>
#include <numbers>
#include <random>
#include <map>
#include <set>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "hbc/region.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

// Signed volume of a cell from its face loops as the cell sees them (fan triangles, origin at
// the first vertex of the cell): positive when the loops point outward.
double cell_volume(const Mesh& m, size_t c) {
  const double* o = &m.points[3 * static_cast<size_t>(test::cell_verts(m, c)[0])];
  double vol = 0;
  for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) {
    auto loop = m.face_verts[m.cell_faces.items[i]];
    const bool rev = m.cell_face_flip[i] != 0;
    const size_t n = loop.size();
    auto p = [&](size_t k, int d) {
      const int32_t v = rev ? loop[(n - k) % n] : loop[k];
      return m.points[3 * static_cast<size_t>(v) + d] - o[d];
    };
    for (size_t k = 1; k + 1 < n; ++k) {
      vol += p(0, 0) * (p(k, 1) * p(k + 1, 2) - p(k, 2) * p(k + 1, 1)) -
             p(0, 1) * (p(k, 0) * p(k + 1, 2) - p(k, 2) * p(k + 1, 0)) +
             p(0, 2) * (p(k, 0) * p(k + 1, 1) - p(k, 1) * p(k + 1, 0));
    }
  }
  return vol / 6.0;
}

struct Counts {
  size_t v, e, f, c, boundary;
};

Counts counts(const Mesh& m) {
  size_t b = 0;
  for (uint8_t x : m.face_boundary) b += x;
  return {m.num_vertices(), m.num_edges(), m.num_faces(), m.num_cells(), b};
}

void expect_counts(const Mesh& m, Counts want) {
  const Counts got = counts(m);
  EXPECT_EQ(got.v, want.v);
  EXPECT_EQ(got.e, want.e);
  EXPECT_EQ(got.f, want.f);
  EXPECT_EQ(got.c, want.c);
  EXPECT_EQ(got.boundary, want.boundary);
  // A solid ball: V - E + F - C = 1.
  EXPECT_EQ(static_cast<int64_t>(got.v) - static_cast<int64_t>(got.e) + static_cast<int64_t>(got.f) -
                static_cast<int64_t>(got.c),
            1);
}

std::map<CellType, size_t> types(const Mesh& m) {
  std::map<CellType, size_t> t;
  for (CellType x : m.cell_type) ++t[x];
  return t;
}

// Every cell positively oriented; returns the total volume.
double expect_positive(const Mesh& m) {
  double total = 0;
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const double v = cell_volume(m, c);
    EXPECT_GT(v, 1e-9) << "cell " << c << " of " << m.source << " is inside-out or flat";
    total += v;
  }
  return total;
}

void expect_no_non_manifold(const Mesh& m) {
  for (size_t v = 0; v < m.num_vertices(); ++v) ASSERT_FALSE(m.vert_non_manifold[v]) << m.source << " vertex " << v;
  for (size_t e = 0; e < m.num_edges(); ++e) ASSERT_TRUE(m.edge_fan_ok(e)) << m.source << " edge " << e;
}

// The centre cell (1,1,1) of a 3x3x3 grid split by `kind` (prisms along `axis`): the counts each
// test derives, the cell types, every cell positive with the grid's volume 27, and no
// non-manifold vertex or edge.
Mesh expect_split_centre(SplitKind kind, Counts want, std::map<CellType, size_t> want_types, int axis = 2) {
  const std::array<int32_t, 3> centre{1, 1, 1};
  const Mesh m = build_mesh(generate_split(3, 3, 3, kind, {&centre, 1}, axis));
  expect_counts(m, want);
  auto t = types(m);
  for (const auto& [type, n] : want_types) EXPECT_EQ(t[type], n) << cell_type_name(type);
  EXPECT_NEAR(expect_positive(m), 27.0, 1e-9);
  expect_no_non_manifold(m);
  return m;
}


TEST(Generate, GridCountsAndValences) {
  // 2x3x4: V = 3*4*5 = 60; E = 2*4*5 + 3*3*5 + 3*4*4 = 133; F = 3*3*4 + 2*4*4 + 2*3*5 = 98;
  // C = 24; boundary 2(3*4 + 2*4 + 2*3) = 52.
  const Mesh m = build_mesh(generate_grid(2, 3, 4));
  expect_counts(m, {60, 133, 98, 24, 52});
  EXPECT_EQ(m.num_hex_cells(), 24u);
  // Interior edges valence 4; boundary edges 2, except the box's 12 edges cut into 4(2+3+4) = 36
  // edges of valence 1. Interior edges: E - boundary edges; boundary edges of a closed quad
  // surface with 52 faces: 2*52 = 104. So 29 interior edges.
  size_t interior = 0, v1 = 0;
  for (size_t e = 0; e < m.num_edges(); ++e) {
    if (!m.edge_boundary[e]) {
      ++interior;
      EXPECT_EQ(m.edge_valence(e), 4);
    } else {
      EXPECT_TRUE(m.edge_valence(e) == 1 || m.edge_valence(e) == 2);
      v1 += m.edge_valence(e) == 1;
    }
  }
  EXPECT_EQ(interior, 29u);
  EXPECT_EQ(v1, 36u);
  EXPECT_NEAR(expect_positive(m), 24.0, 1e-9);
  expect_no_non_manifold(m);
}

TEST(Generate, GridNumberingAndSpacing) {
  const MeshInput in = generate_grid(3, 2, 2, 0.5);
  // Vertex (i,j,l) = i + 4(j + 3l): vertex (1,2,1) is 1 + 4*(2 + 3) = 21 at (0.5, 1, 0.5).
  EXPECT_DOUBLE_EQ(in.points[3 * 21 + 0], 0.5);
  EXPECT_DOUBLE_EQ(in.points[3 * 21 + 1], 1.0);
  EXPECT_DOUBLE_EQ(in.points[3 * 21 + 2], 0.5);
  const Mesh m = build_mesh(in);
  // Cell (i,j,l) = i + 3(j + 2l): cell 10 = (1,1,1) spans vertices with x in {0.5,1}, y in {0.5,1}.
  for (int32_t v : test::cell_verts(m, 10)) {
    const double x = m.points[3 * v], y = m.points[3 * v + 1], z = m.points[3 * v + 2];
    EXPECT_TRUE(x == 0.5 || x == 1.0);
    EXPECT_TRUE(y == 0.5 || y == 1.0);
    EXPECT_TRUE(z == 0.5 || z == 1.0);
  }
  EXPECT_NEAR(expect_positive(m), 12 * 0.125, 1e-12);
}

TEST(Generate, MillionCellGrid) {
  // Its speed is the load benchmark's business (scripts/bench.sh); here, the counts.
  const MeshInput in = generate_grid(100, 100, 100);
  EXPECT_EQ(in.cells.rows(), 1000000u);
  EXPECT_EQ(in.points.size(), 3u * 101 * 101 * 101);
  // F = 3 * 101 * 100 * 100.
  EXPECT_EQ(in.faces.rows(), 3030000u);
}

TEST(Generate, SplitPyramidsKeepsNeighboursHex) {
  // 3x3x3 grid: V 64, E 3*3*4*4 = 144, F 3*4*3*3 = 108, C 27, boundary 54. The centre cell
  // becomes 6 pyramids: +1 vertex (centre), +8 edges (centre to corners), +12 triangles (one per
  // hex edge), +5 cells. Its quads stay, so the 26 other cells stay hexes.
  const Mesh m = expect_split_centre(SplitKind::Pyramids, {65, 152, 120, 32, 54},
                                     {{CellType::Pyramid, 6}, {CellType::Hex, 26}});
  // The 12 hex edges of the split cell now have 4 + 1 cells around them (interior edges).
  size_t five = 0;
  for (size_t e = 0; e < m.num_edges(); ++e) five += !m.edge_boundary[e] && m.edge_valence(e) == 5;
  EXPECT_EQ(five, 12u);
}

TEST(Generate, SplitPrismsSplitsTheColumn) {
  // Column (1,1,*) of a 3x3x3 grid along z: 3 hexes -> 6 prisms (+3 cells); the 4 horizontal quads
  // of the column become 2 triangles each (+4 faces), plus 3 diagonal quads (+3 faces); the 4
  // diagonals are new edges (+4). Top and bottom quads are on the boundary: +2 boundary faces.
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE(axis);
    expect_split_centre(SplitKind::Prisms, {64, 148, 115, 30, 56}, {{CellType::Prism, 6}, {CellType::Hex, 24}}, axis);
  }
  // Two columns from cells of one column give the same mesh as one.
  const std::array<int32_t, 3> two[2] = {{0, 2, 0}, {0, 2, 3}};
  const Mesh m2 = build_mesh(generate_split(2, 3, 4, SplitKind::Prisms, two));
  EXPECT_EQ(types(m2)[CellType::Prism], 8u);
}

TEST(Generate, SplitTetsMakesNeighboursPolyhedra) {
  // Centre of 3x3x3 into 6 Kuhn tets: each of its 6 quads becomes 2 triangles (+6 faces) and 6
  // triangles lie inside (+6); 6 face diagonals and the body diagonal are new edges (+7); +5
  // cells. The 6 face neighbours see 2 triangles instead of a quad: 7-face polyhedra.
  const Mesh m = expect_split_centre(SplitKind::Tets, {64, 151, 120, 32, 54},
                                     {{CellType::Tet, 6}, {CellType::Polyhedron, 6}, {CellType::Hex, 20}});
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (m.cell_type[c] == CellType::Polyhedron) EXPECT_EQ(m.cell_faces.count(c), 7);

  // Corner cell of 2x2x2 (V 27, E 54, F 36, C 8, boundary 24): same increments, and its 3
  // boundary quads become 6 triangles (+3 boundary faces); 3 neighbours become polyhedra.
  const std::array<int32_t, 3> corner{0, 0, 0};
  const Mesh mc = build_mesh(generate_split(2, 2, 2, SplitKind::Tets, {&corner, 1}));
  expect_counts(mc, {27, 61, 48, 13, 27});
  EXPECT_EQ(types(mc)[CellType::Polyhedron], 3u);
  EXPECT_NEAR(expect_positive(mc), 8.0, 1e-9);

  // Two adjacent split cells agree on their shared face: 2x1x1 (V 12, E 20, F 11, C 2, boundary
  // 10): all 11 quads split (+11 faces, +11 edges), 6 inner triangles each (+12), 2 body
  // diagonals; the 10 boundary quads become 20 triangles.
  const std::array<int32_t, 3> both[2] = {{0, 0, 0}, {1, 0, 0}};
  const Mesh mb = build_mesh(generate_split(2, 1, 1, SplitKind::Tets, both));
  expect_counts(mb, {12, 33, 34, 12, 20});
  EXPECT_EQ(types(mb)[CellType::Tet], 12u);
  EXPECT_NEAR(expect_positive(mb), 2.0, 1e-9);
}

TEST(Generate, RandomCellsAreDistinctAndReproducible) {
  const auto a = random_cells(5, 4, 3, 20, 7);
  const auto b = random_cells(5, 4, 3, 20, 7);
  const auto c = random_cells(5, 4, 3, 20, 8);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  std::set<std::array<int32_t, 3>> s(a.begin(), a.end());
  EXPECT_EQ(s.size(), 20u);
  for (const auto& x : a) {
    EXPECT_TRUE(x[0] >= 0 && x[0] < 5 && x[1] >= 0 && x[1] < 4 && x[2] >= 0 && x[2] < 3);
  }
  // The first draw of std::mt19937(7) is fixed by the standard's algorithm: slot 0 swaps with
  // draw mod 60, so the first cell is that id.
  std::mt19937 g(7);
  const int32_t first = static_cast<int32_t>(g() % 60);
  EXPECT_EQ(a[0], (std::array<int32_t, 3>{first % 5, (first / 5) % 4, first / 20}));
  // All cells: a permutation.
  EXPECT_EQ(random_cells(2, 2, 2, 8, 1).size(), 8u);
  EXPECT_THROW(random_cells(2, 2, 2, 9, 1), std::invalid_argument);

  const auto ten = random_cells(5, 5, 5, 10, 3);
  const Mesh m = build_mesh(generate_split(5, 5, 5, SplitKind::Pyramids, ten));
  EXPECT_EQ(m.num_vertices(), 216u + 10);
  EXPECT_EQ(types(m)[CellType::Pyramid], 60u);
  expect_positive(m);
  const Mesh mt = build_mesh(generate_split(5, 5, 5, SplitKind::Tets, ten));
  EXPECT_EQ(types(mt)[CellType::Tet], 60u);
  EXPECT_NEAR(expect_positive(mt), 125.0, 1e-9);
  expect_no_non_manifold(mt);
}

TEST(Generate, SectorHasOneSingularChain) {
  // N=3, R=2, L=3: V2 = 1 + 6 + 12 = 19, Q2 = 12, E2 = 6 + 24 = 30; V = 19*4 = 76, C = 36,
  // E = 30*4 + 19*3 = 177, F = 12*4 + 30*3 = 138, boundary 2*12 + 2*3*2*3 = 60.
  const Mesh m = build_mesh(generate_sector(3, 2, 3));
  expect_counts(m, {76, 177, 138, 36, 60});
  EXPECT_EQ(m.num_hex_cells(), 36u);
  expect_no_non_manifold(m);
  // Cross-section area 3 parallelograms of area sin(120°), height L/R = 1.5.
  EXPECT_NEAR(expect_positive(m), 3 * std::sin(2 * std::numbers::pi / 3) * 1.5, 1e-9);
  for (int valence : {3, 5, 6}) {
    const Mesh s = build_mesh(generate_sector(valence, 2, 3));
    SCOPED_TRACE(valence);
    expect_positive(s);
    // The irregular interior edges are exactly the 3 axis edges (vertex 0 of each layer up).
    std::vector<size_t> irregular;
    for (size_t e = 0; e < s.num_edges(); ++e)
      if (!s.edge_boundary[e] && s.edge_valence(e) != 4) irregular.push_back(e);
    ASSERT_EQ(irregular.size(), 3u);
    for (size_t e : irregular) {
      EXPECT_EQ(s.edge_valence(e), valence);
      const auto ev = s.edge_verts[e];
      const size_t nv2 = 1 + valence * 2 + valence * 4;
      EXPECT_EQ(ev[0] % nv2, 0u);
      EXPECT_EQ(ev[1], ev[0] + nv2);
    }
  }
  // Valence 4 is a (2R)x(2R)xL grid: counts as generate_grid(2, 2, 1).
  const Mesh g = build_mesh(generate_sector(4, 1, 1));
  const Counts want = counts(build_mesh(generate_grid(2, 2, 1)));
  expect_counts(g, want);
  for (size_t e = 0; e < g.num_edges(); ++e)
    if (!g.edge_boundary[e]) EXPECT_EQ(g.edge_valence(e), 4);
}

TEST(Generate, CylinderIsHexDominantWithPrismColumns) {
  // radius 2: core 2x2 (9 vertices, 4 quads, 12 edges, boundary ring of 8); one circular ring of
  // radius 2 with 4*round(4π/4) = 12 vertices: 8 quads + 4 triangles, 12 ring edges and 12
  // spokes. Cross-section V2 = 21, P2 = 16, E2 = 36. With L = 3: V = 84, C = 48 (36 hex, 12
  // prisms), E = 36*4 + 21*3 = 207, F = 16*4 + 36*3 = 172, boundary 2*16 + 12*3 = 68.
  const Mesh m = build_mesh(generate_cylinder(2, 3));
  expect_counts(m, {84, 207, 172, 48, 68});
  auto t = types(m);
  EXPECT_EQ(t[CellType::Hex], 36u);
  EXPECT_EQ(t[CellType::Prism], 12u);
  expect_positive(m);
  expect_no_non_manifold(m);

  const Mesh big = build_mesh(generate_cylinder(8, 4));
  auto tb = types(big);
  EXPECT_EQ(tb[CellType::Hex] + tb[CellType::Prism], big.num_cells());
  EXPECT_GT(tb[CellType::Prism], 0u);
  EXPECT_GT(static_cast<double>(tb[CellType::Hex]) / big.num_cells(), 0.8);
  const double vol = expect_positive(big);
  // Radius 8 (the last ring is a circle of radius a + rings = 8), height 4; the polygon inscribed
  // in the circle is a little smaller.
  EXPECT_LT(vol, std::numbers::pi * 64 * 4);
  EXPECT_GT(vol, 0.95 * std::numbers::pi * 64 * 4);
  expect_no_non_manifold(big);
  // Prisms stack in columns: every prism's top or bottom triangle is shared with a prism or on
  // the boundary.
  for (size_t f = 0; f < big.num_faces(); ++f) {
    if (big.face_verts.count(f) != 3 || big.face_boundary[f]) continue;
    EXPECT_EQ(big.cell_type[big.face_cells[f][0]], CellType::Prism);
    EXPECT_EQ(big.cell_type[big.face_cells[f][1]], CellType::Prism);
  }
}

TEST(Generate, Deterministic) {
  test::expect_same_cells(generate_grid(4, 3, 2, 0.25), generate_grid(4, 3, 2, 0.25));
  const auto cells = random_cells(4, 4, 4, 5, 42);
  for (SplitKind k : {SplitKind::Pyramids, SplitKind::Prisms, SplitKind::Tets})
    test::expect_same_cells(generate_split(4, 4, 4, k, cells), generate_split(4, 4, 4, k, random_cells(4, 4, 4, 5, 42)));
  test::expect_same_cells(generate_sector(5, 3, 2), generate_sector(5, 3, 2));
  test::expect_same_cells(generate_cylinder(6, 2), generate_cylinder(6, 2));
}

TEST(Generate, BadArgumentsThrow) {
  EXPECT_THROW(generate_grid(0, 1, 1), std::invalid_argument);
  EXPECT_THROW(generate_grid(1, 1, 1, -1.0), std::invalid_argument);
  EXPECT_THROW(generate_grid(100000, 100000, 100000), std::invalid_argument);
  const std::array<int32_t, 3> outside{3, 0, 0};
  EXPECT_THROW(generate_split(3, 3, 3, SplitKind::Tets, {&outside, 1}), std::invalid_argument);
  EXPECT_THROW(generate_sector(2, 1, 1), std::invalid_argument);
  EXPECT_THROW(generate_cylinder(0, 1), std::invalid_argument);
}


int run_cli(const std::string& args) { return test::run_cli(args).status; }

TEST(GenerateCli, WritesWhatTheLibraryGenerates) {
  ASSERT_TRUE(std::filesystem::exists(HBC_CLI)) << HBC_CLI;
  const auto dir = std::filesystem::temp_directory_path() / ("hbc_gen_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string d = dir.string();

  ASSERT_EQ(run_cli("generate grid --size 2 3 4 --spacing 0.5 -o '" + d + "/g.mesh'"), 0);
  const Mesh g = load_mesh(d + "/g.mesh");
  expect_counts(g, {60, 133, 98, 24, 52});
  EXPECT_NEAR(expect_positive(g), 24 * 0.125, 1e-9);

  // Tets make 7-face polyhedra, which only OVM can hold; MEDIT refuses them (exit 2).
  ASSERT_EQ(run_cli("generate split --size 4 4 4 --split tets --random 5 --seed 9 -o '" + d + "/t.ovm'"), 0);
  const Mesh t = load_mesh(d + "/t.ovm");
  const Mesh want = build_mesh(generate_split(4, 4, 4, SplitKind::Tets, random_cells(4, 4, 4, 5, 9)));
  expect_counts(t, counts(want));
  EXPECT_EQ(types(t), types(want));
  EXPECT_EQ(run_cli("generate split --size 3 3 3 --split tets --cells 1,1,1 -o '" + d + "/t.mesh'"), 1);

  ASSERT_EQ(run_cli("generate split --size 3 3 3 --split prisms --axis y --cells '0,0,0;2,2,2' -o '" + d + "/p.mesh'"), 0);
  EXPECT_EQ(types(load_mesh(d + "/p.mesh"))[CellType::Prism], 12u);
  ASSERT_EQ(run_cli("generate sector --valence 5 --rings 2 --layers 2 -o '" + d + "/s.mesh'"), 0);
  expect_counts(load_mesh(d + "/s.mesh"), counts(build_mesh(generate_sector(5, 2, 2))));
  ASSERT_EQ(run_cli("generate cylinder --radius-cells 3 --layers 2 -o '" + d + "/c.ovm'"), 0);
  EXPECT_EQ(types(load_mesh(d + "/c.ovm")), types(build_mesh(generate_cylinder(3, 2))));
  ASSERT_EQ(run_cli("generate twisted-pair --section 2 --sections 5 -o '" + d + "/tp.ovm'"), 0);
  EXPECT_EQ(types(load_mesh(d + "/tp.ovm")), types(build_mesh(generate_twisted_pair(2, 5))));

  // Usage errors (a malformed line, or values wrong together): exit 1.
  EXPECT_EQ(run_cli("generate grid --size 2 3 -o '" + d + "/x.mesh'"), 1);
  EXPECT_EQ(run_cli("generate grid --size 2 3 4"), 1);
  EXPECT_EQ(run_cli("generate blob -o '" + d + "/x.mesh'"), 1);
  EXPECT_EQ(run_cli("generate split --size 3 3 3 --split tets --cells 3,0,0 -o '" + d + "/x.mesh'"), 1);
  EXPECT_EQ(run_cli("generate split --size 3 3 3 --split tets -o '" + d + "/x.mesh'"), 1);
  // A value outside its option's type, choices or range: exit 2 (bad input).
  EXPECT_EQ(run_cli("generate split --size 3 3 3 --split cubes --cells 1,1,1 -o '" + d + "/x.mesh'"), 2);
  EXPECT_EQ(run_cli("generate grid --size 2 0 3 -o '" + d + "/x.mesh'"), 2);
  EXPECT_EQ(run_cli("generate sector --valence 2 --rings 1 --layers 1 -o '" + d + "/x.mesh'"), 2);
  EXPECT_EQ(run_cli("generate twisted-pair --section 5 --sections 12 -o '" + d + "/x.mesh'"), 2);
  EXPECT_FALSE(std::filesystem::exists(d + "/x.mesh"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hbc

namespace hbc {
namespace {

// The demo's twisted ring: a 5x5 section with a 4-triangle fan in its middle quad, 12 sections.
// Section: 6x6 grid vertices + the centre = 37; 24 quads + 4 triangles = 28 polygons; 2D edges
// 2*5*6 = 60 grid edges + 4 spokes = 64. Closed ring of 12 layers: V = 37*12 = 444, C = 28*12 =
// 336 (24*12 = 288 hexes, 48 prisms), F = 28*12 section faces + 64*12 side faces = 1104. The ring
// is closed: its boundary is the torus swept by the section's outline, 20 quads a layer = 240.
TEST(Generate, TwistedRingCounts) {
  const Mesh m = build_mesh(generate_twisted_ring(5, 12, 1, true));
  EXPECT_EQ(m.num_vertices(), 444u);
  EXPECT_EQ(m.num_cells(), 336u);
  EXPECT_EQ(m.num_hex_cells(), 288u);
  EXPECT_EQ(m.num_faces(), 1104u);
  size_t boundary = 0;
  for (uint8_t b : m.face_boundary) boundary += b;
  EXPECT_EQ(boundary, 240u);
}

// A 1x1 ring: untwisted, its one sheet along the ring closes on itself as the same layer
// (perfect); a quarter turn brings the layer back crossing itself: a self-intersecting sheet
// (type 3, the rings of test_sheet_types.cpp); sheets at the mesh level (one component).
TEST(Generate, TwistedRingSheets) {
  AnalysisOptions opt;
  opt.sheet_level = Level::Mesh;
  opt.wireframe = false;
  const Mesh flat = build_mesh(generate_twisted_ring(1, 12, 0, false));
  const Analysis a0 = analyze(flat, opt);
  EXPECT_EQ(a0.sheet_stage->sheets.count(SheetType::Type3), 0u);
  const Mesh turned = build_mesh(generate_twisted_ring(1, 12, 1, false));
  const Analysis a1 = analyze(turned, opt);
  EXPECT_EQ(a1.sheet_stage->sheets.count(SheetType::Type3), 1u);
  // The demo's ring, at the complex level: a self-intersecting sheet with subsheets, a type 1
  // sheet (the one through the prism column) and non-hex cells.
  const Mesh demo = build_mesh(generate_twisted_ring(5, 12, 1, true));
  const Analysis d = analyze(demo, {});
  EXPECT_EQ(d.sheet_stage->sheets.count(SheetType::Type3), 1u);
  EXPECT_EQ(d.sheet_stage->sheets.count(SheetType::Type1), 1u);
  ASSERT_TRUE(d.sheet_stage->largest_self_intersecting.has_value());
  const Subsheets* big = d.sheet_stage->subsheets_of(*d.sheet_stage->largest_self_intersecting);
  ASSERT_NE(big, nullptr);
  EXPECT_GT(big->size(), 1u);
  // Prism fans need a middle quad (odd section) or room for fans off the middle (3+ cells).
  EXPECT_THROW(generate_twisted_ring(2, 12, 1, true), std::invalid_argument);
}

}  // namespace
}  // namespace hbc

namespace hbc {
namespace {

// Distance of a cell's corner centroid from the z axis: which of the twisted pair's rings it is in
// (section 4: the inner ring round radius 8, the outer round 16, each cell within 2√2, the half
// diagonal of the section, of its circle).
double cell_radius(const Mesh& m, size_t c) {
  double x = 0, y = 0;
  const std::vector<int32_t> vs = test::cell_verts(m, c);
  for (int32_t v : vs) x += m.points[3 * static_cast<size_t>(v)], y += m.points[3 * static_cast<size_t>(v) + 1];
  return std::hypot(x, y) / static_cast<double>(vs.size());
}

// Section 4, 12 sections. One ring: the 5x5 grid vertices of each of the 12 layer planes = 300,
// 16 quads and 40 grid edges a plane: 16*12 section faces + 40*12 side faces = 672 faces, edges
// 40*12 in the planes + 25*12 round the ring = 780, 16*12 = 192 hexes. Splitting one hex into 6
// pyramids adds its centre (+1 vertex), the 8 edges from it to the corners and 12 triangles (one a
// hex edge), +5 cells. Its boundary: the 16 outline quads of each layer, 192. Each ring is a solid
// torus (V - E + F - C = 0); the pair doubles everything.
TEST(Generate, TwistedPairCounts) {
  const Mesh m = build_mesh(generate_twisted_pair(4, 12));
  expect_no_non_manifold(m);
  EXPECT_EQ(m.num_vertices(), 602u);
  EXPECT_EQ(m.num_edges(), 1576u);
  EXPECT_EQ(m.num_faces(), 1368u);
  EXPECT_EQ(m.num_cells(), 394u);
  EXPECT_EQ(types(m)[CellType::Hex], 382u);
  EXPECT_EQ(types(m)[CellType::Pyramid], 12u);
  size_t boundary = 0;
  for (uint8_t b : m.face_boundary) boundary += b;
  EXPECT_EQ(boundary, 384u);
  EXPECT_EQ(static_cast<int64_t>(m.num_vertices()) - static_cast<int64_t>(m.num_edges()) +
                static_cast<int64_t>(m.num_faces()) - static_cast<int64_t>(m.num_cells()),
            0);
  expect_positive(m);
  // The rings are apart: the first 197 cells (the outer ring) lie round radius 16, the others
  // round 8.
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const double r = cell_radius(m, c);
    EXPECT_LT(std::abs(r - (c < 197 ? 16.0 : 8.0)), 2.0 * std::sqrt(2.0)) << "cell " << c << " at radius " << r;
  }
  EXPECT_THROW(generate_twisted_pair(3, 12), std::invalid_argument);
  EXPECT_THROW(generate_twisted_pair(0, 12), std::invalid_argument);
  EXPECT_THROW(generate_twisted_pair(4, 2), std::invalid_argument);
  test::expect_same_cells(generate_twisted_pair(4, 5), generate_twisted_pair(4, 5));
}

// Why the pair has the sheets it has (complex level, what hbc sheets and hbc analyze report). In
// each ring the pyramid cell, at quad (1, 0) of layer 0 of the 4x4 section, makes its faces'
// planes separation surfaces: the section planes at both ends of layer 0, and the planes along
// the grid lines u = 1, u = 2, v = 1 of the section, which run round the ring and come back turned.
//  - Outer ring, a quarter turn: u = 1 comes back as v = 1, then u = 3, v = 3; u = 2 as v = 2. The
//    section is cut along every grid line: 16 blocks in the rest of the ring, 15 hex ones in layer 0
//    (31). A column of blocks comes back as a row, which crosses it: the sheets of columns 0 and 3
//    and rows 0 and 3 (the frame) are one self-intersecting sheet, those of columns 1, 2 and rows 1,
//    2 another. The pyramid cell's edges along u are curves of column 1, those along v curves of
//    row 0: both sheets have the pyramids in their regions. A region without them would be the
//    same in every layer, and its VSG chains would close round the ring with no end to trace a
//    wireframe from; with them the region differs in layer 0, the valences change at its two
//    section planes, and every VSG chain ends there: both wireframes are non-empty. The two layers
//    of blocks (layer 0 and the rest of the ring) are 2 perfect sheets.
//  - Inner ring, a half turn: u = 1 comes back as u = 3, v = 1 as v = 3, u = 2 as itself. Columns
//    [0,1] [1,2] [2,3] [3,4], rows [0,1] [1,3] [3,4]: 12 blocks in the rest of the ring and 11 hex
//    ones in layer 0 (23). Column [1,2] comes back as column [2,3]: its parallel curves meet those
//    of [2,3] end to end across u = 2, in blocks that share a face and no curve: self-parallel.
//    Columns [0,1] and [3,4] come back as each other, apart (perfect); row [1,3] as itself and rows
//    [0,1], [3,4] as each other (perfect); the two layers (perfect).
TEST(Generate, TwistedPairSheets) {
  const Mesh m = build_mesh(generate_twisted_pair(4, 12));
  const Analysis a = analyze(m, {});
  ASSERT_TRUE(a.sheet_stage);
  const SheetStage& st = *a.sheet_stage;
  size_t cubes[2] = {0, 0};  // inner, outer
  for (size_t k = 0; k < a.complex.num_components(); ++k)
    if (a.complex.component_kind[k] == ComponentKind::Cube) ++cubes[cell_radius(m, a.complex.component_cells[k][0]) > 12.0];
  EXPECT_EQ(cubes[1], 31u);
  EXPECT_EQ(cubes[0], 23u);
  EXPECT_EQ(a.complex.num_components(), 31u + 23u + 12u);
  ASSERT_EQ(st.sheets.size(), 10u);
  EXPECT_EQ(st.sheets.count(SheetType::Perfect), 7u);
  EXPECT_EQ(st.sheets.count(SheetType::Type1), 0u);
  EXPECT_EQ(st.sheets.count(SheetType::Type2), 1u);
  EXPECT_EQ(st.sheets.count(SheetType::Type3), 2u);
  auto outer = [&](int32_t s) {
    const auto cells = st.sheets.sheet_cells[static_cast<size_t>(s)];
    return std::all_of(cells.begin(), cells.end(), [&](int32_t c) { return cell_radius(m, c) > 12.0; });
  };
  for (size_t s = 0; s < st.sheets.size(); ++s) {
    const SheetClass& k = st.sheets.classes[s];
    SCOPED_TRACE(s);
    if (k.type == SheetType::Type3) {
      EXPECT_TRUE(outer(static_cast<int32_t>(s)));
      const auto nh = st.sheets.sheet_non_hex_cells[s];
      EXPECT_FALSE(nh.empty());
      for (int32_t c : nh) EXPECT_EQ(m.cell_type[c], CellType::Pyramid);
      const VsgWireframe w = region_wireframe(m, a, Level::Complex, {}, static_cast<int32_t>(s));
      EXPECT_GT(std::count(w.kind.begin(), w.kind.end(), WireKind::Vsg), 0);
      EXPECT_GT(w.wireframe_edges_simplified(), 0);
      // The outer ring is built first: its section planes 0 and 1 hold vertices 0-24 and 25-49.
      for (size_t k = 0; k < w.size(); ++k) {
        if (w.kind[k] != WireKind::Vsg) continue;
        const auto p = w.polylines[k];
        EXPECT_NE(p.front(), p.back()) << "closed VSG chain " << k;
        EXPECT_LT(p.front(), 50);
        EXPECT_LT(p.back(), 50);
      }
      ASSERT_NE(st.subsheets_of(static_cast<int32_t>(s)), nullptr);
      EXPECT_GT(st.subsheets_of(static_cast<int32_t>(s))->size(), 1u);
    } else if (k.type == SheetType::Type2) {
      EXPECT_FALSE(outer(static_cast<int32_t>(s)));
      EXPECT_FALSE(k.self_parallel_curves.empty());
      EXPECT_TRUE(k.self_intersecting_blocks.empty());
    }
  }
}

// The contrast the pair's pyramids make: the twisted ring with a prism column all round has a
// self-intersecting sheet whose region is the same in every layer: VSG chains, all closed round the
// ring (no chain end), and an empty wireframe.
TEST(Generate, TwistedRingWithoutLocalCellsHasNoSheetWireframe) {
  const Mesh m = build_mesh(generate_twisted_ring(5, 12, 1, true));
  const Analysis a = analyze(m, {});
  ASSERT_TRUE(a.sheet_stage && a.sheet_stage->largest_self_intersecting);
  const VsgWireframe w = region_wireframe(m, a, Level::Complex, {}, a.sheet_stage->largest_self_intersecting);
  EXPECT_GT(w.vsg_chains, 0);
  EXPECT_EQ(std::count(w.vert_vsg.begin(), w.vert_vsg.end(), 1), 0);
  EXPECT_EQ(w.size(), 0u);
}

}  // namespace
}  // namespace hbc
