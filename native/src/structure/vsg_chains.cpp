// The VSG (paper §5.1, "valence-based singularity graph"): irregular edges chained through a vertex
// along their unique straight continuation of the same valence; and what every step makes of
// chains: their mesh-vertex polylines and non-hex kinds.
#include "structure/vsg_chains.hpp"

#include <algorithm>
#include <utility>

#include "parallel/parallel.hpp"

namespace hbc::vsg {

// Each vertex fills its own slots: ranges of vertices in parallel.
std::vector<uint32_t> face_masks(const Region& r, const Threads& par) {
  const CellComplex& cx = r.cx;
  std::vector<uint32_t> mask(cx.vert_edges.items.size(), 0);
  detail::parallel_ranges(cx.num_vertices(), par, [&](size_t b, size_t e, int) {
    for (size_t v = b; v < e; ++v) {
      const auto row = cx.vert_edges[v];
      if (row.size() > 32) continue;
      uint32_t* m = mask.data() + cx.vert_edges.offsets[v];
      for (size_t i = 0; i < row.size(); ++i)
        for (size_t j = i + 1; j < row.size(); ++j)
          if (r.share_face(row[i], row[j])) m[i] |= uint32_t{1} << j, m[j] |= uint32_t{1} << i;
    }
  });
  return mask;
}

// Chains of the VSG rule: the unique straight continuation, when it has the same valence.
Chains valence_chains(const Region& r, const std::vector<uint8_t>& seed, const std::vector<uint8_t>& stop_vert,
                      const Threads& par) {
  return trace_chains(r.cx, seed, stop_vert, [&](int32_t v, int32_t e) {
    const int32_t f = straight_next(r, v, e, [](int32_t) { return true; });
    return f >= 0 && r.valence(f) == r.valence(e) ? f : -1;
  }, par);
}

std::vector<uint8_t> edge_flags(const CellComplex& cx, const Csr<int32_t>& rows) {
  std::vector<uint8_t> out(cx.num_edges(), 0);
  for (int32_t e : rows.items) out[e] = 1;
  return out;
}

namespace {

// Writes the mesh vertices of edge e walked from its end `from` at `out`, its first one only for
// the chain's first edge (otherwise it is the previous edge's last); returns the end of what it wrote.
int32_t* put_points(const CellComplex& cx, int32_t e, int32_t from, bool first, int32_t* out) {
  const auto pts = cx.edge_points[e];
  const bool forward = cx.edge_verts[e][0] == from;
  const size_t n = pts.size();
  for (size_t k = first ? 0 : 1; k < n; ++k) *out++ = forward ? pts[k] : pts[n - 1 - k];
  return out;
}

}  // namespace

// The mesh vertices along each chain (a closed complex edge: its own points). Rows are sized
// first, so ranges of chains then write their own rows in parallel.
Csr<int32_t> polylines(const CellComplex& cx, const Chains& ch, const Threads& par) {
  const size_t n = ch.edges.rows();
  Csr<int32_t> out;
  // A vector of its own, moved in: resizing the one-entry default offsets in place draws GCC 12's
  // -Warray-bounds false positive (the size it assumes for the default row is not n + 1).
  std::vector<int32_t> offsets(n + 1, 0);
  out.offsets = std::move(offsets);
  detail::parallel_ranges(n, par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) {
      int32_t size = 1;
      for (int32_t x : ch.edges[c]) size += cx.edge_points.count(x) - 1;
      out.offsets[c + 1] = size;
    }
  });
  for (size_t c = 0; c < n; ++c) out.offsets[c + 1] += out.offsets[c];
  out.items.resize(static_cast<size_t>(out.offsets[n]));
  detail::parallel_ranges(n, par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) {
      const auto es = ch.edges[c], vs = ch.verts[c];
      int32_t* at = out.items.data() + out.offsets[c];
      if (vs[0] < 0) {
        std::copy(cx.edge_points[es[0]].begin(), cx.edge_points[es[0]].end(), at);
        continue;
      }
      for (size_t i = 0; i < es.size(); ++i) at = put_points(cx, es[i], vs[i], i == 0, at);
    }
  });
  return out;
}

namespace {

// The non-hex kinds of each chain (VsgWireframe::non_hex): those of the non-hex cells around its
// edges and, for an open chain, around the edges at its two ends (every cell at a vertex holds an
// edge there: a mesh cell its own edges, a component the curves of its cells' edges, all of which
// end at a corner). edge_non_hex spares the look-up at the many edges with hex cells only around.
// A chain touches up to hundreds of non-hex cells (on a polyhedral mesh) but few distinct kinds, so
// the row is kept distinct as it grows, by a search in it, and sorted once at the end (sorting the
// kind of every touched cell cost 74 M instructions on eight_voronoi, whose whole wireframe stage
// takes 120 M without the kinds; this way 58 M).
// Adds the kinds of the non-hex cells at edge e (if it borders any) to `out`, each once.
void add_edge_kinds(const CellComplex& cx, int32_t e, std::vector<int32_t>& out) {
  if (!cx.edge_non_hex[e]) return;
  for (int32_t c : cx.edge_cells[e])
    if (cx.cell_non_hex[c] && std::find(out.begin(), out.end(), cx.cell_kind[c]) == out.end())
      out.push_back(cx.cell_kind[c]);
}

// The non-hex kinds around each vertex where a chain ends (empty rows elsewhere), each vertex
// scanned once: at a fan's axis k chains end, and scanning it per chain cost k².
Csr<int32_t> end_kinds(const CellComplex& cx, const Chains& ch, const Threads& par) {
  std::vector<uint8_t> end(cx.vert_edges.rows(), 0);
  for (size_t c = 0; c < ch.verts.rows(); ++c) {
    const auto vs = ch.verts[c];
    if (vs.front() != vs.back()) end[static_cast<size_t>(vs.front())] = end[static_cast<size_t>(vs.back())] = 1;
  }
  return detail::parallel_rows_of<int32_t, std::vector<int32_t>>(
      end.size(), par, [&](size_t v, Csr<int32_t>& out, std::vector<int32_t>& kinds) {
        kinds.clear();
        if (end[v])
          for (int32_t e : cx.vert_edges[v]) add_edge_kinds(cx, e, kinds);
        out.items.insert(out.items.end(), kinds.begin(), kinds.end());
      });
}

}  // namespace

Csr<int32_t> chain_kinds(const CellComplex& cx, const Chains& ch, const Threads& par) {
  const Csr<int32_t> at_end = end_kinds(cx, ch, par);
  return detail::parallel_rows_of<int32_t, std::vector<int32_t>>(
      ch.edges.rows(), par, [&](size_t c, Csr<int32_t>& out, std::vector<int32_t>& kinds) {
        kinds.clear();
        for (int32_t e : ch.edges[c]) add_edge_kinds(cx, e, kinds);
        const auto vs = ch.verts[c];
        if (vs.front() != vs.back())
          for (int32_t v : {vs.front(), vs.back()})
            for (int32_t k : at_end[static_cast<size_t>(v)])
              if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
        std::sort(kinds.begin(), kinds.end());
        out.items.insert(out.items.end(), kinds.begin(), kinds.end());
      });
}

void add_closed(const CellComplex& cx, const std::vector<uint8_t>& seed, Chains& ch) {
  for (size_t e = 0; e < seed.size(); ++e) {
    if (!seed[e] || !cx.closed(e)) continue;
    const int32_t one = static_cast<int32_t>(e), none[2] = {-1, -1};
    ch.edges.push_row(&one, &one + 1);
    ch.verts.push_row(none, none + 2);
  }
}

}  // namespace hbc::vsg
