#pragma once
// The steps of build_mesh, in the order it runs them; exposed so that each can be tested on
// hand-built cells. Each step fills the Mesh arrays named in its comment from the ones the
// steps before it filled. `par` is resolved (see hbc::resolved); results do not depend on it.
// Errors name in.source and the line of the offending cell (in.cell_loc).
//
// A slot is one face of one cell: cell c's slots are cell_faces.offsets[c] .. offsets[c+1]-1,
// its soup faces in row order for a Faces cell, its template faces for an element. A corner k is
// a position in face_verts.items (= face_edge_ids): vertex face_verts.items[k] of its face, and
// the edge from it to the next vertex of the loop.
//
// No step keeps a table per slot or corner beyond the Mesh's own arrays: the pairing of a cell's
// faces along its edges is worked out cell by cell, where it is needed, in a few dozen entries.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "hbc/mesh.hpp"

namespace hbc::mesh_steps {

// "(v0 v1 ...)", for messages.
std::string loop_text(std::span<const int32_t> loop);

// Range, finiteness and polygon checks of what a reader produced.
void validate_input(const MeshInput& in, const Threads& par);

// face_verts, cell_faces, cell_face_flip, face_cells, dropped_faces (+ warning). Slots with the
// same vertex set become one face, numbered in order of first use by a cell (slot order) and
// keeping the loop of that first use. Throws for a cell listing a face twice or a face in 3+
// cells. Consumes in.faces and in.cells. Returns the rank of each vertex in order of first use
// by the cells, which build_edges takes over.
[[nodiscard]] std::vector<int32_t> merge_faces(MeshInput& in, Mesh& m, const Threads& par);

// edge_verts, face_edge_ids: edges numbered in order of first appearance along the face loops
// (corner order). fan_start[e] = the lowest boundary face at e where there is one, else the
// lowest face at e. Returns how many faces, and boundary faces, each edge is in. `rank` is
// merge_faces' result (any order of the vertices would give the same edges; this one keeps the
// grouping's memory accesses near each other) and is consumed.
struct EdgeFaceCount {
  int32_t faces;
  uint8_t boundary_faces;  // up to 255 counted; more make the fan odd anyway
};
// One EdgeFaceCount per edge. Not a std::vector: its resize would zero every entry on the calling
// thread, after the threads had shared the page faults, and the lines would then travel from the
// other core's cache (about 40 ms for 3M edges, the other core idle). build_edges zeroes and
// fills it range by range instead.
class EdgeFaceCounts {
 public:
  EdgeFaceCounts() = default;
  explicit EdgeFaceCounts(size_t n) : data_(std::make_unique_for_overwrite<EdgeFaceCount[]>(n)), size_(n) {}
  size_t size() const { return size_; }
  EdgeFaceCount* data() { return data_.get(); }
  EdgeFaceCount& operator[](size_t e) { return data_[e]; }
  const EdgeFaceCount& operator[](size_t e) const { return data_[e]; }

 private:
  std::unique_ptr<EdgeFaceCount[]> data_;
  size_t size_ = 0;
};
EdgeFaceCounts build_edges(Mesh& m, std::vector<int32_t>&& rank, const Threads& par);

// One pass over the cells. Checks that each is closed (each of its edges in exactly two of its
// faces); makes its loops agree (neighbouring faces walk their shared edge in opposite
// directions), keeping the direction the file gave its first face; sets cell_type; marks
// vert_non_manifold where a cell meets a vertex in fewer than 3 of its faces. An element cell
// (see CellShape) is all of that by construction and only gets its volume.
struct CellCheck {
  std::vector<double> volume;       // signed volume (x6) as now oriented; 0 where loops cannot agree
  bool faces_shared_twice = false;  // some cell has two faces with the same cell beyond
  std::vector<int32_t> pinched;     // vertices where one polyhedral cell's faces form several cycles
};
CellCheck check_cells(Mesh& m, const MeshInput& in, const Threads& par);

// Makes face-neighbouring cells see their shared face in opposite directions and turns each
// face-connected group to a positive total volume, so that tangled cells keep a negative volume.
void orient_groups(Mesh& m, std::vector<double>& cell_vol, const Threads& par);

// face_boundary, edge_boundary, vert_boundary.
void mark_boundary(Mesh& m, const Threads& par);

// odd_fan_faces and valence_small (see Mesh); fan_start of the edges without a cyclic fan.
// Most fans are known to be cyclic from their counts alone (see mesh_fans.cpp); the others are
// walked.
void edge_fans(Mesh& m, const EdgeFaceCounts& counts, const CellCheck& cells, const Threads& par);

// vert_non_manifold = 1 also where the cells around a vertex are not one face-connected group.
void non_manifold_vertices(Mesh& m, const CellCheck& cells, const Threads& par);

// dropped_edges (+ warning): in.declared_edges that no face uses.
void drop_declared_edges(Mesh& m, const MeshInput& in);

}  // namespace hbc::mesh_steps
