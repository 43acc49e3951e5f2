// Structural complexity metrics (metrics.hpp, docs/metrics.md) on small meshes whose values are
// derived by hand in the comments.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "hbc/metrics.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

Metrics metrics_of(const MeshInput& in, const Threads& threads = {}) {
  const Mesh m = build_mesh(in);
  AnalysisOptions o;
  o.wireframe = false;
  return compute_metrics(m, analyze(m, o), threads);
}

// A 2×2×2 grid of unit hexes: one box. Its 12 box edges are boundary edges of valence 1 (2 mesh
// edges each): 24 boundary singular edges in 12 curves cut at the 8 box corners, each curve 2 edges
// long with both ends on the boundary; length 12·2 / diagonal √12. One cube component (8 corners,
// 12 curves, 6 patches) of 8 cells, through which 3 perfect sheets run, pairwise intersecting in
// that block: 3 connected pairs. No non-hex cell; the summary is 0 (one perfect box).
TEST(Metrics, BoxOfHexes) {
  const Metrics m = metrics_of(generate_grid(2, 2, 2));
  EXPECT_EQ(m.value("census", "cells"), 8);
  EXPECT_EQ(m.value("census", "hex_ratio"), 1);
  EXPECT_DOUBLE_EQ(m.value("census", "hex_volume_ratio"), 1);
  EXPECT_EQ(m.value("singular", "edges_interior"), 0);
  EXPECT_EQ(m.value("singular", "edges_boundary"), 24);
  EXPECT_EQ(m.singular_valence_boundary, (std::vector<int64_t>{0, 24}));
  EXPECT_EQ(m.value("singular", "singularities"), 12);
  EXPECT_EQ(m.value("singular", "singularities_boundary_ends"), 12);
  EXPECT_EQ(m.value("singular", "singularities_on_boundary"), 12);
  EXPECT_EQ(m.value("singular", "singularities_closed"), 0);
  EXPECT_EQ(m.value("singular", "singularity_edges_max"), 2);
  EXPECT_DOUBLE_EQ(m.value("singular", "length"), 24 / std::sqrt(12.0));
  EXPECT_EQ(m.value("singular", "singular_vertices"), 8);
  // The deprecated keys read the same values (metric_aliases).
  EXPECT_EQ(m.value("singular", "nodes"), 8);
  EXPECT_EQ(m.value("singular", "curves"), 12);
  EXPECT_EQ(m.value("complex", "hex_components"), 1);
  EXPECT_EQ(m.value("complex", "cube_components"), 1);
  EXPECT_EQ(m.value("complex", "corners"), 8);
  EXPECT_EQ(m.value("complex", "curves"), 12);
  EXPECT_EQ(m.value("complex", "patches"), 6);
  EXPECT_EQ(m.value("complex", "component_cells_median"), 8);
  EXPECT_EQ(m.value("complex", "largest_tenth_share"), 1);
  EXPECT_EQ(m.value("sheets", "sheets"), 3);
  EXPECT_EQ(m.value("sheets", "perfect"), 3);
  EXPECT_EQ(m.value("sheets", "perfect_cell_share"), 1);
  EXPECT_EQ(m.value("sheets", "connectivity_complexity"), 3);
  EXPECT_EQ(m.value("non_hex", "cells"), 0);
  EXPECT_EQ(m.value("non_hex", "regions"), 0);
  EXPECT_TRUE(std::isnan(m.value("non_hex", "boundary_share")));  // a share of no cell
  EXPECT_DOUBLE_EQ(m.value("quality", "sj_min"), 1);
  EXPECT_EQ(m.value("summary", "score"), 0);
  EXPECT_TRUE(std::isnan(m.value("summary", "no_such_metric")));
}

