#include "hbc/base_complex.hpp"

#include <algorithm>
#include <atomic>

#include "parallel/concurrent_union_find.hpp"
#include "parallel/parallel.hpp"
#include "parallel/row_collector.hpp"
#include "platform/atomic_ref.hpp"

namespace hbc {

const char* component_kind_name(ComponentKind k) {
  switch (k) {
    case ComponentKind::Cube: return "cube";
    case ComponentKind::Ring: return "ring";
    case ComponentKind::Other: return "other";
    case ComponentKind::NonHex: return "non-hex";
  }
  return "?";
}

size_t BaseComplex::num_hex_components() const {
  return static_cast<size_t>(std::count(component_kind.begin(), component_kind.end(), ComponentKind::Cube));
}
size_t BaseComplex::num_non_hex_components() const {
  return static_cast<size_t>(std::count(component_kind.begin(), component_kind.end(), ComponentKind::NonHex));
}

namespace {

using detail::append_rows;
using detail::ConcurrentUnionFind;
using detail::number_classes;
using detail::ids_where;
using detail::parallel_ranges;
using detail::assign_touched;
using detail::resize_huge;
using detail::resize_touched;
using detail::parallel_rows;
using detail::range_count;
using detail::RowCollector;

// The face after f around edge e, walking into the cell on f's side `side`; `side` becomes the
// side of that face the walk goes on through. -1 when there is no cell on that side.
int32_t fan_step(const Mesh& m, int32_t e, int32_t f, int32_t& side) {
  const int32_t c = m.face_cells[static_cast<size_t>(f)][static_cast<size_t>(side)];
  if (c < 0) return -1;
  for (int32_t g : m.cell_faces[static_cast<size_t>(c)]) {
    if (g == f) continue;
    const auto fe = m.face_edges(static_cast<size_t>(g));
    if (std::find(fe.begin(), fe.end(), e) == fe.end()) continue;
    side = m.face_cells[static_cast<size_t>(g)][0] == c ? 1 : 0;
    return g;
  }
  return -1;
}

}  // namespace

int32_t straight_face(const Mesh& m, int32_t e, int32_t f, EdgeFan& scratch) {
  if (!m.edge_fan_ok(static_cast<size_t>(e))) return -1;
  // Regular fans, by far the most common: the face two steps around an interior 4-fan, the
  // other end of a boundary 3-fan (reached from a boundary face, whose one cell is on side 0).
  const int32_t ncells = m.edge_valence(static_cast<size_t>(e));
  const bool boundary = m.edge_boundary[static_cast<size_t>(e)] != 0;
  if (ncells == 4 && !boundary) {
    int32_t side = 0;
    const int32_t g = fan_step(m, e, f, side);
    return g < 0 ? -1 : fan_step(m, e, g, side);
  }
  if (ncells == 2 && boundary) {
    if (!m.face_boundary[static_cast<size_t>(f)]) return -1;
    int32_t side = 0;
    const int32_t g = fan_step(m, e, f, side);
    return g < 0 ? -1 : fan_step(m, e, g, side);
  }
  edge_fan(m, e, scratch);
  const auto fc = m.face_cells[static_cast<size_t>(f)];
  int32_t found = -1;
  for (int32_t g : scratch.faces) {
    if (g == f) continue;
    const auto gc = m.face_cells[static_cast<size_t>(g)];
    bool shares = false;
    for (int32_t a : fc)
      for (int32_t b : gc) shares = shares || (a >= 0 && a == b);
    if (shares) continue;
    if (found >= 0) return -1;  // not unique: no straight continuation
    found = g;
  }
  return found;
}

namespace {

// The other face of a hex cell at each edge of each of its faces, found once per hex cell (in
// parallel ranges of cells) instead of by scanning the cell's faces at every step around an edge:
// the straight continuations of the separation surfaces and patches take two such steps per face
// and edge. Row c packs, for face slot j (order of cell_faces[c]) and edge position i of that
// face's loop, the slot of the cell's other face at that edge in 4 bits.
class HexFaceTable {
 public:
  HexFaceTable(const Mesh& m, const Threads& par) {
    resize_touched(other_, m.num_cells(), par);
    parallel_ranges(m.num_cells(), par, [&](size_t b, size_t e, int) {
      for (size_t c = b; c < e; ++c)
        if (m.is_hex(c)) build(m, c);
    });
  }
  // The face of hex cell c other than f at the edge at position i of f's loop.
  int32_t other_face(const Mesh& m, int32_t c, int32_t f, size_t i) const {
    const auto faces = m.cell_faces[static_cast<size_t>(c)];
    const size_t k = 4 * slot_of(faces.data(), 6, f) + i;
    return faces[(other_[static_cast<size_t>(c)][k / 2] >> (4 * (k % 2))) & 15];
  }
  // Position of x among the n ids at p (it is there): a branch-free scan, as the position is
  // unpredictable and a mispredicted early exit costs more than the few compares.
  static size_t slot_of(const int32_t* p, size_t n, int32_t x) {
    size_t j = 0;
    for (size_t k = 1; k < n; ++k) j += (p[k] == x) * k;
    return j;
  }

