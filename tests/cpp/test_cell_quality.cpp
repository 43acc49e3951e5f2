// Cell quality (Verdict's scaled Jacobian and edge ratio, cell_quality.hpp) and cell depth
// (cell_depth.hpp): values derived by hand in the comments, on single cells read from MEDIT text
// (so that the corner frames come from our faces, not from the element's vertex order), on
// generated grids and split grids, and invariants on a real mesh.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "hbc/cell_depth.hpp"
#include "hbc/cell_quality.hpp"
#include "hbc/generate.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using Points = std::vector<std::array<double, 3>>;

// One MEDIT element (keyword `kw`) over all the given points, in their order. The file lists
// vertex j at pts[order[j]] (default: in order), so the vertex ids can be shuffled while the
// element stays the same.
Mesh one_cell(const char* kw, const Points& pts, std::vector<size_t> order = {}) {
  if (order.empty())
    for (size_t i = 0; i < pts.size(); ++i) order.push_back(i);
  std::vector<size_t> file_id(pts.size());
  std::ostringstream t;
  t.precision(17);
  t << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << pts.size() << "\n";
  for (size_t j = 0; j < order.size(); ++j) {
    const auto& p = pts[order[j]];
    t << p[0] << ' ' << p[1] << ' ' << p[2] << " 0\n";
    file_id[order[j]] = j + 1;
  }
  t << kw << "\n1\n";
  for (size_t i = 0; i < pts.size(); ++i) t << file_id[i] << ' ';
  t << "0\nEnd\n";
  return build_mesh(read_medit(t.str(), "cell.mesh"));
}

