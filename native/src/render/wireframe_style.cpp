#include "hbc/wireframe_style.hpp"

#include "hbc/cell_complex.hpp"
#include "hbc/vsg_wireframe.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <span>
#include <utility>

#include "parallel/concurrent_union_find.hpp"
#include "parallel/parallel.hpp"
#include "platform/atomic_ref.hpp"

namespace hbc {

namespace {

using detail::parallel_rows_of;
using detail::PartedRows;
using detail::weighted_parted_rows;

bool share_vertex(const CellComplex& cx, int32_t e, int32_t f) {
  const auto a = cx.edge_verts[e], b = cx.edge_verts[f];
  if (a[0] < 0 || b[0] < 0) return false;
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

// Chains per complex edge, and the distinct mesh vertices of each chain (compact ids) and back.
struct Index {
  std::vector<int32_t> edge_wire;  // ne: chain holding the edge, else -1
  Csr<int32_t> wire_points, point_wires;
};

Index index_points(const CellComplex& cx, const VsgWireframe& w, const Threads& par) {
  Index ix;
  ix.edge_wire.assign(cx.num_edges(), -1);
  // An edge lies on one chain at most: ranges of chains write disjoint entries.
  detail::parallel_ranges(w.size(), par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c)
      for (int32_t x : w.edges[c]) ix.edge_wire[static_cast<size_t>(x)] = static_cast<int32_t>(c);
  });
  int32_t max_id = -1;
  for (int32_t p : w.polylines.items) max_id = std::max(max_id, p);
  // Points numbered in increasing mesh id: flags over the id range, no sort of every point.
  std::vector<int32_t> point_of_mesh(static_cast<size_t>(max_id + 1), -1);
  for (int32_t p : w.polylines.items) point_of_mesh[static_cast<size_t>(p)] = 0;
  int32_t n = 0;
  for (int32_t& id : point_of_mesh)
    if (id == 0) id = n++;
  ix.wire_points = parallel_rows_of<int32_t, std::vector<int32_t>>(w.size(), par, [&](size_t c, Csr<int32_t>& out, std::vector<int32_t>& buf) {
    buf.clear();
    for (int32_t p : w.polylines[c]) buf.push_back(point_of_mesh[p]);
    if (buf.size() > 2 || (buf.size() == 2 && buf[1] <= buf[0])) sort_unique(buf);
    out.items.insert(out.items.end(), buf.begin(), buf.end());
  }, [&](size_t b, size_t e) { return static_cast<size_t>(w.polylines.offsets[e] - w.polylines.offsets[b]); });
  ix.point_wires = detail::transpose(ix.wire_points, static_cast<size_t>(n), par);
  return ix;
}

// Opacity of the points of chain w (see wireframe_style.hpp), `dv` the hops of each vertex.
template <class Value>
void chain_opacity(const CellComplex& cx, const VsgWireframe& wf, const std::vector<uint8_t>& source,
                   const std::vector<int32_t>& dv, int32_t horizon, const Value& value, size_t w,
                   std::vector<float>& point_opacity) {
  const auto es = wf.edges[w];
  bool full = wf.kind[w] == WireKind::Vsg;
  for (int32_t e : es) full = full || cx.edge_non_hex[e];
  if (full) return;
  size_t out = static_cast<size_t>(wf.polylines.offsets[w]);
  if (cx.closed(es[0])) {  // a curve without corners: its own distance is unknown, so the floor
    for (int32_t k = 0; k < wf.polylines.count(w); ++k) point_opacity[out++] = value(source[es[0]] ? 0 : horizon);
    return;
  }
  // Walk the complex edges in polyline order; point k of an edge of n segments from end a to b
  // is min(d(a) + k, d(b) + n - k) hops away.
  // The polyline starts at the end of its first edge whose mesh vertex it starts with.
  int32_t cur = cx.edge_verts[es[0]][wf.polylines[w][0] == cx.edge_points[es[0]][0] ? 0 : 1];
  for (size_t i = 0; i < es.size(); ++i) {
    const int32_t e = es[i];
    const int32_t n = cx.edge_points.count(e) - 1;
    const int32_t next = cx.other_vertex(e, cur);
    for (int32_t k = i == 0 ? 0 : 1; k <= n; ++k) {
      const int32_t d = source[e] ? 0 : std::min(dv[cur] + k, dv[next] + n - k);
      point_opacity[out++] = value(d);
    }
    cur = next;
  }
}

// Hops from the vertices at distance 0 in `dv` (kInf elsewhere), up to `horizon` (farther ones
// keep kInf). Distances beyond opacity_hops all give the floor, so the search stops there; below
// it they are small integers, so the vertices are settled one distance at a time: a sweep in
// vertex order per distance reads the complex in memory order, where a queue would hop across
// it. Shortest distances do not depend on the order vertices are settled in, so ranges of
// vertices sweep at once, lowering distances by atomic minima; an edge of no segment reaches
// vertices at the current distance, which one more sweep of that distance settles.
void hop_distances(const CellComplex& cx, int32_t horizon, const Threads& par, std::vector<int32_t>& dv) {
  const size_t nv = cx.num_vertices();
  const auto nr = static_cast<size_t>(detail::range_count(nv, par));
  int32_t reach = 0;  // the farthest distance given so far: no sweep past it
  for (int32_t d = 0; d <= horizon && d <= reach; ++d) {
    for (bool again = true; again;) {
      std::vector<int32_t> reached(nr, 0);
      std::vector<uint8_t> same(nr, 0);
      detail::parallel_ranges(nv, par, [&](size_t b, size_t end, int k) {
        int32_t my_reach = 0;  // local, stored once: the ranges' entries share a cache line
        bool my_same = false;
        for (size_t v = b; v < end; ++v) {
          if (::hbc::detail::atomic_ref<int32_t>(dv[v]).load(std::memory_order_relaxed) != d) continue;
          for (int32_t e : cx.vert_edges[v]) {
            const int32_t u = cx.other_vertex(e, static_cast<int32_t>(v));
            const int32_t nd = d + cx.edge_points.count(e) - 1;
            if (nd > horizon) continue;
            ::hbc::detail::atomic_ref<int32_t> du(dv[static_cast<size_t>(u)]);
            int32_t old = du.load(std::memory_order_relaxed);
            while (nd < old && !du.compare_exchange_weak(old, nd, std::memory_order_relaxed)) {
            }
            if (nd < old) {
              my_reach = std::max(my_reach, nd);
              my_same = my_same || nd == d;
            }
          }
        }
        reached[static_cast<size_t>(k)] = my_reach;
        same[static_cast<size_t>(k)] = my_same ? 1 : 0;
      });
      reach = std::max(reach, *std::max_element(reached.begin(), reached.end()));
      again = std::find(same.begin(), same.end(), uint8_t{1}) != same.end();
    }
  }
}

void opacity(const CellComplex& cx, const WireframeStyleOptions& opt, const VsgWireframe& wf, const Threads& par,
             WireframeStyle& st) {
  const size_t nv = cx.num_vertices(), ne = cx.num_edges();
  constexpr int32_t kInf = std::numeric_limits<int32_t>::max() / 4;
  std::vector<uint8_t> source(ne, 0);
  std::vector<int32_t> dv(nv, kInf);
  const int32_t horizon = std::max(opt.opacity_hops, 1);
  // Threads only ever store the same 0 into a shared vertex's distance.
  detail::parallel_ranges(ne, par, [&](size_t b, size_t end, int) {
    for (size_t e = b; e < end; ++e) {
      source[e] = wf.edge_vsg[e] || cx.edge_non_hex[e];
      if (!source[e] || cx.closed(e)) continue;
      for (int32_t v : cx.edge_verts[e]) ::hbc::detail::atomic_ref<int32_t>(dv[static_cast<size_t>(v)]).store(0, std::memory_order_relaxed);
    }
  });
  hop_distances(cx, horizon, par, dv);
  const double floor = std::clamp(opt.opacity_floor, 0.0, 1.0);
  auto value = [&](int32_t d) {
    return static_cast<float>(std::max(floor, 1.0 - (1.0 - floor) * double(d) / double(horizon)));
  };
  st.point_opacity.assign(wf.polylines.items.size(), 1.0f);
  // Each chain writes its own points: ranges of chains in parallel.
  detail::parallel_ranges(wf.size(), par, [&](size_t b, size_t e, int) {
    for (size_t w = b; w < e; ++w) chain_opacity(cx, wf, source, dv, horizon, value, w, st.point_opacity);
  });
}

// A point where more wires meet than this is crowded (see colours()).
constexpr size_t kCrowded = 64;

// The distinct points of each class's wires, and the crowded ones among them (numbered densely,
// crowded_point[q] being crowded point q), each row sorted. A class of one wire (most of them)
// reads its wire's points; only larger classes have rows of their own in `merged`.
struct ClassPoints {
  const Csr<int32_t>& class_wires;
  const Index& ix;
  Csr<int32_t> merged, crowded;
  std::vector<int32_t> crowded_point;
  size_t crowded_points = 0;
  std::span<const int32_t> points(size_t c) const {
    const auto ws = class_wires[c];
    return ws.size() == 1 ? ix.wire_points[static_cast<size_t>(ws[0])] : merged[c];
  }
};

// Row c: the distinct points of class c when it has several wires (else empty), in increasing
// order. Each point lists such classes among its wires once, and the transpose then lists every
// class's points in point order: a linear pass instead of a sort of each class's points (a class
// along a sheet of a split grid gathers tens of thousands).
Csr<int32_t> merged_points(const Csr<int32_t>& class_wires, const std::vector<int32_t>& wire_class, const Index& ix,
                           const Threads& par) {
  const Csr<int32_t> point_classes = parallel_rows_of<int32_t, std::vector<int32_t>>(
      ix.point_wires.rows(), par, [&](size_t p, Csr<int32_t>& out, std::vector<int32_t>& buf) {
        buf.clear();
        for (int32_t w : ix.point_wires[p]) {
          const int32_t c = wire_class[static_cast<size_t>(w)];
          if (class_wires.count(static_cast<size_t>(c)) > 1) buf.push_back(c);
        }
        sort_unique(buf);
        out.items.insert(out.items.end(), buf.begin(), buf.end());
      },
      [&](size_t b, size_t e) { return static_cast<size_t>(ix.point_wires.offsets[e] - ix.point_wires.offsets[b]); });
  return detail::transpose(point_classes, class_wires.rows(), par);
}

ClassPoints class_points(const Csr<int32_t>& class_wires, const std::vector<int32_t>& wire_class, const Index& ix,
                         const Threads& par) {
  ClassPoints cp{class_wires, ix, {}, {}, {}, 0};
  const size_t np = ix.point_wires.rows();
  std::vector<int32_t> crowded_id(np, -1);
  for (size_t p = 0; p < np; ++p)
    if (ix.point_wires[p].size() > kCrowded) {
      crowded_id[p] = static_cast<int32_t>(cp.crowded_point.size());
      cp.crowded_point.push_back(static_cast<int32_t>(p));
    }
  cp.crowded_points = cp.crowded_point.size();
  const size_t nc = class_wires.rows();
  cp.merged = merged_points(class_wires, wire_class, ix, par);
  cp.crowded = parallel_rows_of<int32_t, char>(nc, par, [&](size_t c, Csr<int32_t>& out, char&) {
    for (int32_t p : cp.points(c))
      if (crowded_id[static_cast<size_t>(p)] >= 0) out.items.push_back(crowded_id[static_cast<size_t>(p)]);
  });
  return cp;
}

// Row w: (w', |E_w|) by increasing w' (see colours()), ranges of wires in parallel.
PartedRows<std::array<int32_t, 2>> parallel_counts(const CellComplex& cx, const Index& ix, const VsgWireframe& wf,
                                                  const Threads& threads) {
  using Pairs = std::vector<std::array<int32_t, 2>>;  // (w', e) for the current wire
  // Ranges of about as many wire edges each: a few long wires (a singular curve's) take most of
  // the work on some meshes.
  return weighted_parted_rows<std::array<int32_t, 2>, Pairs>(wf.edges.offsets, threads, [&](size_t w, Csr<std::array<int32_t, 2>>& counts, Pairs& par) {
    par.clear();
    for (int32_t e : wf.edges[w])
      for (int32_t f : cx.edge_faces[e]) {
        if (!cx.face_quad[f]) continue;
        for (int32_t g : cx.face_edges[f]) {
          const int32_t w2 = ix.edge_wire[g];
          if (g == e || w2 < 0 || w2 == static_cast<int32_t>(w) || share_vertex(cx, e, g)) continue;
          par.push_back({w2, e});
        }
      }
    sort_unique(par);
    for (size_t i = 0; i < par.size();) {
      size_t j = i;
      while (j < par.size() && par[j][0] == par[i][0]) ++j;
      counts.items.push_back({par[i][0], static_cast<int32_t>(j - i)});
      i = j;
    }
  }, [&](size_t b, size_t e) {
    // A row has a count per (edge, face) incidence of its wire at most (a quad's one opposite edge).
    size_t n = 0;
    for (int32_t x : std::span(wf.edges.items).subspan(static_cast<size_t>(wf.edges.offsets[b]),
                                                      static_cast<size_t>(wf.edges.offsets[e] - wf.edges.offsets[b])))
      n += static_cast<size_t>(cx.edge_faces.count(static_cast<size_t>(x)));
    return n;
  });
}

// Row c, for a class root c: the classes b < c (the ones coloured before c) that c's colour
// avoids, each once (see colours()); other rows are empty. Which they are does not depend on the
// colours, so ranges of classes find them in parallel, each with a stamp table of its own, and
// only the choice of colours itself stays in class order.
Csr<int32_t> earlier_neighbours(const ClassPoints& cp, const Index& ix, const std::vector<int32_t>& wire_class,
                                const Threads& par) {
  const size_t nw = wire_class.size();
  // Ranges of classes holding about as many wires each (the classes along a split grid's sheets
  // are few, low-numbered and hold most of the wires), each range with the stamps of its own,
  // made at its first class root.
  using Stamps = std::vector<int32_t>;
  return concat(weighted_parted_rows<int32_t, Stamps>(cp.class_wires.offsets, par, [&](size_t c, Csr<int32_t>& out, Stamps& stamp) {
                  const auto ci = static_cast<int32_t>(c);
                  if (wire_class[c] != ci) return;
                  if (stamp.empty()) stamp.assign(nw, -1);
                  const auto crowded = cp.crowded[c];
                  const bool by_count = crowded.size() == 1;  // more crowded points: visited, to count each class once
                  for (int32_t p : cp.points(c)) {
                    if (by_count && p == cp.crowded_point[static_cast<size_t>(crowded[0])]) continue;
                    for (int32_t w2 : ix.point_wires[static_cast<size_t>(p)]) {
                      const int32_t b = wire_class[static_cast<size_t>(w2)];
                      if (b >= ci || stamp[static_cast<size_t>(b)] == ci) continue;
                      stamp[static_cast<size_t>(b)] = ci;
                      // A class at the crowded point is in its count already.
                      const auto bc = cp.crowded[static_cast<size_t>(b)];
                      if (by_count && std::binary_search(bc.begin(), bc.end(), crowded[0])) continue;
                      out.items.push_back(b);
                    }
                  }
                }).parts);
}

// The class (lowest wire) of each wire: wires whose parallel edge counts reach rho both ways are
// joined. The counts and the union-find end here, before the class graph is built (the counts
// are the wireframe style's largest table, some 100 MB on the split grid).
std::vector<int32_t> colour_classes(const CellComplex& cx, const WireframeStyleOptions& opt, const Index& ix,
                                    const VsgWireframe& wf, const Threads& threads) {
  const size_t nw = wf.size();
  // (w, w', |E_w|): how many complex edges of wire w are parallel (Definition 1) to an edge of
  // wire w', in (w, w') order. The (w', e) incidences are gathered and counted one wire at a time,
  // so only the counts are kept, never every incidence of the whole wireframe at once.
  // Row w of `counts` holds (w', |E_w|) by increasing w', so the reverse count of a pair is
  // looked up in the short row of w', not searched for among all counts.
  const PartedRows<std::array<int32_t, 2>> counts = parallel_counts(cx, ix, wf, threads);
  // Classes are the same whatever the order of the unions, and a class's root is its lowest
  // wire either way: ranges of wires unite at once.
  detail::ConcurrentUnionFind uf(nw, threads);
  detail::parallel_ranges(nw, threads, [&](size_t begin, size_t end, int) {
    for (size_t a = begin; a < end; ++a)
      for (const auto& [b, na] : counts[a]) {
        if (static_cast<int32_t>(a) > b) continue;
        const auto back = counts[static_cast<size_t>(b)];
        auto it = std::lower_bound(back.begin(), back.end(), std::array<int32_t, 2>{static_cast<int32_t>(a), 0});
        if (it == back.end() || (*it)[0] != static_cast<int32_t>(a)) continue;
        const double fa = double(na) / double(wf.edges.count(a));
        const double fb = double((*it)[1]) / double(wf.edges.count(b));
        if (std::min(fa, fb) >= opt.rho) uf.unite(static_cast<int32_t>(a), b);
      }
  });
  std::vector<int32_t> color_class(nw);
  detail::parallel_ranges(nw, threads, [&](size_t begin, size_t end, int) {
    for (size_t w = begin; w < end; ++w) color_class[w] = uf.find(static_cast<int32_t>(w));
  });
  return color_class;
}

void colours(const CellComplex& cx, const WireframeStyleOptions& opt, const Index& ix, const VsgWireframe& wf,
             const Threads& threads, WireframeStyle& st) {
  const size_t nw = wf.size();
  st.color_class = colour_classes(cx, opt, ix, wf, threads);
  // Class graph: classes of wire edges sharing a point; each class takes the first colour none of
  // its coloured neighbours holds, else the one fewest of them hold. Only the neighbours coloured
  // before a class are listed (each pair once), and a point where thousands of wires meet (a fan
  // of cells around an edge) is not visited through it: such a crowded point keeps a count of its
  // coloured classes per colour instead, which keeps the lists (and the time) from growing with
  // the square of a fan.
  const Csr<int32_t> class_wires = detail::group_by_key(nw, nw, threads, [&](size_t w) { return st.color_class[w]; });
  const ClassPoints cp = class_points(class_wires, st.color_class, ix, threads);
  const Csr<int32_t> earlier = earlier_neighbours(cp, ix, st.color_class, threads);
  const int32_t palette = std::max(opt.palette_size, 1);
  std::vector<int32_t> class_color(nw, -1), used(static_cast<size_t>(palette));
  std::vector<int32_t> crowded_count(cp.crowded_points * static_cast<size_t>(palette), 0);
  for (size_t c = 0; c < nw; ++c) {
    if (st.color_class[c] != static_cast<int32_t>(c)) continue;
    std::fill(used.begin(), used.end(), 0);
    const auto crowded = cp.crowded[c];
    if (crowded.size() == 1)
      for (int32_t k = 0; k < palette; ++k) used[static_cast<size_t>(k)] = crowded_count[static_cast<size_t>(crowded[0] * palette + k)];
    for (int32_t b : earlier[c]) ++used[static_cast<size_t>(class_color[static_cast<size_t>(b)])];
    // The first free colour; with none free, the one fewest neighbours hold.
    class_color[c] = static_cast<int32_t>(std::min_element(used.begin(), used.end()) - used.begin());
    for (int32_t q : crowded) ++crowded_count[static_cast<size_t>(q * palette + class_color[c])];
  }
  st.color.resize(nw);
  for (size_t w = 0; w < nw; ++w) st.color[w] = class_color[st.color_class[w]];
}

}  // namespace

WireframeStyle wireframe_style(const CellComplex& complex, const VsgWireframe& w, const WireframeStyleOptions& options,
                               const Threads& threads) {
  const Threads par = resolved(threads);
  WireframeStyle st;
  opacity(complex, options, w, par, st);
  const Index ix = index_points(complex, w, par);
  colours(complex, options, ix, w, par, st);
  return st;
}

}  // namespace hbc