 private:
  void build(const Mesh& m, size_t c) {
    const auto faces = m.cell_faces[c];
    std::array<int32_t, 24> edge{};
    for (size_t j = 0; j < 6; ++j)
      for (size_t i = 0; i < 4; ++i) edge[4 * j + i] = m.face_edges(static_cast<size_t>(faces[j]))[i];
    auto& row = other_[c];
    row.fill(0);
    // Each edge of a hex is on exactly two of its faces: match each entry with the later one.
    uint32_t matched = 0;
    for (size_t a = 0; a < 24; ++a) {
      if (matched >> a & 1) continue;
      for (size_t b = 4 * (a / 4 + 1); b < 24; ++b)
        if (edge[b] == edge[a]) {
          row[a / 2] |= static_cast<uint8_t>((b / 4) << (4 * (a % 2)));
          row[b / 2] |= static_cast<uint8_t>((a / 4) << (4 * (b % 2)));
          matched |= 1u << b;
          break;
        }
    }
  }
  std::vector<std::array<uint8_t, 12>> other_;
};

// straight_face(m, e, f) for an edge e of the hybrid singularity graph's Regular class (all cells
// hex, valence 4 inside or 2 on the boundary) at position i of f's loop: the same two steps
// around the fan from f through face_cells[f][0], with the cells' other faces from `table`.
int32_t regular_straight_face(const Mesh& m, int32_t e, int32_t f, size_t i, const HexFaceTable& table) {
  if (!m.edge_fan_ok(static_cast<size_t>(e))) return -1;
  if (m.edge_boundary[static_cast<size_t>(e)] && !m.face_boundary[static_cast<size_t>(f)]) return -1;
  const int32_t c0 = m.face_cells[static_cast<size_t>(f)][0];
  const int32_t g = table.other_face(m, c0, f, i);
  const auto gc = m.face_cells[static_cast<size_t>(g)];
  const int32_t c1 = gc[0] == c0 ? gc[1] : gc[0];
  if (c1 < 0) return -1;
  return table.other_face(m, c1, g, HexFaceTable::slot_of(m.face_edges(static_cast<size_t>(g)).data(), 4, e));
}

// State of a face while the separation surfaces grow: separates, waits to be grown from, and in
// the bits from 2 up the position + 1 of the edge it was reached across (0 for a seed); straight
// continuation is symmetric, so that edge leads back to a separation face and is skipped.
// Threads share the states: a face is claimed by one compare-exchange from 0 (the first thread
// to reach it), and only the thread whose range holds a face grows from it. Which thread claims
// a face only changes the skipped edge, which leads to a separation face either way.
constexpr uint8_t kSep = 1, kPending = 2;

uint8_t load(const std::vector<uint8_t>& state, int32_t f) {
  return ::hbc::detail::atomic_ref<const uint8_t>(state[static_cast<size_t>(f)]).load(std::memory_order_relaxed);
}

// Grows the surfaces from pending face f across its Regular inside edges: marks every face reached
// pending and calls reached(next) for it.
template <class Reached>
void spread(const Mesh& m, const SingularityGraph& g, int32_t f, std::vector<uint8_t>& state, const HexFaceTable& table,
            Reached reached) {
  ::hbc::detail::atomic_ref<uint8_t> own(state[static_cast<size_t>(f)]);
  const size_t from = static_cast<size_t>(own.load(std::memory_order_relaxed) >> 2);
  own.store(kSep, std::memory_order_relaxed);
  const auto fe = m.face_edges(static_cast<size_t>(f));
  for (size_t i = 0; i < fe.size(); ++i) {
    const int32_t e = fe[i];
    if (i + 1 == from || g.is_structural(e) || m.edge_boundary[e]) continue;
    const int32_t next = regular_straight_face(m, e, f, i, table);
    if (next < 0 || load(state, next)) continue;
    const auto ne = m.face_edges(static_cast<size_t>(next));
    const size_t at = ne.size() == 4 ? HexFaceTable::slot_of(ne.data(), 4, e) + 1 : 0;
    uint8_t expected = 0;
    if (::hbc::detail::atomic_ref<uint8_t>(state[static_cast<size_t>(next)])
            .compare_exchange_strong(expected, static_cast<uint8_t>(kSep | kPending | at << 2), std::memory_order_relaxed))
      reached(next);
  }
}

// The seeds: boundary faces separate but grow no surface; faces at a structural edge grow one.
std::vector<uint8_t> separation_seeds(const Mesh& m, const SingularityGraph& g, const Threads& par) {
  std::vector<uint8_t> state;
  resize_touched(state, m.num_faces(), par);
  parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) {
      const auto fe = m.face_edges(f);
      state[f] = m.face_boundary[f] ? kSep
                 : std::any_of(fe.begin(), fe.end(), [&](int32_t x) { return g.is_structural(x); }) ? kSep | kPending
                                                                                                   : 0;
    }
  });
  return state;
}

