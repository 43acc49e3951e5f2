#pragma once
// The VSG wireframe's shared pieces (paper §5; the steps in vsg_chains.cpp, vsg_trace.cpp,
// vsg_simplification.cpp, the driver in vsg_wireframe.cpp): the region-relative element tests,
// chains and how they are traced. Internal to structure/.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "hbc/cell_complex.hpp"
#include "hbc/csr.hpp"
#include "hbc/threads.hpp"
#include "parallel/parallel.hpp"

namespace hbc::vsg {

// Sorted-range intersection test. A much longer range (the fan of an edge in thousands of
// cells) is searched for each item of the shorter one instead of walked.
template <class A, class B>
bool intersects(const A& a, const B& b) {
  if (a.size() > 16 * b.size() || b.size() > 16 * a.size()) {
    const auto& small = a.size() < b.size() ? a : b;
    const auto& large = a.size() < b.size() ? b : a;
    return std::any_of(small.begin(), small.end(), [&](int32_t x) { return std::binary_search(large.begin(), large.end(), x); });
  }
  auto i = a.begin(), j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i == *j) return true;
    *i < *j ? ++i : ++j;
  }
  return false;
}

// Region-relative element tests shared by every step (the authors' rules count region cells and
// faces only).
struct Region {
  const CellComplex& cx;
  // Aligned with cx.vert_edges.items: bit j of slot i is set when the row's edges i and j share a
  // face (share_face), for rows of at most 32 edges; empty until face_masks fills it. Chains ask
  // this of the edges at one vertex again and again, each time from far away in memory.
  std::vector<uint32_t> face_mask;
  int32_t valence(int32_t e) const { return cx.edge_cells.count(e); }
  bool regular(int32_t e) const { return valence(e) == (cx.edge_boundary[e] ? 2 : 4); }
  // Two edges in one region face (the authors' "opposite" test for a vertex's two patch edges).
  bool share_region_face(int32_t e, int32_t f) const { return intersects(cx.edge_faces[e], cx.edge_faces[f]); }
  // The tests behind the authors' continuation (get_next_edge) and flood look at the whole mesh.
  bool share_face(int32_t e, int32_t f) const {
    return cx.whole() ? share_region_face(e, f) : intersects(cx.edge_all_faces[e], cx.edge_all_faces[f]);
  }
  bool share_cell(int32_t e, int32_t f) const {
    return cx.whole() ? intersects(cx.edge_cells[e], cx.edge_cells[f]) : intersects(cx.edge_all_cells[e], cx.edge_all_cells[f]);
  }
  bool faces_share_cell(int32_t f, int32_t g) const {
    const auto a = cx.whole() ? cx.face_cells[f] : cx.face_all_cells[f];
    const auto b = cx.whole() ? cx.face_cells[g] : cx.face_all_cells[g];
    for (int32_t x : a)
      if (x >= 0 && (x == b[0] || x == b[1])) return true;
    return false;
  }
  bool mesh_boundary(int32_t e) const { return cx.whole() ? cx.edge_boundary[e] : cx.edge_mesh_boundary[e]; }
  // The authors' mesh marks an edge singular when irregular in the whole mesh or at a non-hex cell.
  bool mesh_singular(int32_t e) const {
    if (cx.whole()) return !regular(e) || cx.edge_non_hex[e];
    return cx.edge_all_cells.count(e) != (mesh_boundary(e) ? 2 : 4) || cx.edge_all_non_hex[e];
  }
  // Calls fn(f, slot) for each edge f at v, in row order, that is not e and shares no face with
  // e; slot is f's position in cx.vert_edges.items.
  template <class F>
  void each_straight(int32_t v, int32_t e, const F& fn) const {
    const auto row = cx.vert_edges[v];
    const size_t off = static_cast<size_t>(cx.vert_edges.offsets[v]);
    if (!face_mask.empty() && row.size() <= 32) {
      const size_t i = static_cast<size_t>(std::find(row.begin(), row.end(), e) - row.begin());
      if (i < row.size()) {
        const uint32_t m = face_mask[off + i] | (uint32_t{1} << i);
        for (size_t j = 0; j < row.size(); ++j)
          if (!(m >> j & 1u)) fn(row[j], off + j);
        return;
      }
    }
    for (size_t j = 0; j < row.size(); ++j)
      if (row[j] != e && !share_face(e, row[j])) fn(row[j], off + j);
  }
  double quad_ratio(int32_t e) const {
    const auto fs = cx.edge_faces[e];
    int32_t q = 0;
    for (int32_t f : fs) q += cx.face_quad[f];
    return fs.empty() ? 0.0 : double(q) / double(fs.size());
  }
  // A boundary edge of one cell whose faces are all quads: a corner the cleaning treats as regular.
  bool quad_corner_edge(int32_t e) const { return valence(e) == 1 && cx.edge_all_quad[e]; }
  int32_t valence_gap(int32_t e) const {  // region valence, whole-mesh boundary (as the authors)
    const int32_t n = valence(e);
    if (mesh_boundary(e)) return n == 1 ? 0 : std::abs(n - 2);
    return std::abs(n - 4);
  }
};

