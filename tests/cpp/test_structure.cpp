// Known answers for the hybrid singularity graph, the hybrid base complex and the sheets on
// generated meshes (derivations in the comments), and invariants on every real mesh.
#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>
#include <set>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

Analysis run(const Mesh& m) { return analyze(m); }

// A 3×4×5 grid: no structure inside. The 12 box edges are boundary edges of valence 1 (irregular),
// each one singularity (its chain is cut at the box corners, where 3 singular edges meet): 12
// singularities and 8 singular vertices. Every separation face is a boundary face: 1 component,
// a cube with 6 patches, 12 curves, 8 corners. Sheets: one per axis, all perfect.
TEST(Structure, Grid) {
  const Mesh m = build_mesh(generate_grid(3, 4, 5));
  const Analysis a = run(m);
  EXPECT_EQ(a.graph.num_singularities(), 12u);
  EXPECT_EQ(a.graph.num_singular_edges(), 4u * (3 + 4 + 5));
  EXPECT_EQ(a.graph.singular_vertices.size(), 8u);
  EXPECT_TRUE(a.graph.pseudo_singular_edges.empty());
  for (size_t s = 0; s < a.graph.num_singularities(); ++s) {
    EXPECT_EQ(a.graph.chain_valence[s], 1);
    EXPECT_TRUE(a.graph.chain_boundary[s]);
    EXPECT_FALSE(a.graph.chain_closed[s]);
  }
  ASSERT_EQ(a.complex.num_components(), 1u);
  EXPECT_EQ(a.complex.component_kind[0], ComponentKind::Cube);
  EXPECT_EQ(a.complex.num_patches(), 6u);
  EXPECT_EQ(a.complex.num_curves(), 12u);
  EXPECT_EQ(a.complex.corners.size(), 8u);
  ASSERT_EQ(a.sheet_stage->sheets.size(), 3u);
  for (const SheetClass& k : a.sheet_stage->sheets.classes) EXPECT_EQ(k.type, SheetType::Perfect);
  // Mesh level: one sheet per layer of cells, 3 + 4 + 5.
  AnalysisOptions mesh_level;
  mesh_level.sheet_level = Level::Mesh;
  const Analysis b = analyze(m, mesh_level);
  EXPECT_EQ(b.sheet_stage->sheets.size(), 12u);
  EXPECT_EQ(b.sheet_stage->sheets.count(SheetType::Perfect), 12u);
}

// A 5×5×5 grid whose centre cell (2,2,2) is cut into 6 pyramids. Its 12 edges and the 8 edges to
// the centre are pseudo-singular; the faces around the 12 edges start separation surfaces that run
// straight to the boundary: the full planes x=2, x=3, y=2, y=3, z=2, z=3. They cut the grid into
// 27 boxes; the centre box is the 6 pyramids, each its own component: 26 + 6 = 32 components, the
// 26 boxes all cube-like. Sheets: per axis, the slabs [0,2], [2,3] (a ring of 8 boxes around the
// pyramids) and [3,5]: 9 sheets, all perfect (parallel curves of a slab all run across it).
TEST(Structure, SplitCellCutsFullPlanes) {
  const std::array<int32_t, 3> centre{2, 2, 2};
  const Mesh m = build_mesh(generate_split(5, 5, 5, SplitKind::Pyramids, std::span(&centre, 1)));
  ASSERT_EQ(m.num_cells(), 124u + 6u);
  const Analysis a = run(m);
  EXPECT_EQ(a.complex.num_components(), 32u);
  EXPECT_EQ(a.complex.num_hex_components(), 26u);
  EXPECT_EQ(a.complex.num_non_hex_components(), 6u);
  EXPECT_EQ(a.graph.pseudo_singular_edges.size(), 20u);
  // A face is a separation face exactly when it lies on the boundary or on one of the six planes
  // (pyramid faces inside the centre box included).
  for (size_t f = 0; f < m.num_faces(); ++f) {
    auto loop = m.face_verts[f];
    bool on_plane = false;
    for (int axis = 0; axis < 3; ++axis) {
      const double x0 = m.points[3 * loop[0] + axis];
      bool flat = true;
      for (int32_t v : loop) flat = flat && m.points[3 * v + axis] == x0;
      on_plane = on_plane || (flat && (x0 == 0 || x0 == 2 || x0 == 3 || x0 == 5));
    }
    bool pyramid = !m.is_hex(m.face_cells[f][0]) || (m.face_cells[f][1] >= 0 && !m.is_hex(m.face_cells[f][1]));
    EXPECT_EQ(a.complex.face_separation[f] != 0, on_plane || pyramid) << "face " << f;
  }
  ASSERT_EQ(a.sheet_stage->sheets.size(), 9u);
  EXPECT_EQ(a.sheet_stage->sheets.count(SheetType::Perfect), 9u);
  // The three ring sheets are the ones touching the pyramids.
  int with_non_hex = 0;
  for (size_t s = 0; s < a.sheet_stage->sheets.size(); ++s) with_non_hex += a.sheet_stage->sheets.sheet_non_hex_cells.count(s) > 0;
  EXPECT_EQ(with_non_hex, 3);
}

