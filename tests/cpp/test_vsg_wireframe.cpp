// The valence singularity graph and its wireframe (SPEC §4): hand-derived results on a plain grid
// and on a grid with a "Y" non-hex column, the three simplification criteria on hand-made
// complexes, reactivation, determinism under renumbering, and invariants on every real mesh.
#include <algorithm>
#include <cstdio>
#include <array>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "hbc/base_complex.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/sheets.hpp"
#include "hbc/singularity_graph.hpp"
#include "hbc/vsg_wireframe.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using Polygon = std::vector<std::array<int, 2>>;

// Counter-clockwise lattice polygons of an n×n cross-section extruded into `layers` unit layers,
// each polygon of each layer one cell (a quad gives a hex). Vertex (x, y, z) has id
// x + (n+1)(y + (n+1) z). Faces are listed once per cell; build_mesh merges the copies.
MeshInput extruded(int n, int layers, const std::vector<Polygon>& polys) {
  MeshInput in;
  in.source = "extruded";
  const int s = n + 1;
  for (int z = 0; z <= layers; ++z)
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) in.points.insert(in.points.end(), {double(x), double(y), double(z)});
  auto id = [&](std::array<int, 2> p, int z) { return p[0] + s * (p[1] + s * z); };
  for (int z = 0; z < layers; ++z)
    for (const Polygon& poly : polys) {
      const size_t k = poly.size();
      std::vector<int32_t> top, bottom;
      for (size_t i = 0; i < k; ++i) {
        top.push_back(id(poly[i], z + 1));
        bottom.push_back(id(poly[k - 1 - i], z));
      }
      std::vector<std::vector<int32_t>> faces{bottom, top};
      for (size_t i = 0; i < k; ++i) {
        const auto a = poly[i], b = poly[(i + 1) % k];
        faces.push_back({id(a, z), id(b, z), id(b, z + 1), id(a, z + 1)});
      }
      for (const auto& f : faces) {
        in.cells.items.push_back(2 * static_cast<int32_t>(in.faces.rows()));
        in.faces.push_row(f.begin(), f.end());
      }
      in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
    }
  return in;
}

std::vector<Polygon> grid_squares(int n, bool skip_centre_block) {
  std::vector<Polygon> out;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (skip_centre_block && i >= 1 && i <= 2 && j >= 1 && j <= 2) continue;
      out.push_back({{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}});
    }
  return out;
}

// The 4×4×4 grid whose 2×2 column x, y in [1, 3] is replaced by a "Y": around the centre line
// (2, 2) three cells with spokes to (2, 1), (3, 2), (2, 3): two quads (hex columns) and one
// hexagon (2,2) (2,3) (1,3) (1,2) (1,1) (2,1) (a column of hexagonal prisms). The vertical line at
// (2, 2) then has 3 cells; the one at (1, 2), a block-side midpoint that is no spoke, has lost one
// cell inside the block and has 3 too; every other line keeps its valence.
Mesh y_mesh() {
  std::vector<Polygon> polys = grid_squares(4, true);
  polys.push_back({{2, 2}, {2, 1}, {3, 1}, {3, 2}});
  polys.push_back({{2, 2}, {3, 2}, {3, 3}, {2, 3}});
  polys.push_back({{2, 2}, {2, 3}, {1, 3}, {1, 2}, {1, 1}, {2, 1}});
  return build_mesh(extruded(4, 4, polys));
}

Mesh grid_mesh(int n) { return build_mesh(extruded(n, n, grid_squares(n, false))); }

std::array<int, 3> coord(const Mesh& m, int32_t v) {
  return {int(m.points[3 * v]), int(m.points[3 * v + 1]), int(m.points[3 * v + 2])};
}

// A polyline as coordinates, in the direction whose first point is smaller (orientation-free).
using Line = std::vector<std::array<int, 3>>;
Line line_of(const Mesh& m, std::span<const int32_t> poly) {
  Line l;
  for (int32_t v : poly) l.push_back(coord(m, v));
  if (l.back() < l.front()) std::reverse(l.begin(), l.end());
  return l;
}

