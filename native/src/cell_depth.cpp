#include "hbc/cell_depth.hpp"

namespace hbc {

std::vector<int32_t> cell_depth(const Mesh& mesh) {
  const size_t nc = mesh.num_cells();
  std::vector<int32_t> depth(nc, -1), queue;
  queue.reserve(nc);
  for (size_t c = 0; c < nc; ++c) {
    for (int32_t v : mesh.cell_verts[c]) {
      if (!mesh.vert_boundary[static_cast<size_t>(v)]) continue;
      depth[c] = 0;
      queue.push_back(static_cast<int32_t>(c));
      break;
    }
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
