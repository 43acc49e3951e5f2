#include "hbc/sheets.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>
#include <cstdlib>
#include <iterator>
#include <memory>
#include <new>
#include <numeric>

#include "parallel/concurrent_union_find.hpp"
#include "parallel/parallel.hpp"
#include "parallel/row_collector.hpp"

namespace hbc {

const char* sheet_type_name(SheetType t) {
  switch (t) {
    case SheetType::Perfect: return "perfect";
    case SheetType::Type1: return "type1";
    case SheetType::Type2: return "type2";
    case SheetType::Type3: return "type3";
  }
  return "?";
}

const char* sheet_type_label(SheetType t) {
  switch (t) {
    case SheetType::Perfect: return "perfect";
    case SheetType::Type1: return "type 1 (non-hex)";
    case SheetType::Type2: return "type 2 (self-parallel)";
    case SheetType::Type3: return "type 3 (self-intersecting)";
  }
  return "?";
}

size_t Sheets::count(SheetType t) const {
  return static_cast<size_t>(
      std::count_if(classes.begin(), classes.end(), [t](const SheetClass& c) { return c.type == t; }));
}

namespace {

using detail::parallel_ranges;
using detail::weighted_range_count;
using detail::weighted_ranges;

bool contains(std::span<const int32_t> sorted, int32_t x) {
  return std::binary_search(sorted.begin(), sorted.end(), x);
}

// The edge of hex cell c at the first vertex of face f that is not an edge of f: it points
// across the face, in the cell's direction orthogonal to f.
int32_t orthogonal_edge(const Mesh& m, int32_t c, int32_t f) {
  // Another face g of the hex at v runs along f on one side of v and across it on the other:
  // the edge of g at v whose far end is not in f.
  const auto fl = m.face_verts[static_cast<size_t>(f)];
  const int32_t v = fl[0];
  auto in_f = [&](int32_t x) { return std::find(fl.begin(), fl.end(), x) != fl.end(); };
  for (int32_t g : m.cell_faces[static_cast<size_t>(c)]) {
    if (g == f) continue;
    const auto gl = m.face_verts[static_cast<size_t>(g)];
    const auto i = static_cast<size_t>(std::find(gl.begin(), gl.end(), v) - gl.begin());
    if (i == gl.size()) continue;
    const size_t n = gl.size(), next = (i + 1) % n, prev = (i + n - 1) % n;
    const auto ge = m.face_edges(static_cast<size_t>(g));  // ge[i] joins gl[i] and gl[i + 1]
    if (!in_f(gl[next])) return ge[i];
    if (!in_f(gl[prev])) return ge[prev];
  }
  return -1;
}

// Membership of blocks in the current sheet without a search per query: a stamp per block.
struct BlockMask {
  std::vector<int32_t> stamp;
  int32_t current = 0;
  explicit BlockMask(size_t nblocks) : stamp(nblocks, 0) {}
  template <class Range>
  void set(const Range& blocks) {
    ++current;
    for (int32_t u : blocks) stamp[u] = current;
  }
  bool operator()(int32_t u) const { return stamp[u] == current; }
};

void sort_unique(std::vector<int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// (end vertex, curve) for every end of an open curve, sorted: curves sharing an end are adjacent.
using CurveEnds = std::vector<std::pair<int32_t, int32_t>>;
CurveEnds sorted_curve_ends(const SheetDomain& d, const std::vector<int32_t>& curves) {
  CurveEnds ends;
  for (int32_t c : curves) {
    const auto [a, b] = d.curve_ends[c];
    if (a < 0) continue;
    ends.push_back({a, c});
    if (b != a) ends.push_back({b, c});
  }
  std::sort(ends.begin(), ends.end());
  return ends;
}

// The configuration of two parallel curves a and b sharing an end (paper §4.2): type 3 when a block
// of the sheet holds both, type 2 when they lie in adjacent blocks, type 1 otherwise.
void classify_pair(const SheetDomain& d, int32_t a, int32_t b, const BlockMask& in_blocks, SheetClass& k) {
  bool common = false;
  for (int32_t u : d.curve_blocks[a])
    if (in_blocks(u) && contains(d.curve_blocks[b], u)) {
      common = true;
      k.self_intersecting_blocks.push_back(u);
    }
  if (common) {
    k.type3 = true;
    return;
  }
  bool adjacent = false;
  for (int32_t ua : d.curve_blocks[a]) {
    if (!in_blocks(ua)) continue;
    for (int32_t ub : d.curve_blocks[b])
      if (in_blocks(ub) && contains(d.block_adjacency[ua], ub)) adjacent = true;
  }
  if (adjacent) {
    k.type2 = true;
    k.self_parallel_curves.push_back(a);
    k.self_parallel_curves.push_back(b);
  } else {
    k.type1 = true;
  }
}

// Every configuration present among the curves sharing an end, and the sheet's type.
void detect_configurations(const SheetDomain& d, const CurveEnds& ends, const BlockMask& in_blocks, SheetClass& k) {
  for (size_t i = 0; i < ends.size();) {
    size_t j = i;
    while (j < ends.size() && ends[j].first == ends[i].first) ++j;
    if (j - i >= 2) k.shared_vertices.push_back(ends[i].first);
    for (size_t p = i; p < j; ++p)
      for (size_t q = p + 1; q < j; ++q) classify_pair(d, ends[p].second, ends[q].second, in_blocks, k);
    i = j;
  }
  sort_unique(k.self_intersecting_blocks);
  sort_unique(k.self_parallel_curves);
  k.type = k.type3 ? SheetType::Type3 : k.type2 ? SheetType::Type2 : k.type1 ? SheetType::Type1 : SheetType::Perfect;
}

// The graph the matching runs on: vertices the distinct curve ends (local ids in increasing
// mesh-vertex order), edges the open curves with two distinct ends (each vertex pair once).
struct EndGraph {
  std::vector<int32_t> verts;                       // nv: mesh vertex of each local vertex
  std::vector<std::pair<int32_t, int32_t>> edges;  // sorted (low, high) local pairs
  Csr<int32_t> adj;                                 // nv rows: neighbours
};

EndGraph end_graph(const SheetDomain& d, const std::vector<int32_t>& curves, const CurveEnds& ends) {
  EndGraph g;
  for (auto [v, c] : ends)
    if (g.verts.empty() || g.verts.back() != v) g.verts.push_back(v);
  auto local = [&](int32_t v) {
    return static_cast<int32_t>(std::lower_bound(g.verts.begin(), g.verts.end(), v) - g.verts.begin());
  };
  for (int32_t c : curves) {
    const auto [a, b] = d.curve_ends[c];
    if (a < 0 || a == b) continue;
    const int32_t la = local(a), lb = local(b);
    g.edges.push_back({std::min(la, lb), std::max(la, lb)});
  }
  std::sort(g.edges.begin(), g.edges.end());
  g.edges.erase(std::unique(g.edges.begin(), g.edges.end()), g.edges.end());
  const size_t nv = g.verts.size();
  g.adj.offsets.assign(nv + 1, 0);
  for (auto [a, b] : g.edges) {
    ++g.adj.offsets[a + 1];
    ++g.adj.offsets[b + 1];
  }
  for (size_t i = 0; i < nv; ++i) g.adj.offsets[i + 1] += g.adj.offsets[i];
  g.adj.items.resize(g.adj.offsets.back());
  std::vector<int32_t> fill(g.adj.offsets.begin(), g.adj.offsets.end() - 1);
  for (auto [a, b] : g.edges) {
    g.adj.items[fill[a]++] = b;
    g.adj.items[fill[b]++] = a;
  }
  return g;
}

// Matches every vertex of degree one with its neighbour (some maximum matching always holds such
// an edge), repeatedly; vertices left without neighbours are unmatched. Returns which vertices
// are still in the graph: the tangled part around shared ends.
std::vector<uint8_t> match_leaves(const EndGraph& g, std::vector<int32_t>& unmatched) {
  const size_t nv = g.verts.size();
  std::vector<int32_t> deg(nv), queue;
  std::vector<uint8_t> alive(nv, 1);
  for (size_t i = 0; i < nv; ++i) {
    deg[i] = g.adj.count(i);
    if (deg[i] == 1) queue.push_back(static_cast<int32_t>(i));
  }
  auto drop = [&](int32_t u) {  // u leaves the graph; its neighbours lose a degree
    alive[u] = 0;
    for (int32_t w : g.adj[u]) {
      if (!alive[w]) continue;
      if (--deg[w] == 1) queue.push_back(w);
      else if (deg[w] == 0) {
        alive[w] = 0;
        unmatched.push_back(g.verts[w]);
      }
    }
  };
  for (size_t q = 0; q < queue.size(); ++q) {
    const int32_t v = queue[q];
    if (!alive[v] || deg[v] != 1) continue;
    int32_t u = -1;
    for (int32_t w : g.adj[v])
      if (alive[w]) u = w;
    alive[v] = 0;
    drop(u);
  }
  return alive;
}

// Boost's Edmonds maximum cardinality matching on the vertices still alive.
void match_rest(const EndGraph& eg, const std::vector<uint8_t>& alive, std::vector<int32_t>& unmatched) {
  std::vector<int32_t> rest, gid(eg.verts.size(), -1);
  for (size_t i = 0; i < eg.verts.size(); ++i)
    if (alive[i]) {
      gid[i] = static_cast<int32_t>(rest.size());
      rest.push_back(static_cast<int32_t>(i));
    }
  if (rest.empty()) return;
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  Graph g(rest.size());
  for (auto [a, b] : eg.edges)
    if (gid[a] >= 0 && gid[b] >= 0) boost::add_edge(static_cast<size_t>(gid[a]), static_cast<size_t>(gid[b]), g);
  std::vector<boost::graph_traits<Graph>::vertex_descriptor> mate(rest.size());
  boost::edmonds_maximum_cardinality_matching(g, &mate[0]);
  for (size_t i = 0; i < rest.size(); ++i)
    if (mate[i] == boost::graph_traits<Graph>::null_vertex()) unmatched.push_back(eg.verts[rest[i]]);
}

// The curve ends a maximum cardinality matching on (curve ends, curves) leaves uncovered, sorted:
// what the figures highlight. Leaves are matched first, which settles most of the graph cheaply.
std::vector<int32_t> unmatched_vertices(const SheetDomain& d, const std::vector<int32_t>& curves,
                                        const CurveEnds& ends) {
  const EndGraph g = end_graph(d, curves, ends);
  std::vector<int32_t> unmatched;
  const std::vector<uint8_t> alive = match_leaves(g, unmatched);
  match_rest(g, alive, unmatched);
  std::sort(unmatched.begin(), unmatched.end());
  return unmatched;
}

// A stamp per mesh vertex: the set of curves last seen at it, negated once a second end met it.
struct EndStamps {
  std::vector<int32_t> stamp;
  int32_t current = 0;
  explicit EndStamps(size_t nverts) : stamp(nverts, 0) {}
};

// The (end vertex, curve) pairs of sorted_curve_ends at the ends two or more curves share: the
// only ones configurations are found at. Most sheets share none, and then nothing is sorted.
CurveEnds shared_curve_ends(const SheetDomain& d, const std::vector<int32_t>& curves, EndStamps& t) {
  const int32_t cur = ++t.current;
  bool any = false;
  auto see = [&](int32_t v) {
    int32_t& s = t.stamp[static_cast<size_t>(v)];
    if (s == cur || s == -cur) {
      s = -cur;
      any = true;
    } else {
      s = cur;
    }
  };
  for (int32_t c : curves) {
    const auto [a, b] = d.curve_ends[c];
    if (a < 0) continue;
    see(a);
    if (b != a) see(b);
  }
  CurveEnds ends;
  if (!any) return ends;
  for (int32_t c : curves) {
    const auto [a, b] = d.curve_ends[c];
    if (a < 0) continue;
    if (t.stamp[static_cast<size_t>(a)] == -cur) ends.push_back({a, c});
    if (b != a && t.stamp[static_cast<size_t>(b)] == -cur) ends.push_back({b, c});
  }
  std::sort(ends.begin(), ends.end());
  return ends;
}

// `stamps` (optional) spares the sort of every curve end when no end is shared.
SheetClass classify(const SheetDomain& d, const std::vector<int32_t>& curves, const BlockMask& in_blocks,
                    EndStamps* stamps = nullptr) {
  SheetClass k;
  if (stamps) {
    detect_configurations(d, shared_curve_ends(d, curves, *stamps), in_blocks, k);
    if (k.type != SheetType::Perfect) k.unmatched_vertices = unmatched_vertices(d, curves, sorted_curve_ends(d, curves));
    return k;
  }
  const CurveEnds ends = sorted_curve_ends(d, curves);
  detect_configurations(d, ends, in_blocks, k);
  if (k.type != SheetType::Perfect) k.unmatched_vertices = unmatched_vertices(d, curves, ends);
  return k;
}

}  // namespace

SheetClass classify_sheet(const SheetDomain& d, const std::vector<int32_t>& curves,
                          const std::vector<int32_t>& blocks) {
  BlockMask mask(d.block_cells.rows());
  mask.set(blocks);
  return classify(d, curves, mask);
}

namespace {

// Mesh edges joined into parallel classes: opposite edges of every quad of a hex cell, and the
// orthogonal directions of two hex cells across a joining face. Each face of a hex cell once, in
// parallel ranges of faces: the classes (their lowest edges as roots) do not depend on the order
// of the unions.
std::vector<int32_t> join_parallel_edges(const Mesh& m, const SheetDomain& d, const Threads& par) {
  detail::ConcurrentUnionFind uf(m.num_edges(), par);
  parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) {
      const auto fc = m.face_cells[f];
      if (!m.is_hex(static_cast<size_t>(fc[0])) && (fc[1] < 0 || !m.is_hex(static_cast<size_t>(fc[1])))) continue;
      const auto fe = m.face_edges(f);
      uf.unite(fe[0], fe[2]);
      uf.unite(fe[1], fe[3]);
      if (d.face_joins[f])
        uf.unite(orthogonal_edge(m, fc[0], static_cast<int32_t>(f)), orthogonal_edge(m, fc[1], static_cast<int32_t>(f)));
    }
  });
  return std::move(uf.parents());
}

