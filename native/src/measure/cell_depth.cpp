#include "hbc/cell_depth.hpp"

#include <algorithm>

namespace hbc {

std::vector<int32_t> cell_depth(const Mesh& mesh) {
  const size_t nc = mesh.num_cells();
  std::vector<int32_t> depth(nc, -1), queue;
  queue.reserve(nc);
  for (size_t c = 0; c < nc; ++c) {
    const auto faces = mesh.cell_faces[c];
    const bool touches = std::any_of(faces.begin(), faces.end(), [&](int32_t f) {
      const auto loop = mesh.face_verts[static_cast<size_t>(f)];
      return std::any_of(loop.begin(), loop.end(), [&](int32_t v) { return mesh.vert_boundary[static_cast<size_t>(v)] != 0; });
    });
    if (!touches) continue;
    depth[c] = 0;
    queue.push_back(static_cast<int32_t>(c));
  }
  for (size_t q = 0; q < queue.size(); ++q) {
    const int32_t c = queue[q];
    for (int32_t f : mesh.cell_faces[static_cast<size_t>(c)]) {
      const auto [a, b] = mesh.face_cells[static_cast<size_t>(f)];
      const int32_t d = a == c ? b : a;
      if (d < 0 || depth[static_cast<size_t>(d)] >= 0) continue;
      depth[static_cast<size_t>(d)] = depth[static_cast<size_t>(c)] + 1;
      queue.push_back(d);
    }
  }
  return depth;
}

}  // namespace hbc
