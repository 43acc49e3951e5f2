// analyze_stats' memory-saving path: the complex-level view built from the base complex and the
// facts taken from the mesh beforehand (no mesh), from a base complex stripped to what it reads,
// equals the view complex_from_base builds from the mesh; and a mesh given up to analyze_stats
// (freed on the way) changes none of the statistics.
#include <tuple>
#include <utility>

#include "hbc/analysis.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/generate.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

const char* const kFiles[] = {
    "hybrid-base-complex/teapot.hedra",
    "hybrid-base-complex/twistcube_s.mesh",
    "hybrid-base-complex/cube_twist-comp.obj.HYBRID",
    "hybrid-base-complex/test_2.HYBRID",
    "cinolib/rockerarm.mesh",
    "hexalab-edge-cone-rectification/block_out.mesh",
};

// Only the arrays complex_from_base(bc, facts) promises to read.
BaseComplex stripped_for_view(const BaseComplex& bc) {
  BaseComplex s;
  s.component_kind = bc.component_kind;
  s.patch_curves = bc.patch_curves;
  s.patch_components = bc.patch_components;
  s.curve_verts = bc.curve_verts;
  s.curve_closed = bc.curve_closed;
  s.component_curves = bc.component_curves;
  return s;
}

TEST(StatsMemory, ViewFromFactsMatchesViewFromMesh) {
  for (const char* file : kFiles) {
    SCOPED_TRACE(file);
    HBC_REQUIRE_DATA(file);
    const Mesh m = test::load_data(file);
    const BaseComplex bc = base_complex(m, singularity_graph(m));
    const BaseViewFacts facts = base_view_facts(m, bc);
    EXPECT_TRUE(facts.whole());
    const CellComplex from_facts = complex_from_base(stripped_for_view(bc), facts);
    EXPECT_TRUE(from_facts.whole());
    test::expect_same_view(from_facts, complex_from_base(m, bc));
  }
}

TEST(StatsMemory, ViewFromFactsWantsTheWholeComplex) {
  const Mesh m = build_mesh(generate_cylinder(4, 3));
  const BaseComplex bc = base_complex(m, singularity_graph(m));
  ASSERT_GT(bc.num_components(), 1u);
  const int32_t first[] = {0};
  const BaseViewFacts facts = base_view_facts(m, bc, first);
  EXPECT_FALSE(facts.whole());
  EXPECT_THROW(complex_from_base(bc, facts), std::invalid_argument);
}

auto counts(const Stats& s) {
  return std::make_tuple(s.cells, s.hex_cells, s.hex_ratio, s.singular_edges, s.singularities, s.pseudo_singular_edges,
                         s.non_manifold_edges, s.singular_vertices, s.components, s.hex_components,
                         s.hex_component_ratio, s.patches, s.curves, s.corners, s.self_adjacent_faces, s.sheets,
                         s.sheets_perfect, s.sheets_type1, s.sheets_type2, s.sheets_type3,
                         s.subsheets_of_largest_self_intersecting, s.vsg_edges, s.wireframe_edges,
                         s.wireframe_edges_simplified);
}

std::vector<std::tuple<int32_t, int32_t, int64_t>> subsheet_rows(const StatsRun& run) {
  std::vector<std::tuple<int32_t, int32_t, int64_t>> out;
  for (const SubsheetCount& x : run.subsheet_counts) out.push_back({x.sheet, x.blocks, x.subsheets});
  return out;
}

// Every variant of the CLI's options: both levels, stages skipped.
TEST(StatsMemory, GivenUpMeshGivesTheSameStatistics) {
  for (const char* file : kFiles) {
    SCOPED_TRACE(file);
    HBC_REQUIRE_DATA(file);
    const Mesh m = test::load_data(file);
    for (int variant = 0; variant < 5; ++variant) {
      SCOPED_TRACE(variant);
      AnalysisOptions opt;
      if (variant == 1) opt.sheet_level = opt.wireframe_level = Level::Mesh;
      if (variant == 4) opt.wireframe_level = Level::Mesh;
      opt.wireframe = variant != 2;
      opt.sheets = variant != 3;
      const Stats want = compute_stats(m, analyze(m, opt));
      const StatsRun kept = analyze_stats(m, opt);
      Mesh copy = m;
      const StatsRun given = analyze_stats(std::move(copy), opt);
      EXPECT_EQ(counts(kept.stats), counts(want));
      EXPECT_EQ(counts(given.stats), counts(want));
      EXPECT_EQ(subsheet_rows(given), subsheet_rows(kept));
    }
  }
}

}  // namespace
}  // namespace hbc
