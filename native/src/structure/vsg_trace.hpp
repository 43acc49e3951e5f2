#pragma once
// The complete VSG wireframe (paper §5: "tracing along all mesh edges from the individual singular
// vertices until they end at another singularity or at the boundary"): vsg_trace.cpp.
#include <cstdint>
#include <vector>

#include "hbc/vsg_wireframe.hpp"
#include "structure/vsg_chains.hpp"

namespace hbc::vsg {

// Faces reached by the flood from the faces at `start` edges (see vsg_trace.cpp).
std::vector<uint8_t> flood_faces(const Region& r, const std::vector<uint8_t>& start, const Threads& par);
// Singular vertices of the complete wireframe: ends of patch edges (all faces flooded or on the
// boundary) with a patch-edge count other than 0 and 2, or two patch edges sharing a face.
std::vector<uint8_t> patch_singular_vertices(const Region& r, const std::vector<uint8_t>& flooded, const Threads& par);
// The complete wireframe's per-chain arrays of `w` (edges, polylines, ends, kind, valence, stop)
// from its chains; w.edge_vsg and w.vert_singular are read.
void fill_complete(const Region& r, const Chains& ch, const Threads& par, VsgWireframe& w);

}  // namespace hbc::vsg
