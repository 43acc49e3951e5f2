// The steps of build_mesh (see hbc/mesh_steps.hpp). Faces and edges are matched by sorting their
// keys within buckets of a counting sort on their lowest vertex: no hash table, and the buckets
// are small and independent, so threads split them by vertex range.
#include "hbc/mesh_steps.hpp"

#include <algorithm>
#include <atomic>
#include <numeric>
#include <sstream>

#include "parallel.hpp"

namespace hbc::mesh_steps {
namespace {

// Same direction of two loops over the same vertex set?
bool same_direction(std::span<const int32_t> a, std::span<const int32_t> b) {
  const size_t n = a.size();
  const size_t p = static_cast<size_t>(std::find(a.begin(), a.end(), b[0]) - a.begin());
  return a[(p + 1) % n] == b[1];
}

// rep[f] = the input face standing for all input faces with f's vertex set: the one a cell uses
// first (lowest first_use), or -1 when no cell uses any of them.
std::vector<int32_t> face_representatives(const Csr<int32_t>& faces, const std::vector<int32_t>& first_use,
                                          size_t nv, const LoadOptions& par) {
  const size_t nf = faces.rows();
  std::vector<int32_t> lowest(nf);
  detail::parallel_ranges(nf, par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) lowest[f] = *std::min_element(faces[f].begin(), faces[f].end());
  });
  const Csr<int32_t> by_lowest = group_by(lowest, nv);
  std::vector<int32_t>().swap(lowest);
  std::vector<int32_t> rep(nf, -1);
  // An unused face sorts after the used ones of its group.
  auto use_rank = [&](int32_t f) { return static_cast<uint32_t>(first_use[f]); };
  detail::parallel_ranges(nv, par, [&](size_t vb, size_t ve, int) {
    std::vector<int32_t> keys, order;
    std::vector<int32_t> key_at;  // start of each bucket member's sorted key in keys
    for (size_t v = vb; v < ve; ++v) {
      auto ids = by_lowest[v];
      if (ids.size() == 1) rep[ids[0]] = first_use[ids[0]] >= 0 ? ids[0] : -1;
      if (ids.size() <= 1) continue;
      keys.clear();
      key_at.clear();
      for (int32_t f : ids) {
        key_at.push_back(static_cast<int32_t>(keys.size()));
        keys.insert(keys.end(), faces[f].begin(), faces[f].end());
        std::sort(keys.begin() + key_at.back(), keys.end());
      }
      key_at.push_back(static_cast<int32_t>(keys.size()));
      auto key = [&](int32_t i) {
        return std::span<const int32_t>(keys.data() + key_at[i], static_cast<size_t>(key_at[i + 1] - key_at[i]));
      };
      auto same_key = [&](int32_t i, int32_t j) { return std::ranges::equal(key(i), key(j)); };
      order.resize(ids.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](int32_t i, int32_t j) {
        auto a = key(i), b = key(j);
        if (a.size() != b.size()) return a.size() < b.size();
        const auto c = std::lexicographical_compare_three_way(a.begin(), a.end(), b.begin(), b.end());
        return c != 0 ? c < 0 : use_rank(ids[i]) < use_rank(ids[j]);
      });
      for (size_t g = 0; g < order.size();) {
        size_t h = g + 1;
        while (h < order.size() && same_key(order[g], order[h])) ++h;
        const int32_t first = ids[order[g]];
        const int32_t r = first_use[first] >= 0 ? first : -1;
        for (size_t i = g; i < h; ++i) rep[ids[order[i]]] = r;
        g = h;
      }
    }
  });
  return rep;
}

// face_cells from cell_faces, in cell order, so that the first offending cell is reported.
void fill_face_cells(const MeshInput& in, Mesh& m) {
  m.face_cells.assign(m.face_verts.rows(), {-1, -1});
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const int32_t ci = static_cast<int32_t>(c);
    for (int32_t u : m.cell_faces[c]) {
      auto& fc = m.face_cells[u];
      if (fc[0] == ci || fc[1] == ci)
        throw InputError(in.source, in.loc_of(in.cell_loc, c),
                         "each face once per cell, cell " + std::to_string(c) + " lists the face " +
                             loop_text(m.face_verts[u]) + " twice");
      if (fc[0] < 0) {
        fc[0] = ci;
      } else if (fc[1] < 0) {
        fc[1] = ci;
      } else {
        throw InputError(in.source, in.loc_of(in.cell_loc, c),
                         "a face shared by at most 2 cells, face " + loop_text(m.face_verts[u]) +
                             " is in cells " + std::to_string(fc[0]) + ", " + std::to_string(fc[1]) +
                             " and " + std::to_string(c));
      }
    }
  }
}

}  // namespace

