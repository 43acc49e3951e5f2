#include "hbc/singularity_graph.hpp"

#include <algorithm>

namespace hbc {

void chain_edges(const Mesh& m, const std::vector<uint8_t>& member, std::span<const int32_t> value,
                 const std::vector<uint8_t>& stop, Csr<int32_t>& verts, Csr<int32_t>& edges,
                 std::vector<uint8_t>& closed) {
  // The walk only ever looks at member edges, so the vertex table needs only them.
  chain_edges(m.edge_verts, vertex_edges(m, member), member, value, stop, verts, edges, closed);
}

void chain_edges(std::span<const std::array<int32_t, 2>> edge_verts, const Csr<int32_t>& vert_edges,
                 const std::vector<uint8_t>& member, std::span<const int32_t> value,
                 const std::vector<uint8_t>& stop, Csr<int32_t>& verts, Csr<int32_t>& edges,
                 std::vector<uint8_t>& closed) {
  verts.clear();
  edges.clear();
  closed.clear();
  const size_t ne = edge_verts.size();
  // Named like the Mesh members so that the walk below reads the same for both callers.
  struct {
    std::span<const std::array<int32_t, 2>> edge_verts;
    const Csr<int32_t>& vert_edges;
    int32_t other_vertex(int32_t e, int32_t v) const {
      return edge_verts[e][0] == v ? edge_verts[e][1] : edge_verts[e][0];
    }
  } m{edge_verts, vert_edges};
  // The member edge at v other than e, when v lets a chain pass (else -1).
  auto pass = [&](int32_t v, int32_t e) -> int32_t {
    if (stop[v]) return -1;
    int32_t other = -1, count = 0;
    for (int32_t f : m.vert_edges[v]) {
      if (!member[f]) continue;
      ++count;
      if (f != e) other = f;
    }
    if (count != 2 || other < 0 || (!value.empty() && value[other] != value[e])) return -1;
    return other;
  };
  std::vector<uint8_t> seen(ne, 0);
  std::vector<int32_t> fwd, bwd, vs, es;  // edges found walking forward / backward from the start
  for (size_t e0 = 0; e0 < ne; ++e0) {
    if (!member[e0] || seen[e0]) continue;
    const int32_t start = static_cast<int32_t>(e0);
    seen[start] = 1;
    fwd.clear();
    bwd.clear();
    bool loop = false;
    // Forward from the hi end, then backward from the lo end.
    int32_t v = m.edge_verts[start][1], e = start;
    int32_t front_v = m.edge_verts[start][0];
    for (;;) {
      int32_t n = pass(v, e);
      if (n < 0) break;
      if (n == start) {
        loop = true;
        break;
      }
      seen[n] = 1;
      fwd.push_back(n);
      e = n;
      v = m.other_vertex(n, v);
    }
    if (!loop) {
      v = front_v;
      e = start;
      for (;;) {
        int32_t n = pass(v, e);
        if (n < 0 || seen[n]) break;
        seen[n] = 1;
        bwd.push_back(n);
        e = n;
        v = m.other_vertex(n, v);
      }
      front_v = v;
    }
    // Vertices along the chain from front_v.
    es.assign(bwd.rbegin(), bwd.rend());
    es.push_back(start);
    es.insert(es.end(), fwd.begin(), fwd.end());
    vs.clear();
    int32_t cur = loop ? m.edge_verts[es[0]][0] : front_v;
    if (loop) {
      // For a loop, the walk direction from edge 0 is lo -> hi... find the start vertex: the
      // vertex of es[0] not shared with es[1] (or lo for a 1- or 2-edge loop).
      if (es.size() > 1) {
        const auto a = m.edge_verts[es[0]];
        const auto b = m.edge_verts[es[1]];
        cur = (a[0] == b[0] || a[0] == b[1]) ? a[1] : a[0];
      }
    }
    for (int32_t x : es) {
      vs.push_back(cur);
      cur = m.other_vertex(x, cur);
    }
    if (!loop) vs.push_back(cur);
    // Canonical orientation for stable output.
    if (!loop) {
      if (vs.back() < vs.front()) {
        std::reverse(vs.begin(), vs.end());
        std::reverse(es.begin(), es.end());
      }
    } else {
      const size_t n = vs.size();
      size_t p = static_cast<size_t>(std::min_element(vs.begin(), vs.end()) - vs.begin());
      std::rotate(vs.begin(), vs.begin() + static_cast<long>(p), vs.end());
      std::rotate(es.begin(), es.begin() + static_cast<long>(p), es.end());
      // vs[0] -> vs[1] via es[0]; the other neighbour of vs[0] is vs[n-1] via es[n-1].
      if (n > 2 && vs[n - 1] < vs[1]) {
        std::reverse(vs.begin() + 1, vs.end());
        std::reverse(es.begin(), es.end());
      }
    }
    verts.push_row(vs.begin(), vs.end());
    edges.push_row(es.begin(), es.end());
    closed.push_back(loop ? 1 : 0);
  }
}

SingularityGraph singularity_graph(const Mesh& m) {
  SingularityGraph g;
  const size_t ne = m.num_edges(), nv = m.num_vertices();
  g.edge_class.assign(ne, EdgeClass::Regular);
  g.edge_irregular.assign(ne, 0);
  std::vector<uint8_t> singular(ne, 0);
  std::vector<int32_t> valence(ne, 0);
  // Edges of non-hex cells (the cells around an edge are those having it).
  std::vector<uint8_t> non_hex_edge(ne, 0);
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (!m.is_hex(c))
      for (int32_t f : m.cell_faces[c])
        for (int32_t e : m.face_edges(static_cast<size_t>(f))) non_hex_edge[static_cast<size_t>(e)] = 1;
  for (size_t e = 0; e < ne; ++e) {
    valence[e] = m.edge_valence(e);
    g.edge_irregular[e] = m.edge_boundary[e] ? valence[e] != 2 : valence[e] != 4;
    const bool non_hex = non_hex_edge[e] != 0;
    const auto [a, b] = m.edge_verts[e];
    if (non_hex) g.edge_class[e] = EdgeClass::PseudoSingular;
    else if (g.edge_irregular[e]) g.edge_class[e] = EdgeClass::Singular;
    else if (m.vert_non_manifold[a] || m.vert_non_manifold[b]) g.edge_class[e] = EdgeClass::NonManifold;
    singular[e] = g.edge_class[e] == EdgeClass::Singular;
    if (g.edge_class[e] == EdgeClass::PseudoSingular) g.pseudo_singular_edges.push_back(static_cast<int32_t>(e));
    if (g.edge_class[e] == EdgeClass::NonManifold) g.non_manifold_edges.push_back(static_cast<int32_t>(e));
  }
  g.vert_pseudo_singular.assign(nv, 0);
  for (size_t e = 0; e < ne; ++e) {
    if (g.edge_class[e] == EdgeClass::PseudoSingular || g.edge_class[e] == EdgeClass::NonManifold) {
      g.vert_pseudo_singular[m.edge_verts[e][0]] = 1;
      g.vert_pseudo_singular[m.edge_verts[e][1]] = 1;
    }
  }
  for (size_t v = 0; v < nv; ++v)
    if (g.vert_pseudo_singular[v]) g.pseudo_singular_vertices.push_back(static_cast<int32_t>(v));

  chain_edges(m, singular, valence, g.vert_pseudo_singular, g.chain_verts, g.chain_edges, g.chain_closed);
  const size_t ns = g.chain_closed.size();
  g.edge_chain.assign(ne, -1);
  g.chain_valence.resize(ns);
  g.chain_boundary.resize(ns);
  for (size_t s = 0; s < ns; ++s) {
    auto es = g.chain_edges[s];
    g.chain_valence[s] = valence[es[0]];
    bool all_boundary = true;
    for (int32_t e : es) {
      g.edge_chain[e] = static_cast<int32_t>(s);
      all_boundary = all_boundary && m.edge_boundary[e];
    }
    g.chain_boundary[s] = all_boundary;
    if (!g.chain_closed[s]) {
      auto vs = g.chain_verts[s];
      for (int32_t v : {vs.front(), vs.back()})
        if (!g.vert_pseudo_singular[v]) g.singular_vertices.push_back(v);
    }
  }
  std::sort(g.singular_vertices.begin(), g.singular_vertices.end());
  g.singular_vertices.erase(std::unique(g.singular_vertices.begin(), g.singular_vertices.end()),
                            g.singular_vertices.end());
  return g;
}

}  // namespace hbc
