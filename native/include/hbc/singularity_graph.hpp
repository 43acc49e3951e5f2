#pragma once
// The hybrid singularity graph G_S (paper §3.2; docs/concepts.md): singular edges chained into
// singularities, pseudo-singular edges (touching a non-hex cell), non-manifold edges (touching a
// non-manifold vertex), and the vertices where they end.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hbc/csr.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

enum class EdgeClass : uint8_t {
  Regular = 0,         // interior valence 4 / boundary valence 2, all cells hex
  Singular = 1,        // irregular, all cells hex
  PseudoSingular = 2,  // at least one non-hex cell
  NonManifold = 3,     // touches a non-manifold vertex, neither of the above
};

struct SingularityGraph {
  std::vector<EdgeClass> edge_class;        // ne
  std::vector<uint8_t> edge_irregular;      // ne: valence differs from 4 inside / 2 on the boundary

  // Singularities: maximal chains of singular edges of equal valence. Row s of chain_verts lists
  // the chain's vertices in order (a closed chain does not repeat its first vertex); row s of
  // chain_edges lists its edges, chain_edges[s][i] joining chain_verts[s][i] and [i+1] (mod n).
  Csr<int32_t> chain_verts;
  Csr<int32_t> chain_edges;
  std::vector<int32_t> chain_valence;       // per singularity
  std::vector<uint8_t> chain_boundary;      // 1 when all its edges are boundary edges
  std::vector<uint8_t> chain_closed;        // 1 for a closed loop
  std::vector<int32_t> edge_chain;          // ne: singularity of a singular edge, else -1

  std::vector<int32_t> pseudo_singular_edges;     // sorted edge ids
  std::vector<int32_t> non_manifold_edges;        // sorted edge ids
  // Sorted: singularity ends that are not pseudo-singular. Not VsgWireframe::singular_vertices
  // (the wireframe's), although `hbc analyze` and `hbc wireframe` print both as "singular_vertices".
  std::vector<int32_t> singular_vertices;
  std::vector<int32_t> pseudo_singular_vertices;  // sorted: ends of pseudo-singular / non-manifold edges
  std::vector<uint8_t> vert_pseudo_singular;      // nv

  size_t num_singularities() const { return chain_valence.size(); }
  size_t num_singular_edges() const { return chain_edges.items.size(); }
  // Singular, pseudo-singular or non-manifold: the edges that stop separation surfaces.
  bool is_structural(int32_t e) const { return edge_class[e] != EdgeClass::Regular; }

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const SingularityGraph&) const = default;
};

// `threads`: see threads.hpp; the graph is the same for any
// number.
SingularityGraph singularity_graph(const Mesh& mesh, const Threads& threads = {});

// Chains the edges marked in `member` (ne flags) into maximal chains of equal `edge_value`
// (ne values, or empty for one value everywhere), cut at vertices marked in `stop` (nv flags), at
// vertices with other than two member edges and where the value changes. Shared by the hybrid singularity graph and the VSG (paper §5).
// Output rows as in SingularityGraph::chain_verts / chain_edges; closed[s] marks loops.
// Chains are ordered by their lowest edge id; an open chain runs from its end with the lower
// vertex id, a closed one from its lowest vertex towards its lower-id neighbour.
// `threads` as for the stages (the chains are the same for any number).
void chain_edges(const Mesh& mesh, const std::vector<uint8_t>& member,
                 std::span<const int32_t> edge_value, const std::vector<uint8_t>& stop,
                 Csr<int32_t>& verts, Csr<int32_t>& edges, std::vector<uint8_t>& closed,
                 const Threads& threads = {});
// The same on any edge graph given by its end vertices (ne pairs) and the edges at each vertex
// (nv rows) in which no edge joins a vertex to itself (mesh edges never do).
void chain_edges(std::span<const std::array<int32_t, 2>> edge_verts, const Csr<int32_t>& vert_edges,
                 const std::vector<uint8_t>& member, std::span<const int32_t> edge_value,
                 const std::vector<uint8_t>& stop, Csr<int32_t>& verts, Csr<int32_t>& edges,
                 std::vector<uint8_t>& closed, const Threads& threads = {});

}  // namespace hbc