const Points kCube{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

TEST(CellQuality, GridIsOneEverywhere) {
  // Every corner of a box has three orthogonal edges (N = 1) and the principal axes X1, X2, X3
  // are 4 × the edges, orthogonal too; all edges have the spacing's length.
  const Mesh m = build_mesh(generate_grid(4, 3, 2, 0.3));
  const CellQuality q = cell_quality(m);
  ASSERT_EQ(q.scaled_jacobian.size(), 24u);
  for (size_t c = 0; c < m.num_cells(); ++c) {
    EXPECT_NEAR(q.scaled_jacobian[c], 1.0, 1e-12) << c;
    EXPECT_NEAR(q.edge_ratio[c], 1.0, 1e-12) << c;
  }
  const QualitySummary s = summarize_quality(m, q);
  EXPECT_EQ(s.scaled_jacobian.count, 24);
  EXPECT_EQ(s.scaled_jacobian.negative, 0);
  EXPECT_NEAR(s.scaled_jacobian.min, 1.0, 1e-12);
  EXPECT_NEAR(s.scaled_jacobian.mean, 1.0, 1e-12);
  EXPECT_EQ(s.scaled_jacobian.histogram.back(), 24);  // 1.0 lands in the last bin [0.9, 1]
  EXPECT_EQ(s.sj_per_type[static_cast<size_t>(CellType::Hex)].count, 24);
  EXPECT_EQ(s.sj_per_type[static_cast<size_t>(CellType::Tet)].count, 0);
  EXPECT_TRUE(std::isnan(s.sj_per_type[static_cast<size_t>(CellType::Tet)].min));
  EXPECT_EQ(s.edge_ratio.histogram.front(), 24);  // 1.0 in [1, 1.25)
}

TEST(CellQuality, ShearedHex) {
  // The unit cube with its top face moved by (0.75, 0, 0): every corner frame is (unit, unit,
  // (±)(0.75, 0, 1)) with determinant 1 and lengths 1, 1, sqrt(1 + 0.5625) = 1.25, so each corner
  // gives 1 / 1.25 = 0.8; the centre axes are 4 × the same vectors, also 0.8. Edge ratio 1.25.
  Points p = kCube;
  for (int i = 4; i < 8; ++i) p[i][0] += 0.75;
  const Mesh m = one_cell("Hexahedra", p);
  ASSERT_EQ(m.cell_type[0], CellType::Hex);
  const CellQuality q = cell_quality(m);
  EXPECT_NEAR(q.scaled_jacobian[0], 0.8, 1e-12);
  EXPECT_NEAR(q.edge_ratio[0], 1.25, 1e-12);
}

TEST(CellQuality, DentedHexIsInvertedAndCounted) {
  // The unit cube with corner 6 = (1,1,1) pulled in to (0.3,0.3,0.3): the volume stays positive
  // (so build_mesh keeps the outward orientation), but at corner 6 the edges to 5, 7, 2 are
  // (0.7,-0.3,0.7), (-0.3,0.7,0.7), (0.7,0.7,-0.3), determinant -1.1, each of length sqrt(1.07):
  // N = -1.1 / 1.07^1.5 = -0.99384125. The other corners: 1 at 0, 1, 3, 4; 0.290 at 2, 5, 7;
  // centre 0.743 (numpy's Verdict formula on the same points), so the minimum is corner 6.
  Points p = kCube;
  p[6] = {0.3, 0.3, 0.3};
  const Mesh m = one_cell("Hexahedra", p);
  const CellQuality q = cell_quality(m);
  EXPECT_NEAR(q.scaled_jacobian[0], -1.1 / std::pow(1.07, 1.5), 1e-12);
  const QualitySummary s = summarize_quality(m, q);
  EXPECT_EQ(s.scaled_jacobian.negative, 1);
  EXPECT_EQ(s.sj_per_type[static_cast<size_t>(CellType::Hex)].negative, 1);
  EXPECT_EQ(s.scaled_jacobian.histogram.front(), 1);  // -0.99 in [-1, -0.9)
}

TEST(CellQuality, Tetrahedra) {
  // Regular: J = det of three edges of length l = l³/sqrt(2), every corner's length product l³,
  // so sqrt(2) J / l³ = 1. The corner tet (0, e_x, e_y, e_z): J = 1, corner products 1 at the
  // origin and 1·sqrt(2)·sqrt(2) = 2 at the others, so sqrt(2) · 1 / 2 = 0.70710678; edge ratio
  // sqrt(2).
  const Mesh reg = one_cell("Tetrahedra", {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}});
  ASSERT_EQ(reg.cell_type[0], CellType::Tet);
  EXPECT_NEAR(cell_quality(reg).scaled_jacobian[0], 1.0, 1e-12);
  EXPECT_NEAR(cell_quality(reg).edge_ratio[0], 1.0, 1e-12);
  const Mesh corner = one_cell("Tetrahedra", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  EXPECT_NEAR(cell_quality(corner).scaled_jacobian[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(cell_quality(corner).edge_ratio[0], std::sqrt(2.0), 1e-12);
}

TEST(CellQuality, Prisms) {
  // Right prism of height 1 over the unit equilateral triangle: every corner has the 60° angle
  // and the vertical edge, N = sin 60° = sqrt(3)/2, times 2/sqrt(3) = 1. Over the right
  // isosceles triangle (legs 1): the 45° corners give sin 45°, q = 2/sqrt(3) · sqrt(1/2) =
  // sqrt(2/3) = 0.81649658; edges 1, 1, sqrt(2), 1 (vertical): ratio sqrt(2).
  const double h = std::sqrt(3.0) / 2;
  const Mesh eq = one_cell("Prisms", {{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, h, 1}});
  ASSERT_EQ(eq.cell_type[0], CellType::Prism);
  EXPECT_NEAR(cell_quality(eq).scaled_jacobian[0], 1.0, 1e-12);
  const Mesh right = one_cell("Prisms", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
  EXPECT_NEAR(cell_quality(right).scaled_jacobian[0], std::sqrt(2.0 / 3.0), 1e-12);
  EXPECT_NEAR(cell_quality(right).edge_ratio[0], std::sqrt(2.0), 1e-12);
}

TEST(CellQuality, Pyramids) {
  // Unit square base, apex at height a over its centre; each of the 4 tets (3 base corners +
  // apex) has J = a and largest corner product max(sqrt(2) r, r³), r = sqrt(1/2 + a²) the slant
  // edge, so q = sqrt(2) · sqrt(2) a / max(sqrt(2) r, r³).
  //  a = 1/sqrt(2) (all 8 edges 1): r = 1, q = 2a / sqrt(2) = 1.
  //  a = 1/2 (the pyramids of a cube split at its centre): r = sqrt(3)/2, q = sqrt(2)/2 / r = sqrt(2/3).
  //  a = 1: r = sqrt(1.5), r³ = 1.8371 > sqrt(2) r = 1.7321, q = 2 / 1.5^1.5 = 1.0887 > 1, so
  //  Verdict reflects it: 2 - 2 / 1.5^1.5 = 0.91135.
  auto pyr = [](double a) { return one_cell("Pyramids", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, a}}); };
  ASSERT_EQ(pyr(0.5).cell_type[0], CellType::Pyramid);
  EXPECT_NEAR(cell_quality(pyr(std::sqrt(0.5))).scaled_jacobian[0], 1.0, 1e-12);
  EXPECT_NEAR(cell_quality(pyr(0.5)).scaled_jacobian[0], std::sqrt(2.0 / 3.0), 1e-12);
  EXPECT_NEAR(cell_quality(pyr(1.0)).scaled_jacobian[0], 2.0 - 2.0 / std::pow(1.5, 1.5), 1e-12);
  EXPECT_NEAR(cell_quality(pyr(std::sqrt(0.5))).edge_ratio[0], 1.0, 1e-12);
}

// Verdict's wedge_scaled_jacobian written out on the element's own order (V_WedgeMetric.cpp):
// at node k, J = v2 · (v1 × v3) with the three edge vectors below, over their length product.
double verdict_wedge(const Points& x) {
  const int nodes[6][4] = {{0, 1, 3, 2}, {1, 2, 4, 0}, {2, 0, 5, 1}, {3, 0, 4, 5}, {4, 1, 5, 3}, {5, 3, 4, 2}};
  double q = 1e300;
  for (const auto& n : nodes) {
    std::array<std::array<double, 3>, 3> v;
    for (int e = 0; e < 3; ++e)
      for (int d = 0; d < 3; ++d) v[e][d] = x[n[e + 1]][d] - x[n[0]][d];
    const auto& [v1, v2, v3] = v;
    const double j = v2[0] * (v1[1] * v3[2] - v1[2] * v3[1]) - v2[1] * (v1[0] * v3[2] - v1[2] * v3[0]) +
                     v2[2] * (v1[0] * v3[1] - v1[1] * v3[0]);
    auto len = [](const std::array<double, 3>& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); };
    q = std::min(q, j / (len(v1) * len(v2) * len(v3)));
  }
  return 2 / std::sqrt(3.0) * q;
}

TEST(CellQuality, IrregularCellsDoNotDependOnVertexIds) {
  // The corner frames come from the faces, so shuffling the vertex ids in the file (which
  // changes each cell's lowest vertex, where the hex centre frame and the tet's J are taken)
  // must not change any value; the irregular prism also matches Verdict's own corner list.
  const Points prism{{0, 0, 0}, {1.2, 0.1, 0}, {0.3, 0.9, 0.1}, {0.1, 0, 1.1}, {1.0, 0.2, 0.8}, {0.4, 1.1, 1.2}};
  const Points pyramid{{0, 0, 0}, {1.1, 0, 0.1}, {1, 0.9, 0}, {-0.1, 1, 0}, {0.7, 0.3, 0.6}};
  const Points tet{{0, 0, 0}, {1.3, 0.2, 0}, {0.2, 0.8, 0.1}, {0.4, 0.3, 1.7}};
  Points hex = kCube;
  hex[6] = {1.3, 0.8, 1.4};
  hex[1] = {0.9, -0.2, 0.1};
  const std::pair<const char*, const Points*> cells[] = {
      {"Prisms", &prism}, {"Pyramids", &pyramid}, {"Tetrahedra", &tet}, {"Hexahedra", &hex}};
  EXPECT_NEAR(cell_quality(one_cell("Prisms", prism)).scaled_jacobian[0], verdict_wedge(prism), 1e-12);
  for (const auto& [kw, pts] : cells) {
    const double q0 = cell_quality(one_cell(kw, *pts)).scaled_jacobian[0];
    EXPECT_GT(q0, 0.0) << kw;
    EXPECT_LT(q0, 1.0) << kw;
    std::vector<size_t> order(pts->size());
    for (size_t shift = 1; shift < order.size(); ++shift) {
      for (size_t j = 0; j < order.size(); ++j) order[j] = (order.size() - 1 - j + shift) % order.size();
      EXPECT_NEAR(cell_quality(one_cell(kw, *pts, order)).scaled_jacobian[0], q0, 1e-12) << kw << " shift " << shift;
    }
  }
}

TEST(CellQuality, OctahedronUsesTheFallback) {
  // No corner of the octahedron has 3 edges, so every consecutive triple of each 4-edge corner
  // counts: at (0,0,1) the edges to (1,0,0), (0,1,0), (-1,0,0) are (1,0,-1), (0,1,-1), (-1,0,-1),
  // |det| = 2, lengths sqrt(2) each: N = 2 / 2^1.5 = 1/sqrt(2), the same at every triple.
  MeshInput in;
  in.source = "octahedron";
  in.points = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  const int32_t tris[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& t : tris) in.faces.push_row(std::begin(t), std::end(t));
  const int32_t cell[8] = {0, 2, 4, 6, 8, 10, 12, 14};
  in.cells.push_row(std::begin(cell), std::end(cell));
  const Mesh m = build_mesh(std::move(in));
  ASSERT_EQ(m.cell_type[0], CellType::Polyhedron);
  EXPECT_NEAR(cell_quality(m).scaled_jacobian[0], std::sqrt(0.5), 1e-12);
}

TEST(CellQuality, SplitGrids) {
  // 3×3×3 grids with the centre cell split (generate.hpp). Pyramids around the centre: apex
  // height 1/2 over a unit square, sqrt(2/3) (see Pyramids). Prisms: the column through the
  // centre becomes right isosceles prisms, sqrt(2/3) (see Prisms). Kuhn tets, e.g.
  // (0,0,0) (1,0,0) (1,1,0) (1,1,1): J = 1, corner products sqrt(6), sqrt(2), sqrt(2), sqrt(6),
  // sqrt(2) / sqrt(6) = 1/sqrt(3); their 6 neighbours are cubes with one quad split in two
  // triangles: polyhedra whose 3-edge corners are the cube's right angles, 1. Hexes stay 1.
  const std::array<int32_t, 3> centre{1, 1, 1};
  const std::pair<SplitKind, double> cases[] = {
      {SplitKind::Pyramids, std::sqrt(2.0 / 3.0)}, {SplitKind::Prisms, std::sqrt(2.0 / 3.0)}, {SplitKind::Tets, 1 / std::sqrt(3.0)}};
  for (const auto& [kind, want] : cases) {
    const Mesh m = build_mesh(generate_split(3, 3, 3, kind, std::span(&centre, 1)));
    const CellQuality q = cell_quality(m);
    int split = 0;
    for (size_t c = 0; c < m.num_cells(); ++c) {
      const bool piece = m.cell_type[c] != CellType::Hex && m.cell_type[c] != CellType::Polyhedron;
      split += piece;
      EXPECT_NEAR(q.scaled_jacobian[c], piece ? want : 1.0, 1e-12) << static_cast<int>(kind) << " cell " << c;
    }
    EXPECT_EQ(split, 6) << static_cast<int>(kind);  // 6 pyramids, 3 × 2 prisms, 6 tets
  }
}

TEST(CellDepth, TenCubedGridLayers) {
  // Cells with a boundary vertex are those with some index 0 or 9; cell (i,j,k) then has depth
  // d = min over its indices of min(i, 9 - i) (one face step changes one index by one, and d
  // steps along that axis reach depth 0). Depth d holds (10-2d)³ - (8-2d)³ cells: 488, 296, 152,
  // 56, 8; depth >= 1 leaves the 8×8×8 = 512 inner cells.
  const Mesh m = build_mesh(generate_grid(10, 10, 10));
  const std::vector<int32_t> depth = cell_depth(m);
  std::array<int, 5> per{};
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const int i = static_cast<int>(c % 10), j = static_cast<int>(c / 10 % 10), k = static_cast<int>(c / 100);
    const int d = std::min({i, 9 - i, j, 9 - j, k, 9 - k});
    ASSERT_EQ(depth[c], d) << c;
    ++per[static_cast<size_t>(d)];
  }
  EXPECT_EQ(per, (std::array<int, 5>{488, 296, 152, 56, 8}));
  EXPECT_EQ(std::count_if(depth.begin(), depth.end(), [](int32_t d) { return d >= 1; }), 512);
}