struct Summary {
  std::multiset<Line> vsg, traces, hidden, shown_important;
  size_t reactivated = 0;
};

Summary summarize(const Mesh& m, const VsgWireframe& w) {
  Summary s;
  for (size_t i = 0; i < w.size(); ++i) {
    const Line l = line_of(m, w.polylines[i]);
    (w.kind[i] == WireKind::Vsg ? s.vsg : s.traces).insert(l);
    if (w.non_important[i]) s.hidden.insert(l);
    else s.shown_important.insert(l);
    s.reactivated += w.reactivated[i];
  }
  return s;
}

TEST(VsgWireframe, PlainGridHidesTheBoxEdgesAtTheCorners) {
  // Only the 12 box edges are irregular (boundary valence 1); they chain corner to corner (three
  // meet at each corner). Every edge at a corner is on the VSG, so there are no traces. All eight
  // corners are boundary corners with one cell and quad faces: non-important, so all 12 chains are
  // (criterion 1), and with nothing shown there is nothing to reconnect.
  const Mesh m = grid_mesh(4);
  for (auto cx : {complex_from_mesh(m), complex_from_base(m, base_complex(m, singularity_graph(m)))}) {
    const VsgWireframe w = vsg_wireframe(cx);
    EXPECT_EQ(w.vsg_chains, 12);
    EXPECT_EQ(w.vsg_edges, cx.level == Level::Mesh ? 48 : 12);
    EXPECT_EQ(w.wireframe_edges(), 12);
    EXPECT_EQ(w.singular_vertices.size(), 8u);
    for (size_t i = 0; i < w.size(); ++i) {
      EXPECT_EQ(w.non_important[i], 1);
      EXPECT_EQ(w.valence[i], 1);
      EXPECT_EQ(w.polylines.count(i), 5);
    }
    EXPECT_EQ(w.wireframe_edges_simplified(), 0);
    EXPECT_EQ(w.reference_components, 1);
    EXPECT_EQ(w.shown_components, 0);
  }
}

