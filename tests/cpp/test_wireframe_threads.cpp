// The VSG wireframe and its style split over threads: every array equals the single-threaded
// result, at both levels, on real meshes and on the all-singleton worst case (a grid with about
// 1 % of its cells split into pyramids, every cell a base-complex component of its own).
#include <array>
#include <string>
#include <vector>

#include "hbc/base_complex.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/generate.hpp"
#include "hbc/io.hpp"
#include "hbc/singularity_graph.hpp"
#include "hbc/vsg_wireframe.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

void expect_same_wireframe(const VsgWireframe& a, const VsgWireframe& b) {
  EXPECT_EQ(a.edge_vsg, b.edge_vsg);
  EXPECT_EQ(a.vert_vsg, b.vert_vsg);
  test::expect_same_csr(a.vsg_chain_edges, b.vsg_chain_edges, "vsg_chain_edges");
  EXPECT_EQ(a.vsg_edges, b.vsg_edges);
  EXPECT_EQ(a.vsg_chains, b.vsg_chains);
  EXPECT_EQ(a.vert_singular, b.vert_singular);
  EXPECT_EQ(a.singular_vertices, b.singular_vertices);
  test::expect_same_csr(a.edges, b.edges, "edges");
  test::expect_same_csr(a.polylines, b.polylines, "polylines");
  EXPECT_EQ(a.ends, b.ends);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.valence, b.valence);
  EXPECT_EQ(a.stop, b.stop);
  EXPECT_EQ(a.vert_non_important, b.vert_non_important);
  EXPECT_EQ(a.non_important, b.non_important);
  EXPECT_EQ(a.reactivated, b.reactivated);
  EXPECT_EQ(a.shown, b.shown);
  test::expect_same_csr(a.simplified_edges, b.simplified_edges, "simplified_edges");
  test::expect_same_csr(a.simplified_polylines, b.simplified_polylines, "simplified_polylines");
  EXPECT_EQ(a.vsg_mesh_edges, b.vsg_mesh_edges);
  EXPECT_EQ(a.wireframe_mesh_edges, b.wireframe_mesh_edges);
  EXPECT_EQ(a.simplified_mesh_edges, b.simplified_mesh_edges);
  EXPECT_EQ(a.reference_components, b.reference_components);
  EXPECT_EQ(a.shown_components, b.shown_components);
  EXPECT_EQ(a.style.point_opacity, b.style.point_opacity);
  EXPECT_EQ(a.style.color_class, b.style.color_class);
  EXPECT_EQ(a.style.color, b.style.color);
}

// A grain of 16 splits even small complexes into ranges, so range boundaries fall inside every
// pass; 3 threads on 2 cores still run the ranges concurrently.
void expect_thread_independent(const CellComplex& cx) {
  const VsgWireframe one = vsg_wireframe(cx, {}, Threads{1, 16});
  EXPECT_GT(one.size(), 0u);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    expect_same_wireframe(one, vsg_wireframe(cx, {}, Threads{threads, 16}));
  }
}

void expect_thread_independent(const Mesh& m) {
  {
    SCOPED_TRACE("mesh level");
    expect_thread_independent(complex_from_mesh(m));
  }
  SCOPED_TRACE("complex level");
  expect_thread_independent(complex_from_base(m, base_complex(m, singularity_graph(m))));
}

TEST(WireframeThreads, EveryArrayEqualsTheSingleThreadedResult) {
  for (const char* rel : {"hexalab-edge-cone-rectification/armadillo_out.mesh", "cinolib/rockerarm.mesh",
                          "hybrid-base-complex/twistcube_s.mesh", "hybrid-base-complex/test_2.HYBRID",
                          "cinolib/eight_voronoi.hedra", "openvolumemesh/Cylinder.ovmb"}) {
    SCOPED_TRACE(rel);
    HBC_REQUIRE_DATA(rel);
    expect_thread_independent(test::load_data(rel));
  }
}

TEST(WireframeThreads, AllSingletonSplitGrid) {
  std::vector<std::array<int, 3>> split;
  for (int i = 0; i < 14 * 14 * 14; i += 97) split.push_back({i % 14, i / 14 % 14, i / 196});
  expect_thread_independent(build_mesh(generate_split(14, 14, 14, SplitKind::Pyramids, split)));
}

}  // namespace
}  // namespace hbc
