#include "hbc/sheets.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>
#include <numeric>

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

size_t Sheets::count(SheetType t) const {
  return static_cast<size_t>(
      std::count_if(classes.begin(), classes.end(), [t](const SheetClass& c) { return c.type == t; }));
}

namespace {

struct UnionFind {
  std::vector<int32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int32_t find(int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int32_t a, int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

bool contains(std::span<const int32_t> sorted, int32_t x) {
  return std::binary_search(sorted.begin(), sorted.end(), x);
}

// The edge of hex cell c at the first vertex of face f that is not an edge of f: it points
// across the face, in the cell's direction orthogonal to f.
int32_t orthogonal_edge(const Mesh& m, int32_t c, int32_t f) {
  const int32_t v = m.face_verts[f][0];
  auto fe = m.face_edges[f];
  for (int32_t e : m.cell_edges[c]) {
    if (m.edge_verts[e][0] != v && m.edge_verts[e][1] != v) continue;
    if (std::find(fe.begin(), fe.end(), e) == fe.end()) return e;
  }
  return -1;
}

void sort_unique(std::vector<int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

SheetClass classify_sheet(const SheetDomain& d, const std::vector<int32_t>& curves,
                          const std::vector<int32_t>& units) {
  SheetClass k;
  // (end vertex, curve) for every open curve.
  std::vector<std::pair<int32_t, int32_t>> ends;
  for (int32_t c : curves) {
    const auto [a, b] = d.curve_ends[c];
    if (a < 0) continue;
    ends.push_back({a, c});
    if (b != a) ends.push_back({b, c});
  }
  std::sort(ends.begin(), ends.end());
  auto in_units = [&](int32_t u) { return std::binary_search(units.begin(), units.end(), u); };
  for (size_t i = 0; i < ends.size();) {
    size_t j = i;
    while (j < ends.size() && ends[j].first == ends[i].first) ++j;
    if (j - i >= 2) k.shared_vertices.push_back(ends[i].first);
    for (size_t p = i; p < j; ++p)
      for (size_t q = p + 1; q < j; ++q) {
        const int32_t a = ends[p].second, b = ends[q].second;
        bool common = false;
        for (int32_t u : d.curve_units[a])
          if (in_units(u) && contains(d.curve_units[b], u)) {
            common = true;
            k.self_intersecting_units.push_back(u);
          }
        if (common) {
          k.type3 = true;
          continue;
        }
        bool adjacent = false;
        for (int32_t ua : d.curve_units[a]) {
          if (!in_units(ua)) continue;
          for (int32_t ub : d.curve_units[b])
            if (in_units(ub) && contains(d.unit_adjacency[ua], ub)) adjacent = true;
        }
        if (adjacent) {
          k.type2 = true;
          k.self_parallel_curves.push_back(a);
          k.self_parallel_curves.push_back(b);
        } else {
          k.type1 = true;
        }
      }
    i = j;
  }
  sort_unique(k.self_intersecting_units);
  sort_unique(k.self_parallel_curves);
  k.type = k.type3 ? SheetType::Type3 : k.type2 ? SheetType::Type2 : k.type1 ? SheetType::Type1 : SheetType::Perfect;

  // Maximum cardinality matching (Edmonds) on (curve ends, curves): the ends it leaves uncovered
  // are what the figures highlight.
  if (k.type != SheetType::Perfect) {
    std::vector<int32_t> verts;
    for (auto [v, c] : ends) verts.push_back(v);
    sort_unique(verts);
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
    Graph g(verts.size());
    auto local = [&](int32_t v) {
      return static_cast<size_t>(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin());
    };
    for (int32_t c : curves) {
      const auto [a, b] = d.curve_ends[c];
      if (a >= 0 && a != b) boost::add_edge(local(a), local(b), g);
    }
    std::vector<boost::graph_traits<Graph>::vertex_descriptor> mate(verts.size());
    boost::edmonds_maximum_cardinality_matching(g, &mate[0]);
    for (size_t i = 0; i < verts.size(); ++i)
      if (mate[i] == boost::graph_traits<Graph>::null_vertex()) k.unmatched_vertices.push_back(verts[i]);
  }
  return k;
}

Sheets extract_sheets(const Mesh& m, const SheetDomain& d) {
  Sheets s;
  s.level = d.level;
  const size_t nc = m.num_cells(), ne = m.num_edges();
  // Mesh edges joined into parallel classes: opposite edges of every quad of a hex cell, and the
  // orthogonal directions of two hex cells across a joining face.
  UnionFind uf(ne);
  for (size_t c = 0; c < nc; ++c) {
    if (!m.is_hex(c)) continue;
    for (int32_t f : m.cell_faces[c]) {
      auto fe = m.face_edges[f];
      uf.unite(fe[0], fe[2]);
      uf.unite(fe[1], fe[3]);
    }
  }
  for (size_t f = 0; f < m.num_faces(); ++f) {
    if (!d.face_joins[f]) continue;
    const auto fc = m.face_cells[f];
    uf.unite(orthogonal_edge(m, fc[0], static_cast<int32_t>(f)), orthogonal_edge(m, fc[1], static_cast<int32_t>(f)));
  }

  // (class root, unit) and (class root, curve) pairs.
  std::vector<std::pair<int32_t, int32_t>> class_units, class_curves;
  for (size_t c = 0; c < nc; ++c) {
    const int32_t u = d.cell_unit[c];
    if (u < 0) continue;
    for (int32_t e : m.cell_edges[c]) class_units.push_back({uf.find(e), u});
  }
  std::sort(class_units.begin(), class_units.end());
  class_units.erase(std::unique(class_units.begin(), class_units.end()), class_units.end());
  for (size_t k = 0; k < d.curve_edges.rows(); ++k) class_curves.push_back({uf.find(d.curve_edges[k][0]), static_cast<int32_t>(k)});
  std::sort(class_curves.begin(), class_curves.end());

  // Each class split into face-connected groups of units: one sheet per group.
  struct Group {
    std::vector<int32_t> units, curves;
  };
  std::vector<Group> groups;
  const size_t nunits = d.unit_cells.rows();
  std::vector<int32_t> stamp(nunits, -1), seen(nunits, -1), stack;
  size_t cc = 0;
  for (size_t i = 0; i < class_units.size();) {
    size_t j = i;
    const int32_t root = class_units[i].first;
    while (j < class_units.size() && class_units[j].first == root) ++j;
    for (size_t p = i; p < j; ++p) stamp[class_units[p].second] = root;
    auto lo = std::lower_bound(class_curves.begin(), class_curves.end(), std::make_pair(root, int32_t{-1}));
    for (size_t p = i; p < j; ++p) {
      const int32_t u0 = class_units[p].second;
      if (seen[u0] == root) continue;
      Group g;
      stack.assign(1, u0);
      seen[u0] = root;
      while (!stack.empty()) {
        const int32_t u = stack.back();
        stack.pop_back();
        g.units.push_back(u);
        for (int32_t w : d.unit_adjacency[u])
          if (stamp[w] == root && seen[w] != root) {
            seen[w] = root;
            stack.push_back(w);
          }
      }
      std::sort(g.units.begin(), g.units.end());
      for (auto it = lo; it != class_curves.end() && it->first == root; ++it) {
        for (int32_t u : d.curve_units[it->second])
          if (std::binary_search(g.units.begin(), g.units.end(), u)) {
            g.curves.push_back(it->second);
            break;
          }
      }
      groups.push_back(std::move(g));
    }
    i = j;
    ++cc;
  }
  std::sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
    if (a.units[0] != b.units[0]) return a.units[0] < b.units[0];
    const int32_t ca = a.curves.empty() ? -1 : a.curves[0], cb = b.curves.empty() ? -1 : b.curves[0];
    return ca < cb;
  });

  std::vector<int32_t> buf;
  for (const Group& g : groups) {
    s.sheet_units.push_row(g.units.begin(), g.units.end());
    buf.clear();
    for (int32_t u : g.units)
      for (int32_t c : d.unit_cells[u]) buf.push_back(c);
    sort_unique(buf);
    s.sheet_cells.push_row(buf.begin(), buf.end());
    s.sheet_curves.push_row(g.curves.begin(), g.curves.end());
    buf.clear();
    for (int32_t k : g.curves)
      for (int32_t e : d.curve_edges[k]) buf.push_back(e);
    sort_unique(buf);
    s.sheet_edges.push_row(buf.begin(), buf.end());
    buf.clear();
    for (int32_t k : g.curves)
      for (int32_t c : d.curve_non_hex_cells[k]) buf.push_back(c);
    sort_unique(buf);
    s.sheet_non_hex_cells.push_row(buf.begin(), buf.end());
    s.classes.push_back(classify_sheet(d, g.curves, g.units));
  }
  return s;
}

Subsheets decompose_sheet(const SheetDomain& d, const Sheets& sheets, int32_t sheet) {
  Subsheets out;
  out.sheet = sheet;
  auto curves = sheets.sheet_curves[sheet];
  auto units = sheets.sheet_units[sheet];
  auto in_sheet = [&](int32_t c) { return std::binary_search(curves.begin(), curves.end(), c); };
  auto in_units = [&](int32_t u) { return std::binary_search(units.begin(), units.end(), u); };
  // Two curves conflict when they share an end inside one unit of the sheet.
  auto conflict = [&](int32_t a, int32_t b) {
    const auto ea = d.curve_ends[a], eb = d.curve_ends[b];
    if (ea[0] < 0 || eb[0] < 0) return false;
    if (!(ea[0] == eb[0] || ea[0] == eb[1] || ea[1] == eb[0] || ea[1] == eb[1])) return false;
    for (int32_t u : d.curve_units[a])
      if (in_units(u) && contains(d.curve_units[b], u)) return true;
    return false;
  };
  std::vector<uint8_t> used(curves.size(), 0);
  auto index_of = [&](int32_t c) {
    return static_cast<size_t>(std::lower_bound(curves.begin(), curves.end(), c) - curves.begin());
  };
  auto emit = [&](const std::vector<int32_t>& kept, const std::vector<int32_t>& subunits) {
    out.curves.push_row(kept.begin(), kept.end());
    out.units.push_row(subunits.begin(), subunits.end());
    std::vector<int32_t> cells;
    for (int32_t u : subunits)
      for (int32_t c : d.unit_cells[u]) cells.push_back(c);
    sort_unique(cells);
    out.cells.push_row(cells.begin(), cells.end());
    out.classes.push_back(classify_sheet(d, kept, subunits));
  };
  std::vector<int32_t> taken, queue, banned, subunits, kept;
  size_t next_seed = 0;
  for (;;) {
    while (next_seed < curves.size() && used[next_seed]) ++next_seed;
    if (next_seed == curves.size()) break;
    const int32_t seed = curves[next_seed];
    taken.assign(1, seed);
    used[next_seed] = 1;
    queue.assign(1, seed);
    banned.clear();
    for (size_t q = 0; q < queue.size(); ++q) {
      for (int32_t b : d.curve_parallels[queue[q]]) {
        if (!in_sheet(b) || used[index_of(b)]) continue;
        bool ok = true;
        for (int32_t c : taken)
          if (conflict(b, c)) {
            ok = false;
            break;
          }
        if (!ok) {
          // The sheet turns here: the units around the rejected curve belong to another subsheet.
          for (int32_t u : d.curve_units[b])
            if (in_units(u)) banned.push_back(u);
          continue;
        }
        used[index_of(b)] = 1;
        taken.push_back(b);
        queue.push_back(b);
      }
    }
    sort_unique(taken);
    sort_unique(banned);
    // Cells: units touched by the subsheet's curves, less those where it turned. Curves left
    // touching none are dropped back into the pool (they seed a later subsheet).
    subunits.clear();
    kept.clear();
    for (int32_t c : taken) {
      bool any = false;
      for (int32_t u : d.curve_units[c])
        if (in_units(u) && !std::binary_search(banned.begin(), banned.end(), u)) {
          subunits.push_back(u);
          any = true;
        }
      if (any) kept.push_back(c);
      else if (c != seed) used[index_of(c)] = 0;
    }
    sort_unique(subunits);
    if (kept.empty()) {
      // Every unit of the seed was taken out: the seed stands alone so that each curve lands in
      // some subsheet and the loop always progresses.
      kept.assign(1, seed);
      for (int32_t u : d.curve_units[seed])
        if (in_units(u)) subunits.push_back(u);
      sort_unique(subunits);
    }
    emit(kept, subunits);
    next_seed = 0;
  }
  return out;
}

int32_t largest_self_intersecting(const Sheets& s) {
  int32_t best = -1;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!s.classes[i].type3) continue;
    if (best < 0 || s.sheet_cells.count(i) > s.sheet_cells.count(static_cast<size_t>(best))) best = static_cast<int32_t>(i);
  }
  return best;
}

}  // namespace hbc