// Fig. 5's situation, derived by hand on y_mesh() at the mesh level:
// VSG: 12 box chains (valence 1, 4 edges each) + the lines (2,2,z) and (1,2,z) (valence 3, 4 edges
// each, from z = 0 to z = 4): 56 irregular edges, 14 chains; singular vertices: the 8 corners and
// the 4 ends of the two lines.
// Traces: a corner has only VSG edges. At c = (2,2,4) the spokes to (2,1), (3,2), (2,3) run on the
// top face; each continues straight on the boundary (the boundary edge sharing no cell) one more
// edge to the box edge: c-(2,1)-(2,0), c-(3,2)-(4,2), c-(2,3)-(2,4), stopping at a VSG vertex. At
// m = (1,2,4): m-(1,1)-(1,0), m-(1,3)-(1,4), and m-(0,2) (one edge). The same at z = 0: 12 traces.
// Criteria: the 12 box chains join two non-important corners (criterion 1). At c, only the spoke
// to (3,2) has quad faces only (the others touch the hexagon), at m only the edge to (0,2): no
// pairs, so criteria 2 and 3 mark nothing and all traces and both valence-3 lines stay.
// Reactivation: R is everything (every trace ends on the box), one component. Shown: the line at c
// with its six traces, and the line at m with its six: two pieces, whose trace ends lie on the
// box edges y = 0 and y = 4 at z = 0 and z = 4 ((2,0) and (1,0), (2,4) and (1,4)). The cheapest
// join is one such box chain (4 edges; none touches a shown VSG chain): exactly one is reactivated.
TEST(VsgWireframe, YColumnMatchesTheHandDerivation) {
  const Mesh m = y_mesh();
  ASSERT_EQ(m.num_cells(), 60u);
  ASSERT_EQ(m.num_hex_cells(), 56u);
  const VsgWireframe w = vsg_wireframe(complex_from_mesh(m));
  EXPECT_EQ(w.vsg_edges, 56);
  EXPECT_EQ(w.vsg_chains, 14);
  EXPECT_EQ(w.singular_vertices.size(), 12u);
  ASSERT_EQ(w.wireframe_edges(), 26);
  const Summary s = summarize(m, w);
  EXPECT_EQ(s.vsg.count(Line{{2, 2, 0}, {2, 2, 1}, {2, 2, 2}, {2, 2, 3}, {2, 2, 4}}), 1u);
  EXPECT_EQ(s.vsg.count(Line{{1, 2, 0}, {1, 2, 1}, {1, 2, 2}, {1, 2, 3}, {1, 2, 4}}), 1u);
  std::multiset<Line> expected;
  for (int z : {0, 4}) {
    auto L = [&](std::vector<std::array<int, 2>> xy) {
      Line l;
      for (auto p : xy) l.push_back({p[0], p[1], z});
      if (l.back() < l.front()) std::reverse(l.begin(), l.end());
      return l;
    };
    expected.insert(L({{2, 2}, {2, 1}, {2, 0}}));
    expected.insert(L({{2, 2}, {3, 2}, {4, 2}}));
    expected.insert(L({{2, 2}, {2, 3}, {2, 4}}));
    expected.insert(L({{1, 2}, {1, 1}, {1, 0}}));
    expected.insert(L({{1, 2}, {1, 3}, {1, 4}}));
    expected.insert(L({{1, 2}, {0, 2}}));
  }
  EXPECT_EQ(s.traces, expected);
  for (size_t i = 0; i < w.size(); ++i) {
    if (w.kind[i] == WireKind::Trace) {
      EXPECT_EQ(w.stop[i], TraceStop::VsgVertex);
      EXPECT_EQ(w.non_important[i], 0);
    } else {
      EXPECT_EQ(w.non_important[i], w.valence[i] == 1 ? 1 : 0) << "chain " << i;
    }
  }
  EXPECT_EQ(s.reactivated, 1u);
  EXPECT_EQ(w.wireframe_edges_simplified(), 15);
  EXPECT_EQ(w.reference_components, 1);
  EXPECT_EQ(w.shown_components, 1);
  for (size_t i = 0; i < w.size(); ++i) {
    if (!w.reactivated[i]) continue;
    const Line l = line_of(m, w.polylines[i]);
    EXPECT_EQ(l.size(), 5u);
    EXPECT_EQ(l.front()[0], 0);
    EXPECT_EQ(l.back()[0], 4);
    EXPECT_TRUE(l.front()[1] == l.back()[1] && (l.front()[1] == 0 || l.front()[1] == 4));
  }
  // Opacity: the traces through (2,1), (2,3), (1,1), (1,3) touch the hexagonal prisms; the rest
  // of every trace lies on an irregular edge, except the point (3,2) of c-(3,2)-(4,2), one hop
  // from the line at c (and from the box): 1 - 0.85 / 6 at z = 0 and z = 4.
  for (size_t k = 0; k < w.point_opacity.size(); ++k) {
    const auto p = coord(m, w.polylines.items[k]);
    const bool one_hop = p[0] == 3 && p[1] == 2;
    EXPECT_FLOAT_EQ(w.point_opacity[k], one_hop ? float(1.0 - 0.85 / 6) : 1.0f);
  }
}