// Separation faces: boundary faces, and the surfaces traced straight from every face around an
// edge of the hybrid singularity graph until they reach another such edge or the boundary.
// The result is a closure, so the order of growth is free: sweeps over each thread's range of
// faces in increasing, then decreasing id (a face reached ahead of the sweep in the same range is
// grown in the same sweep) keep the memory accesses in order, where a breadth-first queue
// scatters them over the whole mesh. A few sweeps settle meshes numbered layer by layer; after
// those, a stack finishes whatever is left.
std::vector<uint8_t> separation_faces(const Mesh& m, const SingularityGraph& g, const HexFaceTable& table,
                                      const Threads& par) {
  const size_t nf = m.num_faces();
  std::vector<uint8_t> state = separation_seeds(m, g, par);
  bool behind = true;
  for (int sweep = 0; sweep < 6 && behind; ++sweep) {
    const bool up = sweep % 2 == 0;
    std::vector<uint8_t> late(static_cast<size_t>(range_count(nf, par)), 0);
    parallel_ranges(nf, par, [&](size_t b, size_t e, int r) {
      bool left = false;  // a face was reached that this sweep will not visit again
      for (size_t k = b; k < e; ++k) {
        const int32_t f = static_cast<int32_t>(up ? k : b + e - 1 - k);
        if (load(state, f) & kPending)
          spread(m, g, f, state, table, [&](int32_t next) {
            const auto n = static_cast<size_t>(next);
            left = left || n < b || n >= e || (up ? next < f : next > f);
          });
      }
      late[static_cast<size_t>(r)] = left;
    });
    behind = std::find(late.begin(), late.end(), 1) != late.end();
  }
  std::vector<int32_t> stack;
  for (size_t f = 0; behind && f < nf; ++f)
    if (state[f] & kPending) stack.push_back(static_cast<int32_t>(f));
  while (!stack.empty()) {
    const int32_t f = stack.back();
    stack.pop_back();
    spread(m, g, f, state, table, [&](int32_t next) { stack.push_back(next); });
  }
  parallel_ranges(nf, par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) state[f] &= kSep;
  });
  return state;
}

