// What analyze_stats frees early on a given-up mesh: release_unanalyzed() keeps num_vertices() and
// every stage result from the singularity graph to the complex-level view's facts and the sheets;
// the statistics stay the same for the option mixes test_stats_memory does not cover; and
// chain_edges without edge values chains as with one value everywhere (the base complex's curves).
#include <tuple>
#include <utility>

#include "hbc/analysis.hpp"
#include "hbc/cell_complex.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

void expect_same_facts(const BaseViewFacts& a, const BaseViewFacts& b) {
  EXPECT_EQ(a.num_mesh_vertices, b.num_mesh_vertices);
  EXPECT_EQ(std::tie(a.component_in, a.patch_in, a.patch_quad, a.curve_in, a.curve_valence, a.curve_boundary),
            std::tie(b.component_in, b.patch_in, b.patch_quad, b.curve_in, b.curve_valence, b.curve_boundary));
  EXPECT_EQ(std::tie(a.corners, a.corner_boundary, a.corner_cells, a.corner_all_quad),
            std::tie(b.corners, b.corner_boundary, b.corner_cells, b.corner_all_quad));
}

TEST(StatsRelease, ReleasedMeshGivesTheSameStages) {
  for (const char* file : test::kVariedMeshes) {
    SCOPED_TRACE(file);
    HBC_REQUIRE_DATA(file);
    const Mesh m = test::load_data(file);
    Mesh r = m;
    release_unanalyzed(r);
    EXPECT_TRUE(r.points.empty());
    EXPECT_EQ(r.num_vertices(), m.num_vertices());
    const SingularityGraph g = singularity_graph(m), gr = singularity_graph(r);
    EXPECT_EQ(gr.edge_class, g.edge_class);
    test::expect_same_csr(gr.chain_edges, g.chain_edges, "chain_edges");
    const BaseComplex bc = base_complex(m, g), bcr = base_complex(r, gr);
    EXPECT_EQ(bcr.cell_component, bc.cell_component);
    EXPECT_EQ(bcr.face_patch, bc.face_patch);
    EXPECT_EQ(bcr.component_kind, bc.component_kind);
    test::expect_same_csr(bcr.curve_verts, bc.curve_verts, "curve_verts");
    test::expect_same_csr(bcr.component_corners, bc.component_corners, "component_corners");
    expect_same_facts(base_view_facts(r, bcr), base_view_facts(m, bc));
    const Sheets s = extract_sheets(m, sheet_domain(m, bc, Level::Complex));
    const Sheets sr = extract_sheets(r, sheet_domain(r, bcr, Level::Complex));
    test::expect_same_csr(sr.sheet_cells, s.sheet_cells, "sheet_cells");
    test::expect_same_csr(sr.sheet_edges, s.sheet_edges, "sheet_edges");
  }
}

// Sheets of either level without a wireframe, and the complex-level wireframe under mesh-level
// sheets: the given-up mesh loses what no stage of the run reads.
TEST(StatsRelease, GivenUpMeshWithoutTheMeshLevelView) {
  for (const char* file : {"cinolib/rockerarm.mesh", "hybrid-base-complex/twistcube_s.mesh",
                           "openvolumemesh/NonManifold.ovm"}) {
    SCOPED_TRACE(file);
    HBC_REQUIRE_DATA(file);
    const Mesh m = test::load_data(file);
    for (int variant = 0; variant < 3; ++variant) {
      SCOPED_TRACE(variant);
      AnalysisOptions opt;
      opt.threads = 2;
      opt.sheet_level = variant == 2 ? Level::Complex : Level::Mesh;
      opt.wireframe = variant == 1;
      const Stats want = compute_stats(m, analyze(m, opt));
      Mesh copy = m;
      const StatsRun given = analyze_stats(std::move(copy), opt);
      test::expect_same_counts(given.stats, want);
      EXPECT_EQ(given.stats.wireframe_edges_simplified, want.wireframe_edges_simplified);
      EXPECT_EQ(given.stats.subsheets_of_largest_self_intersecting, want.subsheets_of_largest_self_intersecting);
    }
  }
}

TEST(StatsRelease, ChainsWithoutValuesAreChainsOfOneValue) {
  for (const char* file : {"cinolib/rockerarm.mesh", "cinolib/eight_voronoi.hedra"}) {
    SCOPED_TRACE(file);
    HBC_REQUIRE_DATA(file);
    const Mesh m = test::load_data(file);
    const BaseComplex bc = base_complex(m, singularity_graph(m));
    Csr<int32_t> verts, edges, verts0, edges0;
    std::vector<uint8_t> closed, closed0;
    chain_edges(m, bc.edge_complex, {}, bc.vert_corner, verts, edges, closed);
    chain_edges(m, bc.edge_complex, std::vector<int32_t>(m.num_edges(), 7), bc.vert_corner, verts0, edges0, closed0);
    ASSERT_GT(edges.rows(), 0u);
    test::expect_same_csr(verts, verts0, "verts");
    test::expect_same_csr(edges, edges0, "edges");
    EXPECT_EQ(closed, closed0);
  }
}

}  // namespace
}  // namespace hbc
