#pragma once
// The conforming polyhedral volume mesh (SPEC §0) in flat index arrays, and the builder that turns
// what a reader found in a file (MeshInput) into it, checking that it is a conforming mesh.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hbc/csr.hpp"
#include "hbc/error.hpp"

namespace hbc {

enum class CellType : uint8_t { Hex = 0, Tet = 1, Prism = 2, Pyramid = 3, Polyhedron = 4 };
const char* cell_type_name(CellType t);

// What a reader produces: vertex positions, a polygon soup and cells referring to it. Faces may be
// listed twice (one copy per cell, as .HYBRID files do) or not be used by any cell; the builder
// merges faces with the same vertex set and drops unused ones.
struct MeshInput {
  std::string source;               // file name, for messages
  bool binary = false;              // locations below are byte offsets instead of lines
  std::vector<double> points;       // 3 * nv, x y z per vertex
  Csr<int32_t> faces;               // nf rows: vertex loop of each face (0-based vertex ids)
  Csr<int32_t> cells;               // nc rows: 2*face + flip, flip = 1 when the cell sees the loop reversed
  std::vector<std::array<int32_t, 2>> declared_edges;  // edges a file lists explicitly (OVM), if any
  std::vector<int64_t> vertex_loc, face_loc, cell_loc;  // where each element is in the file (may be empty)
  std::vector<std::string> warnings;  // what the reader read past (e.g. surface elements); build_mesh keeps them

  SourceLoc loc_of(const std::vector<int64_t>& locs, size_t i) const {
    if (i >= locs.size()) return {};
    return binary ? SourceLoc::at_byte(locs[i]) : SourceLoc::at_line(locs[i]);
  }
};

struct Mesh {
  std::string source;
  std::vector<double> points;                       // 3 * nv

  std::vector<std::array<int32_t, 2>> edge_verts;   // ne, (lo, hi) with lo < hi
  Csr<int32_t> face_verts;                          // nf, vertex loop
  Csr<int32_t> face_edges;                          // nf, edge i joins loop vertices i and i+1
  std::vector<std::array<int32_t, 2>> face_cells;   // nf, second = -1 on the boundary
  Csr<int32_t> cell_faces;                          // nc, face ids
  std::vector<uint8_t> cell_face_flip;              // aligned with cell_faces.items: 1 = loop seen reversed
  Csr<int32_t> cell_verts;                          // nc, sorted vertex ids
  Csr<int32_t> cell_edges;                          // nc, sorted edge ids

  Csr<int32_t> vert_edges, vert_faces, vert_cells;  // sorted ids
  // Faces and cells around each edge in cyclic order where the fan is manifold: f0 c0 f1 c1 ...,
  // with c_i between f_i and f_{i+1}. On the boundary the fan starts at a boundary face and
  // edge_cells has one entry fewer than edge_faces.
  Csr<int32_t> edge_faces, edge_cells;
  std::vector<uint8_t> edge_fan_ok;                 // 1 when the cyclic order above is well defined

  std::vector<uint8_t> vert_boundary, edge_boundary, face_boundary;
  std::vector<CellType> cell_type;
  std::vector<uint8_t> vert_non_manifold;           // SPEC §1

  int64_t dropped_faces = 0;                        // faces in the file used by no cell
  int64_t dropped_edges = 0;                        // edges in the file used by no kept face
  std::vector<std::string> warnings;

  size_t num_vertices() const { return points.size() / 3; }
  size_t num_edges() const { return edge_verts.size(); }
  size_t num_faces() const { return face_verts.rows(); }
  size_t num_cells() const { return cell_faces.rows(); }
  bool is_hex(size_t c) const { return cell_type[c] == CellType::Hex; }
  int32_t edge_valence(size_t e) const { return edge_cells.count(e); }
  int32_t vert_valence(size_t v) const { return vert_cells.count(v); }
  size_t num_hex_cells() const;
  // The other endpoint of edge e.
  int32_t other_vertex(int32_t e, int32_t v) const {
    return edge_verts[e][0] == v ? edge_verts[e][1] : edge_verts[e][0];
  }
};

// How to load: threads = how many threads may split the work (results are identical for any
// number); 0 means the environment variable HBC_THREADS when it holds a positive number, else
// every core of the machine. grain = the fewest elements worth a thread of their own (tests lower
// it to split small meshes into many ranges).
struct LoadOptions {
  int threads = 0;
  int grain = 4096;
};
// The thread count `options` asks for, resolved as described above (always >= 1).
int resolve_threads(const LoadOptions& options);
// options with threads resolved and grain at least 1.
LoadOptions resolved(const LoadOptions& options);

// Builds the topology and checks conformity. Throws InputError (naming input.source and the line
// of the offending element) for: an index out of range, a face with fewer than 3 distinct vertices
// or a repeated vertex, a face shared by 3+ cells, a cell listing a face twice, a cell that is not
// closed, a non-finite coordinate.
Mesh build_mesh(MeshInput input, const LoadOptions& options = {});

// The mesh with vertices and cells renumbered (vertex v becomes vperm[v], cell c becomes
// cperm[c]); used to check that results do not depend on numbering.
MeshInput renumbered(const Mesh& mesh, const std::vector<int32_t>& vperm,
                     const std::vector<int32_t>& cperm);

// A MeshInput describing `mesh` again (faces once, cells with orientation); writers use it.
MeshInput to_input(const Mesh& mesh);

}  // namespace hbc