// Sectors around an axis: N parallelogram columns (each rings×rings×layers hexes) around a
// vertical axis whose edges have valence N. The separation surfaces are the N spoke planes from
// the axis: N components, each a cube-like column. Corners: 2 on the axis, 2 at each spoke end and
// 2 at each outer tip: 2 + 4N. Singularities: the axis (valence N), and per sector the outline
// creases: bottom and top outlines pass straight through the spoke ends (two valence-1 edges meet
// there, the vertical edge between the two sectors is regular) and are cut at the tips, where the
// vertical valence-1 tip edge starts: N bottom + N top + N vertical chains, 3N + 1 in all;
// singular vertices: 2N tips + 2 axis ends. Sheets: one vertical (all columns), and per spoke s
// one made of the two columns beside it (their directions along the spoke): N + 1, all perfect.
void check_sector(int n) {
  const Mesh m = build_mesh(generate_sector(n, 2, 3));
  const Analysis a = run(m);
  EXPECT_EQ(a.complex.num_components(), static_cast<size_t>(n));
  EXPECT_EQ(a.complex.num_hex_components(), static_cast<size_t>(n));
  EXPECT_EQ(a.complex.corners.size(), static_cast<size_t>(2 + 4 * n));
  EXPECT_EQ(a.graph.num_singularities(), static_cast<size_t>(3 * n + 1));
  EXPECT_EQ(a.graph.singular_vertices.size(), static_cast<size_t>(2 * n + 2));
  int axis_chains = 0;
  for (size_t s = 0; s < a.graph.num_singularities(); ++s)
    if (a.graph.chain_valence[s] == n && !a.graph.chain_boundary[s]) {
      ++axis_chains;
      EXPECT_EQ(a.graph.chain_edges.count(s), 3);
    }
  EXPECT_EQ(axis_chains, 1);
  EXPECT_EQ(a.sheet_stage->sheets.size(), static_cast<size_t>(n + 1));
  EXPECT_EQ(a.sheet_stage->sheets.count(SheetType::Perfect), static_cast<size_t>(n + 1));
}

TEST(Structure, SectorValence3) { check_sector(3); }
TEST(Structure, SectorValence5) { check_sector(5); }

// Component partition must not depend on numbering: renumber vertices and cells at random and
// compare the partitions (mapped back) and every order-independent count.
void check_renumbering(const Mesh& m, uint32_t seed) {
  std::mt19937 rng(seed);
  const test::Renumbering rn = test::random_renumbering(m, rng);
  const Analysis a = run(m), b = run(rn.mesh);
  test::expect_same_counts(compute_stats(m, a), compute_stats(rn.mesh, b));
  test::expect_same_partition(a.complex, b.complex, rn.cell);
}

TEST(Structure, RenumberedGeneratedMeshes) {
  const std::array<int32_t, 3> cells[] = {{1, 1, 1}, {3, 2, 0}};
  check_renumbering(build_mesh(generate_split(5, 4, 3, SplitKind::Pyramids, cells)), 1);
  check_renumbering(build_mesh(generate_split(4, 4, 4, SplitKind::Prisms, std::span(cells, 1))), 2);
  check_renumbering(build_mesh(generate_sector(5, 2, 2)), 3);
  check_renumbering(build_mesh(generate_cylinder(3, 3)), 4);
}

