#include "hbc/render_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hbc {

namespace {

constexpr std::array<std::pair<std::string_view, SoupKind>, 8> kSoupNames{{
    {"cells", SoupKind::Cells},
    {"components", SoupKind::Components},
    {"sheets", SoupKind::Sheets},
    {"subsheets", SoupKind::Subsheets},
    {"sheet", SoupKind::Sheet},
    {"sheet_non_hex", SoupKind::SheetNonHex},
    {"non_hex", SoupKind::NonHex},
    {"boundary", SoupKind::Boundary},
}};

// The cell on the other side of face f from cell c (-1 on the boundary).
int32_t across(const Mesh& m, int32_t f, int32_t c) {
  const auto [a, b] = m.face_cells[static_cast<size_t>(f)];
  return a == c ? b : a;
}

// Appends the faces of cell c (oriented out of c) for which keep(face) holds.
template <class Keep>
void add_cell_faces(const Mesh& m, int32_t c, int32_t owner, OwnedFaces& out, Keep keep) {
  for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) {
    const int32_t f = m.cell_faces.items[static_cast<size_t>(i)];
    if (!keep(f)) continue;
    out.owner.push_back(owner);
    out.face.push_back(f);
    out.reversed.push_back(m.cell_face_flip[static_cast<size_t>(i)]);
  }
}

// Each row of `sets` is one block (owner = row id): the faces of its cells whose other side is
// not in the row. `mark` (nc, scratch) remembers the row a cell was last seen in, so rows may
// share cells and no clearing is needed between rows.
void add_cell_set_boundaries(const Mesh& m, const Csr<int32_t>& sets, OwnedFaces& out) {
  std::vector<int32_t> mark(m.num_cells(), -1);
  for (size_t r = 0; r < sets.rows(); ++r) {
    const int32_t owner = static_cast<int32_t>(r);
    for (int32_t c : sets[r]) mark[static_cast<size_t>(c)] = owner;
    for (int32_t c : sets[r])
      add_cell_faces(m, c, owner, out, [&](int32_t f) {
        const int32_t o = across(m, f, c);
        return o < 0 || mark[static_cast<size_t>(o)] != owner;
      });
  }
}

void require_sheet(const Analysis& a, int32_t sheet) {
  if (!a.has_sheets) throw std::invalid_argument("the analysis was run without sheets");
  if (sheet < 0 || static_cast<size_t>(sheet) >= a.sheets.size())
    throw std::invalid_argument("sheet " + std::to_string(sheet) + " out of range: the mesh has " +
                                std::to_string(a.sheets.size()) + " sheets");
}

const Subsheets& require_subsheets(const Analysis& a, int32_t sheet) {
  require_sheet(a, sheet);
  if (!a.has_subsheets) throw std::invalid_argument("the analysis was run without subsheets");
  const Subsheets* sub = a.subsheets_of(sheet);
  if (!sub) throw std::invalid_argument("sheet " + std::to_string(sheet) + " is not self-intersecting");
  return *sub;
}

}  // namespace

SoupKind soup_kind_from_name(std::string_view name) {
  for (const auto& [n, k] : kSoupNames)
    if (n == name) return k;
  std::string msg = "unknown block set '" + std::string(name) + "'; expected one of:";
  for (const auto& [n, k] : kSoupNames) (msg += ' ') += n;
  throw std::invalid_argument(msg);
}

bool soup_kind_needs_sheet(SoupKind kind) {
  return kind == SoupKind::Subsheets || kind == SoupKind::Sheet || kind == SoupKind::SheetNonHex;
}

