// The hybrid singularity graph, the base complex, the sheet domain, the sheets and the
// views at both levels split over threads: every array equals the single-threaded result. A small
// grain splits even these small meshes into many ranges, so that range boundaries fall inside
// chains, components, patches, classes and sheets.
#include <gtest/gtest.h>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

// A component's neighbours, patches, curves and corners by their definition, from the separation
// faces of its cells: the stage gathers them from its patches instead (a patch's faces all have the
// patch's components on their sides).
void expect_component_rows_from_faces(const Mesh& m, const BaseComplex& bc) {
  auto same = [](std::span<const int32_t> row, const std::vector<int32_t>& want, const char* what, size_t k) {
    EXPECT_EQ(std::vector<int32_t>(row.begin(), row.end()), want) << what << " of component " << k;
  };
  for (size_t k = 0; k < bc.num_components(); ++k) {
    std::vector<int32_t> adjacent, patches, curves, corners;
    for (int32_t c : bc.component_cells[k])
      for (int32_t f : m.cell_faces[static_cast<size_t>(c)]) {
        if (!bc.face_separation[static_cast<size_t>(f)]) continue;
        patches.push_back(bc.face_patch[static_cast<size_t>(f)]);
        const auto fc = m.face_cells[static_cast<size_t>(f)];
        const int32_t other = fc[0] == c ? fc[1] : fc[0];
        if (other >= 0 && bc.cell_component[static_cast<size_t>(other)] != static_cast<int32_t>(k))
          adjacent.push_back(bc.cell_component[static_cast<size_t>(other)]);
        for (int32_t e : m.face_edges(static_cast<size_t>(f)))
          if (bc.edge_curve[static_cast<size_t>(e)] >= 0) curves.push_back(bc.edge_curve[static_cast<size_t>(e)]);
        for (int32_t v : m.face_verts[static_cast<size_t>(f)])
          if (bc.vert_corner[static_cast<size_t>(v)]) corners.push_back(v);
      }
    for (auto* v : {&adjacent, &patches, &curves, &corners}) sort_unique(*v);
    same(bc.component_adjacency[k], adjacent, "neighbours", k);
    same(bc.component_patches[k], patches, "patches", k);
    same(bc.component_curves[k], curves, "curves", k);
    same(bc.component_corners[k], corners, "corners", k);
  }
}

// One thread against 2 and 3 (3 threads on 2 cores still run the ranges concurrently), at both
// sheet levels.
void expect_thread_independent(const Mesh& m) {
  const Threads one{1, 8};
  const SingularityGraph g = singularity_graph(m, one);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    test::expect_same(g, singularity_graph(m, Threads{threads, 8}), "the graph");
  }
  const BaseComplex bc = base_complex(m, g, one);
  expect_component_rows_from_faces(m, bc);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    const Threads par{threads, 8};
    const BaseComplex other = base_complex(m, g, par);
    test::expect_same(bc, other, "the base complex");
    {
      // The whole view, and that of every other component (a proper region: fans of the region's
      // cells, and the whole-mesh adjacency).
      SCOPED_TRACE("view");
      test::expect_same_view(complex_from_base(m, bc, one), complex_from_base(m, other, par));
      std::vector<int32_t> region;
      for (size_t k = 0; k < bc.num_components(); k += 2) region.push_back(static_cast<int32_t>(k));
      test::expect_same_view(complex_from_base(m, bc, region, one), complex_from_base(m, other, region, par));
      // The mesh-level view, whole and of the cells of those components.
      test::expect_same_view(complex_from_mesh(m, one), complex_from_mesh(m, par));
      std::vector<int32_t> cells;
      for (int32_t k : region)
        for (int32_t c : bc.component_cells[static_cast<size_t>(k)]) cells.push_back(c);
      test::expect_same_view(complex_from_mesh(m, cells, one), complex_from_mesh(m, cells, par));
    }
    for (Level level : {Level::Complex, Level::Mesh}) {
      SCOPED_TRACE(level == Level::Complex ? "complex level" : "mesh level");
      const SheetDomain d = sheet_domain(m, bc, level, one), d2 = sheet_domain(m, other, level, par);
      test::expect_same(d, d2, "the sheet domain");
      test::expect_same(extract_sheets(m, d, one), extract_sheets(m, d2, par), "the sheets");
    }
  }
}

