#include "hbc/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace hbc {

const char* cell_type_name(CellType t) {
  switch (t) {
    case CellType::Hex: return "hex";
    case CellType::Tet: return "tet";
    case CellType::Prism: return "prism";
    case CellType::Pyramid: return "pyramid";
    case CellType::Polyhedron: return "polyhedron";
  }
  return "?";
}

size_t Mesh::num_hex_cells() const {
  return static_cast<size_t>(std::count(cell_type.begin(), cell_type.end(), CellType::Hex));
}

namespace {

// Scrambles the bits of a key (murmur3 finaliser) so that hashed bucket indices spread evenly.
uint64_t mix(uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

// When more faces (edges) than this have the same lowest vertex, they are filed under a hash of
// their whole vertex set instead: around a vertex of high valence (a fan of thousands of cells)
// one bucket would make every lookup scan thousands of entries. Lookups and the counting pass use
// the same rule, so a bucket may mix both kinds of entries.
constexpr int32_t kHeavyBucket = 64;

// Ids of merged elements (faces, edges) filed under their lowest vertex (see kHeavyBucket). The capacity of each
// vertex's bucket is known from a counting pass, so lookups scan a few neighbouring entries
// instead of probing a hash table spread over the whole memory: large meshes stay cache friendly.
class VertexBuckets {
 public:
  // counts[v] = how many elements may be filed under v (an upper bound).
  explicit VertexBuckets(const std::vector<int32_t>& counts) : offsets_(counts.size() + 1, 0) {
    for (size_t v = 0; v < counts.size(); ++v) offsets_[v + 1] = offsets_[v] + counts[v];
    fill_.assign(offsets_.begin(), offsets_.end() - 1);
    ids_.resize(static_cast<size_t>(offsets_.back()));
  }
  template <class Eq>
  int32_t find(int32_t v, Eq&& eq) const {
    for (int64_t i = offsets_[v]; i < fill_[v]; ++i)
      if (eq(ids_[i])) return ids_[i];
    return -1;
  }
  void insert(int32_t v, int32_t id) { ids_[fill_[v]++] = id; }

 private:
  std::vector<int64_t> offsets_, fill_;
  std::vector<int32_t> ids_;
};

uint64_t edge_key(int32_t a, int32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

std::string loop_text(std::span<const int32_t> loop) {
  std::ostringstream s;
  s << "(";
  for (size_t i = 0; i < loop.size(); ++i) s << (i ? " " : "") << loop[i];
  s << ")";
  return s.str();
}

// Checks what a reader handed over: counts, index ranges, finite coordinates, proper polygons.
void validate_input(const MeshInput& in) {
  const std::string& file = in.source;
  if (in.points.size() % 3 != 0) throw InputError(file, {}, "3 coordinates per vertex");
  const size_t nv = in.points.size() / 3;
  if (nv > static_cast<size_t>(std::numeric_limits<int32_t>::max()) ||
      in.faces.items.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max()) ||
      in.cells.items.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max()))
    throw InputError(file, {}, "fewer than 2^31 vertices, face corners and cell faces");
  for (size_t i = 0; i < in.points.size(); ++i)
    if (!std::isfinite(in.points[i]))
      throw InputError(file, in.loc_of(in.vertex_loc, i / 3),
                       "a finite coordinate for vertex " + std::to_string(i / 3));
  std::vector<int32_t> stamp(nv, -1);
  for (size_t f = 0; f < in.faces.rows(); ++f) {
    auto loop = in.faces[f];
    if (loop.size() < 3)
      throw InputError(file, in.loc_of(in.face_loc, f),
                       "a face with at least 3 vertices, face " + std::to_string(f) + " has " +
                           std::to_string(loop.size()));
    for (int32_t v : loop) {
      if (v < 0 || static_cast<size_t>(v) >= nv)
        throw InputError(file, in.loc_of(in.face_loc, f),
                         "vertex index in [0, " + std::to_string(nv) + ") in face " +
                             std::to_string(f) + ", found " + std::to_string(v));
      if (stamp[v] == static_cast<int32_t>(f))
        throw InputError(file, in.loc_of(in.face_loc, f),
                         "distinct vertices in face " + std::to_string(f) + ", vertex " +
                             std::to_string(v) + " repeats in " + loop_text(loop));
      stamp[v] = static_cast<int32_t>(f);
    }
  }
  const size_t nf = in.faces.rows();
  for (size_t c = 0; c < in.cells.rows(); ++c) {
    if (in.cells.count(c) < 2)
      throw InputError(file, in.loc_of(in.cell_loc, c),
                       "a cell with at least 2 faces, cell " + std::to_string(c) + " has " +
                           std::to_string(in.cells.count(c)));
    for (int32_t r : in.cells[c]) {
      int32_t f = r >> 1;
      if (r < 0 || static_cast<size_t>(f) >= nf)
        throw InputError(file, in.loc_of(in.cell_loc, c),
                         "face index in [0, " + std::to_string(nf) + ") in cell " +
                             std::to_string(c) + ", found " + std::to_string(r < 0 ? r : f));
    }
  }
}

// Same direction of two loops over the same vertex set?
bool same_direction(std::span<const int32_t> a, std::span<const int32_t> b) {
  size_t n = a.size();
  size_t p = static_cast<size_t>(std::find(a.begin(), a.end(), b[0]) - a.begin());
  return a[(p + 1) % n] == b[1];
}

// Files disagree on how cells see their faces (some list every face the same way round), so
// each cell's face loops are made consistent (neighbouring faces walk their shared edge in
// opposite directions), then cells are made consistent with each other (two cells see their
// shared face in opposite directions), and each face-connected group of cells is turned so that
// its total signed volume is positive. Orienting cell by cell by the sign of its own volume would
// turn inverted (tangled) cells against their neighbours; this way they keep a negative volume.
// A cell that cannot be oriented keeps what the file said.
void orient_cells(Mesh& m, const std::vector<int32_t>& partner, const std::vector<int32_t>& slot_face) {
  std::vector<int32_t> state, queue;
  std::vector<double> cell_vol(m.num_cells(), 0.0);
  // Orientation of each face of the current cell, by face id (-1: not yet known); reset per cell.
  std::vector<int8_t> face_state(m.num_faces(), -1);
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const int32_t begin = m.cell_faces.offsets[c];
    auto faces = m.cell_faces[c];
    const size_t n = faces.size();
    face_state[faces[0]] = static_cast<int8_t>(m.cell_face_flip[begin]);
    queue.assign(1, faces[0]);
    bool orientable = true;
    for (size_t q = 0; q < queue.size() && orientable; ++q) {
      const int32_t f = queue[q];
      const int32_t side = m.face_cells[f][0] == static_cast<int32_t>(c) ? 0 : 1;
      for (int32_t k = m.face_edges.offsets[f]; k < m.face_edges.offsets[f + 1]; ++k) {
        const int32_t p = partner[2 * k + side];
        if (p < 0) continue;
        const int32_t k2 = p >> 1, g = slot_face[k2];
        // Same stored direction along the shared edge -> the two faces need opposite flips.
        const int8_t want = static_cast<int8_t>(face_state[f] ^ (m.face_verts.items[k] == m.face_verts.items[k2] ? 1 : 0));
        if (face_state[g] < 0) {
          face_state[g] = want;
          queue.push_back(g);
        } else if (face_state[g] != want) {
          orientable = false;
          break;
        }
      }
    }
    state.resize(n);
    bool complete = orientable;
    for (size_t i = 0; i < n; ++i) {
      state[i] = face_state[faces[i]];
      complete = complete && state[i] >= 0;
      face_state[faces[i]] = -1;
    }
    if (!complete) continue;
    // Signed volume of the cell as its faces are now seen (fans around each face's first vertex,
    // relative to the cell's first vertex for precision).
    const double* o = &m.points[3 * static_cast<size_t>(m.face_verts[faces[0]][0])];
    double vol = 0;
    for (size_t i = 0; i < n; ++i) {
      auto loop = m.face_verts[faces[i]];
      const size_t L = loop.size();
      auto pt = [&](size_t idx, double* out) {
        const size_t v = static_cast<size_t>(loop[state[i] ? (L - idx) % L : idx]);
        for (int a = 0; a < 3; ++a) out[a] = m.points[3 * v + a] - o[a];
      };
      double p0[3], p1[3], p2[3];
      pt(0, p0);
      for (size_t t = 1; t + 1 < L; ++t) {
        pt(t, p1);
        pt(t + 1, p2);
        vol += p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) - p0[1] * (p1[0] * p2[2] - p1[2] * p2[0]) +
               p0[2] * (p1[0] * p2[1] - p1[1] * p2[0]);
      }
    }
    cell_vol[c] = vol;
    for (size_t i = 0; i < n; ++i) m.cell_face_flip[begin + static_cast<int32_t>(i)] = static_cast<uint8_t>(state[i]);
  }

  // Across cells, then per face-connected group.
  const size_t nc = m.num_cells();
  auto flip_of = [&](size_t c, int32_t f) -> uint8_t& {
    const int32_t b = m.cell_faces.offsets[c];
    auto faces = m.cell_faces[c];
    return m.cell_face_flip[b + (std::find(faces.begin(), faces.end(), f) - faces.begin())];
  };
  auto turn = [&](size_t c) {
    for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) m.cell_face_flip[i] ^= 1;
    cell_vol[c] = -cell_vol[c];
  };
  std::vector<uint8_t> seen(nc, 0);
  std::vector<int32_t> group;
  for (size_t c0 = 0; c0 < nc; ++c0) {
    if (seen[c0]) continue;
    seen[c0] = 1;
    group.assign(1, static_cast<int32_t>(c0));
    for (size_t q = 0; q < group.size(); ++q) {
      const size_t c = static_cast<size_t>(group[q]);
      for (int32_t f : m.cell_faces[c]) {
        const auto fc = m.face_cells[f];
        const int32_t d = fc[0] == static_cast<int32_t>(c) ? fc[1] : fc[0];
        if (d < 0 || seen[d]) continue;
        seen[d] = 1;
        if (flip_of(static_cast<size_t>(d), f) == flip_of(c, f)) turn(static_cast<size_t>(d));
        group.push_back(d);
      }
    }
    double vol = 0;
    for (int32_t c : group) vol += cell_vol[c];
    if (vol < 0)
      for (int32_t c : group) turn(static_cast<size_t>(c));
  }
}

}  // namespace

