#pragma once
// The conforming polyhedral volume mesh (paper §3.1; docs/concepts.md) in flat index arrays, and the builder that turns
// what a reader found in a file (MeshInput) into it, checking that it is a conforming mesh.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hbc/csr.hpp"
#include "hbc/error.hpp"
#include "hbc/threads.hpp"

namespace hbc {

enum class CellType : uint8_t { Hex = 0, Tet = 1, Prism = 2, Pyramid = 3, Polyhedron = 4 };
const char* cell_type_name(CellType t);

// The kind of a non-hex cell, as the wireframe's chains carry it (docs/concepts.md, "Non-hex
// kinds"): its type and its number of faces in one code, type << 16 | faces (faces capped at
// 0xffff), so that sorted codes list tets, prisms, pyramids, then polyhedra by face count.
constexpr int32_t non_hex_kind(CellType t, size_t faces) {
  return static_cast<int32_t>(t) << 16 | static_cast<int32_t>(faces < 0xffff ? faces : 0xffff);
}
constexpr CellType non_hex_kind_type(int32_t kind) { return static_cast<CellType>(kind >> 16); }
constexpr int32_t non_hex_kind_faces(int32_t kind) { return kind & 0xffff; }

// How a MeshInput row describes a cell: as references to faces of the polygon soup, or as the
// corners of one of the standard elements in MEDIT's corner order (hex 0-3 bottom, 4-7 top, the
// bottom's right-hand normal pointing into the cell; prism 0-2 bottom, 3-5 top, same rule;
// pyramid 0-3 base, normal towards the apex 4; tet with 0-1-2 counter-clockwise seen from 3).
// Element-list formats give corners, which spares the loader a face soup six times the size.
enum class CellShape : uint8_t { Faces = 0, Tet = 1, Pyramid = 2, Prism = 3, Hex = 4 };
// 4, 5, 6, 8; 0 for Faces.
constexpr int corner_count(CellShape s) {
  constexpr int kCorners[5] = {0, 4, 5, 6, 8};
  return kCorners[static_cast<int>(s)];
}

// What a reader produces: vertex positions, a polygon soup and cells referring to it (or giving
// their corners, see CellShape). Faces may be listed twice (one copy per cell, as .HYBRID files
// do) or not be used by any cell; the builder merges faces with the same vertex set and drops
// unused ones.
struct MeshInput {
  std::string source;               // file name, for messages
  bool binary = false;              // locations below are byte offsets instead of lines
  std::vector<double> points;       // 3 * nv, x y z per vertex
  Csr<int32_t> faces;               // nf rows: vertex loop of each face (0-based vertex ids)
  // nc rows. A Faces cell lists 2*face + flip (flip = 1 when the cell sees the loop reversed);
  // an element lists its corner_count(shape) distinct vertex ids.
  Csr<int32_t> cells;
  std::vector<CellShape> cell_shape;  // nc, or empty when every cell is a Faces cell
  std::vector<std::array<int32_t, 2>> declared_edges;  // edges a file lists explicitly (OVM), if any
  std::vector<int64_t> vertex_loc, face_loc, cell_loc;  // where each element is in the file (may be empty)
  std::vector<std::string> warnings;  // what the reader read past (e.g. surface elements); build_mesh keeps them

  CellShape shape(size_t c) const { return cell_shape.empty() ? CellShape::Faces : cell_shape[c]; }
  SourceLoc loc_of(const std::vector<int64_t>& locs, size_t i) const {
    if (i >= locs.size()) return {};
    return binary ? SourceLoc::at_byte(locs[i]) : SourceLoc::at_line(locs[i]);
  }
};

// `in` with every element turned into Faces cells over new soup faces (the element's face
// loops, outward in MEDIT's convention), numbered in cell order; Faces cells keep their faces.
MeshInput with_face_soup(MeshInput in);

// The conforming polyhedral volume mesh in flat index arrays (32-bit ids). Only incidences that
// cannot be derived cheaply are stored; the others are functions below (edge fans, the vertices
// and edges of a cell), so that a 10^6-cell mesh takes about 240 bytes a cell.
struct Mesh {
  std::string source;
  std::vector<double> points;                       // 3 * nv

  std::vector<std::array<int32_t, 2>> edge_verts;   // ne, (lo, hi) with lo < hi
  Csr<int32_t> face_verts;                          // nf, vertex loop
  std::vector<int32_t> face_edge_ids;               // aligned with face_verts.items: see face_edges()
  std::vector<std::array<int32_t, 2>> face_cells;   // nf, second = -1 on the boundary
  Csr<int32_t> cell_faces;                          // nc, face ids
  std::vector<uint8_t> cell_face_flip;              // aligned with cell_faces.items: 1 = loop seen reversed