void merge_faces(MeshInput& in, Mesh& m, const LoadOptions& par) {
  const size_t nf_in = in.faces.rows(), nslots = in.cells.items.size();
  std::vector<int32_t> first_use(nf_in, -1);
  for (size_t s = 0; s < nslots; ++s) {
    const int32_t f = in.cells.items[s] >> 1;
    if (first_use[f] < 0) first_use[f] = static_cast<int32_t>(s);
  }
  const std::vector<int32_t> rep = face_representatives(in.faces, first_use, m.num_vertices(), par);
  for (size_t f = 0; f < nf_in; ++f) m.dropped_faces += rep[f] < 0;
  if (m.dropped_faces > 0)
    m.warnings.push_back(std::to_string(m.dropped_faces) + " face(s) used by no cell dropped");

  std::vector<int32_t>& face_id = first_use;  // reused: id of each representative, -1 until met
  std::fill(face_id.begin(), face_id.end(), -1);
  m.cell_faces.offsets = std::move(in.cells.offsets);
  m.cell_faces.items.resize(nslots);
  // Exactly the room the merged loops need: growing would copy them again and again.
  size_t kept = 0, corners = 0;
  for (size_t f = 0; f < nf_in; ++f)
    if (rep[f] == static_cast<int32_t>(f)) ++kept, corners += static_cast<size_t>(in.faces.count(f));
  m.face_verts.reserve(kept, corners);
  for (size_t s = 0; s < nslots; ++s) {
    const int32_t r = rep[in.cells.items[s] >> 1];
    if (face_id[r] < 0) {
      face_id[r] = static_cast<int32_t>(m.face_verts.rows());
      m.face_verts.push_row(in.faces[r]);
    }
    m.cell_faces.items[s] = face_id[r];
  }
  // The cell sees the stored loop reversed when exactly one of (input flip, loop copy reversed
  // against the stored one) holds.
  m.cell_face_flip.resize(nslots);
  detail::parallel_ranges(nslots, par, [&](size_t b, size_t e, int) {
    for (size_t s = b; s < e; ++s) {
      const int32_t f = in.cells.items[s] >> 1;
      const bool same = rep[f] == f || same_direction(m.face_verts[m.cell_faces.items[s]], in.faces[f]);
      m.cell_face_flip[s] = static_cast<uint8_t>(((in.cells.items[s] & 1) != 0) == same);
    }
  });
  // The polygon soup is not needed from here on; releasing it (clear() would keep the capacity)
  // lowers the peak memory.
  in.faces = Csr<int32_t>{};
  in.cells = Csr<int32_t>{};
  fill_face_cells(in, m);
}

std::vector<int32_t> slot_faces(const Mesh& m, const LoadOptions& par) {
  std::vector<int32_t> slot_face(m.face_verts.items.size());
  detail::parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f)
      std::fill(slot_face.begin() + m.face_verts.offsets[f], slot_face.begin() + m.face_verts.offsets[f + 1],
                static_cast<int32_t>(f));
  });
  return slot_face;
}

namespace {
// The vertex after slot k along its face loop.
int32_t next_vertex(const Mesh& m, const std::vector<int32_t>& slot_face, size_t k) {
  const int32_t f = slot_face[k];
  return m.face_verts.items[static_cast<int32_t>(k) + 1 == m.face_verts.offsets[f + 1] ? m.face_verts.offsets[f] : k + 1];
}
}  // namespace