// The parallel classes with dense ids, as (class, block) entries and the class of each curve.
struct ParallelClasses {
  int32_t count = 0;
  // Per entry, one per (class, block) with a direction of the class in the block, in order of the
  // block's first cell with it: its class and its block.
  std::vector<int32_t> entry_class, entry_block;
  std::vector<int32_t> curve_class;  // ncurve: class of the curve, -1 for none
};

namespace {

// The classes of edges, over the union-find's table: root() reads it as it comes (any thread, while
// nothing is numbered), and number() then gives roots dense class ids in place, the table holding
// for a root -1 - its class (or itself when no cell has that class) and for any other edge its
// root, so no second per-edge table is needed.
class EdgeClasses {
 public:
  explicit EdgeClasses(std::vector<int32_t>&& parents) : parent_(std::move(parents)) {}
  // Class of edge x, numbering its root's class now if it has none yet.
  int32_t number(int32_t x, int32_t& count) {
    const int32_t r = root(x);
    if (parent_[static_cast<size_t>(r)] == r) parent_[static_cast<size_t>(r)] = -1 - count++;
    return -1 - parent_[static_cast<size_t>(r)];
  }
  // Class of edge x, or -1 when no cell has it.
  int32_t of(int32_t x) const {
    const int32_t r = root(x);
    return parent_[static_cast<size_t>(r)] < 0 ? -1 - parent_[static_cast<size_t>(r)] : -1;
  }
  int32_t root(int32_t x) const {
    while (parent_[static_cast<size_t>(x)] >= 0 && parent_[static_cast<size_t>(x)] != x) x = parent_[static_cast<size_t>(x)];
    return x;
  }

