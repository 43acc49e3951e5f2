#include "hbc/render_geometry.hpp"

#include "hbc/region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hbc {

namespace {

constexpr std::array<std::pair<std::string_view, SoupKind>, 9> kSoupNames{{
    {"cells", SoupKind::Cells},
    {"components", SoupKind::Components},
    {"sheets", SoupKind::Sheets},
    {"subsheets", SoupKind::Subsheets},
    {"sheet", SoupKind::Sheet},
    {"sheet_non_hex", SoupKind::SheetNonHex},
    {"non_hex", SoupKind::NonHex},
    {"boundary", SoupKind::Boundary},
    {"hex", SoupKind::Hex},
}};

}  // namespace

SoupKind soup_kind_from_name(std::string_view name) {
  for (const auto& [n, k] : kSoupNames)
    if (n == name) return k;
  std::string msg = "unknown soup kind '" + std::string(name) + "'; expected one of:";
  for (const auto& [n, k] : kSoupNames) (msg += ' ') += n;
  throw std::invalid_argument(msg);
}

bool soup_kind_needs_sheet(SoupKind kind) {
  return kind == SoupKind::Subsheets || kind == SoupKind::Sheet || kind == SoupKind::SheetNonHex;
}

bool soup_kind_needs_analysis(SoupKind kind) {
  return kind != SoupKind::Cells && kind != SoupKind::NonHex && kind != SoupKind::Hex && kind != SoupKind::Boundary;
}

FaceSelection soup_faces(const Mesh& m, const Analysis& a, SoupKind kind, std::optional<int32_t> sheet) {
  if (soup_kind_needs_sheet(kind) && !sheet) {
    const auto named = std::find_if(kSoupNames.begin(), kSoupNames.end(), [&](const auto& nk) { return nk.second == kind; });
    throw std::invalid_argument("the soup kind '" + std::string(named->first) + "' needs a sheet");
  }
  switch (kind) {
    case SoupKind::Cells: {
      std::vector<int32_t> all(m.num_cells());
      for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int32_t>(c);
      return cells_selection(m, all);
    }
    case SoupKind::NonHex: {
      std::vector<int32_t> non_hex;
      for (size_t c = 0; c < m.num_cells(); ++c)
        if (!m.is_hex(c)) non_hex.push_back(static_cast<int32_t>(c));
      return cells_selection(m, non_hex);
    }
    case SoupKind::Components: return component_selection(m, a.complex);
    case SoupKind::Sheets:
      if (!a.sheet_stage) throw std::invalid_argument("the analysis was run without sheets");
      return sheet_selection(m, a.sheet_stage->sheets);
    case SoupKind::Subsheets: return cell_set_selection(m, require_subsheets(a, *sheet).cells);
    case SoupKind::Sheet: return sheet_component_selection(m, a.complex, require_sheet(a, *sheet).sheets, *sheet);
    case SoupKind::SheetNonHex: {
      const auto cells = require_sheet(a, *sheet).sheets.sheet_non_hex_cells[static_cast<size_t>(*sheet)];
      return cells_selection(m, {cells.begin(), cells.end()});
    }
    case SoupKind::Boundary: return boundary_selection(m);
    case SoupKind::Hex: return hex_region_selection(m);
  }
  throw std::invalid_argument("unknown soup kind");
}

