// The fan and vertex steps of build_mesh (see hbc/mesh_steps.hpp), and the incidences the Mesh
// derives instead of storing: edge fans, the vertices and edges of a cell, the edges at a vertex.
#include <algorithm>
#include <atomic>
#include <numeric>

#include "mesh/mesh_steps.hpp"
#include "platform/huge_pages.hpp"
#include "parallel/parallel.hpp"
#include "platform/atomic_ref.hpp"

namespace hbc {
namespace {

bool has_edge(const Mesh& m, int32_t f, int32_t e) {
  const auto fe = m.face_edges(static_cast<size_t>(f));
  return std::find(fe.begin(), fe.end(), e) != fe.end();
}

// The face of cell c other than f that contains edge e (a closed cell has exactly two), or -1.
int32_t other_face_at(const Mesh& m, int32_t c, int32_t e, int32_t f) {
  for (int32_t g : m.cell_faces[static_cast<size_t>(c)])
    if (g != f && has_edge(m, g, e)) return g;
  return -1;
}

// Walks the fan of edge e from `start` into face_cells[start][0], through the cells, until it
// comes back to `start` or reaches a face with no cell beyond. Stops early (returning false) after
// more than `limit` faces or at a cell with no second face at e.
bool walk(const Mesh& m, int32_t e, int32_t start, size_t limit, EdgeFan& out) {
  out.faces.assign(1, start);
  out.cells.clear();
  int32_t f = start, side = 0;
  for (;;) {
    const int32_t c = m.face_cells[static_cast<size_t>(f)][static_cast<size_t>(side)];
    if (c < 0) return true;  // reached the other boundary face
    out.cells.push_back(c);
    const int32_t g = other_face_at(m, c, e, f);
    if (g < 0) return false;
    side = m.face_cells[static_cast<size_t>(g)][0] == c ? 1 : 0;  // go on through g's far side
    if (g == start) return true;
    if (out.faces.size() == limit) return false;
    out.faces.push_back(g);
    f = g;
  }
}

void odd_fan(const Mesh& m, int32_t e, EdgeFan& out) {
  const auto faces = m.odd_fan_faces[static_cast<size_t>(-1 - m.fan_start[static_cast<size_t>(e)])];
  out.faces.assign(faces.begin(), faces.end());
  out.cells.clear();
  for (int32_t f : faces)
    for (int32_t c : m.face_cells[static_cast<size_t>(f)])
      if (c >= 0) out.cells.push_back(c);
  sort_unique(out.cells);
}

uint8_t small_count(size_t n) { return static_cast<uint8_t>(std::min<size_t>(n, 255)); }

}  // namespace

void edge_fan(const Mesh& m, int32_t e, EdgeFan& out) {
  if (m.fan_start[static_cast<size_t>(e)] < 0) return odd_fan(m, e, out);
  walk(m, e, m.fan_start[static_cast<size_t>(e)], SIZE_MAX, out);
}

int32_t Mesh::edge_valence(size_t e) const {
  if (valence_small[e] < 255) return valence_small[e];
  EdgeFan fan;
  edge_fan(*this, static_cast<int32_t>(e), fan);
  return static_cast<int32_t>(fan.cells.size());
}

void cell_vertices(const Mesh& m, size_t c, std::vector<int32_t>& out) {
  out.clear();
  for (int32_t f : m.cell_faces[c]) {
    const auto loop = m.face_verts[static_cast<size_t>(f)];
    out.insert(out.end(), loop.begin(), loop.end());
  }
  sort_unique(out);
}

void cell_edges(const Mesh& m, size_t c, std::vector<int32_t>& out) {
  out.clear();
  for (int32_t f : m.cell_faces[c]) {
    const auto fe = m.face_edges(static_cast<size_t>(f));
    out.insert(out.end(), fe.begin(), fe.end());
  }
  sort_unique(out);
}

Csr<int32_t> vertex_edges(const Mesh& m, std::span<const uint8_t> keep, const Threads& threads) {
  return detail::group_values_by_key(m.num_edges(), m.num_vertices(), resolved(threads), [&](size_t e, auto&& emit) {
    if (!keep.empty() && !keep[e]) return;
    for (int32_t v : m.edge_verts[e]) emit(v, static_cast<int32_t>(e));
  });
}

namespace mesh_steps {

void mark_boundary(Mesh& m, const Threads& par) {
  m.face_boundary.assign(m.num_faces(), 0);
  m.edge_boundary.assign(m.num_edges(), 0);
  m.vert_boundary.assign(m.num_vertices(), 0);
  // Ranges of faces; an edge or vertex of faces in two ranges may be marked by both, with the
  // same value, hence the atomic stores.
  auto mark = [](uint8_t& flag) { ::hbc::detail::atomic_ref<uint8_t>(flag).store(1, std::memory_order_relaxed); };
  detail::parallel_ranges(m.num_faces(), par, [&](size_t fb, size_t fe, int) {
    for (size_t f = fb; f < fe; ++f) {
      if (m.face_cells[f][1] >= 0) continue;
      m.face_boundary[f] = 1;
      for (int32_t e : m.face_edges(f)) mark(m.edge_boundary[static_cast<size_t>(e)]);
      for (int32_t v : m.face_verts[f]) mark(m.vert_boundary[static_cast<size_t>(v)]);
    }
  });
}

namespace {

// The faces of every edge without a cyclic fan, one row each, numbered in edge order; marks
// those edges' fan_start as -1 - row.
void collect_odd_fans(Mesh& m, const std::vector<uint8_t>& odd) {
  m.odd_fan_faces.clear();
  if (std::find(odd.begin(), odd.end(), 1) == odd.end()) return;  // most meshes: no row table
  std::vector<int32_t> row(m.num_edges(), -1);
  int32_t rows = 0;
  for (size_t e = 0; e < m.num_edges(); ++e)
    if (odd[e]) row[e] = rows++;
  std::vector<int32_t> row_of_item, face_of_item;
  for (size_t f = 0; f < m.num_faces(); ++f)  // faces in increasing order: each row comes out sorted
    for (int32_t e : m.face_edges(f))
      if (row[static_cast<size_t>(e)] >= 0) {
        row_of_item.push_back(row[static_cast<size_t>(e)]);
        face_of_item.push_back(static_cast<int32_t>(f));
      }
  const Csr<int32_t> by_row = group_by(row_of_item, static_cast<size_t>(rows));
  m.odd_fan_faces.offsets = by_row.offsets;
  m.odd_fan_faces.items.resize(by_row.items.size());
  for (size_t i = 0; i < by_row.items.size(); ++i) m.odd_fan_faces.items[i] = face_of_item[static_cast<size_t>(by_row.items[i])];
  for (size_t e = 0; e < m.num_edges(); ++e)
    if (row[e] >= 0) m.fan_start[e] = -1 - row[e];
}

// Whether the counts alone show the fan to be one cycle or one path. Around an edge the faces
// and cells form paths, each between two boundary faces, and cycles; a cell has two faces there,
// so a cycle has at least 3 faces, or 2 where two cells share two faces (`twice`). One path
// (two boundary faces) leaves room for no cycle when the faces are too few to hold both, and
// likewise for two cycles without boundary faces.
bool cyclic_by_count(const EdgeFaceCount& c, bool twice) {
  const int32_t min_cycle = twice ? 2 : 3;
  if (c.boundary_faces == 2) return c.faces < 2 + min_cycle;
  if (c.boundary_faces == 0) return c.faces < 2 * min_cycle;
  return false;
}

}  // namespace

void edge_fans(Mesh& m, const EdgeFaceCounts& counts, const CellCheck& cells, const Threads& par) {
  const size_t ne = m.num_edges();
  std::vector<uint8_t> odd(ne, 0);
  m.valence_small.assign(ne, 0);
  detail::parallel_ranges(ne, par, [&](size_t eb, size_t ee, int) {
    EdgeFan fan;
    for (size_t e = eb; e < ee; ++e) {
      const EdgeFaceCount& c = counts[e];
      bool ok = cyclic_by_count(c, cells.faces_shared_twice);
      if (!ok && (c.boundary_faces == 0 || c.boundary_faces == 2)) {
        // Walk it: cyclic when the walk meets every face.
        ok = walk(m, static_cast<int32_t>(e), m.fan_start[e], static_cast<size_t>(c.faces), fan) &&
             fan.faces.size() == static_cast<size_t>(c.faces);
      }
      odd[e] = ok ? 0 : 1;
      // A path has one cell fewer than faces, a cycle as many.
      if (ok) m.valence_small[e] = small_count(static_cast<size_t>(c.faces - c.boundary_faces / 2));
    }
  });
  collect_odd_fans(m, odd);
  EdgeFan fan;
  for (size_t e = 0; e < ne; ++e)
    if (odd[e]) {
      odd_fan(m, static_cast<int32_t>(e), fan);
      m.valence_small[e] = small_count(fan.cells.size());
    }
}

namespace {

// Union-find over half-edges (edge e at its end j is 2e + j), safe for threads uniting at once:
// a root is linked to a lower one only by compare-and-swap while it is still a root, and path
// halving only ever points a non-root entry to one of its ancestors. The sets do not depend on
// the order of the unions.
class HalfEdgeSets {
 public:
  // With one thread doing every union and find, plain stores: a locked compare-and-swap per
  // union costs more than the rest of the step.
  HalfEdgeSets(size_t n, const Threads& par) : parent_(n, par), shared_(par.count > 1) {
    detail::parallel_ranges(n, par, [&](size_t b, size_t e, int) { std::iota(parent_.data() + b, parent_.data() + e, static_cast<int32_t>(b)); });
  }
  int32_t find(int32_t x) {
    for (;;) {
      int32_t p = at(x).load(std::memory_order_acquire);
      if (p == x) return x;
      const int32_t g = at(p).load(std::memory_order_acquire);
      if (g == p) return p;
      // x now points to its grandparent. A plain store, not a locked compare-exchange: entries
      // only ever point to ancestors, and g stays one of x's whatever other threads link
      // meanwhile, so overwriting a newer, higher parent with g loses nothing.
      if (shared_) at(x).store(g, std::memory_order_release);
      else parent_[static_cast<size_t>(x)] = g;
      x = g;
    }
  }
  void unite(int32_t a, int32_t b) {
    for (;;) {
      a = find(a), b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      if (!shared_) {
        parent_[static_cast<size_t>(a)] = b;
        return;
      }
      int32_t expected = a;
      if (at(a).compare_exchange_strong(expected, b, std::memory_order_acq_rel)) return;
    }
  }

