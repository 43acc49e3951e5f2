#include "hbc/vsg_wireframe.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

#include "hbc/singularity_graph.hpp"

#include "union_find.hpp"

namespace hbc {

int64_t VsgWireframe::wireframe_edges_simplified() const {
  return std::count(shown.begin(), shown.end(), uint8_t{1});
}

namespace {

using MinUnionFind = detail::UnionFind;  // root = lowest member: deterministic class ids

bool share_cell(const CellComplex& cx, int32_t e, int32_t f) {
  const auto a = cx.edge_cells[e], b = cx.edge_cells[f];
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (a[i] == b[j]) return true;
    a[i] < b[j] ? ++i : ++j;
  }
  return false;
}

bool share_vertex(const CellComplex& cx, int32_t e, int32_t f) {
  const auto a = cx.edge_verts[e], b = cx.edge_verts[f];
  if (a[0] < 0 || b[0] < 0) return false;
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

// Appends the points of complex edge e walked from vertex `from` to `poly`, skipping the first
// point when the polyline already ends there.
void append_points(const CellComplex& cx, int32_t e, int32_t from, std::vector<int32_t>& poly) {
  const auto pts = cx.edge_points[e];
  const bool forward = cx.edge_verts[e][0] == from;
  const size_t n = pts.size();
  for (size_t k = poly.empty() ? 0 : 1; k < n; ++k) poly.push_back(forward ? pts[k] : pts[n - 1 - k]);
}

class Builder {
 public:
  Builder(const CellComplex& cx, const WireframeOptions& opt, VsgWireframe& w) : cx_(cx), opt_(opt), w_(w) {}

  void run() {
    find_vsg();
    add_vsg_chains();
    add_traces();
    index_points();
    mark_non_important();
    reactivate();
    opacity();
    colours();
  }

 private:
  const CellComplex& cx_;
  const WireframeOptions& opt_;
  VsgWireframe& w_;
  std::vector<int32_t> edge_wire_;             // ne: wire edge holding the complex edge, else -1
  std::vector<int32_t> point_of_mesh_;         // mesh vertex -> compact point id, else -1
  Csr<int32_t> wire_points_, point_wires_;     // distinct compact points per wire and back

  void push_wire(WireKind kind, std::span<const int32_t> es, const std::vector<int32_t>& poly,
                 std::array<int32_t, 2> ends, int32_t valence, TraceStop stop) {
    const int32_t id = static_cast<int32_t>(w_.kind.size());
    for (int32_t e : es) edge_wire_[e] = id;
    w_.edges.push_row(es);
    w_.polylines.push_row(poly.begin(), poly.end());
    w_.ends.push_back(ends);
    w_.kind.push_back(kind);
    w_.valence.push_back(valence);
    w_.stop.push_back(stop);
  }

  void find_vsg() {
    const size_t ne = cx_.num_edges(), nv = cx_.num_vertices();
    w_.edge_vsg.assign(ne, 0);
    w_.vert_vsg.assign(nv, 0);
    for (size_t e = 0; e < ne; ++e) {
      if (!cx_.irregular(e)) continue;
      w_.edge_vsg[e] = 1;
      ++w_.vsg_edges;
      if (!cx_.closed(e)) w_.vert_vsg[cx_.edge_verts[e][0]] = w_.vert_vsg[cx_.edge_verts[e][1]] = 1;
    }
    edge_wire_.assign(ne, -1);
  }

  void add_vsg_chains() {
    const size_t ne = cx_.num_edges(), nv = cx_.num_vertices();
    // Closed curves have no vertices for chain_edges to walk: each is a closed chain by itself.
    std::vector<uint8_t> member(w_.edge_vsg);
    for (size_t e = 0; e < ne; ++e) member[e] = member[e] && !cx_.closed(e);
    Csr<int32_t> cverts, cedges;
    std::vector<uint8_t> closed;
    chain_edges(cx_.edge_verts, cx_.vert_edges, member, cx_.edge_valence, std::vector<uint8_t>(nv, 0),
                cverts, cedges, closed);
    w_.vert_singular.assign(nv, 0);
    std::vector<int32_t> poly;
    for (size_t s = 0; s < cedges.rows(); ++s) {
      const auto vs = cverts[s];
      const auto es = cedges[s];
      poly.clear();
      for (size_t i = 0; i < es.size(); ++i) append_points(cx_, es[i], vs[i], poly);
      std::array<int32_t, 2> ends{-1, -1};
      if (!closed[s]) {
        ends = {vs.front(), vs.back()};
        w_.vert_singular[vs.front()] = w_.vert_singular[vs.back()] = 1;
      }
      push_wire(WireKind::Vsg, es, poly, ends, cx_.edge_valence[es[0]], TraceStop::None);
    }
    for (size_t e = 0; e < ne; ++e) {
      if (!w_.edge_vsg[e] || !cx_.closed(e)) continue;
      const auto pts = cx_.edge_points[e];
      poly.assign(pts.begin(), pts.end());
      const int32_t one = static_cast<int32_t>(e);
      push_wire(WireKind::Vsg, std::span<const int32_t>(&one, 1), poly, {-1, -1}, cx_.edge_valence[e],
                TraceStop::None);
    }
    w_.vsg_chains = static_cast<int64_t>(w_.kind.size());
    for (size_t v = 0; v < nv; ++v)
      if (w_.vert_singular[v]) w_.singular_vertices.push_back(static_cast<int32_t>(v));
  }

  // The straight continuation of `in` at vertex v (off the VSG), or -1.
  int32_t continuation(int32_t v, int32_t in, bool along_boundary) const {
    int32_t found = -1;
    for (int32_t f : cx_.vert_edges[v]) {
      if (f == in || cx_.closed(f) || (along_boundary && !cx_.edge_boundary[f])) continue;
      if (share_cell(cx_, in, f)) continue;
      if (found >= 0) return -1;
      found = f;
    }
    return found;
  }

  void add_traces() {
    std::vector<int32_t> es, poly;
    for (int32_t v : w_.singular_vertices) {
      for (int32_t e0 : cx_.vert_edges[v]) {
        // A trace joining two singular vertices is found from both; the first one keeps it.
        if (w_.edge_vsg[e0] || cx_.closed(e0) || edge_wire_[e0] >= 0) continue;
        es.clear();
        poly.clear();
        const bool along_boundary = cx_.edge_boundary[e0];
        int32_t cur = v, e = e0;
        TraceStop stop = TraceStop::NoContinuation;
        for (;;) {
          es.push_back(e);
          append_points(cx_, e, cur, poly);
          cur = cx_.other_vertex(e, cur);
          if (w_.vert_vsg[cur]) {
            stop = TraceStop::VsgVertex;
            break;
          }
          if (!along_boundary && cx_.vert_boundary[cur]) {
            stop = TraceStop::Boundary;
            break;
          }
          const int32_t next = continuation(cur, e, along_boundary);
          // A straight line may cross itself through a vertex; it never reuses an edge.
          if (next < 0 || edge_wire_[next] >= 0 || std::find(es.begin(), es.end(), next) != es.end()) break;
          e = next;
        }
        push_wire(WireKind::Trace, es, poly, {v, cur}, cx_.edge_valence[e0], stop);
      }
    }
  }

  void index_points() {
    int32_t max_id = -1;
    for (int32_t p : w_.polylines.items) max_id = std::max(max_id, p);
    point_of_mesh_.assign(static_cast<size_t>(max_id + 1), -1);
    int32_t n = 0;
    std::vector<int32_t> sorted(w_.polylines.items);
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    for (int32_t p : sorted) point_of_mesh_[p] = n++;
    std::vector<int32_t> buf;
    for (size_t w = 0; w < w_.size(); ++w) {
      buf.clear();
      for (int32_t p : w_.polylines[w]) buf.push_back(point_of_mesh_[p]);
      std::sort(buf.begin(), buf.end());
      buf.erase(std::unique(buf.begin(), buf.end()), buf.end());
      wire_points_.push_row(buf.begin(), buf.end());
    }
    point_wires_ = transpose(wire_points_, static_cast<size_t>(n));
  }

  void mark_non_important();
  void reactivate();
  int64_t count_components(const std::vector<uint8_t>& use);
  void opacity();
  void colours();
};

// Paper §5.1. Criterion 1: both ends non-important. Criteria 2 and 3 look at the regular edges
// (trace ends) around each singular vertex: two can be paired when they share no cell and every
// face around each is a quad.
void Builder::mark_non_important() {
  const size_t nv = cx_.num_vertices(), nw = w_.size();
  w_.vert_non_important.assign(nv, 0);
  for (size_t v = 0; v < nv; ++v) {
    const bool all_quad_corner = cx_.vert_boundary[v] && cx_.vert_cell_count[v] == 1 && cx_.vert_all_quad[v];
    w_.vert_non_important[v] = !w_.vert_singular[v] || all_quad_corner;
  }
  w_.non_important.assign(nw, 0);
  auto mark = [&](size_t w, uint8_t criterion) {
    if (w_.non_important[w] == 0 || w_.non_important[w] > criterion) w_.non_important[w] = criterion;
  };
  for (size_t w = 0; w < nw; ++w) {
    const auto [a, b] = w_.ends[w];
    if (a >= 0 && w_.vert_non_important[a] && w_.vert_non_important[b]) mark(w, 1);
  }
  // (vertex, wire, local complex edge) for every trace end at a singular vertex.
  struct Incidence {
    int32_t vert, wire, edge;
  };
  std::vector<Incidence> inc;
  for (size_t w = 0; w < nw; ++w) {
    if (w_.kind[w] != WireKind::Trace) continue;
    const auto es = w_.edges[w];
    const int32_t id = static_cast<int32_t>(w);
    inc.push_back({w_.ends[w][0], id, es.front()});
    if (w_.vert_singular[w_.ends[w][1]]) inc.push_back({w_.ends[w][1], id, es.back()});
  }
  std::stable_sort(inc.begin(), inc.end(), [](const Incidence& x, const Incidence& y) { return x.vert < y.vert; });
  std::vector<std::vector<int32_t>> pairs;  // per candidate at the vertex: the candidates it pairs with
  std::vector<int32_t> cand;
  for (size_t i = 0; i < inc.size();) {
    size_t j = i;
    while (j < inc.size() && inc[j].vert == inc[i].vert) ++j;
    cand.clear();
    for (size_t k = i; k < j; ++k)
      if (cx_.edge_all_quad[inc[k].edge]) cand.push_back(static_cast<int32_t>(k));
    pairs.assign(cand.size(), {});
    for (size_t x = 0; x < cand.size(); ++x)
      for (size_t y = 0; y < cand.size(); ++y) {
        const Incidence &p = inc[cand[x]], &q = inc[cand[y]];
        if (x != y && p.wire != q.wire && !share_cell(cx_, p.edge, q.edge)) pairs[x].push_back(static_cast<int32_t>(y));
      }
    for (size_t x = 0; x < cand.size(); ++x) {
      const auto& px = pairs[x];
      if (px.size() == 1 && pairs[px[0]].size() == 1 && pairs[px[0]][0] == static_cast<int32_t>(x)) {
        mark(inc[cand[x]].wire, 2);
      } else if (px.size() >= 2) {
        bool only_me = true;
        int32_t lowest = std::numeric_limits<int32_t>::max();
        for (int32_t y : px) {
          only_me = only_me && pairs[y].size() == 1 && pairs[y][0] == static_cast<int32_t>(x);
          lowest = std::min(lowest, inc[cand[y]].wire);
        }
        if (only_me) {
          mark(inc[cand[x]].wire, 3);
          mark(lowest, 3);  // the paper picks one partner at random; we take the lowest index
        }
      }
    }
    i = j;
  }
}

int64_t Builder::count_components(const std::vector<uint8_t>& use) {
  MinUnionFind uf(point_wires_.rows());
  std::vector<uint8_t> touched(point_wires_.rows(), 0);
  for (size_t w = 0; w < w_.size(); ++w) {
    if (!use[w]) continue;
    const auto pts = wire_points_[w];
    for (int32_t p : pts) {
      touched[p] = 1;
      uf.unite(pts[0], p);
    }
  }
  int64_t n = 0;
  for (size_t p = 0; p < touched.size(); ++p) n += touched[p] && uf.find(static_cast<int32_t>(p)) == static_cast<int32_t>(p);
  return n;
}

void Builder::reactivate() {
  const size_t nw = w_.size(), np = point_wires_.rows();
  std::vector<uint8_t> in_r(nw, 0), shown(nw, 0);
  for (size_t w = 0; w < nw; ++w) {
    in_r[w] = w_.kind[w] == WireKind::Vsg || w_.stop[w] == TraceStop::VsgVertex;
    shown[w] = w_.non_important[w] == 0;
  }
  MinUnionFind ur(np), us(np);
  std::vector<uint8_t> point_shown(np, 0), point_on_vsg(np, 0);
  for (size_t w = 0; w < nw; ++w) {
    const auto pts = wire_points_[w];
    for (int32_t p : pts) {
      if (in_r[w]) ur.unite(pts[0], p);
      if (shown[w]) {
        us.unite(pts[0], p);
        point_shown[p] = 1;
        if (w_.kind[w] == WireKind::Vsg) point_on_vsg[p] = 1;
      }
    }
  }
  // Cost of showing a hidden R edge: first whether it touches a shown VSG chain, then its length.
  constexpr int64_t kFar = int64_t{1} << 32;
  std::vector<int64_t> cost(nw, 0);
  for (size_t w = 0; w < nw; ++w) {
    bool touches = false;
    for (int32_t p : wire_points_[w]) touches = touches || point_on_vsg[p];
    cost[w] = (touches ? 0 : kFar) + static_cast<int64_t>(w_.polylines.count(w)) - 1;
  }
  // Pieces of shown edges per component of R, visited in order of the component's lowest point.
  std::vector<std::vector<int32_t>> pieces(np);
  for (size_t p = 0; p < np; ++p) {
    if (!point_shown[p]) continue;
    bool in_reference = false;
    for (int32_t w : point_wires_[p]) in_reference = in_reference || in_r[w];
    if (!in_reference) continue;
    auto& list = pieces[ur.find(static_cast<int32_t>(p))];
    const int32_t s = us.find(static_cast<int32_t>(p));
    if (std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
  }
  w_.reactivated.assign(nw, 0);
  std::vector<int64_t> dist(np, std::numeric_limits<int64_t>::max());
  std::vector<int32_t> via_wire(np, -1), via_point(np, -1), reached;
  std::vector<uint8_t> expanded(nw, 0);
  using Item = std::pair<int64_t, int32_t>;
  for (size_t k = 0; k < np; ++k) {
    if (pieces[k].size() < 2) continue;
    const int32_t component = static_cast<int32_t>(k);
    for (;;) {
      // Grow from the piece holding the component's lowest shown point until another piece.
      const int32_t tree = us.find(pieces[k][0]);
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
      for (int32_t p : reached) dist[p] = std::numeric_limits<int64_t>::max(), via_wire[p] = via_point[p] = -1;
      reached.clear();
      std::fill(expanded.begin(), expanded.end(), 0);
      for (size_t p = 0; p < np; ++p)
        if (point_shown[p] && us.find(static_cast<int32_t>(p)) == tree && ur.find(static_cast<int32_t>(p)) == component) {
          dist[p] = 0;
          reached.push_back(static_cast<int32_t>(p));
          pq.push({0, static_cast<int32_t>(p)});
        }
      int32_t target = -1;
      while (!pq.empty()) {
        const auto [d, p] = pq.top();
        pq.pop();
        if (d != dist[p]) continue;
        if (point_shown[p] && us.find(p) != tree) {
          target = p;
          break;
        }
        for (int32_t w : point_wires_[p]) {
          if (!in_r[w] || shown[w] || expanded[w]) continue;
          expanded[w] = 1;
          for (int32_t q : wire_points_[w]) {
            if (d + cost[w] >= dist[q]) continue;
            if (dist[q] == std::numeric_limits<int64_t>::max()) reached.push_back(q);
            dist[q] = d + cost[w];
            via_wire[q] = w;
            via_point[q] = p;
            pq.push({dist[q], q});
          }
        }
      }
      if (target < 0) break;  // cannot happen: R's component is connected
      for (int32_t p = target; via_wire[p] >= 0; p = via_point[p]) {
        const int32_t w = via_wire[p];
        if (shown[w]) continue;
        shown[w] = 1;
        w_.reactivated[w] = 1;
        const auto pts = wire_points_[w];
        for (int32_t q : pts) {
          us.unite(pts[0], q);
          point_shown[q] = 1;
        }
      }
      us.unite(tree, target);
      auto& list = pieces[k];
      for (int32_t& s : list) s = us.find(s);
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
      if (list.size() < 2) break;
    }
  }
  w_.shown = shown;
  w_.reference_components = count_components(in_r);
  w_.shown_components = count_components(shown);
}

void Builder::opacity() {
  const size_t nv = cx_.num_vertices(), ne = cx_.num_edges();
  constexpr int32_t kInf = std::numeric_limits<int32_t>::max() / 4;
  std::vector<uint8_t> source(ne, 0);
  std::vector<int32_t> dv(nv, kInf);
  using Item = std::pair<int32_t, int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  for (size_t e = 0; e < ne; ++e) {
    source[e] = w_.edge_vsg[e] || cx_.edge_non_hex[e];
    if (!source[e] || cx_.closed(e)) continue;
    for (int32_t v : cx_.edge_verts[e])
      if (dv[v] != 0) {
        dv[v] = 0;
        pq.push({0, v});
      }
  }
  // Distances beyond opacity_hops all give the floor, so the search stops there.
  const int32_t horizon = std::max(opt_.opacity_hops, 1);
  while (!pq.empty()) {
    const auto [d, v] = pq.top();
    pq.pop();
    if (d != dv[v]) continue;
    for (int32_t e : cx_.vert_edges[v]) {
      const int32_t u = cx_.other_vertex(e, v);
      const int32_t nd = d + cx_.edge_points.count(e) - 1;
      if (nd < dv[u] && nd <= horizon) {
        dv[u] = nd;
        pq.push({nd, u});
      }
    }
  }
  const double floor = std::clamp(opt_.opacity_floor, 0.0, 1.0);
  auto value = [&](int32_t d) {
    return static_cast<float>(std::max(floor, 1.0 - (1.0 - floor) * double(d) / double(horizon)));
  };
  w_.point_opacity.assign(w_.polylines.items.size(), 1.0f);
  for (size_t w = 0; w < w_.size(); ++w) {
    const auto es = w_.edges[w];
    bool full = w_.kind[w] == WireKind::Vsg;
    for (int32_t e : es) full = full || cx_.edge_non_hex[e];
    if (full) continue;
    // Walk the complex edges in polyline order; point k of an edge of n segments from end a to b
    // is min(d(a) + k, d(b) + n - k) hops away.
    size_t out = static_cast<size_t>(w_.polylines.offsets[w]);
    int32_t cur = w_.ends[w][0];
    for (size_t i = 0; i < es.size(); ++i) {
      const int32_t e = es[i];
      const int32_t n = cx_.edge_points.count(e) - 1;
      const int32_t next = cx_.other_vertex(e, cur);
      for (int32_t k = i == 0 ? 0 : 1; k <= n; ++k) {
        const int32_t d = source[e] ? 0 : std::min(dv[cur] + k, dv[next] + n - k);
        w_.point_opacity[out++] = value(d);
      }
      cur = next;
    }
  }
}

void Builder::colours() {
  const size_t nw = w_.size();
  // (w, w', e): complex edge e of wire w is parallel (Definition 1) to an edge of wire w'.
  std::vector<std::array<int32_t, 3>> par;
  for (size_t w = 0; w < nw; ++w)
    for (int32_t e : w_.edges[w])
      for (int32_t f : cx_.edge_faces[e]) {
        if (!cx_.face_quad[f]) continue;
        for (int32_t g : cx_.face_edges[f]) {
          const int32_t w2 = edge_wire_[g];
          if (g == e || w2 < 0 || w2 == static_cast<int32_t>(w) || share_vertex(cx_, e, g)) continue;
          par.push_back({static_cast<int32_t>(w), w2, e});
        }
      }
  std::sort(par.begin(), par.end());
  par.erase(std::unique(par.begin(), par.end()), par.end());
  // Count per ordered pair, then look up the reverse pair.
  std::vector<std::array<int32_t, 3>> counts;  // (w, w', |E_w|)
  for (size_t i = 0; i < par.size();) {
    size_t j = i;
    while (j < par.size() && par[j][0] == par[i][0] && par[j][1] == par[i][1]) ++j;
    counts.push_back({par[i][0], par[i][1], static_cast<int32_t>(j - i)});
    i = j;
  }
  MinUnionFind uf(nw);
  for (const auto& c : counts) {
    if (c[0] > c[1]) continue;
    auto it = std::lower_bound(counts.begin(), counts.end(), std::array<int32_t, 3>{c[1], c[0], 0});
    if (it == counts.end() || (*it)[0] != c[1] || (*it)[1] != c[0]) continue;
    const double fa = double(c[2]) / double(w_.edges.count(c[0]));
    const double fb = double((*it)[2]) / double(w_.edges.count(c[1]));
    if (std::min(fa, fb) >= opt_.rho) uf.unite(c[0], c[1]);
  }
  w_.color_class.resize(nw);
  for (size_t w = 0; w < nw; ++w) w_.color_class[w] = uf.find(static_cast<int32_t>(w));
  // Class graph: classes of wire edges sharing a point. Each class's neighbours are visited on
  // the fly (a stamp per class counts each once) instead of listed as pairs: the classes at one
  // point form a clique, and a point where thousands of wires meet (a fan of cells around an
  // edge) would make the pair list quadratic in memory.
  Csr<int32_t> wire_class;
  for (size_t w = 0; w < nw; ++w) wire_class.push_row(&w_.color_class[w], &w_.color_class[w] + 1);
  const Csr<int32_t> class_wires = transpose(wire_class, nw);
  const int32_t palette = std::max(opt_.palette_size, 1);
  std::vector<int32_t> class_color(nw, -1), used(static_cast<size_t>(palette)), stamp(nw, -1);
  for (size_t c = 0; c < nw; ++c) {
    if (w_.color_class[c] != static_cast<int32_t>(c)) continue;
    std::fill(used.begin(), used.end(), 0);
    stamp[c] = static_cast<int32_t>(c);
    for (int32_t w : class_wires[c])
      for (int32_t p : wire_points_[w])
        for (int32_t w2 : point_wires_[p]) {
          const int32_t b = w_.color_class[w2];
          if (stamp[b] == static_cast<int32_t>(c)) continue;
          stamp[b] = static_cast<int32_t>(c);
          if (class_color[b] >= 0) ++used[class_color[b]];
        }
    // The first free colour; with none free, the one fewest neighbours hold.
    class_color[c] = static_cast<int32_t>(std::min_element(used.begin(), used.end()) - used.begin());
  }
  w_.color.resize(nw);
  for (size_t w = 0; w < nw; ++w) w_.color[w] = class_color[w_.color_class[w]];
}

}  // namespace

VsgWireframe vsg_wireframe(const CellComplex& complex, const WireframeOptions& options) {
  VsgWireframe w;
  Builder(complex, options, w).run();
  return w;
}

}  // namespace hbc
