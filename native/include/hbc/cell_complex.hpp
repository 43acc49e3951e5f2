#pragma once
// The view: a mesh-like object (vertices, edges, faces, cells) that the valence singularity graph
// and its wireframe (paper §5) are computed on, at one of two levels (docs/concepts.md, "Level"):
//  - Mesh: the fine mesh as it is (edges are mesh edges, cells mesh cells);
//  - Complex: the hybrid base complex seen as a coarse mesh (the paper's): vertices are the
//    corners that end curves, edges the curves (each carrying its polyline of mesh vertices),
//    faces the patches, cells the components.
// Either view may be restricted to a region (a subset of cells, e.g. a sheet's components plus its
// adjacent non-hex components): only elements touching a region cell exist, valences count region
// cells only, and a face with a region cell on one side only is a boundary face.
// Element ids are compact (0..n-1) and ordered like the ids they come from, so results are
// deterministic and follow the numbering of the mesh / base complex.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hbc/base_complex.hpp"
#include "hbc/csr.hpp"
#include "hbc/level.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

struct CellComplex {
  Level level = Level::Mesh;

  // Vertices (nv).
  std::vector<int32_t> vert_mesh;         // nv: mesh vertex id
  std::vector<uint8_t> vert_boundary;     // nv: on a (region) boundary face
  std::vector<int32_t> vert_cell_count;   // nv: distinct region cells around it
  std::vector<uint8_t> vert_all_quad;     // nv: every region face around it is a quad
  Csr<int32_t> vert_edges;                // nv rows: incident edges, sorted, each once

  // Edges (ne).
  std::vector<std::array<int32_t, 2>> edge_verts;  // ne: end vertices; {-1,-1} for a closed curve
  // ne rows: mesh vertices from edge_verts[e][0] to edge_verts[e][1]; a closed curve lists its
  // first vertex again at the end. Mesh level: the two ends.
  Csr<int32_t> edge_points;
  Csr<int32_t> edge_cells;                // ne rows: distinct region cells around it, sorted
  std::vector<int32_t> edge_valence;      // ne: region mesh cells around (a mesh edge of) it
  std::vector<uint8_t> edge_boundary;     // ne: on a (region) boundary face
  std::vector<uint8_t> edge_non_hex;      // ne: some cell around it is non-hex
  std::vector<uint8_t> edge_all_quad;     // ne: every region face around it is a quad
  Csr<int32_t> edge_faces;                // ne rows: region faces around it, sorted
  std::vector<int32_t> edge_source;       // ne: mesh edge / curve id

  // Faces (nf): mesh faces / patches with a region cell on at least one side.
  Csr<int32_t> face_edges;                // nf rows: bounding edges, sorted
  std::vector<uint8_t> face_quad;         // nf: 4 edges and 4 vertices (a topological quad)
  std::vector<int32_t> face_source;       // nf: mesh face / patch id
  std::vector<std::array<int32_t, 2>> face_cells;  // nf: region cells on its two sides, lower first; -1 for a side outside

  // Cells (nc): mesh cells / components in the region.
  std::vector<uint8_t> cell_non_hex;      // nc: non-hex cell / non-hex component
  std::vector<int32_t> cell_source;       // nc: mesh cell / component id
  // nc: non_hex_kind (mesh.hpp) of a non-hex cell, of a non-hex component's one cell; 0 for the others.
  std::vector<int32_t> cell_kind;

  // Whole-mesh adjacency of the region's elements, for the rules that look past the region (the
  // authors' continuation and flood use the whole mesh's faces and cells). Ids are source ids (mesh
  // faces / patches, mesh cells / components). Empty when the region is the whole mesh: then they
  // equal edge_faces, edge_cells, face_cells and edge_boundary.
  Csr<int32_t> edge_all_faces;                        // ne rows, sorted
  Csr<int32_t> edge_all_cells;                        // ne rows, sorted
  std::vector<std::array<int32_t, 2>> face_all_cells; // nf: cells on its sides, -1 off the mesh
  std::vector<uint8_t> edge_mesh_boundary;            // ne: on the mesh boundary
  std::vector<uint8_t> edge_all_non_hex;              // ne: some mesh cell around it is non-hex
  bool whole() const { return edge_all_faces.rows() == 0; }