// Components: cells joined across faces that do not separate, numbered by their lowest cell.
void find_components(const Mesh& m, BaseComplex& bc, const Threads& par) {
  const auto& sep = bc.face_separation;
  ConcurrentUnionFind uf(m.num_cells(), par);
  parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f)
      if (!sep[f] && m.face_cells[f][1] >= 0) uf.unite(m.face_cells[f][0], m.face_cells[f][1]);
  });
  number_classes(uf, m.num_cells(), par, [](size_t) { return true; }, bc.cell_component, bc.component_cells);
}

// Curves: chains of complex edges (every face around them separates) between corners (vertices
// whose every edge is a complex edge).
void find_curves(const Mesh& m, BaseComplex& bc, const Threads& par) {
  const size_t ne = m.num_edges(), nv = m.num_vertices();
  // Complex edges: every face around them separates; corners: every edge at them is complex.
  // Threads only ever write the same value into a shared flag (detail::set_flag).
  auto clear = [](std::vector<uint8_t>& v, int32_t i) { detail::set_flag(v, i, 0); };
  resize_touched(bc.edge_complex, ne, par, uint8_t{1});
  parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f)
      if (!bc.face_separation[f])
        for (int32_t x : m.face_edges(f)) clear(bc.edge_complex, x);
  });
  std::vector<uint8_t> no_edge;
  assign_touched(no_edge, nv, uint8_t{1}, par);
  assign_touched(bc.vert_corner, nv, uint8_t{1}, par);
  parallel_ranges(ne, par, [&](size_t b, size_t e, int) {
    for (size_t x = b; x < e; ++x)
      for (int32_t v : m.edge_verts[x]) {
        clear(no_edge, v);
        if (!bc.edge_complex[x]) clear(bc.vert_corner, v);
      }
  });
  parallel_ranges(nv, par, [&](size_t b, size_t e, int) {
    for (size_t v = b; v < e; ++v) bc.vert_corner[v] &= !no_edge[v];
  });
  bc.corners = ids_where(nv, par, [&](size_t v) { return bc.vert_corner[v] != 0; });
  chain_edges(m, bc.edge_complex, {}, bc.vert_corner, bc.curve_verts, bc.curve_edges, bc.curve_closed, par);
  assign_touched(bc.edge_curve, ne, int32_t{-1}, par);
  // A mesh edge is on one curve at most: ranges of curves write disjoint entries.
  parallel_ranges(bc.curve_edges.rows(), par, [&](size_t b, size_t e, int) {
    for (size_t k = b; k < e; ++k)
      for (int32_t x : bc.curve_edges[k]) bc.edge_curve[x] = static_cast<int32_t>(k);
  });
}

// Patches: separation faces joined straight across edges that are not curves; the components on
// the two sides of each patch are those of its lowest face.
void find_patches(const Mesh& m, BaseComplex& bc, const HexFaceTable& table, const Threads& par) {
  const auto& sep = bc.face_separation;
  ConcurrentUnionFind uf(m.num_faces(), par);
  parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) {
      if (!sep[f]) continue;
      // An edge that is not complex has a face that does not separate, so it is not structural
      // (all faces around a structural edge separate): it is Regular.
      const auto fe = m.face_edges(f);
      for (size_t i = 0; i < fe.size(); ++i) {
        if (bc.edge_complex[fe[i]]) continue;
        const int32_t h = regular_straight_face(m, fe[i], static_cast<int32_t>(f), i, table);
        if (h >= 0 && sep[h]) uf.unite(static_cast<int32_t>(f), h);
      }
    }
  });
  number_classes(uf, m.num_faces(), par, [&](size_t f) { return sep[f] != 0; }, bc.face_patch, bc.patch_faces);
  resize_touched(bc.patch_components, bc.patch_faces.rows(), par);
  parallel_ranges(bc.patch_faces.rows(), par, [&](size_t b, size_t e, int) {
    for (size_t p = b; p < e; ++p) {
      const auto fc = m.face_cells[bc.patch_faces[p][0]];
      bc.patch_components[p] = {bc.cell_component[fc[0]], fc[1] >= 0 ? bc.cell_component[fc[1]] : -1};
    }
  });
}