TEST(ComplexThreads, RealMeshesGiveTheSameArraysForAnyThreadCount) {
  for (const char* rel : test::kVariedMeshes) {
    SCOPED_TRACE(rel);
    HBC_REQUIRE_DATA(rel);
    expect_thread_independent(load_mesh(test::data_path(rel)));
  }
}

// chain_edges by ranges of edges (a grain of 8: chains cross the ranges) gives the hybrid
// singularity graph's chains computed on one thread: cut where the valence changes and at
// pseudo-singular vertices, closed loops included.
TEST(ComplexThreads, ChainsAreTheSameForAnyThreadCount) {
  for (const char* rel : test::kVariedMeshes) {
    SCOPED_TRACE(rel);
    HBC_REQUIRE_DATA(rel);
    const Mesh m = load_mesh(test::data_path(rel));
    const SingularityGraph g = singularity_graph(m, Threads{1});
    std::vector<uint8_t> singular(m.num_edges());
    std::vector<int32_t> valence(m.num_edges());
    for (size_t e = 0; e < m.num_edges(); ++e) {
      singular[e] = g.edge_class[e] == EdgeClass::Singular;
      valence[e] = m.edge_valence(e);
    }
    for (int threads : {1, 2, 3}) {
      SCOPED_TRACE(threads);
      Csr<int32_t> verts, edges;
      std::vector<uint8_t> closed;
      chain_edges(m, singular, valence, g.vert_pseudo_singular, verts, edges, closed, Threads{threads, 8});
      test::expect_same_csr(verts, g.chain_verts, "chain_verts");
      test::expect_same_csr(edges, g.chain_edges, "chain_edges");
      EXPECT_EQ(closed, g.chain_closed);
    }
  }
}

// With few member edges (under one per 64 vertices) chain_edges gives rows to their vertices only:
// a grid's singular edges run along its box's 12 edges (12 * 40 of them, 68,921 vertices), 12
// chains cut at the corners. With 1-3 threads, the graph's chains equal those walked with a row
// for every vertex.
TEST(ComplexThreads, ChainsOfFewMembersEqualThoseOverEveryVertex) {
  const Mesh m = build_mesh(generate_grid(40, 40, 40));
  const SingularityGraph g = singularity_graph(m, Threads{1});
  ASSERT_EQ(g.num_singularities(), 12u);
  ASSERT_LT(g.num_singular_edges() * 64, m.num_vertices());  // the rows of few vertices
  std::vector<uint8_t> singular(m.num_edges());
  std::vector<int32_t> valence(m.num_edges());
  for (size_t e = 0; e < m.num_edges(); ++e) {
    singular[e] = g.edge_class[e] == EdgeClass::Singular;
    valence[e] = m.edge_valence(e);
  }
  const Csr<int32_t> every_vertex = vertex_edges(m, singular);
  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    Csr<int32_t> verts, edges;
    std::vector<uint8_t> closed;
    chain_edges(m.edge_verts, every_vertex, singular, valence, g.vert_pseudo_singular, verts, edges, closed,
                Threads{threads, 8});
    const SingularityGraph sparse = singularity_graph(m, Threads{threads, 8});
    test::expect_same_csr(verts, sparse.chain_verts, "chain_verts");
    test::expect_same_csr(edges, sparse.chain_edges, "chain_edges");
    EXPECT_EQ(closed, sparse.chain_closed);
  }
}

TEST(ComplexThreads, GeneratedMeshesGiveTheSameArraysForAnyThreadCount) {
  // The all-singleton worst case (a grid with about 1 % of its cells split into pyramids) and a
  // hex-dominant cylinder with large components.
  std::vector<std::array<int, 3>> split;
  for (int i = 0; i < 12 * 12 * 12; i += 97) split.push_back({i % 12, i / 12 % 12, i / 144});
  expect_thread_independent(build_mesh(generate_split(12, 12, 12, SplitKind::Pyramids, split)));
  expect_thread_independent(build_mesh(generate_cylinder(6, 8)));
}

}  // namespace
}  // namespace hbc