 private:
  ::hbc::detail::atomic_ref<int32_t> at(int32_t x) { return ::hbc::detail::atomic_ref<int32_t>(parent_[static_cast<size_t>(x)]); }
  detail::RawArray<int32_t> parent_;  // every entry set by the iota above
  bool shared_;
};

// The exact test on a few vertices: the cells around v, joined across the faces at v.
void check_exactly(Mesh& m, const std::vector<uint8_t>& suspect) {
  std::vector<std::array<int32_t, 2>> vc;  // (vertex, cell) for the suspect vertices
  std::vector<int32_t> vs;
  for (size_t c = 0; c < m.num_cells(); ++c) {
    cell_vertices(m, c, vs);
    for (int32_t v : vs)
      if (suspect[static_cast<size_t>(v)]) vc.push_back({v, static_cast<int32_t>(c)});
  }
  std::sort(vc.begin(), vc.end());
  std::vector<int32_t> cells, parent;
  for (size_t i = 0; i < vc.size();) {
    const int32_t v = vc[i][0];
    cells.clear();
    for (; i < vc.size() && vc[i][0] == v; ++i) cells.push_back(vc[i][1]);
    if (cells.size() <= 1 || m.vert_non_manifold[static_cast<size_t>(v)]) continue;
    parent.resize(cells.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int32_t x) {
      while (parent[static_cast<size_t>(x)] != x) x = parent[static_cast<size_t>(x)];
      return x;
    };
    size_t groups = cells.size();
    for (size_t a = 0; a < cells.size(); ++a)
      for (int32_t f : m.cell_faces[static_cast<size_t>(cells[a])]) {
        const auto fc = m.face_cells[static_cast<size_t>(f)];
        const int32_t d = fc[0] == cells[a] ? fc[1] : fc[0];
        const auto loop = m.face_verts[static_cast<size_t>(f)];
        if (d < cells[a] || std::find(loop.begin(), loop.end(), v) == loop.end()) continue;
        const auto b = std::lower_bound(cells.begin(), cells.end(), d) - cells.begin();
        const int32_t ra = root(static_cast<int32_t>(a)), rb = root(static_cast<int32_t>(b));
        if (ra != rb) parent[static_cast<size_t>(std::max(ra, rb))] = std::min(ra, rb), --groups;
      }
    if (groups != 1) m.vert_non_manifold[static_cast<size_t>(v)] = 1;
  }
}

}  // namespace

// The cells around v are one face-connected group exactly when the edges at v are one group,
// joining the two edges of each face at v: a face at v joins its cells and its two edges there;
// all cells of a cyclic fan are joined through its faces; a cell's faces at v form one cycle
// through its edges there unless the cell is pinched at v. Vertices of non-cyclic fans and of
// pinched cells are tested cell by cell instead.
void non_manifold_vertices(Mesh& m, const CellCheck& cells, const Threads& par) {
  const size_t nv = m.num_vertices(), ne = m.num_edges();
  HalfEdgeSets sets(2 * ne, par);
  auto half = [&](int32_t e, int32_t v) { return 2 * e + (m.edge_verts[static_cast<size_t>(e)][1] == v ? 1 : 0); };
  detail::parallel_ranges(m.num_faces(), par, [&](size_t fb, size_t fe, int) {
    for (size_t f = fb; f < fe; ++f) {
      const auto loop = m.face_verts[f];
      const auto edges = m.face_edges(f);
      for (size_t i = 0; i < loop.size(); ++i)
        sets.unite(half(edges[i == 0 ? loop.size() - 1 : i - 1], loop[i]), half(edges[i], loop[i]));
    }
  });
  // A vertex is split when its half-edges are not all in one set: each compared with the set of
  // whichever end got there first (which one does not matter: all equal or not).
  std::vector<int32_t> first(nv, -1);
  std::vector<uint8_t> split(nv, 0), suspect(nv, 0);
  detail::parallel_ranges(ne, par, [&](size_t eb, size_t ee, int) {
    for (size_t e = eb; e < ee; ++e)
      for (int j = 0; j < 2; ++j) {
        const auto v = static_cast<size_t>(m.edge_verts[e][static_cast<size_t>(j)]);
        const int32_t r = sets.find(static_cast<int32_t>(2 * e) + j);
        // Most ends meet a vertex already set: a plain load spares them the locked operation.
        ::hbc::detail::atomic_ref<int32_t> at(first[v]);
        int32_t seen = at.load(std::memory_order_relaxed);
        if (seen < 0 && at.compare_exchange_strong(seen, r, std::memory_order_relaxed)) seen = r;
        if (r != seen) ::hbc::detail::atomic_ref<uint8_t>(split[v]).store(1, std::memory_order_relaxed);
        if (!m.edge_fan_ok(e)) ::hbc::detail::atomic_ref<uint8_t>(suspect[v]).store(1, std::memory_order_relaxed);
      }
  });
  for (int32_t v : cells.pinched) suspect[static_cast<size_t>(v)] = 1;
  for (size_t v = 0; v < nv; ++v)
    if (!suspect[v]) m.vert_non_manifold[v] |= split[v];
  if (std::find(suspect.begin(), suspect.end(), 1) != suspect.end()) check_exactly(m, suspect);
}

void drop_declared_edges(Mesh& m, const MeshInput& in) {
  if (in.declared_edges.empty()) return;
  const Csr<int32_t> ve = vertex_edges(m, {}, Threads{1});
  const auto nv = static_cast<int32_t>(m.num_vertices());
  for (const auto& ab : in.declared_edges) {
    const int32_t a = ab[0], b = ab[1];  // not a structured binding: clang 14 cannot capture one
    if (a < 0 || b < 0 || a >= nv || b >= nv) {
      ++m.dropped_edges;
      continue;
    }
    const auto row = ve[static_cast<size_t>(a)];
    const bool known = std::any_of(row.begin(), row.end(), [&](int32_t e) { return m.other_vertex(e, a) == b; });
    m.dropped_edges += !known;
  }
  if (m.dropped_edges > 0) m.warnings.push_back(std::to_string(m.dropped_edges) + " edge(s) used by no face dropped");
}

}  // namespace mesh_steps
}  // namespace hbc
