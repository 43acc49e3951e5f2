#pragma once
// Cell depth: how many cell layers lie between a cell and the boundary, for peeling the mesh open
// layer by layer (HexaLab's "peeling"; the add-on's per-cell depth attribute).
//
// depth(c) = 0 when c has a boundary vertex (touching the boundary by a face, an edge or only a
// vertex), else 1 + the minimum depth of the cells sharing a face with c: the breadth-first
// distance over face neighbours from the cells with a boundary vertex. Hiding the cells with
// depth < k removes k whole layers: on an n×n×n grid the cells of depth >= k are the inner
// (n-2k)×(n-2k)×(n-2k) cube of cells. Vertices rather than faces, so that peeling one layer leaves no
// cell with a point on the boundary: on a box both rules agree, but at a concave edge or corner of
// the boundary a cell can touch it along an edge or at a vertex only. A cell whose face-connected
// group has no boundary vertex (impossible for a finite mesh, kept for safety) gets -1.
#include <cstdint>
#include <vector>

#include "hbc/mesh.hpp"

namespace hbc {

// nc entries; deterministic (a breadth-first distance does not depend on the visiting order).
std::vector<int32_t> cell_depth(const Mesh& mesh);

}  // namespace hbc