Mesh build_mesh(MeshInput in) {
  validate_input(in);
  const std::string file = in.source;
  Mesh m;
  m.source = in.source;
  m.warnings = std::move(in.warnings);
  const size_t nv = in.points.size() / 3;
  const size_t nf_in = in.faces.rows();
  const size_t nc = in.cells.rows();
  m.points = std::move(in.points);

  // --- faces: merge copies with the same vertex set, in order of first use by a cell ---------
  std::vector<int32_t> face_map(nf_in, -1);
  Csr<int32_t> sorted_unique;  // canonical key of each kept face
  std::vector<int32_t> key;
  std::vector<int32_t> bucket_count(nv, 0);
  for (size_t f = 0; f < nf_in; ++f) {
    auto loop = in.faces[f];
    ++bucket_count[*std::min_element(loop.begin(), loop.end())];
  }
  std::vector<uint8_t> heavy(nv, 0);
  for (size_t v = 0; v < nv; ++v) heavy[v] = bucket_count[v] > kHeavyBucket;
  // Order-independent hash of the vertex set: no sorted key needed for counting.
  auto face_bucket = [&](std::span<const int32_t> loop) {
    const int32_t lowest = *std::min_element(loop.begin(), loop.end());
    if (!heavy[lowest]) return lowest;
    uint64_t h = 0;
    for (int32_t v : loop) h += mix(static_cast<uint64_t>(v) + 1);
    return static_cast<int32_t>(h % nv);
  };
  for (size_t f = 0; f < nf_in; ++f) {
    auto loop = in.faces[f];
    const int32_t lowest = *std::min_element(loop.begin(), loop.end());
    if (heavy[lowest]) {
      --bucket_count[lowest];
      ++bucket_count[face_bucket(loop)];
    }
  }
  VertexBuckets face_table(bucket_count);
  auto canonical = [&](size_t f) {
    auto loop = in.faces[f];
    key.assign(loop.begin(), loop.end());
    if (key.size() <= 8) {
      // Insertion sort: faces are short, and this runs once per face use.
      for (size_t i = 1; i < key.size(); ++i)
        for (size_t j = i; j > 0 && key[j - 1] > key[j]; --j) std::swap(key[j - 1], key[j]);
    } else {
      std::sort(key.begin(), key.end());
    }
    return face_bucket(loop);
  };
  auto find_face = [&](int32_t bucket) {
    return face_table.find(bucket, [&](int32_t u) {
      auto s = sorted_unique[u];
      return s.size() == key.size() && std::equal(s.begin(), s.end(), key.begin());
    });
  };

  m.cell_faces.offsets.reserve(nc + 1);
  m.cell_faces.items.reserve(in.cells.items.size());
  m.cell_face_flip.reserve(in.cells.items.size());
  m.face_cells.reserve(nf_in);
  for (size_t c = 0; c < nc; ++c) {
    for (int32_t r : in.cells[c]) {
      const size_t f = static_cast<size_t>(r >> 1);
      int32_t u = face_map[f];
      if (u < 0) {
        const int32_t bucket = canonical(f);
        u = find_face(bucket);
        if (u < 0) {
          u = static_cast<int32_t>(m.face_verts.rows());
          m.face_verts.push_row(in.faces[f]);
          sorted_unique.push_row(key.begin(), key.end());
          face_table.insert(bucket, u);
          m.face_cells.push_back({-1, -1});
        }
        face_map[f] = u;
      }
      // The cell sees the stored loop reversed when exactly one of (input flip, loop copy
      // reversed against the stored one) holds.
      const bool seen_reversed = ((r & 1) != 0) == same_direction(m.face_verts[u], in.faces[f]);
      auto& fc = m.face_cells[u];
      if (fc[0] == static_cast<int32_t>(c) || fc[1] == static_cast<int32_t>(c))
        throw InputError(file, in.loc_of(in.cell_loc, c),
                         "each face once per cell, cell " + std::to_string(c) +
                             " lists the face " + loop_text(m.face_verts[u]) + " twice");
      if (fc[0] < 0) {
        fc[0] = static_cast<int32_t>(c);
      } else if (fc[1] < 0) {
        fc[1] = static_cast<int32_t>(c);
      } else {
        throw InputError(file, in.loc_of(in.cell_loc, c),
                         "a face shared by at most 2 cells, face " + loop_text(m.face_verts[u]) +
                             " is in cells " + std::to_string(fc[0]) + ", " +
                             std::to_string(fc[1]) + " and " + std::to_string(c));
      }
      m.cell_faces.items.push_back(u);
      m.cell_face_flip.push_back(seen_reversed ? 1 : 0);
    }
    m.cell_faces.offsets.push_back(static_cast<int32_t>(m.cell_faces.items.size()));
  }
  for (size_t f = 0; f < nf_in; ++f) {
    if (face_map[f] >= 0) continue;
    if (find_face(canonical(f)) < 0) ++m.dropped_faces;
  }
  if (m.dropped_faces > 0)
    m.warnings.push_back(std::to_string(m.dropped_faces) + " face(s) used by no cell dropped");
  // The input's polygon soup and the merge tables are not needed from here on; releasing them
  // (clear() would keep the capacity) lowers the peak memory by about a quarter on large grids.
  sorted_unique = Csr<int32_t>{};
  face_table = VertexBuckets({});
  std::vector<int32_t>().swap(face_map);
  in.faces = Csr<int32_t>{};
  in.cells = Csr<int32_t>{};

  const size_t nf = m.face_verts.rows();

  // --- edges, in order of first appearance along the face loops ------------------------------
  std::fill(bucket_count.begin(), bucket_count.end(), 0);
  for (size_t f = 0; f < nf; ++f) {
    auto loop = m.face_verts[f];
    for (size_t i = 0; i < loop.size(); ++i) ++bucket_count[std::min(loop[i], loop[(i + 1) % loop.size()])];
  }
  for (size_t v = 0; v < nv; ++v) heavy[v] = bucket_count[v] > 2 * kHeavyBucket;  // each edge counted per face
  auto edge_bucket = [&](uint64_t k) {
    const auto lo = static_cast<int32_t>(k >> 32);
    return heavy[lo] ? static_cast<int32_t>(mix(k) % nv) : lo;
  };
  for (size_t f = 0; f < nf; ++f) {
    auto loop = m.face_verts[f];
    for (size_t i = 0; i < loop.size(); ++i) {
      const uint64_t k = edge_key(loop[i], loop[(i + 1) % loop.size()]);
      if (heavy[k >> 32]) {
        --bucket_count[k >> 32];
        ++bucket_count[edge_bucket(k)];
      }
    }
  }
  VertexBuckets edge_table(bucket_count);
  std::vector<int32_t>().swap(bucket_count);
  m.face_edges.offsets = m.face_verts.offsets;
  m.face_edges.items.resize(m.face_verts.items.size());
  auto find_edge = [&](uint64_t k) {
    const int32_t lo = static_cast<int32_t>(k >> 32), hi = static_cast<int32_t>(k & 0xffffffffu);
    return edge_table.find(edge_bucket(k), [&](int32_t e) { return m.edge_verts[e][0] == lo && m.edge_verts[e][1] == hi; });
  };
  for (size_t f = 0; f < nf; ++f) {
    auto loop = m.face_verts[f];
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i) {
      int32_t a = loop[i], b = loop[(i + 1) % n];
      uint64_t k = edge_key(a, b);
      int32_t e = find_edge(k);
      if (e < 0) {
        e = static_cast<int32_t>(m.edge_verts.size());
        m.edge_verts.push_back({std::min(a, b), std::max(a, b)});
        edge_table.insert(edge_bucket(k), e);
      }
      m.face_edges.items[m.face_edges.offsets[f] + i] = e;
    }
  }
  for (auto [a, b] : in.declared_edges) {
    if (a < 0 || b < 0 || static_cast<size_t>(a) >= nv || static_cast<size_t>(b) >= nv ||
        find_edge(edge_key(a, b)) < 0)
      ++m.dropped_edges;
  }
  if (m.dropped_edges > 0)
    m.warnings.push_back(std::to_string(m.dropped_edges) + " edge(s) used by no face dropped");
  edge_table = VertexBuckets({});  // edges are all known; release the table before the fan arrays
  const size_t ne = m.edge_verts.size();

  // --- per cell: closedness, vertices, edges, and the two faces of the cell at each edge -----
  // partner[2*slot + side] is the other face of the cell on `side` of face f at the edge in
  // face_edges slot `slot`; it makes the walk around each edge linear.
  std::vector<int32_t> partner(2 * m.face_edges.items.size(), -1);
  m.cell_verts.offsets.reserve(nc + 1);
  m.cell_edges.offsets.reserve(nc + 1);
  // Stamps instead of a sort per cell: an edge's first slot in the current cell waits for its
  // second; anything but exactly two slots means the cell is not closed.
  std::vector<int32_t> edge_stamp(ne, -1), edge_first(ne, -1), edge_count(ne, 0), vert_stamp(nv, -1);
  std::vector<int32_t> ce, cv;
  for (size_t c = 0; c < nc; ++c) {
    const int32_t ci = static_cast<int32_t>(c);
    ce.clear();
    cv.clear();
    for (int32_t f : m.cell_faces[c]) {
      const int32_t side = m.face_cells[f][0] == ci ? 0 : 1;
      for (int32_t k = m.face_edges.offsets[f]; k < m.face_edges.offsets[f + 1]; ++k) {
        const int32_t e = m.face_edges.items[k], slot = 2 * k + side;
        if (edge_stamp[e] != ci) {
          edge_stamp[e] = ci;
          edge_first[e] = slot;
          edge_count[e] = 1;
          ce.push_back(e);
        } else if (++edge_count[e] == 2) {
          partner[edge_first[e]] = slot;
          partner[slot] = edge_first[e];
        }
      }
      for (int32_t v : m.face_verts[f])
        if (vert_stamp[v] != ci) {
          vert_stamp[v] = ci;
          cv.push_back(v);
        }
    }
    std::sort(ce.begin(), ce.end());
    for (int32_t e : ce) {
      if (edge_count[e] == 2) continue;
      auto ev = m.edge_verts[e];
      throw InputError(file, in.loc_of(in.cell_loc, c),
                       "a closed cell (each edge in exactly 2 of its faces), cell " + std::to_string(c) +
                           " has edge (" + std::to_string(ev[0]) + " " + std::to_string(ev[1]) + ") in " +
                           std::to_string(edge_count[e]));
    }
    m.cell_edges.push_row(ce.begin(), ce.end());
    std::sort(cv.begin(), cv.end());
    m.cell_verts.push_row(cv.begin(), cv.end());
  }
  std::vector<int32_t>().swap(edge_stamp);
  std::vector<int32_t>().swap(edge_first);
  std::vector<int32_t>().swap(edge_count);
  std::vector<int32_t>().swap(vert_stamp);
  // slot -> face lookup for partner slots
  std::vector<int32_t> slot_face(m.face_edges.items.size());
  for (size_t f = 0; f < nf; ++f)
    for (int32_t k = m.face_edges.offsets[f]; k < m.face_edges.offsets[f + 1]; ++k)
      slot_face[k] = static_cast<int32_t>(f);

  orient_cells(m, partner, slot_face);

  // --- boundary flags ----------------------------------------------------------------------
  m.face_boundary.assign(nf, 0);
  m.edge_boundary.assign(ne, 0);
  m.vert_boundary.assign(nv, 0);
  for (size_t f = 0; f < nf; ++f) {
    if (m.face_cells[f][1] >= 0) continue;
    m.face_boundary[f] = 1;
    for (int32_t e : m.face_edges[f]) m.edge_boundary[e] = 1;
    for (int32_t v : m.face_verts[f]) m.vert_boundary[v] = 1;
  }

  // --- vertex incidences ---------------------------------------------------------------------
  {
    Csr<int32_t> ev;
    ev.offsets.resize(ne + 1);
    ev.items.resize(2 * ne);
    for (size_t e = 0; e < ne; ++e) {
      ev.offsets[e + 1] = static_cast<int32_t>(2 * (e + 1));
      ev.items[2 * e] = m.edge_verts[e][0];
      ev.items[2 * e + 1] = m.edge_verts[e][1];
    }
    m.vert_edges = transpose(ev, nv);
  }
  m.vert_faces = transpose(m.face_verts, nv);
  m.vert_cells = transpose(m.cell_verts, nv);

  // --- fans around edges, in cyclic order ----------------------------------------------------
  // For each edge, the face slots that carry it: gather (edge -> slot) by counting sort.
  Csr<int32_t> edge_slots;
  edge_slots.offsets.assign(ne + 1, 0);
  for (int32_t e : m.face_edges.items) ++edge_slots.offsets[e + 1];
  for (size_t e = 0; e < ne; ++e) edge_slots.offsets[e + 1] += edge_slots.offsets[e];
  edge_slots.items.resize(m.face_edges.items.size());
  {
    std::vector<int32_t> fill(edge_slots.offsets.begin(), edge_slots.offsets.end() - 1);
    for (size_t k = 0; k < m.face_edges.items.size(); ++k)
      edge_slots.items[fill[m.face_edges.items[k]]++] = static_cast<int32_t>(k);
  }
  m.edge_faces.offsets = edge_slots.offsets;
  m.edge_faces.items.resize(edge_slots.items.size());
  m.edge_cells.offsets.assign(ne + 1, 0);
  m.edge_cells.items.reserve(edge_slots.items.size());
  m.edge_fan_ok.assign(ne, 0);
  std::vector<int32_t> fan_faces, fan_cells;
  std::vector<int32_t> face_stamp(nf, -1);
  for (size_t e = 0; e < ne; ++e) {
    auto slots = edge_slots[e];
    fan_faces.clear();
    fan_cells.clear();
    // Start at the lowest boundary face if there is one, so that a boundary fan is a path.
    int32_t start = -1, nboundary = 0;
    for (int32_t k : slots) {
      if (m.face_boundary[slot_face[k]]) {
        ++nboundary;
        if (start < 0) start = k;
      }
    }
    bool ok = (nboundary == 0 || nboundary == 2);
    if (start < 0) start = slots[0];
    int32_t k = start, side = 0;
    const size_t limit = slots.size();
    while (ok) {
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
      if (fan_faces.size() > limit) {
        ok = false;
        break;
      }
    }
    if (ok) {
      ok = fan_faces.size() == slots.size();
      // Each face once: the walk may have closed early in a pinched fan.
      for (size_t i = 0; ok && i < fan_faces.size(); ++i) {
        ok = face_stamp[fan_faces[i]] != static_cast<int32_t>(e);
        face_stamp[fan_faces[i]] = static_cast<int32_t>(e);
      }
    }
    int32_t* out = m.edge_faces.items.data() + m.edge_faces.offsets[e];
    if (ok) {
      std::copy(fan_faces.begin(), fan_faces.end(), out);
      m.edge_cells.items.insert(m.edge_cells.items.end(), fan_cells.begin(), fan_cells.end());
      m.edge_fan_ok[e] = 1;
    } else {
      // No cyclic order: list faces and cells sorted, each once.
      fan_faces.clear();
      fan_cells.clear();
      for (int32_t s : slots) {
        const int32_t f = slot_face[s];
        fan_faces.push_back(f);
        for (int32_t c : m.face_cells[f])
          if (c >= 0) fan_cells.push_back(c);
      }
      std::sort(fan_faces.begin(), fan_faces.end());
      std::sort(fan_cells.begin(), fan_cells.end());
      fan_cells.erase(std::unique(fan_cells.begin(), fan_cells.end()), fan_cells.end());
      std::copy(fan_faces.begin(), fan_faces.end(), out);
      m.edge_cells.items.insert(m.edge_cells.items.end(), fan_cells.begin(), fan_cells.end());
    }
    m.edge_cells.offsets[e + 1] = static_cast<int32_t>(m.edge_cells.items.size());
  }

  // --- cell types --------------------------------------------------------------------------
  m.cell_type.assign(nc, CellType::Polyhedron);
  std::vector<int32_t> vcount(nv, 0);
  m.vert_non_manifold.assign(nv, 0);
  for (size_t c = 0; c < nc; ++c) {
    auto faces = m.cell_faces[c];
    int tris = 0, quads = 0;
    for (int32_t f : faces) {
      int32_t n = m.face_verts.count(f);
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
    for (int32_t v : m.cell_verts[c]) {
      if (vcount[v] < 3) m.vert_non_manifold[v] = 1;
      vcount[v] = 0;
    }
  }

  // --- non-manifold vertices: cells around the vertex not one face-connected group ------------
  std::vector<int32_t> parent;
  for (size_t v = 0; v < nv; ++v) {
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
      int32_t a = root(local(m.face_cells[f][0])), b = root(local(m.face_cells[f][1]));
      if (a != b) {
        parent[std::max(a, b)] = std::min(a, b);
        --groups;
      }
    }
    if (groups != 1) m.vert_non_manifold[v] = 1;
  }
  return m;
}