// Appends parts[r][i] for r >= 1 to `out` in range order, into room of the exact size (no growth
// slack to copy), freeing each part once appended.
template <size_t N>
void append_parts(Csr<int32_t>& out, std::vector<std::array<Csr<int32_t>, N>>& parts, size_t i) {
  size_t rows = out.offsets.size(), items = out.items.size();
  for (size_t r = 1; r < parts.size(); ++r) {
    rows += parts[r][i].rows();
    items += parts[r][i].items.size();
  }
  out.offsets.reserve(rows);
  out.items.reserve(items);
  for (size_t r = 1; r < parts.size(); ++r) {
    append_rows(out, parts[r][i]);
    parts[r][i] = Csr<int32_t>();
  }
}

// The corners and curves of patches first..last-1, appended to `corners` and `curves`.
void patch_rows(const Mesh& m, const BaseComplex& bc, size_t first, size_t last, Csr<int32_t>& corners,
                Csr<int32_t>& curves) {
  RowCollector by_vertex(m.num_vertices()), by_curve(bc.curve_edges.rows());
  // Quads dominate: room for 4 corners and curves per patch.
  corners.reserve(last - first, 4 * (last - first));
  curves.reserve(last - first, 4 * (last - first));
  for (size_t p = first; p < last; ++p) {
    by_vertex.begin();
    by_curve.begin();
    for (int32_t f : bc.patch_faces[p]) {
      for (int32_t v : m.face_verts[f])
        if (bc.vert_corner[v]) by_vertex.add(v);
      for (int32_t e : m.face_edges(static_cast<size_t>(f)))
        if (bc.edge_curve[e] >= 0) by_curve.add(bc.edge_curve[e]);
    }
    by_vertex.end(corners);
    by_curve.end(curves);
  }
}

// The corners and curves on each patch, in ranges of patches holding about as many faces each.
void patch_incidences(const Mesh& m, BaseComplex& bc, const Threads& par) {
  std::vector<std::array<Csr<int32_t>, 2>> parts(
      static_cast<size_t>(range_count(std::max(bc.patch_faces.rows(), bc.patch_faces.items.size()), par)));
  parallel_rows(bc.patch_faces, par, [&](size_t first, size_t last, int r) {
    // Filled on this thread's stack and moved into place at the end: the growing tables' headers
    // sit next to each other and to the tables the other threads read, and a push per row there
    // would bounce their cache lines between the cores. Range 0 takes over bc's own tables, which
    // patch_rows does not read.
    std::array<Csr<int32_t>, 2> own;
    if (r == 0) own = {std::move(bc.patch_corners), std::move(bc.patch_curves)};
    patch_rows(m, bc, first, last, own[0], own[1]);
    if (r == 0) bc.patch_corners = std::move(own[0]), bc.patch_curves = std::move(own[1]);
    else parts[static_cast<size_t>(r)] = std::move(own);
  });
  append_parts(bc.patch_corners, parts, 0);
  append_parts(bc.patch_curves, parts, 1);
}

// Separation faces with the same component on both sides (reported, never hidden), by ranges of
// faces joined in order.
void find_self_adjacent_faces(const Mesh& m, BaseComplex& bc, const Threads& par) {
  std::vector<std::vector<int32_t>> parts(static_cast<size_t>(range_count(m.num_faces(), par)));
  parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int r) {
    std::vector<int32_t> own;  // on this thread's stack: the parts' headers share cache lines
    for (size_t f = b; f < e; ++f) {
      if (!bc.face_separation[f] || m.face_cells[f][1] < 0) continue;
      if (bc.cell_component[m.face_cells[f][0]] == bc.cell_component[m.face_cells[f][1]]) own.push_back(static_cast<int32_t>(f));
    }
    parts[static_cast<size_t>(r)] = std::move(own);
  });
  for (const auto& part : parts) bc.self_adjacent_faces.insert(bc.self_adjacent_faces.end(), part.begin(), part.end());
}