OwnedFaces soup_faces(const Mesh& m, const Analysis& a, SoupKind kind, int32_t sheet) {
  OwnedFaces out;
  const int32_t nc = static_cast<int32_t>(m.num_cells());
  const auto all = [](int32_t) { return true; };
  switch (kind) {
    case SoupKind::Cells:
      for (int32_t c = 0; c < nc; ++c) add_cell_faces(m, c, c, out, all);
      break;
    case SoupKind::NonHex:
      for (int32_t c = 0; c < nc; ++c)
        if (!m.is_hex(static_cast<size_t>(c))) add_cell_faces(m, c, c, out, all);
      break;
    case SoupKind::Components: {
      // Non-separation faces are inside a component, so the separation faces of a component's
      // cells are exactly its boundary, seen from inside (a self-adjacent face from both sides).
      const auto& sep = a.complex.face_separation;
      for (size_t k = 0; k < a.complex.num_components(); ++k)
        for (int32_t c : a.complex.component_cells[k])
          add_cell_faces(m, c, static_cast<int32_t>(k), out, [&](int32_t f) { return sep[static_cast<size_t>(f)] != 0; });
      break;
    }
    case SoupKind::Sheets:
      if (!a.has_sheets) throw std::invalid_argument("the analysis was run without sheets");
      add_cell_set_boundaries(m, a.sheets.sheet_cells, out);
      break;
    case SoupKind::Subsheets:
      add_cell_set_boundaries(m, require_subsheets(a, sheet).cells, out);
      break;
    case SoupKind::Sheet: {
      require_sheet(a, sheet);
      // One block per component the sheet passes through: at the mesh level a sheet is a slab
      // of a component, at the complex level whole components.
      std::vector<uint8_t> in(m.num_cells(), 0);
      const auto cells = a.sheets.sheet_cells[static_cast<size_t>(sheet)];
      for (int32_t c : cells) in[static_cast<size_t>(c)] = 1;
      const auto& comp = a.complex.cell_component;
      for (int32_t c : cells) {
        const int32_t k = comp[static_cast<size_t>(c)];
        add_cell_faces(m, c, k, out, [&](int32_t f) {
          const int32_t o = across(m, f, c);
          return o < 0 || !in[static_cast<size_t>(o)] || comp[static_cast<size_t>(o)] != k;
        });
      }
      break;
    }
    case SoupKind::SheetNonHex:
      require_sheet(a, sheet);
      for (int32_t c : a.sheets.sheet_non_hex_cells[static_cast<size_t>(sheet)]) add_cell_faces(m, c, c, out, all);
      break;
    case SoupKind::Boundary:
      for (size_t f = 0; f < m.num_faces(); ++f) {
        if (!m.face_boundary[f]) continue;
        const int32_t c = m.face_cells[f][0];
        add_cell_faces(m, c, static_cast<int32_t>(m.cell_type[static_cast<size_t>(c)]), out,
                       [&](int32_t g) { return g == static_cast<int32_t>(f); });
      }
      break;
  }
  return out;
}