// The base complex of y_mesh() cuts along every plane through the Y, so its curves are the mesh
// edges around it and the straight lines; the complex-level wireframe has the same geometry.
TEST(VsgWireframe, YColumnSameGeometryAtBothLevels) {
  const Mesh m = y_mesh();
  const BaseComplex bc = base_complex(m, singularity_graph(m));
  const VsgWireframe fine = vsg_wireframe(complex_from_mesh(m));
  const VsgWireframe coarse = vsg_wireframe(complex_from_base(m, bc));
  const Summary a = summarize(m, fine), b = summarize(m, coarse);
  EXPECT_EQ(a.vsg, b.vsg);
  EXPECT_EQ(a.traces, b.traces);
  EXPECT_EQ(a.hidden, b.hidden);
  EXPECT_EQ(coarse.wireframe_edges_simplified(), fine.wireframe_edges_simplified());
}

// test_2.HYBRID is the paper's Fig. 5 mesh: a 3×3×3 cube whose bottom holds a "Y" of three
// prisms around a boundary line of valence 5 (x = 1.5, z = 1, from y = 0 to y = 3). Fig. 5e/f:
// the box edges are non-important (blue, criterion 1: both ends are all-quad boundary corners);
// at each end of the valence-5 line, the two traces running along the boundary to the box edges
// x = 0 and x = 3 are a mutually unique pair (the purple e_i, e_j, criterion 2); the trace down to
// the bottom and the two up the Y's arms to the top stay. Everything shown is joined through the
// valence-5 line, so nothing is reactivated (the paper shows two more top segments because its
// wireframe splits the box edges where traces end; SPEC §4 cuts chains at branch points only).
TEST(VsgWireframe, PaperFigure5) {
  HBC_REQUIRE_DATA("hybrid-base-complex/test_2.HYBRID");
  const Mesh m = test::load_data("hybrid-base-complex/test_2.HYBRID");
  const BaseComplex bc = base_complex(m, singularity_graph(m));
  for (const CellComplex& cx : {complex_from_mesh(m), complex_from_base(m, bc)}) {
    SCOPED_TRACE(level_name(cx.level));
    const VsgWireframe w = vsg_wireframe(cx);
    EXPECT_EQ(w.vsg_chains, 13);
    ASSERT_EQ(w.wireframe_edges(), 23);
    int box = 0, line5 = 0, pairs = 0, kept = 0;
    for (size_t i = 0; i < w.size(); ++i) {
      const auto poly = w.polylines[i];
      const auto a = m.points.begin() + 3 * poly.front(), b = m.points.begin() + 3 * poly.back();
      if (w.kind[i] == WireKind::Vsg) {
        if (w.valence[i] == 1) box += w.non_important[i] == 1;
        else line5 += w.valence[i] == 5 && w.non_important[i] == 0;
        continue;
      }
      EXPECT_EQ(a[0], 1.5);
      EXPECT_EQ(a[2], 1.0);
      const bool horizontal = b[2] == 1.0 && (b[0] == 0.0 || b[0] == 3.0);
      pairs += horizontal && w.non_important[i] == 2;
      kept += !horizontal && w.non_important[i] == 0;
    }
    EXPECT_EQ(box, 12);
    EXPECT_EQ(line5, 1);
    EXPECT_EQ(pairs, 4);
    EXPECT_EQ(kept, 6);
    EXPECT_EQ(w.wireframe_edges_simplified(), 7);
    EXPECT_EQ(std::count(w.reactivated.begin(), w.reactivated.end(), 1), 0);
    EXPECT_EQ(w.shown_components, 1);
  }
}