void build_edges(Mesh& m, const std::vector<int32_t>& slot_face, const LoadOptions& par) {
  const size_t ns = m.face_verts.items.size();
  std::vector<int32_t>& rep = m.face_edges.items;  // first the lowest slot with the same edge
  rep.resize(ns);
  {
    std::vector<int32_t> lo(ns);
    detail::parallel_ranges(ns, par, [&](size_t b, size_t e, int) {
      for (size_t k = b; k < e; ++k) lo[k] = std::min(m.face_verts.items[k], next_vertex(m, slot_face, k));
    });
    const Csr<int32_t> by_lo = group_by(lo, m.num_vertices());
    std::vector<int32_t>().swap(lo);
    detail::parallel_ranges(m.num_vertices(), par, [&](size_t vb, size_t ve, int) {
      std::vector<uint64_t> hi_slot;  // other end << 32 | slot, sorted
      for (size_t v = vb; v < ve; ++v) {
        hi_slot.clear();
        for (int32_t k : by_lo[v]) {
          const int32_t hi = std::max(m.face_verts.items[k], next_vertex(m, slot_face, k));
          hi_slot.push_back(static_cast<uint64_t>(hi) << 32 | static_cast<uint32_t>(k));
        }
        std::sort(hi_slot.begin(), hi_slot.end());
        for (size_t i = 0; i < hi_slot.size(); ++i) {
          const auto k = static_cast<int32_t>(hi_slot[i] & 0xffffffffu);
          const bool same = i > 0 && (hi_slot[i - 1] >> 32) == (hi_slot[i] >> 32);
          rep[k] = same ? rep[static_cast<int32_t>(hi_slot[i - 1] & 0xffffffffu)] : k;
        }
      }
    });
  }
  // Numbering in slot order: a representative precedes the other slots of its edge, so by the
  // time they are reached it already holds the edge id.
  m.edge_verts.reserve(ns / 2);  // each edge of a closed cell is in two of its face slots
  for (size_t k = 0; k < ns; ++k) {
    if (rep[k] == static_cast<int32_t>(k)) {
      const int32_t a = m.face_verts.items[k], b = next_vertex(m, slot_face, k);
      rep[k] = static_cast<int32_t>(m.edge_verts.size());
      m.edge_verts.push_back({std::min(a, b), std::max(a, b)});
    } else {
      rep[k] = rep[rep[k]];
    }
  }
  m.face_edges.offsets = m.face_verts.offsets;
}

std::vector<int32_t> cell_incidences(Mesh& m, const MeshInput& in, const LoadOptions& par) {
  const size_t nc = m.num_cells();
  std::vector<int32_t> partner(2 * m.face_edges.items.size(), -1);
  const int nr = detail::range_count(nc, par);
  std::vector<Csr<int32_t>> verts(static_cast<size_t>(nr)), edges(static_cast<size_t>(nr));
  detail::parallel_ranges(nc, par, [&](size_t cb, size_t ce, int r) {
    std::vector<uint64_t> edge_slot;  // edge << 32 | (2*slot + side), per slot of the cell: sorts as one integer
    std::vector<int32_t> cv, cedges;
    Csr<int32_t>& vrows = verts[static_cast<size_t>(r)];
    Csr<int32_t>& erows = edges[static_cast<size_t>(r)];
    const size_t slots = static_cast<size_t>(m.cell_faces.offsets[ce] - m.cell_faces.offsets[cb]);
    vrows.reserve(ce - cb, 2 * slots);  // a hex: 6 faces, 8 vertices, 12 edges
    erows.reserve(ce - cb, 2 * slots);
    for (size_t c = cb; c < ce; ++c) {
      edge_slot.clear();
      cv.clear();
      cedges.clear();
      for (int32_t f : m.cell_faces[c]) {
        const int32_t side = m.face_cells[f][0] == static_cast<int32_t>(c) ? 0 : 1;
        for (int32_t k = m.face_edges.offsets[f]; k < m.face_edges.offsets[f + 1]; ++k)
          edge_slot.push_back(static_cast<uint64_t>(m.face_edges.items[k]) << 32 | static_cast<uint32_t>(2 * k + side));
        cv.insert(cv.end(), m.face_verts[f].begin(), m.face_verts[f].end());
      }
      std::sort(edge_slot.begin(), edge_slot.end());
      auto edge = [&](size_t i) { return static_cast<int32_t>(edge_slot[i] >> 32); };
      auto slot = [&](size_t i) { return static_cast<int32_t>(edge_slot[i] & 0xffffffffu); };
      for (size_t i = 0; i < edge_slot.size();) {
        size_t j = i + 1;
        while (j < edge_slot.size() && edge(j) == edge(i)) ++j;
        if (j - i != 2) {
          auto ev = m.edge_verts[edge(i)];
          throw InputError(in.source, in.loc_of(in.cell_loc, c),
                           "a closed cell (each edge in exactly 2 of its faces), cell " + std::to_string(c) +
                               " has edge (" + std::to_string(ev[0]) + " " + std::to_string(ev[1]) + ") in " +
                               std::to_string(j - i));
        }
        partner[slot(i)] = slot(i + 1);
        partner[slot(i + 1)] = slot(i);
        cedges.push_back(edge(i));
        i = j;
      }
      erows.push_row(cedges.begin(), cedges.end());
      sort_unique(cv);
      vrows.push_row(cv.begin(), cv.end());
    }
  });
  m.cell_verts = concat(std::move(verts));
  m.cell_edges = concat(std::move(edges));
  return partner;
}

}  // namespace hbc::mesh_steps