 private:
  std::vector<int32_t> parent_;
};

// The edges a hex cell's three directions are read from: its first face's first two edges and the
// edge across that face.
std::array<int32_t, 3> direction_edges(const Mesh& m, int32_t c) {
  const int32_t f = m.cell_faces[static_cast<size_t>(c)][0];
  const auto fe = m.face_edges(static_cast<size_t>(f));
  return {fe[0], fe[1], orthogonal_edge(m, c, f)};
}

// Per cell, the bits of its direction slots (0-2) where its block meets a class first, the block's
// cells taken in increasing order (as number_classes lists them). A cell is in one block, so
// ranges of blocks write their cells' bits alone.
std::vector<uint8_t> first_meetings(const Mesh& m, const SheetDomain& d, const EdgeClasses& classes,
                                    const Threads& par) {
  std::vector<uint8_t> bits(m.num_cells(), 0);
  detail::weighted_ranges(d.block_cells.offsets, par, [&](size_t b, size_t e, int) {
    std::vector<int32_t> seen;  // roots met in the block so far: three, or a few more
    for (size_t u = b; u < e; ++u) {
      seen.clear();
      for (int32_t c : d.block_cells[u]) {
        const auto dirs = direction_edges(m, c);
        for (size_t s = 0; s < 3; ++s) {
          const int32_t r = classes.root(dirs[s]);
          if (std::find(seen.begin(), seen.end(), r) != seen.end()) continue;
          seen.push_back(r);
          bits[static_cast<size_t>(c)] |= static_cast<uint8_t>(1u << s);
        }
      }
    }
  });
  return bits;
}

}  // namespace

