#pragma once
// The valence singularity graph (VSG) and its simplified wireframe (paper §5, §6.2; SPEC §4),
// computed on a CellComplex (fine mesh or base complex, whole or restricted to a region).
//
// VSG: every irregular edge of the complex (interior valence != 4, boundary != 2), whatever its
// cells, chained by equal valence; chains are cut at branch points and valence changes only. The
// ends of open chains are the VSG's singular vertices.
// Wireframe: the VSG chains plus traces: from each singular vertex, each incident non-VSG edge
// followed straight through vertices off the VSG (interior: the unique edge sharing no cell with
// the incoming one; boundary edge: the unique boundary edge sharing no cell with it) until a VSG
// vertex, the boundary (an interior trace touching a boundary vertex), or no unique continuation.
// Simplification: the paper's three criteria, then reactivation (see VsgWireframe::reactivated).
#include <array>
#include <cstdint>
#include <vector>

#include "hbc/cell_complex.hpp"
#include "hbc/csr.hpp"

namespace hbc {

struct WireframeOptions {
  double rho = 0.8;             // partial-parallel threshold for colour classes
  double opacity_floor = 0.15;  // opacity far from irregular edges and non-hex cells
  int32_t opacity_hops = 6;     // mesh-edge hops over which opacity falls from 1 to the floor
  int32_t palette_size = 8;     // colours available to the greedy colouring
};

enum class WireKind : uint8_t { Vsg = 0, Trace = 1 };
// Why a trace ended at its last vertex.
enum class TraceStop : uint8_t { None = 0, VsgVertex = 1, Boundary = 2, NoContinuation = 3 };

struct VsgWireframe {
  // ---- VSG (ids of the CellComplex) ----
  std::vector<uint8_t> edge_vsg;           // ne: irregular edge
  std::vector<uint8_t> vert_vsg;           // nv: end of an irregular edge
  std::vector<uint8_t> vert_singular;      // nv: end of an open VSG chain
  std::vector<int32_t> singular_vertices;  // sorted complex vertex ids
  int64_t vsg_edges = 0;                   // irregular edges at the chosen level (= VSG complex edges)
  int64_t vsg_chains = 0;                  // wireframe edges of kind Vsg

  // ---- Wireframe edges: the VSG chains first (in chain order), then the traces ----
  // Row w of `edges` lists complex edges in order along it; row w of `polylines` the mesh vertices
  // along it (a closed VSG chain repeats its first vertex at the end). ends[w] are the complex
  // vertices at its two ends ({-1,-1} for a closed chain); a trace starts at ends[w][0].
  Csr<int32_t> edges;
  Csr<int32_t> polylines;
  std::vector<std::array<int32_t, 2>> ends;
  std::vector<WireKind> kind;
  std::vector<int32_t> valence;            // per wire edge: chain valence; traces the valence of
                                           // their (regular) edges, 4 inside or 2 on the boundary
  std::vector<TraceStop> stop;             // per wire edge (None for VSG chains)

  // ---- Simplification ----
  std::vector<uint8_t> vert_non_important; // nv: not singular, or a boundary corner (one cell)
                                           // whose faces are all quads
  // Per wire edge: 0 = important, else the lowest criterion (1, 2, 3) that marked it.
  std::vector<uint8_t> non_important;
  // Per wire edge: non-important but shown again. R = the VSG chains plus the traces joining two
  // VSG vertices; within each connected component of R the shown edges are joined into one
  // connected piece by the cheapest paths of hidden R edges (first those touching a shown VSG
  // chain, then fewer mesh edges, then lowest index). Connectivity is through shared mesh
  // vertices anywhere along the polylines.
  std::vector<uint8_t> reactivated;
  std::vector<uint8_t> shown;              // important or reactivated
  int64_t reference_components = 0;       // connected components of R
  int64_t shown_components = 0;           // connected components of the shown edges

  // ---- Presentation ----
  // Aligned with polylines.items: 1 on VSG chains and on traces with an edge touching a non-hex
  // cell; elsewhere max(floor, 1 - (1 - floor) d / opacity_hops), d = mesh-edge hops along the
  // complex's edges to the nearest point of an irregular edge or of an edge touching a non-hex cell.
  std::vector<float> point_opacity;
  // Per wire edge: colour class (lowest wire edge of a union of partial-parallel pairs, Definition
  // 1 parallels over quad faces, both fractions >= rho) and a palette index; classes holding wire
  // edges that share a mesh vertex get different colours when the palette allows.
  std::vector<int32_t> color_class;
  std::vector<int32_t> color;

  size_t size() const { return kind.size(); }
  int64_t wireframe_edges() const { return static_cast<int64_t>(kind.size()); }
  int64_t wireframe_edges_simplified() const;
};

VsgWireframe vsg_wireframe(const CellComplex& complex, const WireframeOptions& options = {});

}  // namespace hbc
