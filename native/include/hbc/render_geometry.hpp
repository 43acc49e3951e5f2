#pragma once
// Render-ready data made from a mesh and its analysis, so that a viewer (the Blender add-on, via
// the Python binding) only copies flat arrays and never loops over elements itself:
//  - soups (BlockSoup, block_soup: names kept from the Python API hbc.block_soup; the pieces are
//    owners, not sheet blocks): the faces of a set of owners (cells, components, sheets, ...), each
//    owner a separate piece with its own vertex copies so it can be shrunk toward its own centroid;
//  - polyline point positions;
//  - per-sheet / per-subsheet classification flattened to arrays.
// The region of a sheet and its wireframe are part of the analysis (region.hpp).
// Everything is a pure, deterministic function of its arguments.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/csr.hpp"
#include "hbc/face_selection.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

// What the owners of a soup are; the owner id of each face is given in parentheses.
enum class SoupKind : uint8_t {
  Cells,        // every cell, all its faces (cell id)
  Components,   // every base-complex component, its separation faces, once per side (component id)
  Sheets,       // every sheet: the boundary faces of its cell set (sheet id); a cell of two
                // sheets is in both owners
  Subsheets,    // the subsheets of one self-intersecting sheet, as Sheets (subsheet id)
  Sheet,        // one sheet split by component: the boundary faces of the sheet's cells in each
                // component (component id)
  SheetNonHex,  // the non-hex cells adjacent to one sheet, all their faces (cell id)
  NonHex,       // every non-hex cell, all its faces (cell id)
  Boundary,     // the mesh boundary faces (CellType of the face's cell, as an integer)
  Hex,          // the surface of the hex region: faces of hex cells not shared with another hex (0)
};

// "cells", "components", "sheets", "subsheets", "sheet", "sheet_non_hex", "non_hex", "boundary",
// "hex".
// Throws std::invalid_argument listing the accepted names for anything else.
SoupKind soup_kind_from_name(std::string_view name);
bool soup_kind_needs_sheet(SoupKind kind);
// Cells, NonHex and Boundary read only the mesh (any Analysis, even an empty one, will do).
bool soup_kind_needs_analysis(SoupKind kind);

// Selects the faces of `kind`. `sheet` is required for Subsheets, Sheet and SheetNonHex
// (soup_kind_needs_sheet) and ignored otherwise. Throws std::invalid_argument without a sheet
// those kinds need, when the analysis lacks the stage the kind needs (sheets, subsheets), for a
// sheet id out of range, and for Subsheets of a sheet that is not self-intersecting.
FaceSelection soup_faces(const Mesh& mesh, const Analysis& analysis, SoupKind kind,
                         std::optional<int32_t> sheet = std::nullopt);

struct BlockSoup {
  // Points: each owner has its own copies of the mesh vertices its faces use (shared between
  // that owner's faces, never between owners).
  std::vector<float> positions;        // 3 * np: x y z
  std::vector<int32_t> point_vertex;   // np: the mesh vertex the point copies
  // Faces, grouped by increasing owner, in selection order within an owner.
  Csr<int32_t> face_vertices;          // nf rows: point ids, loops outward (right-hand rule)
  std::vector<int32_t> face_owner;     // nf
  std::vector<int32_t> face_source;    // nf: mesh face id
  std::vector<int32_t> face_cell;      // nf: mesh cell on the owner's side of the face (the cell
                                       // whose faces were selected), for per-cell attributes

  size_t num_points() const { return point_vertex.size(); }
  size_t num_faces() const { return face_vertices.rows(); }
};

// Builds the soup of `faces` (ids >= 0 are the owners, faces in range). Every point p of an owner is moved to
// c + (1 - shrink)(p - c), c being the mean of that owner's distinct mesh vertices; shrink must be
// in [0, 1) (std::invalid_argument otherwise). Computed in double, stored as float.
BlockSoup build_soup(const Mesh& mesh, const FaceSelection& faces, double shrink = 0.0);

// soup_faces then build_soup.
BlockSoup block_soup(const Mesh& mesh, const Analysis& analysis, SoupKind kind,
                     std::optional<int32_t> sheet = std::nullopt, double shrink = 0.0);

// The surface of a set of cells (kept[c] != 0; nc entries, else std::invalid_argument): every face
// of a kept cell whose other side is not kept or is the boundary, owner = cell id, pointing out of
// the kept cell. What a viewer draws of a filtered (sliced, peeled, ...) cell view: the faces
// between two kept cells are never seen, so only this surface is rebuilt when a filter changes.
BlockSoup kept_surface_soup(const Mesh& mesh, std::span<const uint8_t> kept, double shrink = 0.0);

// The vertex centroid of every cell: 3 * nc doubles, the mean of the cell's distinct vertices
// (the point the add-on's slicing plane tests, so a cell is on one side or the other as a whole).
std::vector<double> cell_centroids(const Mesh& mesh);

// float32 positions (3 per entry) of the mesh vertices listed in `vertices`, a CSR row set whose
// `offsets` must start at 0, not decrease and end at vertices.size(); vertex ids must be in range.
// Throws std::invalid_argument otherwise.
std::vector<float> polyline_positions(const Mesh& mesh, std::span<const int32_t> offsets,
                                      std::span<const int32_t> vertices);

// The classifications of n sheets or subsheets as flat arrays.
struct ClassArrays {
  std::vector<uint8_t> type;                  // n: SheetType
  std::vector<uint8_t> flags;                 // 3n: type1, type2, type3 configuration present (0/1)
  Csr<int32_t> unmatched_vertices;            // n rows: mesh vertices left unmatched
  Csr<int32_t> shared_vertices;               // n rows: mesh vertices shared by two parallel curves
  Csr<int32_t> self_parallel_curves;          // n rows: curve ids (SheetDomain curves) of type 2 pairs
  Csr<int32_t> self_intersecting_components;  // n rows: base-complex component ids holding type 3 pairs
};
ClassArrays flatten_classes(const SheetDomain& domain, std::span<const SheetClass> classes);

// Rows of sheet blocks (SheetDomain block ids) as sorted, distinct base-complex component ids (at
// the complex level a block is a component; at the mesh level a hex cell, several of which share
// one). The Python binding shows sheets and subsheets by components.
Csr<int32_t> blocks_as_components(const SheetDomain& domain, const Csr<int32_t>& blocks);

}  // namespace hbc