// Dense class ids in order of first appearance over the cells' direction slots, (cell, slot) in
// increasing order; entries in the same order. A class appears first where some block meets it
// first, so numbering the entries in order numbers the classes as a walk over every cell would.
// The entries are found by ranges (of blocks, then of cells); only the numbering, a pass over
// the entries, stays serial.
ParallelClasses parallel_classes(const Mesh& m, const SheetDomain& d, const Threads& par) {
  EdgeClasses classes(join_parallel_edges(m, d, par));
  const std::vector<uint8_t> bits = first_meetings(m, d, classes, par);
  const size_t nc = m.num_cells();
  const std::vector<int64_t> at = detail::range_starts<int64_t>(nc, par, [&](size_t b, size_t e) {
    int64_t n = 0;
    for (size_t c = b; c < e; ++c) n += std::popcount(bits[c]);
    return n;
  });
  ParallelClasses pc;
  pc.entry_class.resize(static_cast<size_t>(at.back()));
  pc.entry_block.resize(static_cast<size_t>(at.back()));
  parallel_ranges(nc, par, [&](size_t b, size_t e, int r) {
    auto k = static_cast<size_t>(at[static_cast<size_t>(r)]);
    for (size_t c = b; c < e; ++c) {
      if (!bits[c]) continue;
      const auto dirs = direction_edges(m, static_cast<int32_t>(c));
      for (size_t s = 0; s < 3; ++s)
        if (bits[c] >> s & 1u) {
          pc.entry_class[k] = classes.root(dirs[s]);  // numbered below
          pc.entry_block[k++] = d.cell_block[c];
        }
    }
  });
  for (int32_t& x : pc.entry_class) x = classes.number(x, pc.count);
  pc.curve_class.resize(d.curve_edges.rows());
  parallel_ranges(pc.curve_class.size(), par, [&](size_t b, size_t e, int) {
    for (size_t k = b; k < e; ++k) pc.curve_class[k] = classes.of(d.curve_edges[k][0]);
  });
  return pc;
}