  // Edge fans, walked by edge_fan(). Where the faces and cells around edge e have a cyclic order
  // (the fan is "ok": a cycle, or on the boundary a path between two boundary faces), fan_start[e]
  // is the face the walk starts from: the lowest-numbered boundary face at e, else the
  // lowest-numbered face at e. Otherwise fan_start[e] = -1 - r, and row r of odd_fan_faces lists
  // the faces at e (sorted).
  std::vector<int32_t> fan_start;                   // ne
  Csr<int32_t> odd_fan_faces;                       // one row per edge without a cyclic fan
  std::vector<uint8_t> valence_small;               // ne, cells around e; 255 = 255 or more (counted)

  std::vector<uint8_t> vert_boundary, edge_boundary, face_boundary;
  std::vector<CellType> cell_type;
  std::vector<uint8_t> vert_non_manifold;           // non-manifold vertex (docs/concepts.md)

  int64_t dropped_faces = 0;                        // faces in the file used by no cell
  int64_t dropped_edges = 0;                        // edges in the file used by no kept face
  std::vector<std::string> warnings;
  size_t released_vertices = 0;                     // num_vertices() once release_unanalyzed() freed the points

  size_t num_vertices() const { return points.empty() ? released_vertices : points.size() / 3; }
  size_t num_edges() const { return edge_verts.size(); }
  size_t num_faces() const { return face_verts.rows(); }
  size_t num_cells() const { return cell_faces.rows(); }
  bool is_hex(size_t c) const { return cell_type[c] == CellType::Hex; }
  // Edge i of face f joins its loop vertices i and i+1.
  std::span<const int32_t> face_edges(size_t f) const {
    return {face_edge_ids.data() + face_verts.offsets[f], static_cast<size_t>(face_verts.count(f))};
  }
  bool edge_fan_ok(size_t e) const { return fan_start[e] >= 0; }
  int32_t edge_valence(size_t e) const;  // cells around edge e
  size_t num_hex_cells() const;
  // The other endpoint of edge e.
  int32_t other_vertex(int32_t e, int32_t v) const {
    return edge_verts[e][0] == v ? edge_verts[e][1] : edge_verts[e][0];
  }

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const Mesh&) const = default;
};

// The faces and cells around edge e. Where the fan is ok they come in cyclic order f0 c0 f1 c1 ...,
// with c_i between f_i and f_{i+1}, starting at fan_start[e] and its first cell face_cells[f0][0];
// on the boundary the fan is a path from one boundary face to the other and has one cell fewer
// than faces. Otherwise both are sorted (each cell once). Reuse one EdgeFan for many edges: its
// vectors keep their room.
struct EdgeFan {
  std::vector<int32_t> faces, cells;
};
void edge_fan(const Mesh& m, int32_t e, EdgeFan& out);

// Frees what the analysis stages (singularity graph, base complex, sheets, complex-level view)
// never read: the vertex positions (num_vertices() stays), the cells' face orientations and the
// boundary vertex flags. For a caller that gives the mesh up to count (analyze_stats).
void release_unanalyzed(Mesh& m);

// The vertices / edges of cell c, sorted, each once, written over `out`.
void cell_vertices(const Mesh& m, size_t c, std::vector<int32_t>& out);
void cell_edges(const Mesh& m, size_t c, std::vector<int32_t>& out);


// Edges at each vertex (sorted ids): the transpose of edge_verts, built for the stages that walk
// from vertex to vertex. `keep` (ne flags, or empty for every edge) restricts it to some edges.
// The same rows for any number of threads.
Csr<int32_t> vertex_edges(const Mesh& m, std::span<const uint8_t> keep = {}, const Threads& threads = {});

// Builds the topology and checks conformity. Throws InputError (naming input.source and the line
// of the offending element) for: an index out of range, a face with fewer than 3 distinct vertices
// or a repeated vertex, a face shared by 3+ cells, a cell listing a face twice, a cell that is not
// closed, a non-finite coordinate.
Mesh build_mesh(MeshInput input, const Threads& threads = {});

// The mesh with vertices and cells renumbered (vertex v becomes vperm[v], cell c becomes
// cperm[c]); used to check that results do not depend on numbering.
MeshInput renumbered(const Mesh& mesh, const std::vector<int32_t>& vperm,
                     const std::vector<int32_t>& cperm);

// A MeshInput describing `mesh` again (faces once, cells with orientation); writers use it.
MeshInput to_input(const Mesh& mesh);

}  // namespace hbc
