#pragma once
// Presentation of a VSG wireframe (paper §6.2), a step separate from the graph (vsg_wireframe.hpp):
// per-point opacity and per-chain colours.
//
// point_opacity (aligned with w.polylines.items): 1 on VSG chains and on chains with an edge
// touching a non-hex cell; elsewhere max(floor, 1 - (1 - floor) d / opacity_hops), d = mesh-edge
// hops along the complex's edges to the nearest point of an irregular edge or of an edge touching
// a non-hex cell.
// color_class (per chain): the lowest chain of a union of partial-parallel pairs (Definition 1
// parallels over quad faces, both fractions >= rho); color: a palette index, classes holding chains
// that share a mesh vertex getting different colours when the palette allows.
#include "hbc/cell_complex.hpp"
#include "hbc/vsg_wireframe.hpp"

namespace hbc {

// Fills w.point_opacity, w.color_class and w.color from the graph part of `w`.
void apply_wireframe_style(const CellComplex& complex, const WireframeOptions& options, VsgWireframe& w);

}  // namespace hbc