// Per component, its patches: patch_components transposed (rows in increasing patch id). Every
// face of a patch has the patch's components on its two sides: faces join across an edge that is
// not complex, hence Regular, whose two other faces (each the straight continuation of the other,
// and separation faces are closed under it) then do not separate and join the cells on each side.
void component_patch_rows(BaseComplex& bc, const Threads& par) {
  bc.component_patches =
      detail::group_values_by_key(bc.patch_components.size(), bc.component_cells.rows(), par, [&](size_t p, auto&& emit) {
        const auto pc = bc.patch_components[p];
        emit(pc[0], static_cast<int32_t>(p));
        if (pc[1] >= 0 && pc[1] != pc[0]) emit(pc[1], static_cast<int32_t>(p));
      });
}

// The adjacent components, curves and corners of components first..last-1, gathered from their
// patches: a component's separation faces are exactly the faces of its patches (see above).
void component_rows(const BaseComplex& bc, size_t first, size_t last, std::array<Csr<int32_t>*, 3> out) {
  RowCollector by_component(bc.component_cells.rows()), by_curve(bc.curve_edges.rows()),
      by_vertex(bc.vert_corner.size());
  // Cubes dominate: room for 6 neighbours, 12 curves and 8 corners per component.
  const size_t n = last - first;
  out[0]->reserve(n, 6 * n);
  out[1]->reserve(n, 12 * n);
  out[2]->reserve(n, 8 * n);
  for (size_t k = first; k < last; ++k) {
    by_component.begin();
    by_curve.begin();
    by_vertex.begin();
    for (int32_t p : bc.component_patches[k]) {
      for (int32_t j : bc.patch_components[static_cast<size_t>(p)])
        if (j >= 0 && j != static_cast<int32_t>(k)) by_component.add(j);
      for (int32_t c : bc.patch_curves[static_cast<size_t>(p)]) by_curve.add(c);
      for (int32_t v : bc.patch_corners[static_cast<size_t>(p)]) by_vertex.add(v);
    }
    by_component.end(*out[0]);
    by_curve.end(*out[1]);
    by_vertex.end(*out[2]);
  }
}

// Per component: its patches, then the adjacent components, curves and corners, in ranges of
// components holding about as many patches each; range 0 writes straight into bc.
void component_incidences(BaseComplex& bc, const Threads& par) {
  component_patch_rows(bc, par);
  const Csr<int32_t>& rows = bc.component_patches;
  const size_t nr = static_cast<size_t>(range_count(std::max(rows.rows(), rows.items.size()), par));
  std::vector<std::array<Csr<int32_t>, 3>> parts(nr);
  const std::array<Csr<int32_t>*, 3> mine = {&bc.component_adjacency, &bc.component_curves, &bc.component_corners};
  parallel_rows(rows, par, [&](size_t first, size_t last, int r) {
    // On this thread's stack, then moved into place (see patch_incidences); component_rows does
    // not read the tables range 0 takes over.
    std::array<Csr<int32_t>, 3> own;
    if (r == 0)
      for (size_t i = 0; i < 3; ++i) own[i] = std::move(*mine[i]);
    component_rows(bc, first, last, {&own[0], &own[1], &own[2]});
    if (r == 0)
      for (size_t i = 0; i < 3; ++i) *mine[i] = std::move(own[i]);
    else parts[static_cast<size_t>(r)] = std::move(own);
  });
  // One array at a time, each part freed once appended: the stage's peak is here at 10^7 cells.
  for (size_t i = 0; i < 3; ++i) append_parts(*mine[i], parts, i);
}