// A hand-made complex: singular vertex 0 at the end of an irregular edge 0 (0 -> 1, interior
// valence 3), and regular interior edges 1.. from vertex 0 to boundary vertices 2.., one per entry
// of `cells` (the cells around that edge). Each regular edge is one trace that stops at the
// boundary.
CellComplex star(const std::vector<std::vector<int32_t>>& cells, std::vector<uint8_t> all_quad = {}) {
  CellComplex cx;
  const size_t k = cells.size();
  if (all_quad.empty()) all_quad.assign(k, 1);
  const size_t nv = k + 2, ne = k + 1;
  for (size_t v = 0; v < nv; ++v) {
    cx.vert_mesh.push_back(static_cast<int32_t>(v));
    cx.vert_boundary.push_back(v >= 2);
    cx.vert_cell_count.push_back(4);
    cx.vert_all_quad.push_back(1);
  }
  int32_t ncell = 0;
  for (size_t e = 0; e < ne; ++e) {
    const int32_t b = e == 0 ? 1 : static_cast<int32_t>(e + 1);
    cx.edge_verts.push_back({0, b});
    const int32_t pts[2] = {0, b};
    cx.edge_points.push_row(pts, pts + 2);
    std::vector<int32_t> cs = e == 0 ? std::vector<int32_t>{100, 101, 102} : cells[e - 1];
    std::sort(cs.begin(), cs.end());
    for (int32_t c : cs) ncell = std::max(ncell, c + 1);
    cx.edge_cells.push_row(cs.begin(), cs.end());
    cx.edge_valence.push_back(e == 0 ? 3 : 4);
    cx.edge_boundary.push_back(0);
    cx.edge_non_hex.push_back(0);
    cx.edge_all_quad.push_back(e == 0 ? 1 : all_quad[e - 1]);
    cx.edge_faces.push_row(pts, pts);
    cx.edge_source.push_back(static_cast<int32_t>(e));
  }
  cx.cell_non_hex.assign(static_cast<size_t>(ncell), 0);
  cx.cell_source.resize(static_cast<size_t>(ncell));
  std::iota(cx.cell_source.begin(), cx.cell_source.end(), 0);
  Csr<int32_t> ev;
  for (auto ab : cx.edge_verts) ev.push_row(ab.begin(), ab.end());
  cx.vert_edges = transpose(ev, nv);
  return cx;
}

// Criterion of the trace along regular edge i (1-based) of star().
int criterion(const VsgWireframe& w, int32_t edge) {
  for (size_t i = 0; i < w.size(); ++i)
    if (w.kind[i] == WireKind::Trace && w.edges[i][0] == edge) return w.non_important[i];
  ADD_FAILURE() << "no trace along edge " << edge;
  return -1;
}

TEST(VsgWireframe, CriterionTwoMutuallyUniquePair) {
  // Fig. 6a: edges 1 and 2 share no cell and nothing else pairs with either (edge 3 shares a cell
  // with both): both non-important by criterion 2; edge 3 stays.
  const VsgWireframe w = vsg_wireframe(star({{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 4, 5}}));
  ASSERT_EQ(w.vsg_chains, 1);
  EXPECT_EQ(criterion(w, 1), 2);
  EXPECT_EQ(criterion(w, 2), 2);
  EXPECT_EQ(criterion(w, 3), 0);
  // Edge 2 touching a non-quad face cannot be paired: nothing is marked.
  const VsgWireframe v = vsg_wireframe(star({{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 4, 5}}, {1, 0, 1}));
  EXPECT_EQ(criterion(v, 1), 0);
  EXPECT_EQ(criterion(v, 2), 0);
}

TEST(VsgWireframe, CriterionThreeOneToMany) {
  // Fig. 6b: edge 1 pairs with 2 and 3, which share cells 4, 5 and pair only with 1: edge 1 is
  // non-important, and of its partners the lowest (edge 2's trace) too.
  const VsgWireframe w = vsg_wireframe(star({{0, 1, 2, 3}, {4, 5, 6, 7}, {4, 5, 8, 9}}));
  EXPECT_EQ(criterion(w, 1), 3);
  EXPECT_EQ(criterion(w, 2), 3);
  EXPECT_EQ(criterion(w, 3), 0);
}

TEST(VsgWireframe, AllMultiplyPairedEdgesStayImportant) {
  // Fig. 6c: four edges with pairwise disjoint cells: each pairs with three others.
  const VsgWireframe w = vsg_wireframe(star({{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}, {12, 13, 14, 15}}));
  for (int32_t e = 1; e <= 4; ++e) EXPECT_EQ(criterion(w, e), 0) << e;
}