// Chains of edges. A chain continues through vertex v from edge e along next(v, e) (an edge id or
// -1) unless v is a stop vertex; each edge joins at most one chain (the first that reaches it).
struct Chains {
  Csr<int32_t> edges, verts;  // verts: one more than edges; a closed chain repeats its start
};

using detail::set_flag;

// Appends to vs / es the walk from vertex v along edge e and on through next, taking each edge not
// yet used, up to a stop vertex, an edge already used or no continuation.
template <class Next>
void walk_on(const CellComplex& cx, int32_t v, int32_t e, const std::vector<uint8_t>& stop_vert, std::vector<uint8_t>& used,
             const Next& next, std::vector<int32_t>& vs, std::vector<int32_t>& es) {
  while (e >= 0 && !used[e]) {
    used[e] = 1;
    es.push_back(e);
    v = cx.other_vertex(e, v);
    vs.push_back(v);
    if (stop_vert[v]) break;
    e = next(v, e);
  }
}

// Chains through the seed edges that `take` accepts (in increasing id order), traced first from
// the seed's second end through it, then from its first end: the two walks are joined at the
// seed. The second walk is written straight into the chain's row, after the first one reversed.
// `from` receives each chain's seed.
template <class Next, class Take>
Chains trace_in_order(const CellComplex& cx, const std::vector<uint8_t>& seed, const std::vector<uint8_t>& stop_vert,
                      const Next& next, const Take& take, std::vector<int32_t>& from) {
  Chains out;
  // Room for the most there can be (a chain per seed, each edge on one chain at most), reserved
  // rather than grown: millions of rows would otherwise be copied at every doubling.
  const size_t seeds = static_cast<size_t>(std::count(seed.begin(), seed.end(), uint8_t{1}));
  out.edges.reserve(seeds, cx.num_edges());
  out.verts.reserve(seeds, cx.num_edges() + seeds);
  from.reserve(seeds);
  std::vector<int32_t>& ov = out.verts.items;
  std::vector<int32_t>& oe = out.edges.items;
  std::vector<uint8_t> used(cx.num_edges(), 0);
  std::vector<int32_t> lv, le;
  for (size_t s = 0; s < seed.size(); ++s) {
    const int32_t e = static_cast<int32_t>(s);
    if (!seed[e] || used[e] || cx.closed(e) || !take(s)) continue;
    const auto [v0, v1] = cx.edge_verts[e];
    lv.assign(1, v1);
    le.clear();
    walk_on(cx, v1, e, stop_vert, used, next, lv, le);
    if (lv.front() == lv.back()) {
      ov.insert(ov.end(), lv.begin(), lv.end());
      oe.insert(oe.end(), le.begin(), le.end());
    } else {
      // The first walk ran v1, v0, ... over e, ...: reversed, without its first two vertices and
      // first edge, it leads up to v0, where the second walk (v0, v1, ... over e, ...) goes on.
      used[e] = 0;
      ov.insert(ov.end(), lv.rbegin(), lv.rend() - 2);
      oe.insert(oe.end(), le.rbegin(), le.rend() - 1);
      ov.push_back(v0);
      walk_on(cx, v0, e, stop_vert, used, next, ov, oe);
    }
    out.verts.offsets.push_back(static_cast<int32_t>(ov.size()));
    out.edges.offsets.push_back(static_cast<int32_t>(oe.size()));
    from.push_back(e);
  }
  return out;
}

// Rows, edges and lone seeds of one range of seed ids (see trace_chains).
struct ChainCount {
  int64_t rows = 0, edges = 0, lone = 0;
  ChainCount& operator+=(const ChainCount& o) {
    rows += o.rows, edges += o.edges, lone += o.lone;
    return *this;
  }
};