// A sheet before it is written out: its blocks and parallel curves.
struct Group {
  std::vector<int32_t> blocks, curves;
};

// Each class's blocks split into face-connected groups, one sheet per group, class after class
// and within a class in order of their first block with the class; each group's blocks sorted,
// and its curves: the curves of the class held by its blocks, increasing.
// The groups are the classes of (class, block) entries joined across the faces between blocks,
// found block by block and curve by curve in memory order (a flood per class would hop across
// the blocks of a layer). A group's root is its lowest entry, which in its class's order (entries
// come in cell order) is its first block: ordering the roots by class gives the groups' order.
std::vector<Group> block_groups(const SheetDomain& d, const ParallelClasses& pc, const Threads& par) {
  const size_t ne = pc.entry_class.size(), nb = d.block_cells.rows();
  const Csr<int32_t> block_entries = detail::group_by_key(ne, nb, par, [&](size_t a) { return pc.entry_block[a]; });
  auto entry_of = [&](int32_t u, int32_t k) {
    for (int32_t a : block_entries[static_cast<size_t>(u)])
      if (pc.entry_class[static_cast<size_t>(a)] == k) return a;
    return -1;
  };
  detail::ConcurrentUnionFind uf(ne, par);
  parallel_ranges(nb, par, [&](size_t b, size_t e, int) {
    for (size_t u = b; u < e; ++u)
      for (int32_t w : d.block_adjacency[u]) {
        if (static_cast<size_t>(w) <= u) continue;  // face adjacency is symmetric: each pair once
        for (int32_t a : block_entries[u]) {
          const int32_t x = entry_of(w, pc.entry_class[static_cast<size_t>(a)]);
          if (x >= 0) uf.unite(a, x);
        }
      }
  });
  std::vector<int32_t> root(ne);
  parallel_ranges(ne, par, [&](size_t b, size_t e, int) {
    for (size_t a = b; a < e; ++a) root[a] = uf.find(static_cast<int32_t>(a));
  });
  std::vector<int32_t> root_class;  // per root in entry order: its class
  for (size_t a = 0; a < ne; ++a)
    if (root[a] == static_cast<int32_t>(a)) root_class.push_back(pc.entry_class[a]);
  const Csr<int32_t> by_class =
      detail::group_by_key(root_class.size(), static_cast<size_t>(pc.count), par, [&](size_t r) { return root_class[r]; });
  std::vector<int32_t> group_of_root(root_class.size());
  for (size_t g = 0; g < by_class.items.size(); ++g) group_of_root[static_cast<size_t>(by_class.items[g])] = static_cast<int32_t>(g);
  // Entry -> group: roots come in entry order, so a root's rank among them is its index.
  std::vector<int32_t> group(ne);
  for (size_t a = 0, r = 0; a < ne; ++a)
    if (root[a] == static_cast<int32_t>(a)) group[a] = group_of_root[r++];
  parallel_ranges(ne, par, [&](size_t b, size_t e, int) {
    for (size_t a = b; a < e; ++a)
      if (root[a] != static_cast<int32_t>(a)) group[a] = group[static_cast<size_t>(root[a])];
  });
  // Each group's blocks, then its curves, gathered by ranges of blocks and of curves in order
  // (so each row comes out increasing) and copied into the groups at their exact sizes.
  const size_t ng = root_class.size();
  std::vector<Group> out(ng);
  auto fill = [&](const Csr<int32_t>& rows, std::vector<int32_t> Group::*member) {
    parallel_ranges(ng, par, [&](size_t b, size_t e, int) {
      for (size_t g = b; g < e; ++g) (out[g].*member).assign(rows[g].begin(), rows[g].end());
    });
  };
  fill(detail::group_values_by_key(nb, ng, par, [&](size_t u, auto&& emit) {
         for (int32_t a : block_entries[u]) emit(group[static_cast<size_t>(a)], static_cast<int32_t>(u));
       }),
       &Group::blocks);
  // A curve joins each group holding one of its blocks' entries of its class once.
  auto group_at = [&](int32_t u, int32_t k) {
    const int32_t a = entry_of(u, k);
    return a < 0 ? -1 : group[static_cast<size_t>(a)];
  };
  fill(detail::group_values_by_key(pc.curve_class.size(), ng, par, [&](size_t c, auto&& emit) {
         const int32_t k = pc.curve_class[c];
         if (k < 0) return;
         const auto us = d.curve_blocks[c];
         for (size_t i = 0; i < us.size(); ++i) {
           const int32_t g = group_at(us[i], k);
           bool before = false;
           for (size_t j = 0; j < i && !before; ++j) before = group_at(us[j], k) == g;
           if (g >= 0 && !before) emit(g, static_cast<int32_t>(c));
         }
       }),
       &Group::curves);
  return out;
}

