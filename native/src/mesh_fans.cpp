// Incidence, fan and classification steps of build_mesh (see hbc/mesh_steps.hpp).
#include <algorithm>
#include <atomic>
#include <numeric>

#include "hbc/mesh_steps.hpp"
#include "parallel.hpp"

namespace hbc::mesh_steps {

void mark_boundary(Mesh& m) {
  m.face_boundary.assign(m.num_faces(), 0);
  m.edge_boundary.assign(m.num_edges(), 0);
  m.vert_boundary.assign(m.num_vertices(), 0);
  for (size_t f = 0; f < m.num_faces(); ++f) {
    if (m.face_cells[f][1] >= 0) continue;
    m.face_boundary[f] = 1;
    for (int32_t e : m.face_edges[f]) m.edge_boundary[e] = 1;
    for (int32_t v : m.face_verts[f]) m.vert_boundary[v] = 1;
  }
}

void vertex_incidences(Mesh& m, const MeshInput& in, const LoadOptions& par) {
  const size_t nv = m.num_vertices();
  detail::parallel_invoke(
      par,
      [&] {
        // Both ends of every edge as a CSR, row e = edge e.
        Csr<int32_t> ev;
        std::vector<int32_t> offsets(m.num_edges() + 1);
        for (size_t e = 0; e < offsets.size(); ++e) offsets[e] = static_cast<int32_t>(2 * e);
        ev.offsets = std::move(offsets);
        ev.items.resize(2 * m.num_edges());
        for (size_t e = 0; e < m.num_edges(); ++e) {
          ev.items[2 * e] = m.edge_verts[e][0];
          ev.items[2 * e + 1] = m.edge_verts[e][1];
        }
        m.vert_edges = transpose(ev, nv);
      },
      [&] { m.vert_faces = transpose(m.face_verts, nv); },
      [&] { m.vert_cells = transpose(m.cell_verts, nv); });
  for (auto [a, b] : in.declared_edges) {
    const bool known = a >= 0 && b >= 0 && static_cast<size_t>(a) < nv && static_cast<size_t>(b) < nv &&
                       std::ranges::any_of(m.vert_edges[a], [&](int32_t e) { return m.other_vertex(e, a) == b; });
    m.dropped_edges += !known;
  }
  if (m.dropped_edges > 0)
    m.warnings.push_back(std::to_string(m.dropped_edges) + " edge(s) used by no face dropped");
}

namespace {

// Walks the fan of edge e (its face slots `slots`) in cyclic order through the cells, starting at
// its lowest boundary face if it has one, so that a boundary fan is a path. False when the fan
// has no such order (more than two boundary faces, a pinched or non-manifold fan).
bool walk_fan(const Mesh& m, std::span<const int32_t> slots, const std::vector<int32_t>& partner,
              const std::vector<int32_t>& slot_face, std::vector<int32_t>& fan_faces,
              std::vector<int32_t>& fan_cells, std::vector<int32_t>& scratch) {
  fan_faces.clear();
  fan_cells.clear();
  int32_t start = -1, nboundary = 0;
  for (int32_t k : slots) {
    if (m.face_boundary[slot_face[k]]) {
      ++nboundary;
      if (start < 0) start = k;
    }
  }
  if (nboundary != 0 && nboundary != 2) return false;
  if (start < 0) start = slots[0];
  int32_t k = start, side = 0;
  while (true) {
    const int32_t f = slot_face[k];
    fan_faces.push_back(f);
    const int32_t c = m.face_cells[f][side];
    if (c < 0) break;  // reached the other boundary face
    fan_cells.push_back(c);
    // partner entries are 2*slot + side, the side on which c lies of the next face; the walk
    // continues on the far side of it.
    const int32_t pk = partner[2 * k + side];
    k = pk >> 1;
    side = 1 - (pk & 1);
    if (k == start) break;
    if (fan_faces.size() > slots.size()) return false;
  }
  if (fan_faces.size() != slots.size()) return false;
  // Each face once: the walk may have closed early in a pinched fan.
  scratch = fan_faces;
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) == scratch.end();
}

}  // namespace