TEST(VsgWireframe, DeterministicUnderRenumbering) {
  const Mesh m = y_mesh();
  const VsgWireframe a = vsg_wireframe(complex_from_mesh(m));
  const VsgWireframe again = vsg_wireframe(complex_from_mesh(m));
  EXPECT_EQ(a.polylines.items, again.polylines.items);
  EXPECT_EQ(a.shown, again.shown);
  EXPECT_EQ(a.color, again.color);
  EXPECT_EQ(a.point_opacity, again.point_opacity);
  std::mt19937 rng(7);
  const test::Renumbering rn = test::random_renumbering(m, rng);
  const Mesh& r = rn.mesh;
  for (bool coarse : {false, true}) {
    auto run = [&](const Mesh& x) {
      return coarse ? vsg_wireframe(complex_from_base(x, base_complex(x, singularity_graph(x))))
                    : vsg_wireframe(complex_from_mesh(x));
    };
    const VsgWireframe wa = run(m), wb = run(r);
    const Summary sa = summarize(m, wa), sb = summarize(r, wb);
    EXPECT_EQ(sa.vsg, sb.vsg);
    EXPECT_EQ(sa.traces, sb.traces);
    EXPECT_EQ(sa.hidden, sb.hidden);
    EXPECT_EQ(sa.shown_important, sb.shown_important);
    EXPECT_EQ(sa.reactivated, sb.reactivated);  // which box chain is a lowest-index tie-break
    EXPECT_EQ(wa.shown_components, wb.shown_components);
  }
}

TEST(VsgWireframe, RegionCountsValenceInsideTheRegion) {
  // The lower half of a 4×4×4 grid as a region: its top (z = 2) becomes boundary, so the region
  // is a 4×4×2 box and its VSG is that box's 12 edges.
  const Mesh m = grid_mesh(4);
  std::vector<int32_t> cells;
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (m.points[3 * m.cell_verts[c][0] + 2] < 2) cells.push_back(static_cast<int32_t>(c));
  const CellComplex cx = complex_from_mesh(m, cells);
  EXPECT_EQ(cx.num_cells(), 32u);
  const VsgWireframe w = vsg_wireframe(cx);
  EXPECT_EQ(w.vsg_chains, 12);
  EXPECT_EQ(w.vsg_edges, 4 * 8 + 4 * 2);
  for (int32_t p : w.polylines.items) EXPECT_LE(m.points[3 * p + 2], 2.0);
}

// Hop distances over all mesh edges from irregular edges and non-hex cells: the opacity oracle
// at the mesh level.
std::vector<int32_t> hop_distances(const Mesh& m) {
  std::vector<int32_t> d(m.num_vertices(), -1), queue;
  const SingularityGraph g = singularity_graph(m);
  for (size_t e = 0; e < m.num_edges(); ++e) {
    bool src = g.edge_irregular[e];
    for (int32_t c : m.edge_cells[e]) src = src || !m.is_hex(c);
    if (!src) continue;
    for (int32_t v : m.edge_verts[e])
      if (d[v] < 0) d[v] = 0, queue.push_back(v);
  }
  for (size_t q = 0; q < queue.size(); ++q)
    for (int32_t e : m.vert_edges[queue[q]]) {
      const int32_t u = m.other_vertex(e, queue[q]);
      if (d[u] < 0) d[u] = d[queue[q]] + 1, queue.push_back(u);
    }
  return d;
}