BlockSoup build_soup(const Mesh& m, const OwnedFaces& in, double shrink) {
  if (!(shrink >= 0.0 && shrink < 1.0))
    throw std::invalid_argument("shrink must be in [0, 1), not " + std::to_string(shrink));
  const size_t n = in.face.size();
  if (in.owner.size() != n || in.reversed.size() != n)
    throw std::invalid_argument("owned faces: owner, face and reversed differ in length");
  int32_t num_owners = 0;
  size_t corners = 0;  // face corners: the soup's face_vertices and an upper bound on its points
  for (size_t i = 0; i < n; ++i) {
    if (in.owner[i] < 0) throw std::invalid_argument("owned faces: negative owner");
    if (in.face[i] < 0 || static_cast<size_t>(in.face[i]) >= m.num_faces())
      throw std::invalid_argument("owned faces: face id out of range: " + std::to_string(in.face[i]));
    num_owners = std::max(num_owners, in.owner[i] + 1);
    corners += static_cast<size_t>(m.face_verts.count(static_cast<size_t>(in.face[i])));
  }
  // Stable counting sort by owner, so each owner's faces form one run in selection order.
  std::vector<int32_t> start(static_cast<size_t>(num_owners) + 1, 0);
  for (int32_t o : in.owner) ++start[static_cast<size_t>(o) + 1];
  for (size_t o = 0; o < static_cast<size_t>(num_owners); ++o) start[o + 1] += start[o];
  std::vector<int32_t> order(n);
  {
    std::vector<int32_t> next(start.begin(), start.end() - 1);
    for (size_t i = 0; i < n; ++i) order[static_cast<size_t>(next[static_cast<size_t>(in.owner[i])]++)] = static_cast<int32_t>(i);
  }

  BlockSoup s;
  s.face_sizes.reserve(n);
  s.face_owner.reserve(n);
  s.face_source.reserve(n);
  s.face_vertices.reserve(corners);
  s.point_vertex.reserve(corners);
  s.positions.reserve(3 * corners);
  // Mesh vertex -> point of the current owner; `seen` holds the owner that made the point, so the
  // table needs no clearing between owners.
  std::vector<int32_t> point_of(m.num_vertices(), -1), seen(m.num_vertices(), -1);
  for (int32_t o = 0; o < num_owners; ++o) {
    const size_t first_point = s.point_vertex.size();
    for (int32_t k = start[static_cast<size_t>(o)]; k < start[static_cast<size_t>(o) + 1]; ++k) {
      const size_t i = static_cast<size_t>(order[static_cast<size_t>(k)]);
      const auto loop = m.face_verts[static_cast<size_t>(in.face[i])];
      s.face_sizes.push_back(static_cast<int32_t>(loop.size()));
      s.face_owner.push_back(o);
      s.face_source.push_back(in.face[i]);
      for (size_t j = 0; j < loop.size(); ++j) {
        const int32_t v = in.reversed[i] ? loop[loop.size() - 1 - j] : loop[j];
        if (seen[static_cast<size_t>(v)] != o) {
          seen[static_cast<size_t>(v)] = o;
          point_of[static_cast<size_t>(v)] = static_cast<int32_t>(s.point_vertex.size());
          s.point_vertex.push_back(v);
        }
        s.face_vertices.push_back(point_of[static_cast<size_t>(v)]);
      }
    }
    const size_t np = s.point_vertex.size() - first_point;
    if (np == 0) continue;
    std::array<double, 3> c{0, 0, 0};
    for (size_t p = first_point; p < s.point_vertex.size(); ++p)
      for (int d = 0; d < 3; ++d) c[d] += m.points[3 * static_cast<size_t>(s.point_vertex[p]) + d];
    for (double& x : c) x /= static_cast<double>(np);
    for (size_t p = first_point; p < s.point_vertex.size(); ++p)
      for (int d = 0; d < 3; ++d) {
        const double x = m.points[3 * static_cast<size_t>(s.point_vertex[p]) + d];
        // shrink == 0 must reproduce the vertex exactly, not c + (x - c) rounded.
        s.positions.push_back(static_cast<float>(shrink == 0.0 ? x : c[d] + (1.0 - shrink) * (x - c[d])));
      }
  }
  return s;
}

BlockSoup block_soup(const Mesh& m, const Analysis& a, SoupKind kind, int32_t sheet, double shrink) {
  return build_soup(m, soup_faces(m, a, kind, sheet), shrink);
}

std::vector<float> polyline_positions(const Mesh& m, std::span<const int32_t> offsets,
                                      std::span<const int32_t> vertices) {
  if (offsets.empty() || offsets.front() != 0 || static_cast<size_t>(offsets.back()) != vertices.size())
    throw std::invalid_argument("polyline offsets must start at 0 and end at len(vertices)");
  if (std::adjacent_find(offsets.begin(), offsets.end(), [](int32_t x, int32_t y) { return y < x; }) != offsets.end())
    throw std::invalid_argument("polyline offsets must not decrease");
  std::vector<float> out;
  out.reserve(3 * vertices.size());
  for (int32_t v : vertices) {
    if (v < 0 || static_cast<size_t>(v) >= m.num_vertices())
      throw std::invalid_argument("polyline vertex id out of range: " + std::to_string(v));
    for (int d = 0; d < 3; ++d) out.push_back(static_cast<float>(m.points[3 * static_cast<size_t>(v) + d]));
  }
  return out;
}

