#pragma once
// Presentation of a VSG wireframe (paper §6.2), the render layer's step after the analysis
// (vsg_wireframe.hpp): per-point opacity and per-chain colours, a pure function of the wireframe,
// its view and the style options, so that a new ρ restyles a wireframe without analysing again.
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

#include "hbc/cell_complex.hpp"
#include "hbc/threads.hpp"
#include "hbc/vsg_wireframe.hpp"

namespace hbc {

struct WireframeStyleOptions {
  // Partial-parallel threshold of the colour classes (paper §6.2, Definition 2): it sets the
  // classes and colours only, and no count of the analysis depends on it.
  double rho = 0.8;
  double opacity_floor = 0.15;  // opacity far from irregular edges and non-hex cells
  int32_t opacity_hops = 6;     // mesh-edge hops over which opacity falls from 1 to the floor
  int32_t palette_size = 8;     // colours available to the greedy colouring
};

struct WireframeStyle {
  std::vector<float> point_opacity;  // aligned with the wireframe's polylines.items
  std::vector<int32_t> color_class;  // per chain
  std::vector<int32_t> color;        // per chain, in [0, palette_size)

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const WireframeStyle&) const = default;
};

// The style of wireframe `w`, computed on `complex`, the view it was computed on (for an
// Analysis, its WireframeStage; for a region, region_wireframe_stage). `threads`: see
// threads.hpp; the result is the same for any thread count.
WireframeStyle wireframe_style(const CellComplex& complex, const VsgWireframe& w,
                               const WireframeStyleOptions& options = {}, const Threads& threads = {});

}  // namespace hbc