void edge_fans(Mesh& m, const std::vector<int32_t>& partner, const std::vector<int32_t>& slot_face, const LoadOptions& par) {
  const size_t ne = m.num_edges();
  // The face slots carrying each edge; each row is then overwritten with the faces of the fan.
  m.edge_faces = group_by(m.face_edges.items, ne);
  m.edge_fan_ok.assign(ne, 0);
  const int nr = detail::range_count(ne, par);
  std::vector<Csr<int32_t>> cells(static_cast<size_t>(nr));
  detail::parallel_ranges(ne, par, [&](size_t eb, size_t ee, int r) {
    std::vector<int32_t> slots, fan_faces, fan_cells, scratch;
    Csr<int32_t>& rows = cells[static_cast<size_t>(r)];
    rows.reserve(ee - eb, static_cast<size_t>(m.edge_faces.offsets[ee] - m.edge_faces.offsets[eb]));
    for (size_t e = eb; e < ee; ++e) {
      auto row = m.edge_faces.row(e);
      slots.assign(row.begin(), row.end());
      if (walk_fan(m, slots, partner, slot_face, fan_faces, fan_cells, scratch)) {
        m.edge_fan_ok[e] = 1;
      } else {
        // No cyclic order: faces and cells sorted, each once.
        fan_faces.clear();
        fan_cells.clear();
        for (int32_t s : slots) {
          const int32_t f = slot_face[s];
          fan_faces.push_back(f);
          for (int32_t c : m.face_cells[f])
            if (c >= 0) fan_cells.push_back(c);
        }
        std::sort(fan_faces.begin(), fan_faces.end());
        sort_unique(fan_cells);
      }
      std::copy(fan_faces.begin(), fan_faces.end(), row.begin());
      rows.push_row(fan_cells.begin(), fan_cells.end());
    }
  });
  m.edge_cells = concat(std::move(cells));
}

void cell_types(Mesh& m, const LoadOptions& par) {
  const size_t nc = m.num_cells();
  m.cell_type.assign(nc, CellType::Polyhedron);
  m.vert_non_manifold.assign(m.num_vertices(), 0);
  detail::parallel_ranges(nc, par, [&](size_t cb, size_t ce, int) {
    std::vector<int32_t> vcount(m.num_vertices(), 0);  // faces of the cell at each vertex
    for (size_t c = cb; c < ce; ++c) {
      auto faces = m.cell_faces[c];
      int tris = 0, quads = 0;
      for (int32_t f : faces) {
        const int32_t n = m.face_verts.count(f);
        tris += n == 3;
        quads += n == 4;
        for (int32_t v : m.face_verts[f]) ++vcount[v];
      }
      const size_t nfc = faces.size(), nvc = m.cell_verts.count(c), nec = m.cell_edges.count(c);
      bool three_each = true;
      for (int32_t v : m.cell_verts[c]) three_each = three_each && vcount[v] == 3;
      CellType t = CellType::Polyhedron;
      if (nfc == 6 && quads == 6 && nvc == 8 && nec == 12 && three_each) t = CellType::Hex;
      else if (nfc == 4 && tris == 4 && nvc == 4) t = CellType::Tet;
      else if (nfc == 5 && tris == 2 && quads == 3 && nvc == 6 && three_each) t = CellType::Prism;
      else if (nfc == 5 && tris == 4 && quads == 1 && nvc == 5) t = CellType::Pyramid;
      m.cell_type[c] = t;
      // A cell meeting a vertex in fewer than 3 of its faces is flat or folded there (SPEC §1).
      // Cells of several ranges may mark the same vertex: the same value, stored atomically.
      for (int32_t v : m.cell_verts[c]) {
        if (vcount[v] < 3) std::atomic_ref<uint8_t>(m.vert_non_manifold[v]).store(1, std::memory_order_relaxed);
        vcount[v] = 0;
      }
    }
  });
}

void non_manifold_vertices(Mesh& m, const LoadOptions& par) {
  detail::parallel_ranges(m.num_vertices(), par, [&](size_t vb, size_t ve, int) {
    std::vector<int32_t> parent;
    for (size_t v = vb; v < ve; ++v) {
      auto cells = m.vert_cells[v];
      if (cells.size() <= 1 || m.vert_non_manifold[v]) continue;
      parent.resize(cells.size());
      std::iota(parent.begin(), parent.end(), 0);
      auto local = [&](int32_t c) {
        return static_cast<int32_t>(std::lower_bound(cells.begin(), cells.end(), c) - cells.begin());
      };
      auto root = [&](int32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
      };
      size_t groups = cells.size();
      for (int32_t f : m.vert_faces[v]) {
        if (m.face_cells[f][1] < 0) continue;
        const int32_t a = root(local(m.face_cells[f][0])), b = root(local(m.face_cells[f][1]));
        if (a != b) {
          parent[std::max(a, b)] = std::min(a, b);
          --groups;
        }
      }
      if (groups != 1) m.vert_non_manifold[v] = 1;
    }
  });
}

}  // namespace hbc::mesh_steps
