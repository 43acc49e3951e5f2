#include "hbc/face_selection.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace hbc {
namespace {

// The cell on the other side of face f from cell c (-1 on the boundary).
int32_t across(const Mesh& m, int32_t f, int32_t c) {
  const auto [a, b] = m.face_cells[static_cast<size_t>(f)];
  return a == c ? b : a;
}

// Appends the faces of cell c (oriented out of c) for which keep(face) holds, with id `id`.
template <class Keep>
void add_cell_faces(const Mesh& m, int32_t c, int32_t id, FaceSelection& out, Keep keep) {
  for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) {
    const int32_t f = m.cell_faces.items[static_cast<size_t>(i)];
    if (!keep(f)) continue;
    out.ids.push_back(id);
    out.faces.push_back(f);
    out.cells.push_back(c);
    out.reversed.push_back(m.cell_face_flip[static_cast<size_t>(i)]);
  }
}

}  // namespace

bool reversed_for_outward(const Mesh& mesh, int32_t face, int32_t cell) {
  const int32_t begin = mesh.cell_faces.offsets[static_cast<size_t>(cell)];
  auto row = mesh.cell_faces[static_cast<size_t>(cell)];
  const auto it = std::find(row.begin(), row.end(), face);
  if (it == row.end())
    throw std::invalid_argument("face " + std::to_string(face) + " is not a face of cell " + std::to_string(cell));
  return mesh.cell_face_flip[static_cast<size_t>(begin + (it - row.begin()))] != 0;
}

FaceSelection boundary_selection(const Mesh& m) {
  FaceSelection sel;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    if (!m.face_boundary[f]) continue;
    const int32_t c = m.face_cells[f][0];
    add_cell_faces(m, c, static_cast<int32_t>(m.cell_type[static_cast<size_t>(c)]), sel,
                   [&](int32_t g) { return g == static_cast<int32_t>(f); });
  }
  return sel;
}

FaceSelection cells_selection(const Mesh& m, std::span<const int32_t> cells) {
  FaceSelection sel;
  sel.separate_ids = true;
  for (int32_t c : cells) add_cell_faces(m, c, c, sel, [](int32_t) { return true; });
  return sel;
}

FaceSelection cell_set_selection(const Mesh& m, const Csr<int32_t>& sets, std::optional<int32_t> only) {
  FaceSelection sel;
  sel.separate_ids = true;
  // The row a cell was last marked for, so rows may share cells and nothing is cleared between rows.
  std::vector<int32_t> mark(m.num_cells(), -1);
  for (size_t r = 0; r < sets.rows(); ++r) {
    const int32_t id = static_cast<int32_t>(r);
    if (only && id != *only) continue;
    for (int32_t c : sets[r]) mark[static_cast<size_t>(c)] = id;
    for (int32_t c : sets[r])
      add_cell_faces(m, c, id, sel, [&](int32_t f) {
        const int32_t o = across(m, f, c);
        return o < 0 || mark[static_cast<size_t>(o)] != id;
      });
  }
  return sel;
}

FaceSelection hex_region_selection(const Mesh& m) {
  Csr<int32_t> hex;
  std::vector<int32_t> cells;
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (m.is_hex(c)) cells.push_back(static_cast<int32_t>(c));
  hex.push_row(cells.begin(), cells.end());
  return cell_set_selection(m, hex);
}

FaceSelection patch_selection(const Mesh& m, const BaseComplex& bc) {
  FaceSelection sel;
  sel.separate_ids = true;
  for (size_t p = 0; p < bc.num_patches(); ++p) {
    // Orient the whole patch out of the component on one of its sides, so its faces agree.
    const int32_t side = bc.patch_components[p][0];
    for (int32_t f : bc.patch_faces[p]) {
      const auto fc = m.face_cells[f];
      const int32_t cell = bc.cell_component[fc[0]] == side || fc[1] < 0 ? fc[0] : fc[1];
      sel.faces.push_back(f);
      sel.cells.push_back(cell);
      sel.reversed.push_back(reversed_for_outward(m, f, cell) ? 1 : 0);
      sel.ids.push_back(static_cast<int32_t>(p));
    }
  }
  return sel;
}

FaceSelection component_selection(const Mesh& m, const BaseComplex& bc) {
  FaceSelection sel;
  sel.separate_ids = true;
  // Non-separation faces are inside a component, so the separation faces of a component's cells
  // are exactly its boundary, seen from inside (a self-adjacent face from both sides).
  const auto& sep = bc.face_separation;
  for (size_t k = 0; k < bc.num_components(); ++k)
    for (int32_t c : bc.component_cells[k])
      add_cell_faces(m, c, static_cast<int32_t>(k), sel, [&](int32_t f) { return sep[static_cast<size_t>(f)] != 0; });
  return sel;
}

FaceSelection sheet_selection(const Mesh& m, const Sheets& sheets, std::optional<int32_t> sheet) {
  return cell_set_selection(m, sheets.sheet_cells, sheet);
}

FaceSelection sheet_component_selection(const Mesh& m, const BaseComplex& bc, const Sheets& sheets, int32_t sheet) {
  FaceSelection sel;
  sel.separate_ids = true;
  std::vector<uint8_t> in(m.num_cells(), 0);
  const auto cells = sheets.sheet_cells[static_cast<size_t>(sheet)];
  for (int32_t c : cells) in[static_cast<size_t>(c)] = 1;
  const auto& comp = bc.cell_component;
  for (int32_t c : cells) {
    const int32_t k = comp[static_cast<size_t>(c)];
    add_cell_faces(m, c, k, sel, [&](int32_t f) {
      const int32_t o = across(m, f, c);
      return o < 0 || !in[static_cast<size_t>(o)] || comp[static_cast<size_t>(o)] != k;
    });
  }
  return sel;
}

}  // namespace hbc
