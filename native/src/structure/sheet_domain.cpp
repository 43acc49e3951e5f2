// The block / curve structure sheets are computed on, at the base complex level or the mesh level.
#include <algorithm>

#include "hbc/sheets.hpp"
#include "parallel/parallel.hpp"

namespace hbc {
namespace {

void push_sorted_unique(std::vector<int32_t>& v, Csr<int32_t>& out) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  out.push_row(v.begin(), v.end());
}

bool share_end(const std::array<int32_t, 2>& a, const std::array<int32_t, 2>& b) {
  if (a[0] < 0 || b[0] < 0) return false;
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

// Parallel pairs of every quad (4 curves, no shared end within a pair); `quads` rows list the
// curves of each quad.
Csr<int32_t> parallels_from_quads(const Csr<int32_t>& quads, const std::vector<std::array<int32_t, 2>>& ends,
                                  size_t ncurves, const Threads& par) {
  // Grouped by curve, then each (short) row sorted and deduped: no global sort of all pairs.
  Csr<int32_t> out = detail::group_values_by_key(quads.rows(), ncurves, par, [&](size_t q, auto&& emit) {
    const auto c = quads[q];
    if (c.size() != 4) return;
    for (size_t i = 0; i < 4; ++i)
      for (size_t j = i + 1; j < 4; ++j) {
        if (ends[c[i]][0] < 0 || ends[c[j]][0] < 0 || share_end(ends[c[i]], ends[c[j]])) continue;
        emit(c[i], c[j]);
        emit(c[j], c[i]);
      }
  });
  // Rows sorted and deduped in place by ranges of curves. Two quads rarely share two curves, so
  // the rows mostly keep every entry (all of them on the split grid's 12M): they are then left as
  // they are, and otherwise compacted in place, without a second table of as many fresh pages.
  std::vector<int32_t> kept(ncurves);
  const std::vector<int64_t> at = detail::range_starts<int64_t>(ncurves, par, [&](size_t b, size_t e) {
    int64_t n = 0;
    for (size_t k = b; k < e; ++k) {
      auto r = out.row(k);
      std::sort(r.begin(), r.end());
      kept[k] = static_cast<int32_t>(std::unique(r.begin(), r.end()) - r.begin());
      n += kept[k];
    }
    return n;
  });
  if (at.back() == static_cast<int64_t>(out.items.size())) return out;
  int32_t to = 0, from = 0;
  for (size_t k = 0; k < ncurves; ++k) {
    const int32_t row = from;
    from = out.offsets[k + 1];
    std::copy(out.items.begin() + row, out.items.begin() + row + kept[k], out.items.begin() + to);
    to += kept[k];
    out.offsets[k + 1] = to;
  }
  out.items.resize(static_cast<size_t>(to));
  return out;
}

// Row per curve listing map[o] for each owner o whose row of `owner_curves` (sorted, distinct)
// holds the curve, skipping map[o] < 0: a transpose through a monotonic map, so rows come out
// sorted and distinct.
Csr<int32_t> curve_owner_rows(const Csr<int32_t>& owner_curves, const std::vector<int32_t>& map, size_t ncurves,
                              const Threads& par) {
  return detail::transpose_mapped(
      owner_curves, ncurves, par, [&](size_t o) { return map[o]; }, [](int32_t k) { return k; });
}

// Level complex: the blocks are the hex components, the curves the base complex's curves and the
// quads its patches.
void complex_level_domain(const Mesh& m, const BaseComplex& bc, const Threads& par, SheetDomain& d) {
  const size_t nc = m.num_cells(), nf = m.num_faces();
  std::vector<int32_t> buf;
  std::vector<int32_t> comp_block(bc.num_components(), -1);
  for (size_t k = 0; k < bc.num_components(); ++k) {
    if (bc.component_kind[k] == ComponentKind::NonHex) continue;
    comp_block[k] = static_cast<int32_t>(d.block_component.size());
    d.block_component.push_back(static_cast<int32_t>(k));
    d.block_cells.push_row(bc.component_cells[k]);
  }
  detail::parallel_ranges(nc, par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) d.cell_block[c] = m.is_hex(c) ? comp_block[bc.cell_component[c]] : -1;
  });
  // comp_block only grows with the component, so the kept neighbours stay sorted and distinct.
  d.block_adjacency.reserve(d.block_component.size(), bc.component_adjacency.items.size());
  for (int32_t k : d.block_component) {
    buf.clear();
    for (int32_t j : bc.component_adjacency[k])
      if (comp_block[j] >= 0) buf.push_back(comp_block[j]);
    d.block_adjacency.push_row(buf.begin(), buf.end());
  }
  d.curve_edges = bc.curve_edges;
  // Plain resize: with huge-page advice (resize_touched) this array took 8-12 ms on the
  // cylinder's 822k curves, against 2 ms without, likely because advised huge pages come
  // untouched from the system where plain ones reuse the pages the stages before freed.
  d.curve_ends.resize(bc.curve_verts.rows());
  detail::parallel_ranges(bc.curve_verts.rows(), par, [&](size_t b, size_t e, int) {
    for (size_t k = b; k < e; ++k) {
      const auto vs = bc.curve_verts[k];
      d.curve_ends[k] = bc.curve_closed[k] ? std::array<int32_t, 2>{-1, -1} : std::array<int32_t, 2>{vs.front(), vs.back()};
    }
  });
  detail::parallel_ranges(nf, par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) {
      const auto fc = m.face_cells[f];
      d.face_joins[f] = !bc.face_separation[f] && fc[1] >= 0 && m.is_hex(fc[0]) && m.is_hex(fc[1]);
    }
  });
  d.curve_parallels = parallels_from_quads(bc.patch_curves, d.curve_ends, d.curve_edges.rows(), par);
  // Blocks and non-hex cells at each curve, without walking the fans of its edges: a cell at a
  // curve edge has both its faces there among the separation faces, so the curve is one of its
  // component's curves, and conversely. A non-hex cell is a component of its own, and
  // components are numbered by their lowest cell, so both maps below keep the order.
  std::vector<int32_t> non_hex_cell(bc.num_components(), -1);
  for (size_t k = 0; k < bc.num_components(); ++k)
    if (bc.component_kind[k] == ComponentKind::NonHex) non_hex_cell[k] = bc.component_cells[k][0];
  d.curve_blocks = curve_owner_rows(bc.component_curves, comp_block, d.curve_edges.rows(), par);
  d.curve_non_hex_cells = curve_owner_rows(bc.component_curves, non_hex_cell, d.curve_edges.rows(), par);
  // The transpose of curve_blocks is each hex component's own curves (sorted, distinct), whose
  // rows are copied in order instead of scattered curve by curve.
  d.block_curves.reserve(d.block_component.size(), 0);
  size_t n = 0;
  for (int32_t k : d.block_component) n += bc.component_curves[k].size();
  d.block_curves.items.reserve(n);
  for (int32_t k : d.block_component) {
    const auto row = bc.component_curves[k];
    d.block_curves.items.insert(d.block_curves.items.end(), row.begin(), row.end());
    d.block_curves.offsets.push_back(static_cast<int32_t>(d.block_curves.items.size()));
  }
}