// Sorted, distinct rows[r] for r in `keys`, concatenated, as one row of `out`. Rows of disjoint
// sorted sets listed in the order of their lowest ids (the cells of blocks, or of single-edge
// curves) come out sorted already: then there is nothing to sort. Gathered in place at the end of
// `out`, row by row: the largest sheets hold a good part of the mesh, and a copy through a buffer
// was a third of the time here.
void push_union_row(const Csr<int32_t>& rows, const std::vector<int32_t>& keys, Csr<int32_t>& out) {
  const auto start = static_cast<std::ptrdiff_t>(out.items.size());
  for (int32_t r : keys) {
    const auto row = rows[r];
    out.items.insert(out.items.end(), row.begin(), row.end());
  }
  const auto first = out.items.begin() + start;
  if (!std::is_sorted(first, out.items.end())) std::sort(first, out.items.end());
  out.items.erase(std::unique(first, out.items.end()), out.items.end());
  out.offsets.push_back(static_cast<int32_t>(out.items.size()));
}

// Sheets first..last-1 of `groups`, with their cells, curves, edges, adjacent non-hex cells and
// classification, appended to `s`.
void sheet_rows(const SheetDomain& d, size_t nverts, std::vector<Group>& groups, size_t first, size_t last, Sheets& s) {
  BlockMask mask(d.block_cells.rows());
  EndStamps stamps(nverts);
  for (size_t i = first; i < last; ++i) {
    Group& g = groups[i];
    sort_unique(g.curves);
    s.sheet_blocks.push_row(g.blocks.begin(), g.blocks.end());
    push_union_row(d.block_cells, g.blocks, s.sheet_cells);
    s.sheet_curves.push_row(g.curves.begin(), g.curves.end());
    push_union_row(d.curve_edges, g.curves, s.sheet_edges);
    push_union_row(d.curve_non_hex_cells, g.curves, s.sheet_non_hex_cells);
    mask.set(g.blocks);
    s.classes.push_back(classify(d, g.curves, mask, &stamps));
  }
}

