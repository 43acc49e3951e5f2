// Orientation step of build_mesh (see hbc/mesh_steps.hpp): files disagree on how cells see their
// faces (some list every face the same way round). Orienting cell by cell by the sign of its own
// volume would turn inverted (tangled) cells against their neighbours; making neighbours agree
// and fixing the sign per face-connected group keeps their negative volume.
#include <algorithm>

#include "hbc/mesh_steps.hpp"
#include "parallel.hpp"

namespace hbc::mesh_steps {
namespace {

// Flips making the loops of cell c agree with each other (state[i] for its i-th face), found by
// a walk over the faces through their shared edges; false when they cannot agree. face_state
// (by face id, all -1) is scratch and is left all -1.
bool orient_within(const Mesh& m, size_t c, const std::vector<int32_t>& partner,
                   const std::vector<int32_t>& slot_face, std::vector<int8_t>& face_state,
                   std::vector<int32_t>& queue, std::vector<int8_t>& state) {
  auto faces = m.cell_faces[c];
  face_state[faces[0]] = static_cast<int8_t>(m.cell_face_flip[m.cell_faces.offsets[c]]);
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
  state.resize(faces.size());
  bool complete = orientable;
  for (size_t i = 0; i < faces.size(); ++i) {
    state[i] = face_state[faces[i]];
    complete = complete && state[i] >= 0;
    face_state[faces[i]] = -1;
  }
  return complete;
}

// Signed volume of cell c with its faces seen as `state` says (fans around each face's first
// vertex, relative to the cell's first vertex for precision).
double signed_volume(const Mesh& m, size_t c, const std::vector<int8_t>& state) {
  auto faces = m.cell_faces[c];
  const double* o = &m.points[3 * static_cast<size_t>(m.face_verts[faces[0]][0])];
  double vol = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
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
  return vol;
}

// Makes face-neighbouring cells see their shared face in opposite directions and turns each
// face-connected group to a positive total volume.
void orient_groups(Mesh& m, std::vector<double>& cell_vol) {
  const size_t nc = m.num_cells();
  auto flip_of = [&](size_t c, int32_t f) -> uint8_t& {
    auto faces = m.cell_faces[c];
    return m.cell_face_flip[m.cell_faces.offsets[c] + (std::find(faces.begin(), faces.end(), f) - faces.begin())];
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

void orient_cells(Mesh& m, const std::vector<int32_t>& partner, const std::vector<int32_t>& slot_face,
                  const LoadOptions& par) {
  std::vector<double> cell_vol(m.num_cells(), 0.0);
  detail::parallel_ranges(m.num_cells(), par, [&](size_t cb, size_t ce, int) {
    std::vector<int8_t> face_state(m.num_faces(), -1), state;
    std::vector<int32_t> queue;
    for (size_t c = cb; c < ce; ++c) {
      if (!orient_within(m, c, partner, slot_face, face_state, queue, state)) continue;
      cell_vol[c] = signed_volume(m, c, state);
      const int32_t begin = m.cell_faces.offsets[c];
      for (size_t i = 0; i < state.size(); ++i) m.cell_face_flip[begin + static_cast<int32_t>(i)] = static_cast<uint8_t>(state[i]);
    }
  });
  orient_groups(m, cell_vol);
}

}  // namespace hbc::mesh_steps