ClassArrays flatten_classes(const SheetDomain& domain, std::span<const SheetClass> classes) {
  ClassArrays out;
  std::vector<int32_t> comps;
  for (const SheetClass& k : classes) {
    out.type.push_back(static_cast<uint8_t>(k.type));
    out.flags.insert(out.flags.end(), {uint8_t(k.type1), uint8_t(k.type2), uint8_t(k.type3)});
    out.unmatched.push_row(k.unmatched_vertices.begin(), k.unmatched_vertices.end());
    out.shared.push_row(k.shared_vertices.begin(), k.shared_vertices.end());
    out.self_parallel.push_row(k.self_parallel_curves.begin(), k.self_parallel_curves.end());
    comps.clear();
    for (int32_t u : k.self_intersecting_units) comps.push_back(domain.unit_component[static_cast<size_t>(u)]);
    std::sort(comps.begin(), comps.end());
    comps.erase(std::unique(comps.begin(), comps.end()), comps.end());
    out.self_intersecting.push_row(comps.begin(), comps.end());
  }
  return out;
}

Csr<int32_t> units_as_components(const SheetDomain& domain, const Csr<int32_t>& units) {
  Csr<int32_t> out;
  std::vector<int32_t> comps;
  for (size_t r = 0; r < units.rows(); ++r) {
    comps.clear();
    for (int32_t u : units[r]) comps.push_back(domain.unit_component[static_cast<size_t>(u)]);
    std::sort(comps.begin(), comps.end());
    comps.erase(std::unique(comps.begin(), comps.end()), comps.end());
    out.push_row(comps.begin(), comps.end());
  }
  return out;
}

std::vector<int32_t> region_cells(const Mesh& m, const Analysis& a, int32_t sheet, int32_t subsheet) {
  std::vector<int32_t> cells;
  if (sheet < 0) {
    if (subsheet >= 0) throw std::invalid_argument("a subsheet needs its sheet");
    cells.resize(m.num_cells());
    for (size_t c = 0; c < cells.size(); ++c) cells[c] = static_cast<int32_t>(c);
    return cells;
  }
  require_sheet(a, sheet);
  if (subsheet < 0) {
    for (auto row : {a.sheets.sheet_cells[static_cast<size_t>(sheet)], a.sheets.sheet_non_hex_cells[static_cast<size_t>(sheet)]})
      cells.insert(cells.end(), row.begin(), row.end());
  } else {
    const Subsheets& sub = require_subsheets(a, sheet);
    if (static_cast<size_t>(subsheet) >= sub.size())
      throw std::invalid_argument("subsheet " + std::to_string(subsheet) + " out of range: sheet " +
                                  std::to_string(sheet) + " has " + std::to_string(sub.size()) + " subsheets");
    const auto own = sub.cells[static_cast<size_t>(subsheet)];
    cells.assign(own.begin(), own.end());
    // A sheet's adjacent non-hex cells are those touching its curves; the same rule for a subsheet.
    for (int32_t k : sub.curves[static_cast<size_t>(subsheet)]) {
      const auto nh = a.domain.curve_non_hex_cells[static_cast<size_t>(k)];
      cells.insert(cells.end(), nh.begin(), nh.end());
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

VsgWireframe region_wireframe(const Mesh& m, const Analysis& a, Level level,
                              const WireframeOptions& options, int32_t sheet, int32_t subsheet) {
  CellComplex cx;
  if (sheet < 0 && subsheet < 0) {
    cx = level == Level::Complex ? complex_from_base(m, a.complex) : complex_from_mesh(m);
  } else {
    const std::vector<int32_t> cells = region_cells(m, a, sheet, subsheet);
    cx = level == Level::Complex ? complex_from_base(m, a.complex, components_of_cells(a.complex, cells))
                                        : complex_from_mesh(m, cells);
  }
  return vsg_wireframe(cx, options);
}

}  // namespace hbc