// trace_in_order over every seed, the same chains in the same order, with the seeds whose ends
// are both stop vertices left out of the ordered trace: such a seed is a chain of its own, v0, v1
// over it, whatever the order (its walks stop at once, and no other walk goes on into it, as a
// walk goes on only at a vertex that is not a stop). Those chains are written by ranges of seed
// ids, between the traced ones; on the split grid nearly every seed is one.
template <class Next>
Chains trace_chains(const CellComplex& cx, const std::vector<uint8_t>& seed, const std::vector<uint8_t>& stop_vert,
                    const Next& next, const Threads& par) {
  const size_t n = seed.size();
  const int nr = detail::range_count(n, par);
  auto lone = [&](size_t e) { return stop_vert[cx.edge_verts[e][0]] && stop_vert[cx.edge_verts[e][1]]; };
  std::vector<int32_t> from;
  Chains traced = trace_in_order(cx, seed, stop_vert, next, [&](size_t e) { return nr == 1 || !lone(e); }, from);
  if (nr == 1) return traced;
  auto lone_chain = [&](size_t e) { return seed[e] && !cx.closed(static_cast<int32_t>(e)) && lone(e); };
  auto traced_at = [&](size_t e) {
    return static_cast<size_t>(std::lower_bound(from.begin(), from.end(), static_cast<int32_t>(e)) - from.begin());
  };
  const std::vector<ChainCount> first = detail::range_starts<ChainCount>(n, par, [&](size_t b, size_t e) {
    ChainCount c;
    for (size_t s = b; s < e; ++s) c.lone += lone_chain(s);
    const size_t t0 = traced_at(b), t1 = traced_at(e);
    c.rows = c.lone + static_cast<int64_t>(t1 - t0);
    c.edges = c.lone + traced.edges.offsets[t1] - traced.edges.offsets[t0];
    return c;
  });
  const ChainCount& all = first.back();
  if (all.lone == 0) return traced;
  Chains out;
  out.edges.offsets.resize(static_cast<size_t>(all.rows) + 1);
  out.verts.offsets.resize(static_cast<size_t>(all.rows) + 1);
  out.edges.items.resize(static_cast<size_t>(all.edges));
  out.verts.items.resize(static_cast<size_t>(all.edges + all.rows));  // a vertex more than edges each
  detail::parallel_ranges(n, par, [&](size_t b, size_t e, int r) {
    auto row = static_cast<size_t>(first[static_cast<size_t>(r)].rows);
    auto ke = static_cast<size_t>(first[static_cast<size_t>(r)].edges), kv = ke + row;
    size_t t = traced_at(b);
    for (size_t s = b; s < e; ++s) {
      if (lone_chain(s)) {
        out.edges.items[ke++] = static_cast<int32_t>(s);
        out.verts.items[kv++] = cx.edge_verts[s][0];
        out.verts.items[kv++] = cx.edge_verts[s][1];
      } else if (t < from.size() && from[t] == static_cast<int32_t>(s)) {
        for (int32_t x : traced.edges[t]) out.edges.items[ke++] = x;
        for (int32_t x : traced.verts[t]) out.verts.items[kv++] = x;
        ++t;
      } else {
        continue;
      }
      ++row;
      out.edges.offsets[row] = static_cast<int32_t>(ke);
      out.verts.offsets[row] = static_cast<int32_t>(kv);
    }
  });
  return out;
}

// The edge at v sharing no face with e, if there is exactly one (else -1); `allow` filters.
template <class Allow>
int32_t straight_next(const Region& r, int32_t v, int32_t e, const Allow& allow) {
  int32_t found = -1;
  bool several = false;
  r.each_straight(v, e, [&](int32_t f, size_t) {
    if (several || r.cx.closed(f) || !allow(f)) return;
    if (found >= 0) several = true;
    found = f;
  });
  return several ? -1 : found;
}

// The two ends of every open chain c that take(c) accepts, flagged by ranges of chains: threads
// only ever store 1 into a shared flag.
template <class Take>
std::vector<uint8_t> chain_end_flags(const CellComplex& cx, const Chains& ch, const Threads& par, const Take& take) {
  std::vector<uint8_t> out(cx.num_vertices(), 0);
  detail::parallel_ranges(ch.verts.rows(), par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) {
      const auto vs = ch.verts[c];
      if (take(c) && vs.front() != vs.back()) set_flag(out, vs.front()), set_flag(out, vs.back());
    }
  });
  return out;
}

// Sets edge[x] for every edge x that take(x) accepts at a vertex v with vert[v] set, by ranges of
// vertices: threads only ever store 1 into a shared flag.
template <class Take>
void flag_edges_at(const CellComplex& cx, const std::vector<uint8_t>& vert, std::vector<uint8_t>& edge, const Threads& par,
                   const Take& take) {
  detail::parallel_ranges(vert.size(), par, [&](size_t b, size_t e, int) {
    for (size_t v = b; v < e; ++v)
      if (vert[v])
        for (int32_t x : cx.vert_edges[v])
          if (take(x)) set_flag(edge, x);
  });
}

// ---- The VSG (§5.1): vsg_chains.cpp ----

// Bits of Region::face_mask (see there).
std::vector<uint32_t> face_masks(const Region& r, const Threads& par);
// Chains of the VSG rule: the unique straight continuation, when it has the same valence.
Chains valence_chains(const Region& r, const std::vector<uint8_t>& seed, const std::vector<uint8_t>& stop_vert,
                      const Threads& par);
// Closed complex edges (curves without corners) are chains by themselves when seeded.
void add_closed(const CellComplex& cx, const std::vector<uint8_t>& seed, Chains& ch);
// 1 for every complex edge in a row of `rows`.
std::vector<uint8_t> edge_flags(const CellComplex& cx, const Csr<int32_t>& rows);
// The mesh vertices along each chain (a closed complex edge: its own points).
Csr<int32_t> polylines(const CellComplex& cx, const Chains& ch, const Threads& par);
// The non-hex kinds of each chain (VsgWireframe::non_hex).
Csr<int32_t> chain_kinds(const CellComplex& cx, const Chains& ch, const Threads& par);

}  // namespace hbc::vsg
