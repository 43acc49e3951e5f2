// The non-hex kinds of the VSG wireframe's chains (docs/concepts.md, "Non-hex kinds"): on split
// grids whose non-hex cells are placed by hand, the kinds derived in the comments; on real
// hex-dominant meshes of several cell types, the rule recomputed from the mesh alone at both levels.
#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/base_complex.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/generate.hpp"
#include "hbc/singularity_graph.hpp"
#include "hbc/vsg_wireframe.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using Kinds = std::vector<int32_t>;

std::vector<CellComplex> both_levels(const Mesh& m) {
  std::vector<CellComplex> out;
  out.push_back(complex_from_mesh(m));
  out.push_back(complex_from_base(m, base_complex(m, singularity_graph(m))));
  return out;
}

// Mesh vertices of the cells of the grid cells (i, j, l), whatever they were split into: the
// corners of the grid cell and, for a pyramid split, its centre (the vertices after the grid's).
std::set<int32_t> split_cell_vertices(const Mesh& m, const std::vector<size_t>& cells) {
  std::set<int32_t> out;
  std::vector<int32_t> vs;
  for (size_t c : cells) {
    cell_vertices(m, c, vs);
    out.insert(vs.begin(), vs.end());
  }
  return out;
}

bool touches(std::span<const int32_t> poly, const std::set<int32_t>& verts) {
  return std::any_of(poly.begin(), poly.end(), [&](int32_t v) { return verts.count(v) != 0; });
}

// Every polyline of both wireframes carries `kind` exactly when it passes through one of `verts`.
void expect_kind_where_it_touches(const VsgWireframe& w, const std::set<int32_t>& verts, int32_t kind) {
  size_t with = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    const bool t = touches(w.polylines[i], verts);
    with += t;
    EXPECT_EQ(Kinds(w.non_hex[i].begin(), w.non_hex[i].end()), t ? Kinds{kind} : Kinds{}) << "chain " << i;
  }
  for (size_t i = 0; i < w.simplified_polylines.rows(); ++i) {
    const bool t = touches(w.simplified_polylines[i], verts);
    EXPECT_EQ(Kinds(w.simplified_non_hex[i].begin(), w.simplified_non_hex[i].end()), t ? Kinds{kind} : Kinds{})
        << "simplified chain " << i;
  }
  EXPECT_GT(with, 0u);
  EXPECT_LT(with, w.size());  // the chains along the box's far edges touch no split cell
}

// The non-hex cells of a split grid (cells numbered in grid order, the split cell's pieces last
// of their row): those whose type is not Hex.
std::vector<size_t> non_hex_cells(const Mesh& m) {
  std::vector<size_t> out;
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (!m.is_hex(c)) out.push_back(c);
  return out;
}

// 3×3×3 grid, the centre hex (1,1,1) split into 6 pyramids around its centre (5 faces each). Both
// levels see the same structure: the pyramids' faces start separation surfaces along the whole
// planes x, y, z = 1, 2, so every grid vertex is a corner and every curve one mesh edge. A chain
// touches a pyramid exactly when its polyline passes through one of the split cell's 9 vertices
// (8 corners and the centre): it ends there (the end rule), or it goes on through a corner of the
// cube, and every straight line through a corner runs along a cube edge on one side, which is a
// pyramid edge (an edge rule); the spokes to the centre are pyramid edges. So each chain carries
// {pyramid, 5 faces} when it passes through those vertices and nothing otherwise.
TEST(WireframeKinds, PyramidsLabelTheChainsThroughTheSplitCell) {
  const std::array<int32_t, 3> centre{1, 1, 1};
  const Mesh m = build_mesh(generate_split(3, 3, 3, SplitKind::Pyramids, std::span(&centre, 1)));
  const std::vector<size_t> split = non_hex_cells(m);
  ASSERT_EQ(split.size(), 6u);
  const std::set<int32_t> verts = split_cell_vertices(m, split);
  ASSERT_EQ(verts.size(), 9u);
  for (const CellComplex& cx : both_levels(m)) {
    SCOPED_TRACE(level_name(cx.level));
    expect_kind_where_it_touches(vsg_wireframe(cx), verts, non_hex_kind(CellType::Pyramid, 5));
  }
}