TEST(CellQuality, ArmadilloInvariants) {
  // A real all-hex mesh: every value in Verdict's ranges, and the numbering does not matter
  // (the corner frames are rebuilt from faces after renumbering vertices and cells).
  const std::string rel = "hexalab-edge-cone-rectification/armadillo_out.mesh";
  HBC_REQUIRE_DATA(rel);
  const Mesh m = test::load_data(rel);
  const CellQuality q = cell_quality(m);
  for (size_t c = 0; c < m.num_cells(); ++c) {
    ASSERT_GE(q.scaled_jacobian[c], -1.0 - 1e-12);
    ASSERT_LE(q.scaled_jacobian[c], 1.0 + 1e-12);
    ASSERT_GE(q.edge_ratio[c], 1.0);
  }
  const size_t nv = m.num_vertices(), nc = m.num_cells();
  std::vector<int32_t> vperm(nv), cperm(nc);
  for (size_t v = 0; v < nv; ++v) vperm[v] = static_cast<int32_t>(nv - 1 - v);
  for (size_t c = 0; c < nc; ++c) cperm[c] = static_cast<int32_t>((c * 7919) % nc);
  ASSERT_EQ(std::gcd(size_t{7919}, nc), 1u);
  const Mesh r = build_mesh(renumbered(m, vperm, cperm));
  const CellQuality qr = cell_quality(r);
  for (size_t c = 0; c < nc; ++c) {
    ASSERT_NEAR(qr.scaled_jacobian[static_cast<size_t>(cperm[c])], q.scaled_jacobian[c], 1e-12) << c;
    ASSERT_DOUBLE_EQ(qr.edge_ratio[static_cast<size_t>(cperm[c])], q.edge_ratio[c]) << c;
  }
}

}  // namespace
}  // namespace hbc