MeshInput to_input(const Mesh& mesh) {
  MeshInput in;
  in.source = mesh.source;
  in.points = mesh.points;
  in.faces = mesh.face_verts;
  in.cells.offsets = mesh.cell_faces.offsets;
  in.cells.items.resize(mesh.cell_faces.items.size());
  for (size_t i = 0; i < mesh.cell_faces.items.size(); ++i)
    in.cells.items[i] = 2 * mesh.cell_faces.items[i] + mesh.cell_face_flip[i];
  return in;
}

MeshInput renumbered(const Mesh& mesh, const std::vector<int32_t>& vperm,
                     const std::vector<int32_t>& cperm) {
  MeshInput in;
  in.source = mesh.source;
  const size_t nv = mesh.num_vertices(), nc = mesh.num_cells();
  in.points.resize(3 * nv);
  for (size_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) in.points[3 * vperm[v] + k] = mesh.points[3 * v + k];
  in.faces.offsets = mesh.face_verts.offsets;
  in.faces.items.resize(mesh.face_verts.items.size());
  for (size_t i = 0; i < mesh.face_verts.items.size(); ++i)
    in.faces.items[i] = vperm[mesh.face_verts.items[i]];
  std::vector<int32_t> inv(nc);
  for (size_t c = 0; c < nc; ++c) inv[cperm[c]] = static_cast<int32_t>(c);
  for (size_t nc_i = 0; nc_i < nc; ++nc_i) {
    const size_t c = static_cast<size_t>(inv[nc_i]);
    for (int32_t i = mesh.cell_faces.offsets[c]; i < mesh.cell_faces.offsets[c + 1]; ++i)
      in.cells.items.push_back(2 * mesh.cell_faces.items[i] + mesh.cell_face_flip[i]);
    in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
  }
  return in;
}

}  // namespace hbc