// 3×3×3 grid, the column through (1,1,·) along z split into prism pairs (5 faces each), cut along
// the diagonal from (1,1) to (2,2). Again every plane x, y, z = 1, 2 separates, so both levels agree.
// The column's 16 vertices: a chain through one of them ends there (at (1,1,z) and (2,2,z) the
// straight continuation of an outer edge is not unique, the diagonal sharing no face with it
// either) or goes on along a side of the column, a prism edge. So each chain carries {prism, 5}
// when it passes through the column's vertices and nothing otherwise.
TEST(WireframeKinds, PrismsLabelTheChainsAlongTheColumn) {
  const std::array<int32_t, 3> cell{1, 1, 1};
  const Mesh m = build_mesh(generate_split(3, 3, 3, SplitKind::Prisms, std::span(&cell, 1), 2));
  const std::vector<size_t> split = non_hex_cells(m);
  ASSERT_EQ(split.size(), 6u);
  const std::set<int32_t> verts = split_cell_vertices(m, split);
  ASSERT_EQ(verts.size(), 16u);
  for (const CellComplex& cx : both_levels(m)) {
    SCOPED_TRACE(level_name(cx.level));
    expect_kind_where_it_touches(vsg_wireframe(cx), verts, non_hex_kind(CellType::Prism, 5));
  }
}

// The rule recomputed from the mesh alone: the kinds of the non-hex cells holding a mesh edge of
// the polyline, or (an open polyline: first vertex other than last) holding its first or last
// vertex. At the complex level a chain's edges are curves, and a non-hex component (one cell) lies
// around a curve exactly when its cell holds a mesh edge of it, so the same rule holds there.
struct KindTables {
  std::vector<std::set<int32_t>> vert, edge;  // kinds of the non-hex cells at each vertex / edge
};
KindTables kind_tables(const Mesh& m) {
  KindTables t{std::vector<std::set<int32_t>>(m.num_vertices()), std::vector<std::set<int32_t>>(m.num_edges())};
  std::vector<int32_t> buf;
  for (size_t c = 0; c < m.num_cells(); ++c) {
    if (m.is_hex(c)) continue;
    const int32_t k = non_hex_kind(m.cell_type[c], static_cast<size_t>(m.cell_faces.count(c)));
    cell_vertices(m, c, buf);
    for (int32_t v : buf) t.vert[v].insert(k);
    cell_edges(m, c, buf);
    for (int32_t e : buf) t.edge[e].insert(k);
  }
  return t;
}

// Edge ids by their ends, so that the recomputation does not scan every edge per step.
struct EdgeIndex {
  std::vector<std::pair<std::array<int32_t, 2>, int32_t>> sorted;
  explicit EdgeIndex(const Mesh& m) {
    for (size_t e = 0; e < m.num_edges(); ++e) sorted.push_back({m.edge_verts[e], static_cast<int32_t>(e)});
    std::sort(sorted.begin(), sorted.end());
  }
  int32_t operator()(int32_t a, int32_t b) const {
    const std::array<int32_t, 2> key{std::min(a, b), std::max(a, b)};
    auto it = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(key, INT32_MIN));
    return it != sorted.end() && it->first == key ? it->second : -1;
  }
};

void expect_rule(const Mesh& m, const VsgWireframe& w, std::set<int32_t>& seen) {
  const KindTables t = kind_tables(m);
  const EdgeIndex edge(m);
  auto expected = [&](std::span<const int32_t> poly) {
    std::set<int32_t> out;
    for (size_t i = 0; i + 1 < poly.size(); ++i) {
      const int32_t e = edge(poly[i], poly[i + 1]);
      EXPECT_GE(e, 0);
      if (e >= 0) out.insert(t.edge[e].begin(), t.edge[e].end());
    }
    if (poly.front() != poly.back())
      for (int32_t v : {poly.front(), poly.back()}) out.insert(t.vert[v].begin(), t.vert[v].end());
    return Kinds(out.begin(), out.end());
  };
  for (size_t i = 0; i < w.size(); ++i) {
    EXPECT_EQ(Kinds(w.non_hex[i].begin(), w.non_hex[i].end()), expected(w.polylines[i])) << "chain " << i;
    seen.insert(w.non_hex[i].begin(), w.non_hex[i].end());
  }
  for (size_t i = 0; i < w.simplified_polylines.rows(); ++i)
    EXPECT_EQ(Kinds(w.simplified_non_hex[i].begin(), w.simplified_non_hex[i].end()),
              expected(w.simplified_polylines[i])) << "simplified chain " << i;
}

