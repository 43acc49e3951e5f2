#pragma once
// Presentation of a VSG wireframe (paper §6.2), a step separate from the graph (vsg_wireframe.hpp):
// per-point opacity and per-chain colours, computed from the graph and never read by it.
//
// point_opacity (aligned with w.polylines.items): 1 on chains of VSG edges and on chains with an
// edge touching a non-hex cell; elsewhere max(floor, 1 - (1 - floor) d / opacity_hops), d = mesh-edge
// hops along the complex's edges to the nearest point of an irregular edge or of an edge touching
// a non-hex cell.
// color_class (per chain): the lowest chain of a union of partial-parallel pairs (Definition 1
// parallels over quad faces, both fractions >= rho); color: a palette index, classes holding chains
// that share a mesh vertex getting different colours when the palette allows.
#include <cstdint>
#include <vector>

namespace hbc {

struct CellComplex;
struct VsgWireframe;
struct WireframeOptions;
struct Threads;

struct WireframeStyle {
  std::vector<float> point_opacity;  // aligned with the wireframe's polylines.items
  std::vector<int32_t> color_class;  // per chain
  std::vector<int32_t> color;        // per chain, in [0, palette_size)

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const WireframeStyle&) const = default;
};

// `threads`: see threads.hpp.
WireframeStyle wireframe_style(const CellComplex& complex, const VsgWireframe& w, const WireframeOptions& options,
                               const Threads& threads);

}  // namespace hbc
