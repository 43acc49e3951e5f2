#include "hbc/vsg_wireframe.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <utility>

#include "parallel/concurrent_union_find.hpp"
#include "parallel/parallel.hpp"
#include "parallel/union_find.hpp"

namespace hbc {

namespace {

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

// Chains of the VSG rule: the unique straight continuation, when it has the same valence.
Chains valence_chains(const Region& r, const std::vector<uint8_t>& seed, const std::vector<uint8_t>& stop_vert,
                      const Threads& par) {
  return trace_chains(r.cx, seed, stop_vert, [&](int32_t v, int32_t e) {
    const int32_t f = straight_next(r, v, e, [](int32_t) { return true; });
    return f >= 0 && r.valence(f) == r.valence(e) ? f : -1;
  }, par);
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

std::vector<uint8_t> edge_flags(const CellComplex& cx, const Csr<int32_t>& rows) {
  std::vector<uint8_t> out(cx.num_edges(), 0);
  for (int32_t e : rows.items) out[e] = 1;
  return out;
}

// Faces reachable from the faces at `start` edges, across edges that do not stop the flood, into
// the faces at the crossed edge sharing no cell with the current face. The authors' mesh marks an
// edge singular (a stop) when irregular, at a non-hex cell (mesh level); their base-complex mesh
// marks none, so there only the boundary stops.
// Crossing is symmetric (it depends on the edge and on the two faces alone), so the reachable
// faces are the classes, under "crossed into each other", of the start faces: classes are joined
// edge by edge, which reads the complex in memory order instead of hopping from face to face.
// Which faces a class holds does not depend on the order of the unions, so ranges of edges
// unite at once.
std::vector<uint8_t> flood_faces(const Region& r, const std::vector<uint8_t>& start, const Threads& par) {
  const CellComplex& cx = r.cx;
  const bool mesh_level = cx.level == Level::Mesh;
  detail::ConcurrentUnionFind uf(cx.num_faces(), par);
  detail::parallel_ranges(cx.num_edges(), par, [&](size_t begin, size_t end, int) {
    std::vector<int32_t> rest, next, queue;
    for (size_t g = begin; g < end; ++g) {
      const int32_t e = static_cast<int32_t>(g);
      if (cx.edge_faces.count(g) < 2 || r.mesh_boundary(e) || (mesh_level && r.mesh_singular(e))) continue;
      // Classes of the faces around g under "share no cell": a search in the complement of the
      // share-a-cell relation, each test either settling a face or charged to a sharing pair, so a
      // fan of thousands of faces costs about as many tests as it has faces.
      const auto fs = cx.edge_faces[g];
      rest.assign(fs.begin() + 1, fs.end());
      queue.assign(1, fs[0]);
      for (size_t q = 0;; ++q) {
        if (q == queue.size()) {
          if (rest.empty()) break;
          queue.push_back(rest.back());
          rest.pop_back();
        }
        const int32_t f = queue[q];
        next.clear();
        for (int32_t h : rest) {
          if (r.faces_share_cell(f, h)) {
            next.push_back(h);
          } else {
            uf.unite(f, h);
            queue.push_back(h);
          }
        }
        rest.swap(next);
      }
    }
  });
  std::vector<uint8_t> root_seen(cx.num_faces(), 0);
  for (size_t e = 0; e < start.size(); ++e)
    if (start[e])
      for (int32_t f : cx.edge_faces[e]) root_seen[static_cast<size_t>(uf.find(f))] = 1;
  std::vector<uint8_t> seen(cx.num_faces(), 0);
  detail::parallel_ranges(seen.size(), par, [&](size_t begin, size_t end, int) {
    for (size_t f = begin; f < end; ++f) seen[f] = root_seen[static_cast<size_t>(uf.find(static_cast<int32_t>(f)))];
  });
  return seen;
}

// Singular vertices of the complete wireframe: ends of patch edges (all faces flooded or on the
// boundary) with a patch-edge count other than 0 and 2, or two patch edges sharing a face.
// Each element's flag depends on its neighbours' only: ranges in parallel.
std::vector<uint8_t> patch_singular_vertices(const Region& r, const std::vector<uint8_t>& flooded, const Threads& par) {
  const CellComplex& cx = r.cx;
  std::vector<uint8_t> patch_edge(cx.num_edges(), 0);
  detail::parallel_ranges(patch_edge.size(), par, [&](size_t b, size_t end, int) {
    for (size_t e = b; e < end; ++e) {
      bool all = !cx.edge_faces[e].empty();
      for (int32_t f : cx.edge_faces[e]) all = all && (flooded[f] || cx.face_cells[f][1] < 0);
      patch_edge[e] = all;
    }
  });
  std::vector<uint8_t> out(cx.num_vertices(), 0);
  detail::parallel_ranges(out.size(), par, [&](size_t b, size_t end, int) {
    int32_t at[2] = {-1, -1};
    for (size_t v = b; v < end; ++v) {
      size_t n = 0;
      for (int32_t e : cx.vert_edges[v])
        if (patch_edge[e] && n++ < 2) at[n - 1] = e;
      out[v] = (n != 0 && n != 2) || (n == 2 && r.share_region_face(at[0], at[1]));
    }
  });
  return out;
}

// Writes the mesh vertices of edge e walked from its end `from` at `out`, its first one only for
// the chain's first edge (otherwise it is the previous edge's last); returns the end of what it wrote.
int32_t* put_points(const CellComplex& cx, int32_t e, int32_t from, bool first, int32_t* out) {
  const auto pts = cx.edge_points[e];
  const bool forward = cx.edge_verts[e][0] == from;
  const size_t n = pts.size();
  for (size_t k = first ? 0 : 1; k < n; ++k) *out++ = forward ? pts[k] : pts[n - 1 - k];
  return out;
}

// The mesh vertices along each chain (a closed complex edge: its own points). Rows are sized
// first, so ranges of chains then write their own rows in parallel.
Csr<int32_t> polylines(const CellComplex& cx, const Chains& ch, const Threads& par) {
  const size_t n = ch.edges.rows();
  Csr<int32_t> out;
  out.offsets.resize(n + 1);
  out.offsets[0] = 0;
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

// Closed complex edges (curves without corners) are chains by themselves when seeded.
void add_closed(const CellComplex& cx, const std::vector<uint8_t>& seed, Chains& ch) {
  for (size_t e = 0; e < seed.size(); ++e) {
    if (!seed[e] || !cx.closed(e)) continue;
    const int32_t one = static_cast<int32_t>(e), none[2] = {-1, -1};
    ch.edges.push_row(&one, &one + 1);
    ch.verts.push_row(none, none + 2);
  }
}


}  // namespace

int64_t covered_mesh_edges(const CellComplex& cx, const Csr<int32_t>& chains) {
  std::vector<uint8_t> on = edge_flags(cx, chains);
  int64_t n = 0;
  for (size_t e = 0; e < on.size(); ++e)
    if (on[e]) n += cx.edge_points.count(e) - 1;
  return n;
}

namespace {

// ---- Simplification (the authors' cleaning) ----

struct Cleaning {
  std::vector<uint8_t> redundant_vert, non_important, reactivated, kept;
};

// Chain ids per edge (-1 off the wireframe).
struct ChainIndex {
  std::vector<int32_t> edge_chain;
};

// Each edge lies on one chain at most, so ranges of chains write disjoint entries.
ChainIndex index_chains(const CellComplex& cx, const Chains& ch, const std::vector<uint8_t>& keep, const Threads& par) {
  ChainIndex ix;
  ix.edge_chain.assign(cx.num_edges(), -1);
  detail::parallel_ranges(ch.edges.rows(), par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c)
      if (keep[c])
        for (int32_t x : ch.edges[c]) ix.edge_chain[x] = static_cast<int32_t>(c);
  });
  return ix;
}

// Distinct chains through v: every vertex of a chain ends one of its edges.
int32_t chains_at(const CellComplex& cx, const ChainIndex& ix, int32_t v, std::vector<int32_t>& buf) {
  buf.clear();
  for (int32_t e : cx.vert_edges[v])
    if (ix.edge_chain[e] >= 0) buf.push_back(ix.edge_chain[e]);
  sort_unique(buf);
  return static_cast<int32_t>(buf.size());
}

// A redundant singular vertex: the corner of one cell with only quads around it, or one whose
// wireframe edges are all of regular valence (or all-quad corner edges).
bool redundant_vertex(const Region& r, const ChainIndex& ix, int32_t v) {
  if (r.cx.vert_cell_count[v] == 1 && r.cx.vert_all_quad[v]) return true;
  for (int32_t e : r.cx.vert_edges[v])
    if (ix.edge_chain[e] >= 0 && !r.regular(e) && !r.quad_corner_edge(e)) return false;
  return true;
}

// Candidate removable pairs of edges at v: a regular wireframe edge (or an all-quad corner edge)
// with only quads around it, and its straight continuation (the only edge sharing no face with it,
// else the only such all-quad edge) if that is a candidate too. `cand` is scratch room, reused
// from vertex to vertex (a million vertices would otherwise mean a million allocations).
void candidate_pairs(const Region& r, const ChainIndex& ix, int32_t v, std::vector<int32_t>& cand,
                     std::vector<std::array<int32_t, 2>>& pairs) {
  cand.clear();
  pairs.clear();
  for (int32_t e : r.cx.vert_edges[v])
    if ((ix.edge_chain[e] >= 0 && r.regular(e)) || r.quad_corner_edge(e)) cand.push_back(e);
  for (int32_t e : cand) {
    if (!r.cx.edge_all_quad[e]) continue;
    int32_t next = -1, quad_next = -1, n = 0, nq = 0;
    r.each_straight(v, e, [&](int32_t f, size_t) {
      next = f, ++n;
      if (r.cx.edge_all_quad[f]) quad_next = f, ++nq;
    });
    const int32_t pick = n == 1 ? next : nq == 1 ? quad_next : -1;
    if (pick < 0 || std::find(cand.begin(), cand.end(), pick) == cand.end()) continue;
    const std::array<int32_t, 2> p{std::min(e, pick), std::max(e, pick)};
    if (std::find(pairs.begin(), pairs.end(), p) == pairs.end()) pairs.push_back(p);
  }
}

// Pairs sharing an edge form a group; a group of one pair stays, a larger one keeps the one pair of
// lowest valence gap, else of highest quad ratio, else none (the authors' tie-breaks).
void resolve_pairs(const Region& r, const std::vector<std::array<int32_t, 2>>& pairs, std::vector<std::array<int32_t, 2>>& out) {
  const size_t n = pairs.size();
  out.clear();
  if (n <= 1) {  // no group of two or more: nothing to break ties in
    out = pairs;
    return;
  }
  detail::UnionFind uf(n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      if (intersects(pairs[i], pairs[j]))
        uf.unite(static_cast<int32_t>(i), static_cast<int32_t>(j));
  for (size_t g = 0; g < n; ++g) {
    if (uf.find(static_cast<int32_t>(g)) != static_cast<int32_t>(g)) continue;
    std::vector<size_t> members;
    for (size_t i = 0; i < n; ++i)
      if (uf.find(static_cast<int32_t>(i)) == static_cast<int32_t>(g)) members.push_back(i);
    if (members.size() == 1) {
      out.push_back(pairs[members[0]]);
      continue;
    }
    auto gap = [&](size_t i) { return r.valence_gap(pairs[i][0]) + r.valence_gap(pairs[i][1]); };
    auto qr = [&](size_t i) { return r.quad_ratio(pairs[i][0]) + r.quad_ratio(pairs[i][1]); };
    int32_t best_gap = gap(members[0]);
    for (size_t i : members) best_gap = std::min(best_gap, gap(i));
    std::vector<size_t> low;
    for (size_t i : members)
      if (gap(i) == best_gap) low.push_back(i);
    double best_qr = qr(low[0]);
    for (size_t i : low) best_qr = std::max(best_qr, qr(i));
    size_t count = 0, pick = 0;
    for (size_t i : low)
      if (qr(i) == best_qr) ++count, pick = i;
    if (low.size() == 1 || count == 1) out.push_back(pairs[low.size() == 1 ? low[0] : pick]);
  }
}

// Chain pairs (sorted, second -1 when both edges lie on one chain or one is off the wireframe).
using ChainPair = std::array<int32_t, 2>;
ChainPair chain_pair(const ChainIndex& ix, const std::array<int32_t, 2>& p) {
  int32_t a = ix.edge_chain[p[0]], b = ix.edge_chain[p[1]];
  if (a < 0 || a == b) a = b, b = -1;
  if (b >= 0 && b < a) std::swap(a, b);
  return {a, b};
}

struct PairTable {
  Csr<ChainPair> at;  // nv rows: resolved chain pairs at the vertex (empty: none)
};

ChainPair make_pair_of(int32_t a, int32_t b) {
  if (a == b) return {a, -1};
  return {std::min(a, b), std::max(a, b)};
}

bool in_pair(std::span<const ChainPair> ps, int32_t c) {
  for (const auto& p : ps)
    if (p[0] == c || p[1] == c) return true;
  return false;
}

// The chain's edge at its end v.
int32_t end_edge(const Chains& ch, int32_t c, int32_t v) {
  const auto es = ch.edges[c];
  return ch.verts[c].front() == v ? es.front() : es.back();
}

// Chains continuing chain c at its end v: those holding an edge at v sharing no face with c's
// edge there; at a vertex with pairs, c's partners if any, else the chains in no pair. With none,
// along the boundary: boundary edges at v with the same cells as c's edge (sheet-parallel ones
// dropped when that leaves several).
// Scratch rows of next_chains, reused from call to call (millions of calls otherwise allocate).
struct NextScratch {
  std::vector<int32_t> found, partners, free, side;
};

// `ps`: the chain pairs at v.
void next_chains(const Region& r, const Chains& ch, const ChainIndex& ix, std::span<const ChainPair> ps,
                 const std::vector<uint8_t>& parallel, int32_t c, int32_t v, NextScratch& s) {
  const CellComplex& cx = r.cx;
  const int32_t e = end_edge(ch, c, v);
  std::vector<int32_t>& found = s.found;
  found.clear();
  r.each_straight(v, e, [&](int32_t f, size_t) {
    if (ix.edge_chain[f] >= 0) found.push_back(ix.edge_chain[f]);
  });
  if (!ps.empty()) {
    s.partners.clear();
    s.free.clear();
    for (int32_t x : found) {
      if (std::find(ps.begin(), ps.end(), make_pair_of(c, x)) != ps.end()) s.partners.push_back(x);
      if (!in_pair(ps, x)) s.free.push_back(x);
    }
    found.swap(s.partners.empty() ? s.free : s.partners);
  }
  if (found.empty() && cx.vert_boundary[v] && cx.edge_boundary[ch.edges[c][0]]) {
    std::vector<int32_t>& side = s.side;
    side.clear();
    for (int32_t f : cx.vert_edges[v]) {
      const auto a = cx.edge_cells[e], b = cx.edge_cells[f];
      if (f != e && cx.edge_boundary[f] && std::equal(a.begin(), a.end(), b.begin(), b.end())) side.push_back(f);
    }
    if (side.size() > 1) std::erase_if(side, [&](int32_t f) { return parallel[f] != 0; });
    for (int32_t f : side)
      if (ix.edge_chain[f] >= 0) found.push_back(ix.edge_chain[f]);
  }
}

// The reactivation's graph: rows 2c and 2c+1 list the continuations of chain c at its first and
// at its last vertex; they stay empty for a closed chain and at a vertex where no non-important
// chain has an edge (continuations there are chains with an edge there, all kept anyway). What
// continues a chain depends on the tables only, never on what is kept so far, so every row is
// found at once, in chain order (the complex's memory order), ranges of chains in parallel.
Csr<int32_t> continuations(const Region& r, const Chains& ch, const ChainIndex& ix, const PairTable& pt,
                           const std::vector<uint8_t>& parallel, const std::vector<uint8_t>& non_important,
                           const Threads& par) {
  const CellComplex& cx = r.cx;
  std::vector<uint8_t> open(cx.num_vertices(), 0);
  detail::parallel_ranges(open.size(), par, [&](size_t b, size_t e, int) {
    for (size_t v = b; v < e; ++v)
      for (int32_t f : cx.vert_edges[v])
        if (ix.edge_chain[f] >= 0 && non_important[ix.edge_chain[f]]) open[v] = 1;
  });
  const size_t nc = ch.edges.rows();
  std::vector<Csr<int32_t>> parts(static_cast<size_t>(detail::range_count(nc, par)));
  detail::parallel_ranges(nc, par, [&](size_t b, size_t e, int k) {
    Csr<int32_t> out;  // on this thread's stack: the parts' headers share cache lines
    out.reserve(2 * (e - b), e - b);
    NextScratch s;
    for (size_t c = b; c < e; ++c) {
      const auto vs = ch.verts[c];
      for (int32_t v : {vs.front(), vs.back()}) {
        if (vs.front() != vs.back() && open[v]) {
          next_chains(r, ch, ix, pt.at[v], parallel, static_cast<int32_t>(c), v, s);
          out.items.insert(out.items.end(), s.found.begin(), s.found.end());
        }
        out.offsets.push_back(static_cast<int32_t>(out.items.size()));
      }
    }
    parts[static_cast<size_t>(k)] = std::move(out);
  });
  return concat(std::move(parts));
}

// Reactivation: every chain reached from a kept one (`kept`, the chains kept so far) through its
// continuations stays. The kept set is everything reachable, whatever the visiting order, so the
// chains are expanded in one sweep in id order (the complex's memory order, where a chain's
// continuations mostly lie close by): a chain reached ahead of the sweep waits for it, one
// reached behind it is expanded at once from a stack.
std::vector<uint8_t> reactivate(const Csr<int32_t>& next, size_t chains, const std::vector<int32_t>& kept) {
  enum : uint8_t { Unreached = 0, Reached = 1, Expanded = 2 };
  std::vector<uint8_t> state(chains, Unreached);
  for (int32_t c : kept) state[c] = Reached;
  std::vector<int32_t> stack;
  for (size_t s = 0; s < chains; ++s) {
    if (state[s] != Reached) continue;
    stack.assign(1, static_cast<int32_t>(s));
    while (!stack.empty()) {
      const size_t c = static_cast<size_t>(stack.back());
      stack.pop_back();
      state[c] = Expanded;
      for (size_t row : {2 * c, 2 * c + 1})
        for (int32_t x : next[row]) {
          if (state[x] != Unreached) continue;
          state[x] = Reached;
          if (static_cast<size_t>(x) < s) stack.push_back(x);
        }
    }
  }
  for (uint8_t& k : state) k = k != Unreached;
  return state;
}

// Resolved chain pairs at each singular, non-redundant vertex, and which singular vertices are
// redundant: ranges of vertices in parallel, each into rows of its own, joined in order.
struct PairScratch {
  std::vector<int32_t> cand;
  std::vector<std::array<int32_t, 2>> pairs, kept;
};
PairTable pair_table(const Region& r, const ChainIndex& ix, const std::vector<uint8_t>& singular,
                     const Threads& par, std::vector<uint8_t>& redundant) {
  const size_t nv = r.cx.num_vertices();
  redundant.assign(nv, 0);
  return PairTable{detail::parallel_rows_of<ChainPair, PairScratch>(nv, par, [&](size_t v, Csr<ChainPair>& out, PairScratch& s) {
    const int32_t vi = static_cast<int32_t>(v);
    redundant[v] = singular[v] && redundant_vertex(r, ix, vi);
    if (!singular[v] || redundant[v]) return;
    candidate_pairs(r, ix, vi, s.cand, s.pairs);
    resolve_pairs(r, s.pairs, s.kept);
    for (const auto& p : s.kept) {
      const ChainPair cp = chain_pair(ix, p);
      if (cp[0] >= 0) out.items.push_back(cp);
    }
  })};
}

Cleaning clean_chains(const Region& r, const Chains& ch, const std::vector<uint8_t>& singular,
                      const std::vector<uint8_t>& parallel, const Threads& par) {
  const size_t nc = ch.edges.rows();
  const ChainIndex ix = index_chains(r.cx, ch, std::vector<uint8_t>(nc, 1), par);
  Cleaning cl;
  const PairTable pt = pair_table(r, ix, singular, par, cl.redundant_vert);
  cl.non_important.assign(nc, 0);
  for (const ChainPair& p : pt.at.items)
    for (int32_t c : p)
      if (c >= 0) cl.non_important[c] = 2;
  std::vector<int32_t> stack;
  for (size_t c = 0; c < nc; ++c) {
    if (cl.non_important[c]) continue;
    const auto vs = ch.verts[c];
    const bool open = vs.front() != vs.back();
    if (open && cl.redundant_vert[vs.front()] && cl.redundant_vert[vs.back()]) cl.non_important[c] = 1;
    else stack.push_back(static_cast<int32_t>(c));
  }
  const Csr<int32_t> nexts = continuations(r, ch, ix, pt, parallel, cl.non_important, par);
  cl.kept = reactivate(nexts, nc, stack);
  cl.reactivated.assign(nc, 0);
  detail::parallel_ranges(nc, par, [&](size_t b, size_t end, int) {
    for (size_t c = b; c < end; ++c) {
      cl.reactivated[c] = cl.kept[c] && cl.non_important[c];
      bool all_parallel = true;
      for (int32_t e : ch.edges[c]) all_parallel = all_parallel && parallel[e];
      if (all_parallel) cl.kept[c] = 0;
    }
  });
  return cl;
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

// The kept chains re-chained: a kept chain end stays singular unless exactly two kept chains pass
// through it with no two of its wireframe edges in one cell; chains are then traced from the edges
// at the remaining singular vertices along the unique kept straight continuation. (Chains that
// touch no remaining singular vertex, closed ones included, drop out, as in the authors' code.)
Chains final_chains(const Region& r, const Chains& ch, const std::vector<uint8_t>& kept, const Threads& par) {
  const CellComplex& cx = r.cx;
  const ChainIndex ix = index_chains(cx, ch, kept, par);
  const auto on = [&](int32_t e) { return ix.edge_chain[e] >= 0; };
  const std::vector<uint8_t> end = chain_end_flags(cx, ch, par, [&](size_t c) { return kept[c] != 0; });
  std::vector<uint8_t> singular(cx.num_vertices(), 0);
  detail::parallel_ranges(end.size(), par, [&](size_t b, size_t e, int) {
    std::vector<int32_t> at;
    for (size_t v = b; v < e; ++v) {
      if (!end[v]) continue;
      const int32_t vi = static_cast<int32_t>(v);
      singular[v] = chains_at(cx, ix, vi, at) != 2;
      at.clear();
      for (int32_t x : cx.vert_edges[v])
        if (on(x)) at.push_back(x);
      for (size_t i = 0; i < at.size() && !singular[v]; ++i)
        for (size_t j = i + 1; j < at.size(); ++j)
          if (r.share_cell(at[i], at[j])) singular[v] = 1;
    }
  });
  std::vector<uint8_t> seeds(cx.num_edges(), 0);
  flag_edges_at(cx, singular, seeds, par, on);
  return trace_chains(cx, seeds, singular, [&](int32_t v, int32_t e) {
    return straight_next(r, v, e, [&](int32_t f) { return on(f); });
  }, par);
}

void fill_complete(const Region& r, const Chains& ch, const Threads& par, VsgWireframe& w) {
  const CellComplex& cx = r.cx;
  const size_t n = ch.edges.rows();
  w.edges = ch.edges;
  w.polylines = polylines(cx, ch, par);
  w.ends.resize(n);
  w.kind.resize(n);
  w.valence.resize(n);
  w.stop.resize(n);
  detail::parallel_ranges(n, par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) {
      const auto es = ch.edges[c], vs = ch.verts[c];
      const bool closed = vs.front() == vs.back();
      w.ends[c] = closed ? std::array<int32_t, 2>{-1, -1} : std::array<int32_t, 2>{vs.front(), vs.back()};
      bool all_vsg = true;
      for (int32_t x : es) all_vsg = all_vsg && w.edge_vsg[x];
      w.kind[c] = all_vsg ? WireKind::Vsg : WireKind::Trace;
      w.valence[c] = r.valence(es[0]);
      const int32_t last = vs.back();
      w.stop[c] = closed ? TraceStop::None
                  : w.vert_singular[last] ? TraceStop::SingularVertex
                  : cx.vert_boundary[last] ? TraceStop::Boundary
                                           : TraceStop::NoContinuation;
    }
  });
}

// Connected components of the chains: their vertices are joined chain by chain, and each set of
// wireframe vertices is one component (its root, the lowest member, counted once); a chain of a
// closed curve alone has no vertex and is a component by itself.
// The sets do not depend on the order of the unions, so ranges of chains unite at once.
int64_t components(const CellComplex& cx, const Csr<int32_t>& chains, const Threads& par) {
  const size_t nv = cx.num_vertices();
  detail::ConcurrentUnionFind uf(nv, par);
  std::vector<uint8_t> on(nv, 0);
  std::vector<int64_t> closed(static_cast<size_t>(detail::range_count(chains.rows(), par)), 0);
  detail::parallel_ranges(chains.rows(), par, [&](size_t b, size_t e, int r) {
    int64_t alone = 0;  // local: the ranges' counts share a cache line
    for (size_t c = b; c < e; ++c) {
      int32_t first = -1;
      for (int32_t x : chains[c])
        for (int32_t v : cx.edge_verts[x]) {
          if (v < 0) continue;
          set_flag(on, v);
          if (first < 0) first = v;
          else uf.unite(first, v);
        }
      alone += first < 0;
    }
    closed[static_cast<size_t>(r)] = alone;
  });
  std::vector<int64_t> roots(static_cast<size_t>(detail::range_count(nv, par)), 0);
  detail::parallel_ranges(nv, par, [&](size_t b, size_t e, int r) {
    int64_t n = 0;
    for (size_t v = b; v < e; ++v) n += on[v] && uf.find(static_cast<int32_t>(v)) == static_cast<int32_t>(v);
    roots[static_cast<size_t>(r)] = n;
  });
  int64_t n = 0;
  for (int64_t k : closed) n += k;
  for (int64_t k : roots) n += k;
  return n;
}

}  // namespace

VsgWireframe vsg_wireframe_graph(const CellComplex& cx, const WireframeOptions& opt, const Threads& threads) {
  const Threads par = resolved(threads);
  Region r{cx, {}};
  r.face_mask = face_masks(r, par);
  VsgWireframe w;
  const size_t ne = cx.num_edges(), nv = cx.num_vertices();
  w.edge_vsg.assign(ne, 0);
  detail::parallel_ranges(ne, par, [&](size_t b, size_t end, int) {
    for (size_t e = b; e < end; ++e) w.edge_vsg[e] = !r.regular(static_cast<int32_t>(e));
  });
  w.vsg_edges = std::count(w.edge_vsg.begin(), w.edge_vsg.end(), uint8_t{1});

  // VSG: chains of seeds, broken only where the continuation is not unique or changes valence.
  Chains vsg = valence_chains(r, w.edge_vsg, std::vector<uint8_t>(nv, 0), par);
  add_closed(cx, w.edge_vsg, vsg);
  w.vsg_chain_edges = vsg.edges;
  w.vsg_chains = static_cast<int64_t>(vsg.edges.rows());
  w.vert_vsg = chain_end_flags(cx, vsg, par, [](size_t) { return true; });

  // Complete wireframe: flood from the VSG's edges and from every edge at a VSG vertex.
  std::vector<uint8_t> start = edge_flags(cx, vsg.edges);
  const auto any = [](int32_t) { return true; };
  flag_edges_at(cx, w.vert_vsg, start, par, any);
  const std::vector<uint8_t> flooded = flood_faces(r, start, par);
  w.vert_singular = patch_singular_vertices(r, flooded, par);
  w.singular_vertices = detail::ids_where(nv, par, [&](size_t v) { return w.vert_singular[v] != 0; });
  std::vector<uint8_t> seeds(ne, 0);
  flag_edges_at(cx, w.vert_singular, seeds, par, any);
  const Chains complete = valence_chains(r, seeds, w.vert_singular, par);
  fill_complete(r, complete, par, w);
  w.non_hex = chain_kinds(cx, complete, par);

  // Simplification.
  std::vector<uint8_t> parallel(ne, 0);
  for (int32_t e : opt.parallel_edges)
    if (e >= 0 && static_cast<size_t>(e) < ne) parallel[e] = 1;
  const Cleaning cl = clean_chains(r, complete, w.vert_singular, parallel, par);
  w.vert_non_important.resize(nv);
  detail::parallel_ranges(nv, par, [&](size_t b, size_t end, int) {
    for (size_t v = b; v < end; ++v) w.vert_non_important[v] = !w.vert_singular[v] || cl.redundant_vert[v];
  });
  w.non_important = cl.non_important;
  w.reactivated = cl.reactivated;
  const Chains simple = final_chains(r, complete, cl.kept, par);
  w.simplified_edges = simple.edges;
  w.simplified_polylines = polylines(cx, simple, par);
  w.simplified_non_hex = chain_kinds(cx, simple, par);
  const std::vector<uint8_t> on = edge_flags(cx, simple.edges);
  w.shown.assign(w.size(), 0);
  detail::parallel_ranges(w.size(), par, [&](size_t b, size_t end, int) {
    for (size_t c = b; c < end; ++c) {
      bool all = true;
      for (int32_t e : w.edges[c]) all = all && on[e];
      w.shown[c] = all;
    }
  });
  w.vsg_mesh_edges = covered_mesh_edges(cx, w.vsg_chain_edges);
  w.wireframe_mesh_edges = covered_mesh_edges(cx, w.edges);
  w.simplified_mesh_edges = covered_mesh_edges(cx, w.simplified_edges);
  w.reference_components = components(cx, w.edges, par);
  w.shown_components = components(cx, w.simplified_edges, par);
  return w;
}

VsgWireframe vsg_wireframe(const CellComplex& cx, const WireframeOptions& opt, const Threads& threads) {
  const Threads par = resolved(threads);
  VsgWireframe w = vsg_wireframe_graph(cx, opt, par);
  w.style = wireframe_style(cx, w, opt, par);
  return w;
}

}  // namespace hbc