// Level mesh: the blocks are the hex cells, the curves the mesh edges and the quads the faces of
// hex cells.
void mesh_level_domain(const Mesh& m, const BaseComplex& bc, const Threads& par, SheetDomain& d) {
  const size_t nc = m.num_cells(), nf = m.num_faces();
  std::vector<int32_t> buf;
  for (size_t c = 0; c < nc; ++c) {
    if (!m.is_hex(c)) continue;
    d.cell_block[c] = static_cast<int32_t>(d.block_component.size());
    d.block_component.push_back(bc.cell_component[c]);
    const int32_t row[1] = {static_cast<int32_t>(c)};
    d.block_cells.push_row(row, row + 1);
  }
  for (size_t u = 0; u < d.block_cells.rows(); ++u) {
    const int32_t c = d.block_cells[u][0];
    buf.clear();
    for (int32_t f : m.cell_faces[c]) {
      const auto fc = m.face_cells[f];
      const int32_t o = fc[0] == c ? fc[1] : fc[0];
      if (o >= 0 && d.cell_block[o] >= 0) buf.push_back(d.cell_block[o]);
    }
    push_sorted_unique(buf, d.block_adjacency);
  }
  for (size_t e = 0; e < m.num_edges(); ++e) {
    const int32_t row[1] = {static_cast<int32_t>(e)};
    d.curve_edges.push_row(row, row + 1);
    d.curve_ends.push_back(m.edge_verts[e]);
  }
  // Quads: faces of hex cells, with their edges as the curves.
  Csr<int32_t> quads;
  for (size_t f = 0; f < nf; ++f) {
    const auto fc = m.face_cells[f];
    const bool hex_face = m.is_hex(fc[0]) || (fc[1] >= 0 && m.is_hex(fc[1]));
    if (hex_face && m.face_verts.count(f) == 4) quads.push_row(m.face_edges(f));
  }
  d.curve_parallels = parallels_from_quads(quads, d.curve_ends, m.num_edges(), par);
  // The blocks holding each curve, and the non-hex cells touching it, from the edge fans.
  EdgeFan fan;
  std::vector<int32_t> non_hex;
  for (size_t k = 0; k < d.curve_edges.rows(); ++k) {
    buf.clear();
    non_hex.clear();
    for (int32_t e : d.curve_edges[k]) {
      edge_fan(m, e, fan);
      for (int32_t c : fan.cells) {
        if (d.cell_block[c] >= 0) buf.push_back(d.cell_block[c]);
        if (!m.is_hex(c)) non_hex.push_back(c);
      }
    }
    push_sorted_unique(buf, d.curve_blocks);
    push_sorted_unique(non_hex, d.curve_non_hex_cells);
  }
  d.block_curves = transpose(d.curve_blocks, d.block_cells.rows());
}

}  // namespace

SheetDomain sheet_domain(const Mesh& m, const BaseComplex& bc, Level level, const Threads& threads) {
  const Threads par = resolved(threads);
  SheetDomain d;
  d.level = level;
  d.cell_block.assign(m.num_cells(), -1);
  d.face_joins.assign(m.num_faces(), 0);
  if (level == Level::Complex) complex_level_domain(m, bc, par, d);
  else mesh_level_domain(m, bc, par, d);
  return d;
}

}  // namespace hbc