// The sheets in a stable order (lowest block, then lowest curve), written by ranges of sheets
// gathering about as many cells and edges each.
Sheets write_sheets(const SheetDomain& d, size_t nverts, std::vector<Group>& groups, const Threads& par) {
  std::sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
    if (a.blocks[0] != b.blocks[0]) return a.blocks[0] < b.blocks[0];
    const int32_t ca = a.curves.empty() ? -1 : a.curves[0], cb = b.curves.empty() ? -1 : b.curves[0];
    return ca < cb;
  });
  // The cells and edges gathered before each sheet: the ranges' work is in gathering them.
  std::vector<size_t> weight(groups.size() + 1, 0);
  parallel_ranges(groups.size(), detail::with_grain(par, 1), [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i) {
      size_t w = groups[i].blocks.size() + groups[i].curves.size();
      for (int32_t u : groups[i].blocks) w += static_cast<size_t>(d.block_cells.count(static_cast<size_t>(u)));
      for (int32_t c : groups[i].curves) w += static_cast<size_t>(d.curve_edges.count(static_cast<size_t>(c)));
      weight[i + 1] = w;
    }
  });
  for (size_t i = 0; i < groups.size(); ++i) weight[i + 1] += weight[i];
  const auto nr = static_cast<size_t>(weighted_range_count(weight, par));
  std::vector<Sheets> parts(nr);
  weighted_ranges(weight, par, [&](size_t b, size_t e, int r) {
    Sheets own;  // on this thread's stack: neighbouring parts share cache lines
    sheet_rows(d, nverts, groups, b, e, own);
    parts[static_cast<size_t>(r)] = std::move(own);
  });
  // Each table joined at its exact size, each part freed once copied: appending to the first
  // part would grow it by doubling, with the old copy alive while the new one fills (the peak of
  // the analysis on the split grid).
  auto join = [&](Csr<int32_t> Sheets::*rows) {
    std::vector<Csr<int32_t>> tables(nr);
    for (size_t r = 0; r < nr; ++r) tables[r] = std::move(parts[r].*rows);
    return concat(std::move(tables));
  };
  Sheets s;
  s.level = d.level;
  s.sheet_blocks = join(&Sheets::sheet_blocks);
  s.sheet_cells = join(&Sheets::sheet_cells);
  s.sheet_curves = join(&Sheets::sheet_curves);
  s.sheet_edges = join(&Sheets::sheet_edges);
  s.sheet_non_hex_cells = join(&Sheets::sheet_non_hex_cells);
  s.classes = std::move(parts[0].classes);
  for (size_t r = 1; r < nr; ++r)
    std::move(parts[r].classes.begin(), parts[r].classes.end(), std::back_inserter(s.classes));
  return s;
}

}  // namespace

Sheets extract_sheets(const Mesh& m, const SheetDomain& d, const Threads& threads) {
  const Threads par = resolved(threads);
  // The classes end with the groups made from them, before the sheets are written.
  std::vector<Group> groups = block_groups(d, parallel_classes(m, d, par), par);
  return write_sheets(d, m.num_vertices(), groups, par);
}

std::optional<int32_t> largest_self_intersecting(const Sheets& s) {
  std::optional<int32_t> best;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!s.classes[i].type3) continue;
    if (!best || s.sheet_cells.count(i) > s.sheet_cells.count(static_cast<size_t>(*best))) best = static_cast<int32_t>(i);
  }
  return best;
}

}  // namespace hbc