// 5×3×3 grid, the hexes (1,1,1) and (3,1,1) split into 6 tets each (4 faces). A hex across one of
// their quads sees two triangles there and becomes a polyhedron of 7 faces, (2,1,1) between both
// one of 8. The kinds met on the wireframe are those three, each recomputed per chain from the mesh.
TEST(WireframeKinds, TetsAndPolyhedraByFaceCount) {
  const std::array<int32_t, 3> cells[] = {{1, 1, 1}, {3, 1, 1}};
  const Mesh m = build_mesh(generate_split(5, 3, 3, SplitKind::Tets, cells));
  std::multiset<int32_t> faces;
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (m.cell_type[c] == CellType::Polyhedron) faces.insert(m.cell_faces.count(c));
  ASSERT_EQ(faces, (std::multiset<int32_t>{7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 8}));
  const std::set<int32_t> all{non_hex_kind(CellType::Tet, 4), non_hex_kind(CellType::Polyhedron, 7),
                              non_hex_kind(CellType::Polyhedron, 8)};
  for (const CellComplex& cx : both_levels(m)) {
    SCOPED_TRACE(level_name(cx.level));
    std::set<int32_t> seen;
    expect_rule(m, vsg_wireframe(cx), seen);
    EXPECT_EQ(seen, all);
  }
}

// Real hex-dominant meshes of several cell types: twistcube_s (prisms, tets, a pyramid, polyhedra
// of 5 and 7 corners), cube_twist-comp (a prism and polyhedra of 4 to 9 faces), teapot (flat
// 4-face polyhedra). Every kind named on a chain is that of a non-hex cell it touches, and every
// non-hex cell it touches is named, at both levels; at the mesh level every kind of the mesh is
// met on some chain (every non-hex cell has irregular or boundary edges there).
TEST(WireframeKinds, RuleHoldsOnRealMeshes) {
  for (const char* f : {"hybrid-base-complex/twistcube_s.mesh", "hybrid-base-complex/cube_twist-comp.obj.HYBRID",
                        "hybrid-base-complex/teapot.hedra"}) {
    HBC_REQUIRE_DATA(f);
    SCOPED_TRACE(f);
    const Mesh m = test::load_data(f);
    std::set<int32_t> mesh_kinds;
    for (size_t c = 0; c < m.num_cells(); ++c)
      if (!m.is_hex(c)) mesh_kinds.insert(non_hex_kind(m.cell_type[c], static_cast<size_t>(m.cell_faces.count(c))));
    for (const CellComplex& cx : both_levels(m)) {
      SCOPED_TRACE(level_name(cx.level));
      std::set<int32_t> seen;
      expect_rule(m, vsg_wireframe(cx), seen);
      EXPECT_TRUE(std::includes(mesh_kinds.begin(), mesh_kinds.end(), seen.begin(), seen.end()));
      if (cx.level == Level::Mesh) EXPECT_EQ(seen, mesh_kinds);
    }
  }
}

TEST(WireframeKinds, AllHexMeshHasNone) {
  const Mesh m = build_mesh(generate_grid(3, 3, 3));
  for (const CellComplex& cx : both_levels(m)) {
    const VsgWireframe w = vsg_wireframe(cx);
    EXPECT_EQ(w.non_hex.rows(), w.size());
    EXPECT_TRUE(w.non_hex.items.empty());
    EXPECT_EQ(w.simplified_non_hex.rows(), w.simplified_polylines.rows());
  }
}

}  // namespace
}  // namespace hbc