BlockSoup build_soup(const Mesh& m, const FaceSelection& in, double shrink) {
  if (!(shrink >= 0.0 && shrink < 1.0))
    throw std::invalid_argument("shrink must be in [0, 1), not " + std::to_string(shrink));
  const size_t n = in.faces.size();
  if (in.ids.size() != n || in.reversed.size() != n || in.cells.size() != n)
    throw std::invalid_argument("face selection: faces, cells, reversed and ids differ in length");
  int32_t num_owners = 0;
  size_t corners = 0;  // face corners: the soup's face_vertices items and an upper bound on its points
  for (size_t i = 0; i < n; ++i) {
    if (in.ids[i] < 0) throw std::invalid_argument("face selection: negative id");
    if (in.faces[i] < 0 || static_cast<size_t>(in.faces[i]) >= m.num_faces())
      throw std::invalid_argument("face selection: face id out of range: " + std::to_string(in.faces[i]));
    if (in.cells[i] < 0 || static_cast<size_t>(in.cells[i]) >= m.num_cells())
      throw std::invalid_argument("face selection: cell id out of range: " + std::to_string(in.cells[i]));
    num_owners = std::max(num_owners, in.ids[i] + 1);
    corners += static_cast<size_t>(m.face_verts.count(static_cast<size_t>(in.faces[i])));
  }
  // Stable counting sort by owner, so each owner's faces form one run in selection order.
  std::vector<int32_t> start(static_cast<size_t>(num_owners) + 1, 0);
  for (int32_t o : in.ids) ++start[static_cast<size_t>(o) + 1];
  for (size_t o = 0; o < static_cast<size_t>(num_owners); ++o) start[o + 1] += start[o];
  std::vector<int32_t> order(n);
  {
    std::vector<int32_t> next(start.begin(), start.end() - 1);
    for (size_t i = 0; i < n; ++i) order[static_cast<size_t>(next[static_cast<size_t>(in.ids[i])]++)] = static_cast<int32_t>(i);
  }

  BlockSoup s;
  s.face_owner.reserve(n);
  s.face_source.reserve(n);
  s.face_cell.reserve(n);
  s.face_vertices.reserve(n, corners);
  s.point_vertex.reserve(corners);
  s.positions.reserve(3 * corners);
  // Mesh vertex -> point of the current owner; `seen` holds the owner that made the point, so the
  // table needs no clearing between owners.
  std::vector<int32_t> point_of(m.num_vertices(), -1), seen(m.num_vertices(), -1);
  for (int32_t o = 0; o < num_owners; ++o) {
    const size_t first_point = s.point_vertex.size();
    for (int32_t k = start[static_cast<size_t>(o)]; k < start[static_cast<size_t>(o) + 1]; ++k) {
      const size_t i = static_cast<size_t>(order[static_cast<size_t>(k)]);
      const auto loop = m.face_verts[static_cast<size_t>(in.faces[i])];
      s.face_owner.push_back(o);
      s.face_source.push_back(in.faces[i]);
      s.face_cell.push_back(in.cells[i]);
      for (size_t j = 0; j < loop.size(); ++j) {
        const int32_t v = in.reversed[i] ? loop[loop.size() - 1 - j] : loop[j];
        if (seen[static_cast<size_t>(v)] != o) {
          seen[static_cast<size_t>(v)] = o;
          point_of[static_cast<size_t>(v)] = static_cast<int32_t>(s.point_vertex.size());
          s.point_vertex.push_back(v);
        }
        s.face_vertices.items.push_back(point_of[static_cast<size_t>(v)]);
      }
      s.face_vertices.offsets.push_back(static_cast<int32_t>(s.face_vertices.items.size()));
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

BlockSoup block_soup(const Mesh& m, const Analysis& a, SoupKind kind, std::optional<int32_t> sheet, double shrink) {
  return build_soup(m, soup_faces(m, a, kind, sheet), shrink);
}

BlockSoup kept_surface_soup(const Mesh& m, std::span<const uint8_t> kept, double shrink) {
  if (kept.size() != m.num_cells())
    throw std::invalid_argument("kept: " + std::to_string(kept.size()) + " entries for " +
                                std::to_string(m.num_cells()) + " cells");
  // One pass over the faces in order (streaming face_cells): this runs on every drag of a slicing
  // plane, and a pass over the cells' faces reads face_cells at random, several times slower.
  FaceSelection out;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const auto [a, b] = m.face_cells[f];
    const bool ka = kept[static_cast<size_t>(a)] != 0, kb = b >= 0 && kept[static_cast<size_t>(b)] != 0;
    if (ka == kb) continue;
    const int32_t c = ka ? a : b;
    out.ids.push_back(c);
    out.faces.push_back(static_cast<int32_t>(f));
    out.cells.push_back(c);
    out.reversed.push_back(reversed_for_outward(m, static_cast<int32_t>(f), c) ? 1 : 0);
  }
  return build_soup(m, out, shrink);
}

std::vector<double> cell_centroids(const Mesh& m) {
  const size_t nc = m.num_cells();
  std::vector<double> out(3 * nc, 0.0);
  // `seen` holds the last cell that counted a vertex, so no clearing is needed between cells.
  std::vector<int32_t> seen(m.num_vertices(), -1);
  for (size_t c = 0; c < nc; ++c) {
    size_t count = 0;
    for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i)
      for (int32_t v : m.face_verts[static_cast<size_t>(m.cell_faces.items[static_cast<size_t>(i)])]) {
        if (seen[static_cast<size_t>(v)] == static_cast<int32_t>(c)) continue;
        seen[static_cast<size_t>(v)] = static_cast<int32_t>(c);
        ++count;
        for (int d = 0; d < 3; ++d) out[3 * c + d] += m.points[3 * static_cast<size_t>(v) + d];
      }
    if (count)
      for (int d = 0; d < 3; ++d) out[3 * c + d] /= static_cast<double>(count);
  }
  return out;
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
    out.unmatched_vertices.push_row(k.unmatched_vertices.begin(), k.unmatched_vertices.end());
    out.shared_vertices.push_row(k.shared_vertices.begin(), k.shared_vertices.end());
    out.self_parallel_curves.push_row(k.self_parallel_curves.begin(), k.self_parallel_curves.end());
    comps.clear();
    for (int32_t u : k.self_intersecting_blocks) comps.push_back(domain.block_component[static_cast<size_t>(u)]);
    std::sort(comps.begin(), comps.end());
    comps.erase(std::unique(comps.begin(), comps.end()), comps.end());
    out.self_intersecting_components.push_row(comps.begin(), comps.end());
  }
  return out;
}

Csr<int32_t> blocks_as_components(const SheetDomain& domain, const Csr<int32_t>& blocks) {
  Csr<int32_t> out;
  std::vector<int32_t> comps;
  for (size_t r = 0; r < blocks.rows(); ++r) {
    comps.clear();
    for (int32_t u : blocks[r]) comps.push_back(domain.block_component[static_cast<size_t>(u)]);
    std::sort(comps.begin(), comps.end());
    comps.erase(std::unique(comps.begin(), comps.end()), comps.end());
    out.push_row(comps.begin(), comps.end());
  }
  return out;
}

}  // namespace hbc
