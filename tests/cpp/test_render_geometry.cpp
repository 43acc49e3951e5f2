// Render geometry (render_geometry.hpp) on generated meshes whose counts follow from construction:
// a 2×2×2 grid, and a 3×3×3 grid whose centre cell is split into 6 pyramids.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <utility>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "hbc/region.hpp"
#include "hbc/render_geometry.hpp"

namespace hbc {
namespace {

struct Analysed {
  Mesh mesh;
  Analysis analysis;
};

Analysed grid2(Level level = Level::Complex) {
  Analysed r{build_mesh(generate_grid(2, 2, 2)), {}};
  AnalysisOptions opt;
  opt.sheet_level = level;
  r.analysis = analyze(r.mesh, opt);
  return r;
}

Analysed split3() {
  const std::array<int32_t, 3> centre{1, 1, 1};
  Analysed r{build_mesh(generate_split(3, 3, 3, SplitKind::Pyramids, std::span(&centre, 1))), {}};
  r.analysis = analyze(r.mesh);
  return r;
}

std::set<int32_t> owners(const BlockSoup& s) { return {s.face_owner.begin(), s.face_owner.end()}; }

// Every undirected point pair of an owner's faces, with how many faces use it; and whether each
// directed pair appears once (a consistently oriented closed surface uses each edge once per way).
void expect_closed_oriented(const BlockSoup& s, int32_t owner) {
  std::map<std::pair<int32_t, int32_t>, int> directed;
  for (size_t f = 0; f < s.num_faces(); ++f) {
    const auto loop = s.face_vertices[f];
    if (s.face_owner[f] == owner)
      for (size_t i = 0; i < loop.size(); ++i) ++directed[{loop[i], loop[(i + 1) % loop.size()]}];
  }
  ASSERT_FALSE(directed.empty());
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << "edge used by one face only";
  }
}

TEST(RenderGeometry, GridCellsComponentsBoundary) {
  const Analysed g = grid2();
  const BlockSoup cells = block_soup(g.mesh, g.analysis, SoupKind::Cells);
  EXPECT_EQ(cells.num_faces(), 48u);  // 8 cells × 6 quads
  EXPECT_EQ(cells.num_points(), 64u);  // 8 corners each, not shared between cells
  EXPECT_EQ(cells.face_vertices.items.size(), 192u);
  EXPECT_EQ(owners(cells).size(), 8u);
  for (int32_t c = 0; c < 8; ++c) expect_closed_oriented(cells, c);

  // One cube component: its 24 boundary quads over the 26 boundary vertices (27 minus the centre).
  const BlockSoup comps = block_soup(g.mesh, g.analysis, SoupKind::Components);
  EXPECT_EQ(comps.num_faces(), 24u);
  EXPECT_EQ(comps.num_points(), 26u);
  EXPECT_EQ(owners(comps), std::set<int32_t>{0});
  expect_closed_oriented(comps, 0);

  const BlockSoup boundary = block_soup(g.mesh, g.analysis, SoupKind::Boundary);
  EXPECT_EQ(boundary.num_faces(), 24u);
  EXPECT_EQ(boundary.num_points(), 26u);
  EXPECT_EQ(owners(boundary), std::set<int32_t>{static_cast<int32_t>(CellType::Hex)});

  EXPECT_EQ(block_soup(g.mesh, g.analysis, SoupKind::NonHex).num_faces(), 0u);
  // shrink = 0 copies the vertices exactly.
  for (size_t p = 0; p < comps.num_points(); ++p)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(comps.positions[3 * p + d], static_cast<float>(g.mesh.points[3 * static_cast<size_t>(comps.point_vertex[p]) + d]));
}

TEST(RenderGeometry, ShrinkTowardOwnerCentroid) {
  const Analysed g = grid2();
  // The component's vertex centroid is the grid centre (1,1,1); halfway in, corner (0,0,0) lands at
  // (0.5,0.5,0.5) and (2,2,2) at (1.5,1.5,1.5).
  const BlockSoup s = block_soup(g.mesh, g.analysis, SoupKind::Components, std::nullopt, 0.5);
  for (size_t p = 0; p < s.num_points(); ++p)
    for (int d = 0; d < 3; ++d) {
      const double x = g.mesh.points[3 * static_cast<size_t>(s.point_vertex[p]) + d];
      EXPECT_FLOAT_EQ(s.positions[3 * p + d], static_cast<float>(1.0 + 0.5 * (x - 1.0)));
    }
  // Cells shrink toward their own centres: cell 0 spans [0,1]^3.
  const BlockSoup c = block_soup(g.mesh, g.analysis, SoupKind::Cells, std::nullopt, 0.5);
  for (size_t p = 0; p < 8; ++p)
    for (int d = 0; d < 3; ++d) {
      const float v = c.positions[3 * p + d];
      EXPECT_TRUE(v == 0.25f || v == 0.75f) << v;
    }
  EXPECT_THROW(block_soup(g.mesh, g.analysis, SoupKind::Cells, std::nullopt, 1.0), std::invalid_argument);
  EXPECT_THROW(block_soup(g.mesh, g.analysis, SoupKind::Cells, std::nullopt, -0.5), std::invalid_argument);
}

TEST(RenderGeometry, GridSheets) {
  // Complex level: the single cube component carries 3 sheets, each holding all 8 cells.
  const Analysed g = grid2();
  ASSERT_EQ(g.analysis.sheet_stage->sheets.size(), 3u);
  const BlockSoup sheets = block_soup(g.mesh, g.analysis, SoupKind::Sheets);
  EXPECT_EQ(sheets.num_faces(), 72u);  // 3 × the 24 boundary quads
  EXPECT_EQ(sheets.num_points(), 78u);
  EXPECT_EQ(owners(sheets), (std::set<int32_t>{0, 1, 2}));
  const BlockSoup one = block_soup(g.mesh, g.analysis, SoupKind::Sheet, 1);
  EXPECT_EQ(one.num_faces(), 24u);
  EXPECT_EQ(owners(one), std::set<int32_t>{0});  // component 0
  EXPECT_THROW(block_soup(g.mesh, g.analysis, SoupKind::Sheet, 3), std::invalid_argument);
  EXPECT_THROW(block_soup(g.mesh, g.analysis, SoupKind::Subsheets, 0), std::invalid_argument);
  EXPECT_THROW(block_soup(g.mesh, g.analysis, SoupKind::Sheet), std::invalid_argument);  // no sheet given
  EXPECT_THROW(block_soup(g.mesh, g.analysis, SoupKind::Sheet, -1), std::invalid_argument);

  // Mesh level: 6 one-cell-thick slabs of 2×2×1 cells; each slab's boundary has 8 + 8 quads and
  // 18 vertices, and within the one component it stays one owner.
  const Analysed fine = grid2(Level::Mesh);
  ASSERT_EQ(fine.analysis.sheet_stage->sheets.size(), 6u);
  const BlockSoup slabs = block_soup(fine.mesh, fine.analysis, SoupKind::Sheets);
  EXPECT_EQ(slabs.num_faces(), 96u);
  EXPECT_EQ(slabs.num_points(), 108u);
  for (int32_t s = 0; s < 6; ++s) {
    expect_closed_oriented(slabs, s);
    const BlockSoup slab = block_soup(fine.mesh, fine.analysis, SoupKind::Sheet, s);
    EXPECT_EQ(slab.num_faces(), 16u);
    EXPECT_EQ(owners(slab), std::set<int32_t>{0});
  }
}

TEST(RenderGeometry, SplitGrid) {
  // The split cuts the grid along the planes through the centre cell: 26 one-hex components and
  // 6 pyramid components; every face is a separation face.
  const Analysed g = split3();
  ASSERT_EQ(g.mesh.num_cells(), 32u);
  ASSERT_EQ(g.analysis.complex.num_components(), 32u);
  const BlockSoup nonhex = block_soup(g.mesh, g.analysis, SoupKind::NonHex);
  EXPECT_EQ(nonhex.num_faces(), 30u);   // 6 pyramids × (4 triangles + 1 quad)
  EXPECT_EQ(nonhex.num_points(), 30u);  // 5 apexes and corners each
  EXPECT_EQ(owners(nonhex).size(), 6u);
  for (int32_t o : owners(nonhex)) expect_closed_oriented(nonhex, o);
  int triangles = 0;
  for (size_t f = 0; f < nonhex.num_faces(); ++f) triangles += nonhex.face_vertices.count(f) == 3;
  EXPECT_EQ(triangles, 24);

  const BlockSoup comps = block_soup(g.mesh, g.analysis, SoupKind::Components);
  EXPECT_EQ(comps.num_faces(), 26u * 6 + 30);  // every face of every cell, once per side
  EXPECT_EQ(comps.num_points(), 26u * 8 + 30);
  EXPECT_EQ(owners(comps).size(), 32u);
  for (int32_t o : owners(comps)) expect_closed_oriented(comps, o);

  const BlockSoup boundary = block_soup(g.mesh, g.analysis, SoupKind::Boundary);
  EXPECT_EQ(boundary.num_faces(), 54u);
  EXPECT_EQ(boundary.num_points(), 56u);  // 64 grid vertices minus the 8 inside

  // The sheets through the centre are type 1 (their shared corners come from the pyramids) and
  // have those pyramids as adjacent non-hex cells.
  size_t with_pyramids = 0;
  for (size_t s = 0; s < g.analysis.sheet_stage->sheets.size(); ++s) {
    const BlockSoup nh = block_soup(g.mesh, g.analysis, SoupKind::SheetNonHex, static_cast<int32_t>(s));
    EXPECT_EQ(nh.num_faces(), 5 * g.analysis.sheet_stage->sheets.sheet_non_hex_cells.count(s));
    with_pyramids += nh.num_faces() > 0;
  }
  EXPECT_GT(with_pyramids, 0u);
}

TEST(RenderGeometry, FaceCellAndCentroids) {
  // face_cell is the cell on the owner's side: the owner itself for cell kinds, a cell of the
  // owner component for components; every face bounds its face_cell.
  const Analysed g = split3();
  const Mesh& m = g.mesh;
  for (SoupKind kind : {SoupKind::Cells, SoupKind::NonHex, SoupKind::Components, SoupKind::Boundary}) {
    const BlockSoup s = block_soup(m, g.analysis, kind);
    ASSERT_EQ(s.face_cell.size(), s.num_faces());
    for (size_t f = 0; f < s.num_faces(); ++f) {
      const auto [a, b] = m.face_cells[static_cast<size_t>(s.face_source[f])];
      EXPECT_TRUE(s.face_cell[f] == a || s.face_cell[f] == b);
      if (kind == SoupKind::Cells || kind == SoupKind::NonHex) EXPECT_EQ(s.face_cell[f], s.face_owner[f]);
      if (kind == SoupKind::Components)
        EXPECT_EQ(g.analysis.complex.cell_component[static_cast<size_t>(s.face_cell[f])], s.face_owner[f]);
    }
  }
  // Centroids of a 2x1x1 grid of spacing 1: (0.5, 0.5, 0.5) and (1.5, 0.5, 0.5), in some order.
  const Mesh two = build_mesh(generate_grid(2, 1, 1));
  const std::vector<double> c = cell_centroids(two);
  ASSERT_EQ(c.size(), 6u);
  std::set<std::array<double, 3>> got{{c[0], c[1], c[2]}, {c[3], c[4], c[5]}};
  EXPECT_EQ(got, (std::set<std::array<double, 3>>{{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}}));
}

TEST(RenderGeometry, KeptSurface) {
  // 3x3x3 split grid (26 hexes + 6 pyramids filling the centre cell): all kept gives the 54
  // boundary faces; the pyramids alone give their 6 quad bases (against the hex neighbours; their
  // triangles are shared between pyramids); none kept, nothing; one cell alone, its closed surface.
  const Analysed g = split3();
  const Mesh& m = g.mesh;
  std::vector<uint8_t> kept(m.num_cells(), 1);
  EXPECT_EQ(kept_surface_soup(m, kept).num_faces(), 54u);
  for (size_t c = 0; c < m.num_cells(); ++c) kept[c] = m.is_hex(c) ? 0 : 1;
  const BlockSoup pyr = kept_surface_soup(m, kept);
  EXPECT_EQ(pyr.num_faces(), 6u);
  for (size_t f = 0; f < pyr.num_faces(); ++f) EXPECT_EQ(pyr.face_vertices.count(f), 4);
  std::fill(kept.begin(), kept.end(), 0);
  EXPECT_EQ(kept_surface_soup(m, kept).num_faces(), 0u);
  kept[0] = 1;
  const BlockSoup one = kept_surface_soup(m, kept);
  EXPECT_EQ(one.num_faces(), m.cell_faces.count(0));
  expect_closed_oriented(one, 0);
  EXPECT_THROW(kept_surface_soup(m, std::vector<uint8_t>(3, 1)), std::invalid_argument);
}

TEST(RenderGeometry, Polylines) {
  const Analysed g = grid2();
  const std::vector<int32_t> offsets{0, 2, 5}, verts{0, 1, 26, 25, 24};
  const std::vector<float> p = polyline_positions(g.mesh, offsets, verts);
  ASSERT_EQ(p.size(), 15u);
  EXPECT_EQ(p[6], 2.0f);  // vertex 26 = (2,2,2)
  EXPECT_EQ(p[12], 0.0f);  // vertex 24 = (0,2,2)
  EXPECT_EQ(p[13], 2.0f);
  EXPECT_THROW(polyline_positions(g.mesh, std::vector<int32_t>{0, 6}, verts), std::invalid_argument);
  EXPECT_THROW(polyline_positions(g.mesh, std::vector<int32_t>{0, 1}, std::vector<int32_t>{27}), std::invalid_argument);
  EXPECT_THROW(soup_kind_from_name("patches"), std::invalid_argument);
  EXPECT_EQ(soup_kind_from_name("sheet_non_hex"), SoupKind::SheetNonHex);
}

TEST(RenderGeometry, RegionsAndClasses) {
  const Analysed g = grid2();
  EXPECT_EQ(region_cells(g.mesh, g.analysis, std::nullopt).size(), 8u);
  EXPECT_EQ(region_cells(g.mesh, g.analysis, 0).size(), 8u);
  EXPECT_THROW(region_cells(g.mesh, g.analysis, 0, 0), std::invalid_argument);  // not type 3
  EXPECT_THROW(region_cells(g.mesh, g.analysis, -1), std::invalid_argument);    // an id, not "none"
  EXPECT_THROW(region_cells(g.mesh, g.analysis, std::nullopt, 0), std::invalid_argument);  // no sheet
  const VsgWireframe whole = region_wireframe(g.mesh, g.analysis, Level::Complex, {}, std::nullopt);
  EXPECT_EQ(whole.wireframe_edges(), g.analysis.wireframe_stage->wireframe.wireframe_edges());
  const ClassArrays k = flatten_classes(g.analysis.sheet_stage->domain, g.analysis.sheet_stage->sheets.classes);
  EXPECT_EQ(k.type, std::vector<uint8_t>(3, 0));  // a grid's sheets are perfect
  EXPECT_EQ(k.flags.size(), 9u);
  EXPECT_EQ(k.unmatched_vertices.rows(), 3u);
  const Csr<int32_t> comps = blocks_as_components(g.analysis.sheet_stage->domain, g.analysis.sheet_stage->sheets.sheet_blocks);
  EXPECT_EQ(comps.items, std::vector<int32_t>(3, 0));
  const Analysed fine = grid2(Level::Mesh);
  const Csr<int32_t> fine_comps = blocks_as_components(fine.analysis.sheet_stage->domain, fine.analysis.sheet_stage->sheets.sheet_blocks);
  EXPECT_EQ(fine_comps.items, std::vector<int32_t>(6, 0));  // 4 cells per slab, one component
}

}  // namespace
}  // namespace hbc
