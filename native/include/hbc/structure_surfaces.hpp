#pragma once
// Face selections (see surface.hpp) for the structures: base complex patches, component
// boundaries and sheet block surfaces, each face oriented out of the block it bounds and tagged
// with the id that colours it.
#include "hbc/analysis.hpp"
#include "hbc/surface.hpp"

namespace hbc {

// Every separation face once, id = its patch; oriented out of its first cell.
FaceSelection patch_selection(const Mesh& mesh, const BaseComplex& bc);

// For every component, the faces bounding it (separation faces of its cells), oriented out of
// it; id = component. A face between two components appears once for each.
FaceSelection component_selection(const Mesh& mesh, const BaseComplex& bc);

// For every sheet, the faces of its cells whose other side is not a cell of the sheet, oriented
// out of the sheet; id = sheet. `sheet` >= 0 keeps that sheet only.
FaceSelection sheet_selection(const Mesh& mesh, const Sheets& sheets, int32_t sheet = -1);

}  // namespace hbc
