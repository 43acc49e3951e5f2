// The cell steps of build_mesh (see hbc/mesh_steps.hpp): closedness, orientation and type, each
// cell on its own with a few dozen entries of scratch, then orientation across cells.
//
// Files disagree on how cells see their faces (some list every face the same way round).
// Orienting cell by cell by the sign of its own volume would turn inverted (tangled) cells
// against their neighbours; making neighbours agree and fixing the sign per face-connected group
// keeps their negative volume.
#include <algorithm>
#include <atomic>

#include "hbc/check.hpp"
#include "mesh/mesh_steps.hpp"
#include "platform/huge_pages.hpp"
#include "parallel/parallel.hpp"
#include "parallel/small_table.hpp"
#include "platform/atomic_ref.hpp"

namespace hbc::mesh_steps {
namespace {

// The corners of one cell's faces, paired along the cell's edges.
struct CellCorners {
  std::vector<int32_t> face_begin;  // local face i has entries face_begin[i] .. face_begin[i+1]-1
  std::vector<int32_t> corner;      // per entry: the corner (position in face_verts.items)
  std::vector<int32_t> partner;     // per entry: the entry of the other face of the cell at its edge
  std::vector<int32_t> face_of;     // per entry: its local face
  std::vector<int8_t> state;        // per local face: 1 = seen reversed, -1 = not reached
  std::vector<int32_t> queue;
  detail::SmallTable edges, verts;  // per edge: entries; per vertex: faces of the cell there

