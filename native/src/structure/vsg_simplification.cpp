// VSG wireframe simplification (paper §5.2), by the rules of the authors' cleaning: non-important
// vertices (not singular, or a redundant all-quad corner), non-important edges (both ends
// non-important, or a removable pair at a singular vertex), reactivation of the chains that
// continue a kept one, and the kept chains re-chained.
#include "structure/vsg_simplification.hpp"

#include <algorithm>
#include <array>
#include <span>

#include "parallel/parallel.hpp"
#include "parallel/union_find.hpp"

namespace hbc::vsg {

namespace {

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

}  // namespace

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

}  // namespace hbc::vsg