// Invariants on every real mesh of the shared data.
class RealMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(RealMesh, Invariants) {
  HBC_REQUIRE_DATA(GetParam());
  const Mesh m = test::load_data(GetParam());
  const Analysis a = run(m);
  const BaseComplex& bc = a.complex;
  // Every cell in exactly one component, components numbered by their lowest cell.
  std::vector<int32_t> seen(m.num_cells(), 0);
  for (size_t k = 0; k < bc.num_components(); ++k) {
    auto cells = bc.component_cells[k];
    ASSERT_FALSE(cells.empty());
    if (k > 0) EXPECT_LT(bc.component_cells[k - 1][0], cells[0]);
    for (int32_t c : cells) {
      ++seen[c];
      EXPECT_EQ(bc.cell_component[c], static_cast<int32_t>(k));
    }
  }
  for (int32_t s : seen) ASSERT_EQ(s, 1);
  // Non-hex cells stand alone; every face of a non-hex cell separates.
  for (size_t c = 0; c < m.num_cells(); ++c) {
    if (m.is_hex(c)) continue;
    EXPECT_EQ(bc.component_cells.count(bc.cell_component[c]), 1);
    for (int32_t f : m.cell_faces[c]) EXPECT_TRUE(bc.face_separation[f]);
  }
  // Faces between two cells of one component do not separate unless reported.
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const auto fc = m.face_cells[f];
    if (fc[1] < 0) {
      EXPECT_TRUE(bc.face_separation[f]);
      continue;
    }
    if (bc.cell_component[fc[0]] == bc.cell_component[fc[1]] && bc.face_separation[f])
      EXPECT_TRUE(std::binary_search(bc.self_adjacent_faces.begin(), bc.self_adjacent_faces.end(), static_cast<int32_t>(f)));
  }
  // Singular edges are irregular, all-hex; chains have one valence.
  for (size_t s = 0; s < a.graph.num_singularities(); ++s)
    for (int32_t e : a.graph.chain_edges[s]) {
      EXPECT_TRUE(a.graph.edge_irregular[e]);
      EXPECT_EQ(m.edge_valence(e), a.graph.chain_valence[s]);
    }
  // Sheets: every curve of a self-intersecting sheet is in one of its subsheets (the authors'
  // layers may overlap, and may leave one type 3: docs/validation.md); sheet curves are curves of
  // its blocks.
  for (const Subsheets& x : *a.sheet_stage->subsheets) {
    std::set<int32_t> seen;
    for (size_t i = 0; i < x.size(); ++i) seen.insert(x.curves[i].begin(), x.curves[i].end());
    const auto all = a.sheet_stage->sheets.sheet_curves[x.sheet];
    EXPECT_EQ(seen, std::set<int32_t>(all.begin(), all.end()));
  }
  for (size_t s = 0; s < a.sheet_stage->sheets.size(); ++s) {
    EXPECT_FALSE(a.sheet_stage->sheets.sheet_blocks[s].empty());
    const bool perfect = a.sheet_stage->sheets.classes[s].type == SheetType::Perfect;
    EXPECT_EQ(perfect, a.sheet_stage->sheets.classes[s].shared_vertices.empty());
    if (perfect) EXPECT_TRUE(a.sheet_stage->sheets.classes[s].unmatched_vertices.empty());
  }
}

std::vector<std::string> real_meshes() {
  return {"hybrid-base-complex/test_2.HYBRID",
          "hybrid-base-complex/cube_twist-comp.obj.HYBRID",
          "hybrid-base-complex/teapot.hedra",
          "hybrid-base-complex/twistcube_s.mesh",
          "openvolumemesh/Cube_with_props.ovm",
          "openvolumemesh/Cylinder.ovm",
          "openvolumemesh/NonManifold.ovm",
          "cinolib/eight_voronoi.hedra",
          "cinolib/ellipsoid.mesh",
          "cinolib/rockerarm.mesh",
          "hexalab-edge-cone-rectification/block_out.mesh",
          "hexalab-edge-cone-rectification/cap_out.mesh",
          "hexalab-edge-cone-rectification/bust_out.mesh",
          "hexalab-edge-cone-rectification/hanger_stresstest_out.mesh",
          "hexalab-edge-cone-rectification/dragon_out.mesh",
          "hexalab-edge-cone-rectification/armadillo_out.mesh"};
}

INSTANTIATE_TEST_SUITE_P(Shared, RealMesh, ::testing::ValuesIn(real_meshes()), [](const auto& info) {
  std::string n = std::filesystem::path(info.param).stem().string();
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
});

class RealMeshRenumbered : public ::testing::TestWithParam<std::string> {};
TEST_P(RealMeshRenumbered, SameStructure) {
  HBC_REQUIRE_DATA(GetParam());
  check_renumbering(test::load_data(GetParam()), 7);
}
INSTANTIATE_TEST_SUITE_P(Shared, RealMeshRenumbered,
                         ::testing::Values("hybrid-base-complex/teapot.hedra", "hybrid-base-complex/twistcube_s.mesh",
                                           "hybrid-base-complex/cube_twist-comp.obj.HYBRID", "cinolib/rockerarm.mesh"),
                         [](const auto& info) {
                           std::string n = std::filesystem::path(info.param).stem().string();
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

}  // namespace
}  // namespace hbc
