#include "hbc/singularity_graph.hpp"

#include <algorithm>
#include <atomic>

#include "parallel/parallel.hpp"

namespace hbc {

namespace {

// The member edges as a graph of chains: a chain passes a vertex between its two member edges
// when the vertex is not a stop and their values agree. pass() is symmetric, so every chain is a
// path or a cycle, and the edge a chain reaches a vertex by is the one it leaves it by, backwards.
// VertexEdges: rows of the member edges at each vertex (a Csr over every vertex, or
// SparseVertexEdges).
template <class VertexEdges>
struct ChainGraph {
  std::span<const std::array<int32_t, 2>> edge_verts;
  const VertexEdges& vert_edges;
  std::span<const uint8_t> member;
  std::span<const int32_t> value;
  const std::vector<uint8_t>& stop;
  int32_t other_vertex(int32_t e, int32_t v) const { return edge_verts[e][0] == v ? edge_verts[e][1] : edge_verts[e][0]; }
  // The member edge at v other than e, when v lets a chain pass (else -1).
  int32_t pass(int32_t v, int32_t e) const {
    if (stop[v]) return -1;
    int32_t other = -1, count = 0;
    for (int32_t f : vert_edges[static_cast<size_t>(v)]) {
      if (!member[f]) continue;
      ++count;
      if (f != e) other = f;
    }
    if (count != 2 || other < 0 || (!value.empty() && value[other] != value[e])) return -1;
    return other;
  }
};

// The member edges at each vertex that has some, for few members (a grid's singular edges, along
// its box's edges): rows of those vertices only, found by binary search. A table of every vertex
// costs an offset per vertex and a count per vertex and thread, some 120 MB of fresh memory at
// 10^7 cells, for a few thousand edges.
struct SparseVertexEdges {
  std::vector<int32_t> verts;  // sorted, each once
  Csr<int32_t> rows;           // row i: the members at verts[i], in increasing order
  std::span<const int32_t> operator[](size_t v) const {
    const auto it = std::lower_bound(verts.begin(), verts.end(), static_cast<int32_t>(v));
    if (it == verts.end() || *it != static_cast<int32_t>(v)) return {};
    return rows[static_cast<size_t>(it - verts.begin())];
  }
};

SparseVertexEdges sparse_vertex_edges(std::span<const std::array<int32_t, 2>> edge_verts, std::span<const int32_t> members) {
  std::vector<std::array<int32_t, 2>> at;  // (vertex, edge)
  at.reserve(2 * members.size());
  for (int32_t e : members)
    for (int32_t v : edge_verts[static_cast<size_t>(e)]) at.push_back({v, e});
  std::sort(at.begin(), at.end());
  SparseVertexEdges out;
  for (size_t i = 0; i < at.size(); ++i) {
    if (i == 0 || at[i][0] != at[i - 1][0]) {
      if (i > 0) out.rows.offsets.push_back(static_cast<int32_t>(i));
      out.verts.push_back(at[i][0]);
    }
    out.rows.items.push_back(at[i][1]);
  }
  if (!at.empty()) out.rows.offsets.push_back(static_cast<int32_t>(at.size()));
  return out;
}

// One chain, as chain_edges gives it.
struct Chain {
  std::vector<int32_t> fwd, bwd, vs, es;  // edges found walking forward / backward from the start
  bool loop = false;
  int32_t front_v = -1;
};

// The chain through `start`: forward from its hi end, then backward from its lo end, calling
// reached(edge) for every other edge on it.
template <class G, class Reached>
void walk_chain(const G& g, int32_t start, Chain& ch, Reached&& reached) {
  ch.fwd.clear();
  ch.bwd.clear();
  ch.loop = false;
  int32_t v = g.edge_verts[start][1], e = start;
  ch.front_v = g.edge_verts[start][0];
  for (int32_t n; (n = g.pass(v, e)) >= 0; e = n, v = g.other_vertex(n, v)) {
    if (n == start) {
      ch.loop = true;
      return;
    }
    reached(n);
    ch.fwd.push_back(n);
  }
  // A path (no loop): backwards from the lo end, which cannot lead back to the start.
  v = ch.front_v;
  e = start;
  for (int32_t n; (n = g.pass(v, e)) >= 0 && n != start; e = n, v = g.other_vertex(n, v)) {
    reached(n);
    ch.bwd.push_back(n);
  }
  ch.front_v = v;
}

// The walked chain's vertices and edges from its start in canonical orientation (see
// chain_edges in the header).
template <class G>
void orient_chain(const G& g, int32_t start, Chain& ch) {
  auto& vs = ch.vs;
  auto& es = ch.es;
  es.assign(ch.bwd.rbegin(), ch.bwd.rend());
  es.push_back(start);
  es.insert(es.end(), ch.fwd.begin(), ch.fwd.end());
  vs.clear();
  int32_t cur = ch.loop ? g.edge_verts[es[0]][0] : ch.front_v;
  // A loop starts from the vertex of es[0] not shared with es[1] (lo for a 1- or 2-edge loop).
  if (ch.loop && es.size() > 1) {
    const auto a = g.edge_verts[es[0]];
    const auto b = g.edge_verts[es[1]];
    cur = (a[0] == b[0] || a[0] == b[1]) ? a[1] : a[0];
  }
  for (int32_t x : es) {
    vs.push_back(cur);
    cur = g.other_vertex(x, cur);
  }
  if (!ch.loop) {
    vs.push_back(cur);
    if (vs.back() < vs.front()) {
      std::reverse(vs.begin(), vs.end());
      std::reverse(es.begin(), es.end());
    }
    return;
  }
  const size_t n = vs.size();
  const auto p = std::min_element(vs.begin(), vs.end()) - vs.begin();
  std::rotate(vs.begin(), vs.begin() + p, vs.end());
  std::rotate(es.begin(), es.begin() + p, es.end());
  // vs[0] -> vs[1] via es[0]; the other neighbour of vs[0] is vs[n-1] via es[n-1].
  if (n > 2 && vs[n - 1] < vs[1]) {
    std::reverse(vs.begin() + 1, vs.end());
    std::reverse(es.begin(), es.end());
  }
}

struct ChainRows {
  Csr<int32_t> verts, edges;
  std::vector<uint8_t> closed;
};

// Each chain is written by the range holding its lowest edge, which is where a walk in increasing
// edge order starts it, so the chains come out in that order for any number of ranges. A range
// walks each chain with an edge in it once (it marks the chain's edges in `seen`, its own slice of
// the edges), and skips the chains whose lowest edge lies before it.
template <class VertexEdges>
void chain_rows(std::span<const std::array<int32_t, 2>> edge_verts, const VertexEdges& vert_edges,
                std::span<const uint8_t> member, std::span<const int32_t> value, const std::vector<uint8_t>& stop,
                Csr<int32_t>& verts, Csr<int32_t>& edges, std::vector<uint8_t>& closed, const Threads& par) {
  const ChainGraph<VertexEdges> g{edge_verts, vert_edges, member, value, stop};
  const size_t ne = edge_verts.size();
  std::vector<ChainRows> parts(static_cast<size_t>(detail::range_count(ne, par)));
  detail::parallel_ranges(ne, par, [&](size_t b, size_t e, int r) {
    ChainRows out;  // on this thread's stack: the parts' headers share cache lines
    Chain ch;
    std::vector<uint8_t> seen(e - b, 0);  // zeroed by the range's own thread
    for (size_t e0 = b; e0 < e; ++e0) {
      if (!member[e0] || seen[e0 - b]) continue;
      const auto start = static_cast<int32_t>(e0);
      seen[e0 - b] = 1;
      bool first = true;  // the start is the chain's lowest edge
      walk_chain(g, start, ch, [&](int32_t n) {
        first = first && n > start;
        if (static_cast<size_t>(n) >= b && static_cast<size_t>(n) < e) seen[static_cast<size_t>(n) - b] = 1;
      });
      if (!first) continue;
      orient_chain(g, start, ch);
      out.verts.push_row(ch.vs.begin(), ch.vs.end());
      out.edges.push_row(ch.es.begin(), ch.es.end());
      out.closed.push_back(ch.loop ? 1 : 0);
    }
    parts[static_cast<size_t>(r)] = std::move(out);
  });
  std::vector<Csr<int32_t>> vparts, eparts;
  closed.clear();
  for (ChainRows& p : parts) {
    vparts.push_back(std::move(p.verts));
    eparts.push_back(std::move(p.edges));
    closed.insert(closed.end(), p.closed.begin(), p.closed.end());
  }
  verts = concat(std::move(vparts));
  edges = concat(std::move(eparts));
}

}  // namespace

void chain_edges(const Mesh& m, const std::vector<uint8_t>& member, std::span<const int32_t> value,
                 const std::vector<uint8_t>& stop, Csr<int32_t>& verts, Csr<int32_t>& edges,
                 std::vector<uint8_t>& closed, const Threads& threads) {
  // The walk only ever looks at member edges, so the vertex table needs only them; when they are
  // few, only their vertices get rows (the chains are the same either way).
  const Threads par = resolved(threads);
  const auto is_member = [&](size_t e) { return member[e] != 0; };
  if (detail::count_where(m.num_edges(), par, is_member) * 64 < m.num_vertices())
    chain_rows(m.edge_verts, sparse_vertex_edges(m.edge_verts, detail::ids_where(m.num_edges(), par, is_member)),
               member, value, stop, verts, edges, closed, par);
  else
    chain_rows(m.edge_verts, vertex_edges(m, member, par), member, value, stop, verts, edges, closed, par);
}

void chain_edges(std::span<const std::array<int32_t, 2>> edge_verts, const Csr<int32_t>& vert_edges,
                 const std::vector<uint8_t>& member, std::span<const int32_t> value,
                 const std::vector<uint8_t>& stop, Csr<int32_t>& verts, Csr<int32_t>& edges,
                 std::vector<uint8_t>& closed, const Threads& threads) {
  chain_rows(edge_verts, vert_edges, member, value, stop, verts, edges, closed, resolved(threads));
}

namespace {

using detail::set_flag;

// Each chain's valence and boundary flag, the chain of each edge, and the chains' ends that are
// not pseudo-singular (the singular vertices), by ranges of chains.
void chain_facts(const Mesh& m, std::span<const int32_t> valence, SingularityGraph& g, const Threads& par) {
  const size_t ns = g.chain_closed.size();
  detail::assign_touched(g.edge_chain, m.num_edges(), int32_t{-1}, par);
  g.chain_valence.resize(ns);
  g.chain_boundary.resize(ns);
  std::vector<uint8_t> end;
  detail::assign_touched(end, m.num_vertices(), uint8_t{0}, par);
  detail::parallel_ranges(ns, par, [&](size_t b, size_t e, int) {
    for (size_t s = b; s < e; ++s) {
      const auto es = g.chain_edges[s];
      g.chain_valence[s] = valence[es[0]];
      bool all_boundary = true;
      for (int32_t x : es) {
        g.edge_chain[x] = static_cast<int32_t>(s);  // an edge is on one chain
        all_boundary = all_boundary && m.edge_boundary[x];
      }
      g.chain_boundary[s] = all_boundary;
      if (g.chain_closed[s]) continue;
      const auto vs = g.chain_verts[s];
      for (int32_t v : {vs.front(), vs.back()})
        if (!g.vert_pseudo_singular[v]) set_flag(end, v);
    }
  });
  g.singular_vertices = detail::ids_where(end.size(), par, [&](size_t v) { return end[v] != 0; });
}

}  // namespace

SingularityGraph singularity_graph(const Mesh& m, const Threads& threads) {
  const Threads par = resolved(threads);
  SingularityGraph g;
  const size_t ne = m.num_edges(), nv = m.num_vertices();
  // The edges' tables are fresh memory at 10^7 cells (hundreds of MB): their pages are first
  // touched by every thread, and the valences, which the pass below writes whole, are not zeroed.
  detail::resize_touched(g.edge_class, ne, par, EdgeClass::Regular);
  detail::resize_touched(g.edge_irregular, ne, par);
  std::vector<uint8_t> singular;
  detail::resize_touched(singular, ne, par);
  detail::RawArray<int32_t> valence(ne, par);
  // Edges of non-hex cells (the cells around an edge are those having it).
  std::vector<uint8_t> non_hex_edge;
  detail::assign_touched(non_hex_edge, ne, uint8_t{0}, par);
  detail::parallel_ranges(m.num_cells(), par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c)
      if (!m.is_hex(c))
        for (int32_t f : m.cell_faces[c])
          for (int32_t x : m.face_edges(static_cast<size_t>(f))) set_flag(non_hex_edge, x);
  });
  detail::assign_touched(g.vert_pseudo_singular, nv, uint8_t{0}, par);
  detail::parallel_ranges(ne, par, [&](size_t b, size_t end, int) {
    for (size_t e = b; e < end; ++e) {
      valence[e] = m.edge_valence(e);
      g.edge_irregular[e] = m.edge_boundary[e] ? valence[e] != 2 : valence[e] != 4;
      const auto [v0, v1] = m.edge_verts[e];
      if (non_hex_edge[e]) g.edge_class[e] = EdgeClass::PseudoSingular;
      else if (g.edge_irregular[e]) g.edge_class[e] = EdgeClass::Singular;
      else if (m.vert_non_manifold[v0] || m.vert_non_manifold[v1]) g.edge_class[e] = EdgeClass::NonManifold;
      singular[e] = g.edge_class[e] == EdgeClass::Singular;
      if (g.edge_class[e] == EdgeClass::PseudoSingular || g.edge_class[e] == EdgeClass::NonManifold)
        set_flag(g.vert_pseudo_singular, v0), set_flag(g.vert_pseudo_singular, v1);
    }
  });
  g.pseudo_singular_edges = detail::ids_where(ne, par, [&](size_t e) { return g.edge_class[e] == EdgeClass::PseudoSingular; });
  g.non_manifold_edges = detail::ids_where(ne, par, [&](size_t e) { return g.edge_class[e] == EdgeClass::NonManifold; });
  g.pseudo_singular_vertices = detail::ids_where(nv, par, [&](size_t v) { return g.vert_pseudo_singular[v] != 0; });
  const std::span<const int32_t> valences(valence.data(), ne);
  chain_edges(m, singular, valences, g.vert_pseudo_singular, g.chain_verts, g.chain_edges, g.chain_closed, par);
  chain_facts(m, valences, g, par);
  return g;
}

}  // namespace hbc