  // Fills the entries of cell c and pairs them; throws when an edge is not in exactly two faces.
  void gather(const Mesh& m, const MeshInput& in, size_t c);
  // Flips making the loops agree with each other, the first keeping the file's; false when
  // they cannot agree.
  bool orient(const Mesh& m, size_t c);
};

void CellCorners::gather(const Mesh& m, const MeshInput& in, size_t c) {
  face_begin.assign(1, 0);
  corner.clear();
  face_of.clear();
  const auto faces = m.cell_faces[c];
  for (size_t i = 0; i < faces.size(); ++i) {
    const auto f = static_cast<size_t>(faces[i]);
    for (int32_t k = m.face_verts.offsets[f]; k < m.face_verts.offsets[f + 1]; ++k) {
      corner.push_back(k);
      face_of.push_back(static_cast<int32_t>(i));
    }
    face_begin.push_back(static_cast<int32_t>(corner.size()));
  }
  edges.reset(corner.size());
  verts.reset(corner.size());
  partner.resize(corner.size());
  bool closed = true;
  for (size_t x = 0; x < corner.size(); ++x) {
    const auto k = static_cast<size_t>(corner[x]);
    ++verts[m.face_verts.items[k]].count;
    auto& e = edges[m.face_edge_ids[k]];
    if (e.count == 1) {
      partner[x] = e.first;
      partner[static_cast<size_t>(e.first)] = static_cast<int32_t>(x);
    }
    e.first = e.count == 0 ? static_cast<int32_t>(x) : e.first;
    closed = closed && ++e.count <= 2;
  }
  for (size_t i = 0; i < edges.size() && closed; ++i) closed = edges.at(i).count == 2;
  if (closed) return;
  // The lowest edge not in exactly two faces, as a message names it.
  const detail::SmallTable::Entry* bad = nullptr;
  for (size_t i = 0; i < edges.size(); ++i)
    if (edges.at(i).count != 2 && (!bad || edges.at(i).key < bad->key)) bad = &edges.at(i);
  const auto ev = m.edge_verts[static_cast<size_t>(bad->key)];
  throw InputError(in.source, in.loc_of(in.cell_loc, c),
                   "a closed cell (each edge in exactly 2 of its faces), cell " + std::to_string(c) + " has edge (" +
                       std::to_string(ev[0]) + " " + std::to_string(ev[1]) + ") in " + std::to_string(bad->count) + kSkipInvalidHint);
}

bool CellCorners::orient(const Mesh& m, size_t c) {
  const size_t nfc = face_begin.size() - 1;
  state.assign(nfc, -1);
  state[0] = static_cast<int8_t>(m.cell_face_flip[static_cast<size_t>(m.cell_faces.offsets[c])]);
  queue.assign(1, 0);
  for (size_t q = 0; q < queue.size(); ++q) {
    const auto i = static_cast<size_t>(queue[q]);
    for (int32_t x = face_begin[i]; x < face_begin[i + 1]; ++x) {
      const int32_t y = partner[static_cast<size_t>(x)];
      const auto j = static_cast<size_t>(face_of[static_cast<size_t>(y)]);
      // Same stored direction along the shared edge -> the two faces need opposite flips.
      const bool same = m.face_verts.items[static_cast<size_t>(corner[static_cast<size_t>(x)])] ==
                        m.face_verts.items[static_cast<size_t>(corner[static_cast<size_t>(y)])];
      const auto want = static_cast<int8_t>(state[i] ^ (same ? 1 : 0));
      if (state[j] < 0) {
        state[j] = want;
        queue.push_back(static_cast<int32_t>(j));
      } else if (state[j] != want) {
        return false;
      }
    }
  }
  return queue.size() == nfc;
}

// Signed volume (x6) of cell c with its faces seen as `state` says (fans around each face's first
// vertex, relative to the cell's first vertex for precision).
template <class Flips>
double signed_volume(const Mesh& m, size_t c, const Flips& state) {
  auto faces = m.cell_faces[c];
  const double* o = &m.points[3 * static_cast<size_t>(m.face_verts[static_cast<size_t>(faces[0])][0])];
  double vol = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    auto loop = m.face_verts[static_cast<size_t>(faces[i])];
    const size_t L = loop.size();
    auto pt = [&](size_t idx, double* out) {
      const size_t v = static_cast<size_t>(loop[state[i] && idx > 0 ? L - idx : idx]);  // no modulo: a division
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
  return vol;
}

// The cell's type from its face sizes and vertices; marks the vertices it meets in fewer than 3
// of its faces as non-manifold (the cell is flat or folded there; docs/concepts.md).
CellType classify(Mesh& m, const CellCorners& cc) {
  int tris = 0, quads = 0;
  const size_t nfc = cc.face_begin.size() - 1;
  for (size_t i = 0; i < nfc; ++i) {
    const int32_t n = cc.face_begin[i + 1] - cc.face_begin[i];
    tris += n == 3;
    quads += n == 4;
  }
  const size_t nvc = cc.verts.size();
  bool three_each = true;
  for (size_t i = 0; i < nvc; ++i) {
    const auto& v = cc.verts.at(i);
    three_each = three_each && v.count == 3;
    // Cells of several ranges may mark the same vertex: the same value, stored atomically.
    if (v.count < 3) ::hbc::detail::atomic_ref<uint8_t>(m.vert_non_manifold[static_cast<size_t>(v.key)]).store(1, std::memory_order_relaxed);
  }
  const size_t nec = cc.corner.size() / 2;
  if (nfc == 6 && quads == 6 && nvc == 8 && nec == 12 && three_each) return CellType::Hex;
  if (nfc == 4 && tris == 4 && nvc == 4) return CellType::Tet;
  if (nfc == 5 && tris == 2 && quads == 3 && nvc == 6 && three_each) return CellType::Prism;
  if (nfc == 5 && tris == 4 && quads == 1 && nvc == 5) return CellType::Pyramid;
  return CellType::Polyhedron;
}

}  // namespace

namespace {

// Vertices of a polyhedral cell whose faces there form more than one cycle around the vertex (the
// cell pinched there, as two cones meeting at their apex): found by joining, per vertex, the two
// edges of each face at it. Appends them to `out`.
void pinched_vertices(const Mesh& m, const CellCorners& cc, std::vector<int32_t>& out) {
  for (size_t i = 0; i < cc.verts.size(); ++i) {
    const auto& v = cc.verts.at(i);
    if (v.count < 4) continue;  // 3 faces around a vertex make one cycle
    std::vector<std::array<int32_t, 2>> links;  // the edges in and out of v of each face
    for (size_t f = 0; f + 1 < cc.face_begin.size(); ++f)
      for (int32_t x = cc.face_begin[f]; x < cc.face_begin[f + 1]; ++x) {
        if (m.face_verts.items[static_cast<size_t>(cc.corner[static_cast<size_t>(x)])] != v.key) continue;
        const int32_t prev = x == cc.face_begin[f] ? cc.face_begin[f + 1] - 1 : x - 1;
        links.push_back({m.face_edge_ids[static_cast<size_t>(cc.corner[static_cast<size_t>(prev)])],
                         m.face_edge_ids[static_cast<size_t>(cc.corner[static_cast<size_t>(x)])]});
      }
    // The links form disjoint cycles over the edges at v; one cycle reaches every link.
    std::vector<uint8_t> used(links.size(), 0);
    int32_t at = links[0][1];
    used[0] = 1;
    for (size_t step = 1; step < links.size(); ++step) {
      size_t next = links.size();
      for (size_t j = 0; j < links.size() && next == links.size(); ++j)
        if (!used[j] && (links[j][0] == at || links[j][1] == at)) next = j;
      if (next == links.size()) break;
      used[next] = 1;
      at = links[next][0] == at ? links[next][1] : links[next][0];
    }
    if (std::find(used.begin(), used.end(), 0) != used.end()) out.push_back(v.key);
  }
}

// True when two of cell c's faces have the same cell on their other side.
bool repeats_a_neighbour(const Mesh& m, size_t c, std::vector<int32_t>& scratch) {
  scratch.clear();
  for (int32_t f : m.cell_faces[c]) {
    const auto fc = m.face_cells[static_cast<size_t>(f)];
    const int32_t d = fc[0] == static_cast<int32_t>(c) ? fc[1] : fc[0];
    if (d < 0) continue;
    if (std::find(scratch.begin(), scratch.end(), d) != scratch.end()) return true;
    scratch.push_back(d);
  }
  return false;
}

constexpr CellType kElementType[5] = {CellType::Polyhedron, CellType::Tet, CellType::Pyramid, CellType::Prism, CellType::Hex};

}  // namespace

CellCheck check_cells(Mesh& m, const MeshInput& in, const Threads& par) {
  const size_t nc = m.num_cells();
  CellCheck out;
  detail::assign_touched(out.volume, nc, 0.0, par);
  m.cell_type.assign(nc, CellType::Polyhedron);
  m.vert_non_manifold.assign(m.num_vertices(), 0);
  const int nr = detail::range_count(nc, par);
  std::vector<std::vector<int32_t>> pinched(static_cast<size_t>(nr));
  std::vector<uint8_t> repeats(static_cast<size_t>(nr), 0);
  detail::parallel_ranges(nc, par, [&](size_t cb, size_t ce, int r) {
    CellCorners cc;
    std::vector<int32_t> scratch;
    // Kept local and stored once: the ranges' flags share a cache line, and a byte store per cell
    // there (a char store, which the compiler cannot keep in a register) had the cores contend for it.
    bool repeat = false;
    for (size_t c = cb; c < ce; ++c) {
      repeat = repeats_a_neighbour(m, c, scratch) || repeat;
      const auto flips = std::span<const uint8_t>(m.cell_face_flip).subspan(static_cast<size_t>(m.cell_faces.offsets[c]), m.cell_faces.count(c));
      if (in.shape(c) != CellShape::Faces) {
        // An element with distinct corners is its template: closed, its loops agreeing as the
        // face merging set them, each corner in 3 faces (a pyramid's apex in 4).
        m.cell_type[c] = kElementType[static_cast<int>(in.shape(c))];
        out.volume[c] = signed_volume(m, c, flips);
        continue;
      }
      cc.gather(m, in, c);
      m.cell_type[c] = classify(m, cc);
      if (m.cell_type[c] == CellType::Polyhedron) pinched_vertices(m, cc, pinched[static_cast<size_t>(r)]);
      if (!cc.orient(m, c)) continue;
      out.volume[c] = signed_volume(m, c, cc.state);
      const auto begin = static_cast<size_t>(m.cell_faces.offsets[c]);
      for (size_t i = 0; i < cc.state.size(); ++i) m.cell_face_flip[begin + i] = static_cast<uint8_t>(cc.state[i]);
    }
    repeats[static_cast<size_t>(r)] = repeat ? 1 : 0;
  });
  for (const auto& p : pinched) out.pinched.insert(out.pinched.end(), p.begin(), p.end());
  out.faces_shared_twice = std::find(repeats.begin(), repeats.end(), 1) != repeats.end();
  return out;
}

namespace {

// Whether every cell has a positive volume and every pair of neighbours sees their shared face in
// opposite directions: then no cell or group needs turning (most files, written by meshers that
// orient their cells). Checked in parallel, as the walk below cannot be.
bool oriented_already(const Mesh& m, const std::vector<double>& cell_vol, const Threads& par) {
  const int nr = detail::range_count(m.num_cells(), par);
  std::vector<uint8_t> ok(static_cast<size_t>(nr), 1);
  detail::parallel_ranges(m.num_cells(), par, [&](size_t cb, size_t ce, int r) {
    for (size_t c = cb; c < ce && ok[static_cast<size_t>(r)]; ++c) {
      if (!(cell_vol[c] > 0)) ok[static_cast<size_t>(r)] = 0;
      for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) {
        const int32_t f = m.cell_faces.items[static_cast<size_t>(i)];
        const auto fc = m.face_cells[static_cast<size_t>(f)];
        const int32_t d = fc[0] == static_cast<int32_t>(c) ? fc[1] : fc[0];
        if (d < static_cast<int32_t>(c)) continue;  // each shared face once; none on the boundary
        const auto df = m.cell_faces[static_cast<size_t>(d)];
        const auto j = static_cast<size_t>(m.cell_faces.offsets[static_cast<size_t>(d)] + (std::find(df.begin(), df.end(), f) - df.begin()));
        if (m.cell_face_flip[static_cast<size_t>(i)] == m.cell_face_flip[j]) ok[static_cast<size_t>(r)] = 0;
      }
    }
  });
  return std::find(ok.begin(), ok.end(), 0) == ok.end();
}

}  // namespace

void orient_groups(Mesh& m, std::vector<double>& cell_vol, const Threads& par) {
  if (oriented_already(m, cell_vol, par)) return;
  const size_t nc = m.num_cells();
  auto flip_of = [&](size_t c, int32_t f) -> uint8_t& {
    auto faces = m.cell_faces[c];
    return m.cell_face_flip[static_cast<size_t>(m.cell_faces.offsets[c] + (std::find(faces.begin(), faces.end(), f) - faces.begin()))];
  };
  auto turn = [&](size_t c) {
    for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) m.cell_face_flip[static_cast<size_t>(i)] ^= 1;
    cell_vol[c] = -cell_vol[c];
  };
  std::vector<uint8_t> seen(nc, 0);
  std::vector<int32_t> group;
  for (size_t c0 = 0; c0 < nc; ++c0) {
    if (seen[c0]) continue;
    seen[c0] = 1;
    group.assign(1, static_cast<int32_t>(c0));
    for (size_t q = 0; q < group.size(); ++q) {
      const auto c = static_cast<size_t>(group[q]);
      for (int32_t f : m.cell_faces[c]) {
        const auto fc = m.face_cells[static_cast<size_t>(f)];
        const int32_t d = fc[0] == static_cast<int32_t>(c) ? fc[1] : fc[0];
        if (d < 0 || seen[static_cast<size_t>(d)]) continue;
        seen[static_cast<size_t>(d)] = 1;
        if (flip_of(static_cast<size_t>(d), f) == flip_of(c, f)) turn(static_cast<size_t>(d));
        group.push_back(d);
      }
    }
    double vol = 0;
    for (int32_t c : group) vol += cell_vol[static_cast<size_t>(c)];
    if (vol < 0)
      for (int32_t c : group) turn(static_cast<size_t>(c));
  }
}

}  // namespace hbc::mesh_steps
