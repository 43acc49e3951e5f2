#include "hbc/structure_surfaces.hpp"

#include <algorithm>

namespace hbc {
namespace {

void add(FaceSelection& sel, const Mesh& m, int32_t f, int32_t cell, int32_t id) {
  sel.faces.push_back(f);
  sel.reversed.push_back(reversed_for_outward(m, f, cell) ? 1 : 0);
  sel.ids.push_back(id);
}

}  // namespace

FaceSelection patch_selection(const Mesh& m, const BaseComplex& bc) {
  FaceSelection sel;
  sel.separate_ids = true;
  for (size_t p = 0; p < bc.num_patches(); ++p) {
    // Orient the whole patch out of the component on one of its sides, so its faces agree.
    const int32_t side = bc.patch_components[p][0];
    for (int32_t f : bc.patch_faces[p]) {
      const auto fc = m.face_cells[f];
      const int32_t cell = bc.cell_component[fc[0]] == side || fc[1] < 0 ? fc[0] : fc[1];
      add(sel, m, f, cell, static_cast<int32_t>(p));
    }
  }
  return sel;
}

FaceSelection component_selection(const Mesh& m, const BaseComplex& bc) {
  FaceSelection sel;
  sel.separate_ids = true;
  for (size_t k = 0; k < bc.num_components(); ++k)
    for (int32_t c : bc.component_cells[k])
      for (int32_t f : m.cell_faces[c])
        if (bc.face_separation[f]) add(sel, m, f, c, static_cast<int32_t>(k));
  return sel;
}

FaceSelection sheet_selection(const Mesh& m, const Sheets& sheets, int32_t only) {
  FaceSelection sel;
  sel.separate_ids = true;
  for (size_t s = 0; s < sheets.size(); ++s) {
    if (only >= 0 && static_cast<int32_t>(s) != only) continue;
    auto cells = sheets.sheet_cells[s];
    auto in_sheet = [&](int32_t c) { return c >= 0 && std::binary_search(cells.begin(), cells.end(), c); };
    for (int32_t c : cells)
      for (int32_t f : m.cell_faces[c]) {
        const auto fc = m.face_cells[f];
        const int32_t other = fc[0] == c ? fc[1] : fc[0];
        if (!in_sheet(other)) add(sel, m, f, c, static_cast<int32_t>(s));
      }
  }
  return sel;
}

}  // namespace hbc
