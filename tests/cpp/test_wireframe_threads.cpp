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
#include "hbc/wireframe_style.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

// A grain of 16 splits even small complexes into ranges, so range boundaries fall inside every
// pass; 3 threads on 2 cores still run the ranges concurrently.
void expect_thread_independent(const CellComplex& cx) {
  const VsgWireframe one = vsg_wireframe(cx, {}, Threads{1, 16});
  EXPECT_GT(one.size(), 0u);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    test::expect_same(one, vsg_wireframe(cx, {}, Threads{threads, 16}), "the wireframe");
  }
  // The style, a render step of its own, split over threads too.
  const WireframeStyle style = wireframe_style(cx, one, {}, Threads{1, 16});
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    EXPECT_TRUE(style == wireframe_style(cx, one, {}, Threads{threads, 16})) << "the style";
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