// A 3×3×3 grid whose centre cell is split into 6 pyramids around its centre: 26 hexes and 6
// pyramids (32 cells), hex ratio 26/32, hex volume 26 of 27. The pyramids form one face-connected
// region of 6 cells, none with a boundary face; each is a non-hex component of its own.
TEST(Metrics, PyramidsInTheCentre) {
  const std::array<std::array<int32_t, 3>, 1> centre{{{1, 1, 1}}};
  const Metrics m = metrics_of(generate_split(3, 3, 3, SplitKind::Pyramids, centre));
  EXPECT_EQ(m.value("census", "cells"), 32);
  EXPECT_EQ(m.value("census", "pyramids"), 6);
  EXPECT_DOUBLE_EQ(m.value("census", "hex_ratio"), 26.0 / 32.0);
  EXPECT_NEAR(m.value("census", "hex_volume_ratio"), 26.0 / 27.0, 1e-12);
  EXPECT_EQ(m.value("non_hex", "cells"), 6);
  EXPECT_EQ(m.value("non_hex", "regions"), 1);
  EXPECT_EQ(m.non_hex_region_cells, (std::vector<int32_t>{6}));
  EXPECT_EQ(m.value("non_hex", "boundary_share"), 0);
  EXPECT_EQ(m.value("complex", "non_hex_components"), 6);
  EXPECT_NEAR(m.summary_vector[0], 1.0 / 27.0, 1e-12);  // the non-hex volume share
}

// Two opposite corner cells of a 3×3×3 grid split into pyramids: two regions of 6. A corner cell
// has 3 of its 6 quads on the boundary, and each pyramid stands on one quad (its apex is the
// cell's centre), so 3 of each 6 pyramids touch the boundary: share 6/12.
TEST(Metrics, PyramidsInTwoCorners) {
  const std::array<std::array<int32_t, 3>, 2> corners{{{0, 0, 0}, {2, 2, 2}}};
  const Metrics m = metrics_of(generate_split(3, 3, 3, SplitKind::Pyramids, corners));
  EXPECT_EQ(m.value("non_hex", "regions"), 2);
  EXPECT_EQ(m.non_hex_region_cells, (std::vector<int32_t>{6, 6}));
  EXPECT_EQ(m.value("non_hex", "region_cells_max"), 6);
  EXPECT_EQ(m.value("non_hex", "boundary_share"), 0.5);
}

// A valence-5 sector, 2 layers: the 2 axis edges are interior edges of valence 5, one singular
// curve off the boundary (from the bottom face to the top one: both ends on the boundary).
TEST(Metrics, ValenceFiveSector) {
  const Metrics m = metrics_of(generate_sector(5, 1, 2));
  EXPECT_EQ(m.value("singular", "edges_interior"), 2);
  EXPECT_EQ(m.singular_valence_interior, (std::vector<int64_t>{0, 0, 0, 0, 0, 2}));
  EXPECT_EQ(m.value("singular", "singularities") - m.value("singular", "singularities_on_boundary"), 1);
  EXPECT_EQ(m.value("singular", "singularities_interior_ends"), 0);
  EXPECT_NEAR(m.summary_vector[1], std::log10(2.0), 1e-12);  // the summary is rounded to 1e-12
}

// The same metrics for any thread count (the volumes and scaled Jacobians are split over threads).
TEST(Metrics, SameForAnyThreadCount) {
  const MeshInput in = generate_twisted_pair(4, 8);
  const Metrics one = metrics_of(in, Threads{1, 1, nullptr});
  const Metrics four = metrics_of(in, Threads{4, 1, nullptr});
  ASSERT_EQ(one.values.size(), four.values.size());
  for (size_t i = 0; i < one.values.size(); ++i) {
    if (std::isnan(one.values[i])) {
      EXPECT_TRUE(std::isnan(four.values[i])) << metric_fields()[i].key;
    } else {
      EXPECT_EQ(one.values[i], four.values[i]) << metric_fields()[i].key;
    }
  }
  EXPECT_EQ(one.summary_vector, four.summary_vector);
}

// Every field has a distinct group.key, and metric_index finds it.
TEST(Metrics, FieldsAreDistinct) {
  const auto fields = metric_fields();
  for (size_t i = 0; i < fields.size(); ++i)
    EXPECT_EQ(metric_index(fields[i].group, fields[i].key), static_cast<int>(i)) << fields[i].key;
}

}  // namespace
}  // namespace hbc
