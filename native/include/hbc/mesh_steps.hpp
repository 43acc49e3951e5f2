#pragma once
// The steps of build_mesh, in the order it runs them; exposed so that each can be tested on
// hand-built cells. Each step fills the Mesh arrays named in its comment from the ones the
// steps before it filled. `par` is resolved (see hbc::resolved); results do not depend on it. Errors name in.source
// and the line of the offending cell (in.cell_loc).
//
// A face slot k is a position in face_verts.items (= face_edges.items): the corner of face
// slot_face[k] whose edge runs from face_verts.items[k] to the next vertex of the loop.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hbc/mesh.hpp"

namespace hbc::mesh_steps {

// "(v0 v1 ...)", for messages.
std::string loop_text(std::span<const int32_t> loop);

// Range, finiteness and polygon checks of what a reader produced.
void validate_input(const MeshInput& in);

// face_verts, cell_faces, cell_face_flip, face_cells, dropped_faces (+ warning). Input faces with
// the same vertex set become one face, numbered in order of first use by a cell and keeping the
// loop of that first use. Throws for a cell listing a face twice or a face in 3+ cells.
// Consumes in.faces and in.cells.
void merge_faces(MeshInput& in, Mesh& m, const LoadOptions& par);

// slot_face[k] = the face of slot k; size face_verts.items.size().
std::vector<int32_t> slot_faces(const Mesh& m, const LoadOptions& par);

// edge_verts, face_edges: edges numbered in order of first appearance along the face loops.
void build_edges(Mesh& m, const std::vector<int32_t>& slot_face, const LoadOptions& par);

// cell_verts and cell_edges (sorted), after checking each cell is closed (each of its edges in
// exactly two of its faces). Returns partner: partner[2k + side] = 2k' + side', where k' is the
// slot of the other face of the same cell at the edge of slot k, and side (side') tells on which
// side of face slot_face[k] (slot_face[k']) that cell lies (0: face_cells[f][0], 1: [1]).
std::vector<int32_t> cell_incidences(Mesh& m, const MeshInput& in, const LoadOptions& par);

// cell_face_flip made consistent: within each cell (neighbouring faces walk their shared edge in
// opposite directions), across cells (a shared face seen in opposite directions), and each
// face-connected group turned to a positive total signed volume. Tangled cells thus keep a
// negative volume; a cell that cannot be oriented keeps what the file said.
void orient_cells(Mesh& m, const std::vector<int32_t>& partner, const std::vector<int32_t>& slot_face,
                  const LoadOptions& par);

// face_boundary, edge_boundary, vert_boundary.
void mark_boundary(Mesh& m);

// edge_faces, edge_cells, edge_fan_ok (see Mesh).
void edge_fans(Mesh& m, const std::vector<int32_t>& partner, const std::vector<int32_t>& slot_face,
               const LoadOptions& par);

// vert_edges, vert_faces, vert_cells; then dropped_edges (+ warning) for in.declared_edges
// that no face uses.
void vertex_incidences(Mesh& m, const MeshInput& in, const LoadOptions& par);

// cell_type, and vert_non_manifold = 1 where a cell meets a vertex in fewer than 3 faces.
void cell_types(Mesh& m, const LoadOptions& par);

// vert_non_manifold = 1 also where the cells around a vertex are not one face-connected group.
void non_manifold_vertices(Mesh& m, const LoadOptions& par);

}  // namespace hbc::mesh_steps
