#pragma once
// Face selections: which mesh faces to draw, each oriented out of the owner it bounds (a cell,
// component, patch, sheet, ...) and tagged with the id of that owner. One type for every consumer:
// the OpenMesh surfaces of `hbc export-surface` (surface.hpp) and the soups of the viewer
// (render_geometry.hpp).
// Every selector is a pure function; faces follow the mesh's cell and face order.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "hbc/base_complex.hpp"
#include "hbc/csr.hpp"
#include "hbc/mesh.hpp"
#include "hbc/sheets.hpp"

namespace hbc {

// All arrays have one entry per selected face: `faces` mesh face ids, `cells` the mesh cell on the
// owner's side (the face points out of it), `reversed` 1 when the face's stored loop is to be
// walked backwards to point out of that cell, `ids` the owner (patch, component, sheet, cell, ...)
// that holds it and sets its colour. A face bounding two owners appears once for each.
struct FaceSelection {
  std::vector<int32_t> faces;
  std::vector<int32_t> cells;
  std::vector<uint8_t> reversed;
  std::vector<int32_t> ids;
  // Surfaces: weld vertices only between faces of the same id, so that each id is its own piece
  // (faces of one id are then consecutive). Soups always keep owners apart.
  bool separate_ids = false;

  size_t size() const { return faces.size(); }
};

// Whether face f's stored loop must be reversed to point out of `cell` (a cell of f): cells see
// their face loops outward once their cell_face_flip is applied.
bool reversed_for_outward(const Mesh& mesh, int32_t face, int32_t cell);

// Every boundary face in increasing id, oriented out of the mesh; id = the CellType (as int) of
// its cell, so non-hex cells show on the surface.
FaceSelection boundary_selection(const Mesh& mesh);

// Every face of each listed cell, id = the cell.
FaceSelection cells_selection(const Mesh& mesh, std::span<const int32_t> cells);

// Each row of `sets` (mesh cells) is an owner, id = its row (with `only`, that row alone): the
// faces of its cells whose other side is not in the row (or is outside the mesh). Rows may share
// cells. Sheets, subsheets and the hex region are such sets.
FaceSelection cell_set_selection(const Mesh& mesh, const Csr<int32_t>& sets, std::optional<int32_t> only = std::nullopt);

// The surface of the hex cells (one owner, id 0): hex faces whose other side is not a hex cell.
FaceSelection hex_region_selection(const Mesh& mesh);

// Every separation face once, id = its patch; oriented out of its first cell.
FaceSelection patch_selection(const Mesh& mesh, const BaseComplex& bc);

// For every component, the faces bounding it (separation faces of its cells), oriented out of
// it; id = component. A face between two components appears once for each.
FaceSelection component_selection(const Mesh& mesh, const BaseComplex& bc);

// For every sheet (or that one `sheet` only), the faces of its cells whose other side is not a
// cell of the sheet, oriented out of the sheet; id = sheet.
FaceSelection sheet_selection(const Mesh& mesh, const Sheets& sheets, std::optional<int32_t> sheet = std::nullopt);

// One sheet split by component: the faces of the sheet's cells in each component whose other side
// is outside the sheet or in another component; id = component. At the mesh level a sheet is a
// slab of a component, at the complex level whole components.
FaceSelection sheet_component_selection(const Mesh& mesh, const BaseComplex& bc, const Sheets& sheets, int32_t sheet);

}  // namespace hbc