void check_invariants(const Mesh& m, const CellComplex& cx, const VsgWireframe& w, const std::string& what) {
  SCOPED_TRACE(what);
  const WireframeOptions opt;
  std::set<std::pair<int32_t, int32_t>> mesh_edges;
  for (auto [a, b] : m.edge_verts) mesh_edges.insert({a, b});
  ASSERT_EQ(w.point_opacity.size(), w.polylines.items.size());
  // The oracle holds for the whole fine mesh (a region has its own irregular edges and graph).
  const bool whole_mesh = cx.level == Level::Mesh && cx.num_cells() == m.num_cells();
  const std::vector<int32_t> hops = whole_mesh ? hop_distances(m) : std::vector<int32_t>{};
  for (size_t i = 0; i < w.size(); ++i) {
    const auto poly = w.polylines[i];
    ASSERT_GE(poly.size(), 2u);
    for (size_t k = 0; k + 1 < poly.size(); ++k)
      ASSERT_TRUE(mesh_edges.count({std::min(poly[k], poly[k + 1]), std::max(poly[k], poly[k + 1])}))
          << "wire " << i << " point " << k;
    for (int32_t e : w.edges[i]) ASSERT_EQ(w.edge_vsg[e], w.kind[i] == WireKind::Vsg ? 1 : 0);
    if (w.kind[i] == WireKind::Vsg)
      for (int32_t e : w.edges[i]) ASSERT_TRUE(cx.irregular(e));
    else
      ASSERT_TRUE(w.vert_singular[w.ends[i][0]]);
    ASSERT_LT(w.color[i], opt.palette_size);
    ASSERT_GE(w.color[i], 0);
    bool opaque = w.kind[i] == WireKind::Vsg;
    for (int32_t e : w.edges[i]) opaque = opaque || cx.edge_non_hex[e];
    for (int32_t k = w.polylines.offsets[i]; k < w.polylines.offsets[i + 1]; ++k) {
      const float o = w.point_opacity[k];
      ASSERT_GE(o, float(opt.opacity_floor) - 1e-6f);
      ASSERT_LE(o, 1.0f);
      if (opaque) ASSERT_EQ(o, 1.0f);
      if (!hops.empty() && !opaque) {
        const int32_t d = hops[w.polylines.items[k]];
        const double expect = std::max(opt.opacity_floor, 1.0 - (1.0 - opt.opacity_floor) * d / opt.opacity_hops);
        ASSERT_NEAR(o, expect, 1e-5) << "hops " << d;
      }
    }
    if (w.reactivated[i]) ASSERT_NE(w.non_important[i], 0);
    ASSERT_EQ(w.shown[i], w.non_important[i] == 0 || w.reactivated[i]);
  }
  for (size_t e = 0; e < cx.num_edges(); ++e) ASSERT_EQ(w.edge_vsg[e], cx.irregular(e) ? 1 : 0);
  EXPECT_EQ(std::count(w.edge_vsg.begin(), w.edge_vsg.end(), 1), w.vsg_edges);
  EXPECT_LE(w.shown_components, w.reference_components);
}

TEST(VsgWireframe, InvariantsOnRealMeshes) {
  const char* files[] = {
      "hybrid-base-complex/test_2.HYBRID", "hybrid-base-complex/cube_twist-comp.obj.HYBRID",
      "hybrid-base-complex/teapot.hedra", "hybrid-base-complex/twistcube_s.mesh",
      "openvolumemesh/Cube_with_props.ovm", "openvolumemesh/Cylinder.ovm",
      "openvolumemesh/NonManifold.ovm", "cinolib/eight_voronoi.hedra", "cinolib/ellipsoid.mesh",
      "cinolib/rockerarm.mesh", "hexalab-edge-cone-rectification/block_out.mesh",
      "hexalab-edge-cone-rectification/bust_out.mesh"};
  for (const char* f : files) {
    HBC_REQUIRE_DATA(f);
    const Mesh m = test::load_data(f);
    const BaseComplex bc = base_complex(m, singularity_graph(m));
    const CellComplex fine = complex_from_mesh(m), coarse = complex_from_base(m, bc);
    check_invariants(m, fine, vsg_wireframe(fine), std::string(f) + " mesh level");
    check_invariants(m, coarse, vsg_wireframe(coarse), std::string(f) + " complex level");
  }
}

