#pragma once
// The valence singularity graph (VSG) and its wireframe (paper §5, §6.2; docs/concepts.md), computed on
// a CellComplex view (fine mesh or base complex, whole or restricted to a region), by the rules of
// the authors' implementation (which made the paper's figures; docs/validation.md compares the two):
//
// VSG: seed edges are the valence-irregular edges (region valence = distinct region cells; interior
// != 4, boundary != 2). From each seed both ways, a chain continues through a vertex along the one
// edge there sharing no face with the current one, if it has the same valence. The ends of open
// chains are the VSG's vertices.
// Complete wireframe: faces are flooded from every face at a chain edge or at an edge of a VSG
// vertex, across edges that stop nothing (not boundary; at mesh level also not irregular and not
// touching a non-hex cell) into the faces sharing no cell with the current one. Edges whose faces
// are all flooded or boundary are "patch edges"; a vertex is singular when it has a number of patch
// edges other than 0 and 2, or 2 that share a face (a turn). The wireframe is then the chains
// traced (the VSG rule, stopping at singular vertices) from every edge at a singular vertex.
// (As in the authors' code, "sharing a face" in a continuation, "sharing a cell" in the flood and
// in the re-chaining, and the flood's stops look at the whole mesh, not only at the region.)
// Simplification: redundant singular vertices (an all-quad corner of one cell, or only regular
// wireframe edges around it), removable pairs of regular all-quad wireframe edges continuing each
// other at a singular vertex (ties broken by valence gap, then quad ratio; unresolved ties keep
// both), chains with two redundant ends; reactivation keeps every removable chain reached from a
// kept one through its continuation; the kept chains are re-chained through the vertices that stop
// being singular (exactly two kept chains through it, no two of its wireframe edges in one cell).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hbc/cell_complex.hpp"
#include "hbc/csr.hpp"

namespace hbc {

// The wireframe's one option; its presentation (opacity, ρ colour classes) is a step of the render
// layer, wireframe_style.hpp, which the wireframe never reads.
struct WireframeOptions {
  // Complex edges (ids of the CellComplex) removed last when they make up a whole simplified
  // chain: a sheet's parallel edges, so a sheet's wireframe shows what crosses it.
  std::vector<int32_t> parallel_edges;
};

// Kind of a complete-wireframe chain: made of VSG (irregular) edges only, or not (JSON "vsg" / "trace").
enum class WireKind : uint8_t { Vsg = 0, Trace = 1 };
// Where a chain's last vertex lies (None for a closed chain): a singular vertex of the complete
// wireframe (JSON "vsg_vertex", the name scripts read), the boundary, or no continuation.
enum class TraceStop : uint8_t { None = 0, SingularVertex = 1, Boundary = 2, NoContinuation = 3 };

struct VsgWireframe {
  // ---- VSG (ids of the CellComplex) ----
  std::vector<uint8_t> edge_vsg;           // ne: seed (irregular) edge
  std::vector<uint8_t> vert_vsg;           // nv: end of a VSG chain (a VSG vertex)
  Csr<int32_t> vsg_chain_edges;            // VSG chains: complex edges in order
  int64_t vsg_edges = 0;                   // seed edges
  int64_t vsg_chains = 0;                  // rows of vsg_chain_edges

  // ---- Complete wireframe ----
  // The wireframe's singular vertices (where the VSG's separation surfaces meet), not the
  // singularity graph's (SingularityGraph::singular_vertices, singularity ends); both are printed
  // as "singular_vertices", by `hbc wireframe` and by `hbc analyze` respectively.
  std::vector<uint8_t> vert_singular;      // nv
  std::vector<int32_t> singular_vertices;  // sorted view vertex ids
  // Row w of `edges` lists complex edges in order along chain w; row w of `polylines` the mesh
  // vertices along it (a closed chain repeats its first vertex at the end). ends[w] are its two end
  // vertices ({-1,-1} for a closed chain).
  Csr<int32_t> edges;
  Csr<int32_t> polylines;
  std::vector<std::array<int32_t, 2>> ends;
  std::vector<WireKind> kind;
  std::vector<int32_t> valence;            // per chain: region valence of its first edge
  std::vector<TraceStop> stop;             // per chain: what its second end is

  // Non-hex kinds of each chain (docs/concepts.md, "Non-hex kinds"): row w lists, sorted and each
  // once, the non_hex_kind codes (mesh.hpp) of the view's non-hex cells around an edge of chain w
  // or at an end of it (the first and last vertex of an open chain). Empty rows on an all-hex view.
  Csr<int32_t> non_hex;

  // ---- Simplification (per complete chain) ----
  std::vector<uint8_t> vert_non_important; // nv: redundant singular vertex, or not singular
  // 0 = kept; 1 = both ends redundant; 2 = in a removable pair at a singular vertex.
  std::vector<uint8_t> non_important;
  std::vector<uint8_t> reactivated;        // non-important but kept (continues a kept chain)
  std::vector<uint8_t> shown;              // every edge lies on the simplified wireframe (JSON/Python "shown")
  // The simplified wireframe: kept chains re-chained through the vertices that stop being singular.
  Csr<int32_t> simplified_edges;
  Csr<int32_t> simplified_polylines;
  Csr<int32_t> simplified_non_hex;         // the non-hex kinds of each simplified chain, as non_hex
  // Distinct mesh edges covered by the VSG chains, the complete and the simplified wireframe
  // (JSON/Python vsg_mesh_edges, wireframe_mesh_edges, wireframe_mesh_edges_simplified).
  int64_t vsg_mesh_edges = 0, wireframe_mesh_edges = 0, simplified_mesh_edges = 0;
  // Connected pieces of the complete and of the simplified wireframe (JSON/Python
  // wireframe_components, wireframe_components_simplified).
  int64_t components = 0;
  int64_t simplified_components = 0;

  size_t size() const { return kind.size(); }
  int64_t wireframe_edges() const { return static_cast<int64_t>(kind.size()); }
  int64_t wireframe_edges_simplified() const { return static_cast<int64_t>(simplified_edges.rows()); }

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const VsgWireframe&) const = default;
};

// Distinct mesh edges along the rows (complex edges) of `chains` (a complex edge of k+1 points
// covers k mesh edges).
int64_t covered_mesh_edges(const CellComplex& complex, const Csr<int32_t>& chains);

// The VSG, the complete wireframe and its simplification (no presentation: wireframe_style.hpp).
// `threads`: see threads.hpp; results are the same for any thread count.
VsgWireframe vsg_wireframe(const CellComplex& complex, const WireframeOptions& options = {},
                           const Threads& threads = {});

}  // namespace hbc