  size_t num_vertices() const { return vert_mesh.size(); }
  size_t num_edges() const { return edge_verts.size(); }
  size_t num_faces() const { return face_source.size(); }
  size_t num_cells() const { return cell_source.size(); }
  // Interior valence other than 4, boundary valence other than 2 (paper §5).
  bool irregular(size_t e) const {
    return edge_boundary[e] ? edge_valence[e] != 2 : edge_valence[e] != 4;
  }
  bool closed(size_t e) const { return edge_verts[e][0] < 0; }
  // The other end of edge e at vertex v (v itself for a loop through one corner).
  int32_t other_vertex(int32_t e, int32_t v) const {
    return edge_verts[e][0] == v ? edge_verts[e][1] : edge_verts[e][0];
  }

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const CellComplex&) const = default;
};

// The fine mesh. `region_cells` (mesh cell ids, any order, repeats ignored) restricts the view;
// without it every cell is in. `threads`: see threads.hpp; the view is the same for any number.
CellComplex complex_from_mesh(const Mesh& mesh, const Threads& threads = {});
CellComplex complex_from_mesh(const Mesh& mesh, std::span<const int32_t> region_cells, const Threads& threads = {});

// The base complex as a coarse mesh. `region_components` (component ids) restricts the view.
// `threads`: see threads.hpp; the view is the same for any number.
CellComplex complex_from_base(const Mesh& mesh, const BaseComplex& bc, const Threads& threads = {});
CellComplex complex_from_base(const Mesh& mesh, const BaseComplex& bc, std::span<const int32_t> region_components,
                              const Threads& threads = {});

// What the complex-level view takes from the mesh, per base complex element (patch, curve) and per
// vertex of the view (corner), so that the view can be built once the mesh is gone: analyze_stats
// frees the mesh before building it, and the view and the mesh need not be held at once.
struct BaseViewFacts {
  size_t num_mesh_vertices = 0;
  std::vector<uint8_t> component_in;      // ncomp: in the region
  std::vector<int32_t> component_kind;    // ncomp: non_hex_kind of a non-hex component's cell, else 0
  std::vector<uint8_t> patch_in;          // npatch: a region cell on one of its sides
  std::vector<uint8_t> patch_quad;        // npatch: 4 curves and 4 corners
  std::vector<uint8_t> curve_in;          // ncurve: a region cell at its first mesh edge
  std::vector<int32_t> curve_valence;     // ncurve: region cells around its first mesh edge (0 when out)
  std::vector<uint8_t> curve_boundary;    // ncurve: a mesh edge of it on a region boundary face
  std::vector<int32_t> corners;           // the view's vertices: mesh ids of the curves' ends, sorted
  std::vector<uint8_t> corner_boundary;   // per corner: on a region boundary face
  std::vector<int32_t> corner_cells;      // per corner: region components with a cell there
  std::vector<uint8_t> corner_all_quad;   // per corner: every region patch there is a quad
  bool whole() const;
};
BaseViewFacts base_view_facts(const Mesh& mesh, const BaseComplex& bc, const Threads& threads = {});
BaseViewFacts base_view_facts(const Mesh& mesh, const BaseComplex& bc, std::span<const int32_t> region_components,
                              const Threads& threads = {});

// complex_from_base(mesh, bc) from the facts of the whole base complex and these arrays of `bc`
// alone: component_kind, patch_curves, patch_components, curve_verts, curve_closed,
// component_curves (the others may have been released). Throws for the facts of a proper region
// (their view needs the mesh for the whole-mesh adjacency).
CellComplex complex_from_base(const BaseComplex& bc, const BaseViewFacts& facts, const Threads& threads = {});

// The complex edges (ids of `cx`) holding the given mesh edges, sorted and distinct; mesh edges
// off the view (or, at the complex level, on no curve) are skipped. `bc` is read at the complex
// level only.
std::vector<int32_t> complex_edges_of(const CellComplex& cx, const BaseComplex& bc, std::span<const int32_t> mesh_edges);

// The components holding the given mesh cells, sorted and distinct (to turn a sheet's cells into a
// complex-level region).
std::vector<int32_t> components_of_cells(const BaseComplex& bc, std::span<const int32_t> cells);

}  // namespace hbc