TEST(VsgWireframe, SheetRegions) {
  HBC_REQUIRE_DATA("hybrid-base-complex/teapot.hedra");
  const Mesh m = test::load_data("hybrid-base-complex/teapot.hedra");
  const BaseComplex bc = base_complex(m, singularity_graph(m));
  // The whole mesh given as a region is the whole mesh.
  std::vector<int32_t> all(bc.num_components());
  std::iota(all.begin(), all.end(), 0);
  const VsgWireframe a = vsg_wireframe(complex_from_base(m, bc)), b = vsg_wireframe(complex_from_base(m, bc, all));
  EXPECT_EQ(a.polylines.items, b.polylines.items);
  EXPECT_EQ(a.shown, b.shown);
  // Every sheet with its adjacent non-hex cells, at both levels.
  const Sheets sheets = extract_sheets(m, sheet_domain(m, bc, Level::Complex));
  ASSERT_EQ(sheets.size(), 23u);
  for (size_t k = 0; k < sheets.size(); ++k) {
    std::vector<int32_t> cells;
    for (auto row : {sheets.sheet_cells[k], sheets.sheet_non_hex_cells[k]}) cells.insert(cells.end(), row.begin(), row.end());
    const CellComplex fine = complex_from_mesh(m, cells);
    const CellComplex coarse = complex_from_base(m, bc, components_of_cells(bc, cells));
    EXPECT_EQ(fine.num_cells(), cells.size());
    check_invariants(m, fine, vsg_wireframe(fine), "sheet " + std::to_string(k) + " mesh level");
    check_invariants(m, coarse, vsg_wireframe(coarse), "sheet " + std::to_string(k) + " complex level");
  }
}

TEST(VsgWireframe, ColoursSeparateAdjacentClasses) {
  HBC_REQUIRE_DATA("hybrid-base-complex/teapot.hedra");
  const Mesh m = test::load_data("hybrid-base-complex/teapot.hedra");
  const VsgWireframe w = vsg_wireframe(complex_from_base(m, base_complex(m, singularity_graph(m))));
  std::map<int32_t, std::set<int32_t>> at_point;
  for (size_t i = 0; i < w.size(); ++i)
    for (int32_t p : w.polylines[i]) at_point[p].insert(static_cast<int32_t>(i));
  int conflicts = 0, adjacent = 0;
  for (const auto& [p, ws] : at_point)
    for (int32_t a : ws)
      for (int32_t b : ws) {
        if (a >= b || w.color_class[a] == w.color_class[b]) continue;
        ++adjacent;
        conflicts += w.color[a] == w.color[b];
      }
  EXPECT_GT(adjacent, 0);
  // Greedy colouring with 8 colours: a clash only where a class already has 8+ coloured neighbours.
  EXPECT_LE(conflicts, adjacent / 20) << conflicts << " of " << adjacent;
}

TEST(VsgWireframe, CommandLine) {
  HBC_REQUIRE_DATA("hybrid-base-complex/test_2.HYBRID");
  const std::string file = test::data_path("hybrid-base-complex/test_2.HYBRID");
  test::CliRun r = test::run_cli("wireframe " + file + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j["wireframe_edges"], 23);
  EXPECT_EQ(j["wireframe_edges_simplified"], 7);
  EXPECT_EQ(j["level"], "complex");
  EXPECT_EQ(j["edges"].size(), 23u);
  r = test::run_cli("wireframe " + file + " --obj --level mesh");
  EXPECT_EQ(r.status, 0) << r.err;
  size_t lines = 0;
  for (size_t k = r.out.find("\nl "); k != std::string::npos; k = r.out.find("\nl ", k + 1)) ++lines;
  EXPECT_EQ(lines, 7u);
  r = test::run_cli("wireframe " + file + " --level coarse");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--level"), std::string::npos) << r.err;
  r = test::run_cli("wireframe " + file + " --sheet 9999");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("sheets"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hbc