// The number of distinct ids in v (sorted on the way).
size_t distinct(std::vector<int32_t>& v) {
  std::sort(v.begin(), v.end());
  return static_cast<size_t>(std::unique(v.begin(), v.end()) - v.begin());
}

// Euler characteristic V - E + F of the boundary surface of component k (faces counted once per
// side): 2 for a ball, 0 for a solid torus. The distinct edges and vertices are counted by sorting
// the ids met (`edges`, `verts`: reused buffers), not by stamps over every mesh edge and vertex:
// only the components that are not cubes get here, and tables over the whole mesh (160 MB at
// 10^7 cells) would add to the stage's peak.
int64_t boundary_euler(const Mesh& m, const BaseComplex& bc, int32_t k, std::vector<int32_t>& edges,
                       std::vector<int32_t>& verts) {
  int64_t F = 0;
  edges.clear();
  verts.clear();
  for (int32_t c : bc.component_cells[k])
    for (int32_t f : m.cell_faces[c]) {
      if (!bc.face_separation[f]) continue;
      const auto fc = m.face_cells[f];
      const int32_t other = fc[0] == c ? fc[1] : fc[0];
      if (other >= 0 && bc.cell_component[other] == k) continue;  // a cut inside: not the boundary
      ++F;
      const auto fe = m.face_edges(static_cast<size_t>(f));
      const auto fv = m.face_verts[f];
      edges.insert(edges.end(), fe.begin(), fe.end());
      verts.insert(verts.end(), fv.begin(), fv.end());
    }
  return static_cast<int64_t>(distinct(verts)) - static_cast<int64_t>(distinct(edges)) + F;
}

// The kind of each component: a single non-hex cell; a cube (6 quad patches, 12 curves, 8
// corners, no cut inside); a ring (cut by a self-adjacent face, or a torus-like boundary); other.
// Ranges of components holding about as many cells each.
void classify_components(const Mesh& m, BaseComplex& bc, const Threads& par) {
  const size_t ncomp = bc.component_cells.rows();
  std::vector<uint8_t> self_cut(ncomp, 0);
  for (int32_t f : bc.self_adjacent_faces) self_cut[bc.cell_component[m.face_cells[f][0]]] = 1;
  bc.component_kind.assign(ncomp, ComponentKind::Other);
  parallel_rows(bc.component_cells, par, [&](size_t first, size_t last, int) {
    std::vector<int32_t> edges, verts;
    for (size_t k = first; k < last; ++k) {
      const auto cells = bc.component_cells[k];
      if (cells.size() == 1 && !m.is_hex(cells[0])) {
        bc.component_kind[k] = ComponentKind::NonHex;
        continue;
      }
      bool cube = !self_cut[k] && bc.component_patches.count(k) == 6 && bc.component_curves.count(k) == 12 &&
                  bc.component_corners.count(k) == 8;
      for (int32_t p : bc.component_patches[k])
        cube = cube && bc.patch_curves.count(p) == 4 && bc.patch_corners.count(p) == 4;
      if (cube) bc.component_kind[k] = ComponentKind::Cube;
      else if (self_cut[k] || boundary_euler(m, bc, static_cast<int32_t>(k), edges, verts) == 0)
        bc.component_kind[k] = ComponentKind::Ring;
    }
  });
}

}  // namespace

BaseComplex base_complex(const Mesh& m, const SingularityGraph& g, const Threads& threads) {
  const Threads par = resolved(threads);
  BaseComplex bc;
  {
    // Gone before the incidences, where the stage peaks.
    const HexFaceTable table(m, par);
    bc.face_separation = separation_faces(m, g, table, par);
    find_components(m, bc, par);
    find_curves(m, bc, par);
    find_patches(m, bc, table, par);
  }
  patch_incidences(m, bc, par);
  find_self_adjacent_faces(m, bc, par);
  component_incidences(bc, par);
  classify_components(m, bc, par);
  return bc;
}

}  // namespace hbc
