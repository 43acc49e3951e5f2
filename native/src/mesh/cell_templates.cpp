#include "mesh/cell_templates.hpp"

#include "parallel/small_table.hpp"

#include <algorithm>

namespace hbc {

namespace detail {

void CellAppender::end_cell(CellShape shape, int64_t loc) {
  in_.cells.offsets.push_back(static_cast<int32_t>(in_.cells.items.size()));
  in_.cell_shape.push_back(shape);
  in_.cell_loc.push_back(loc);
}

void CellAppender::element(Element e, const int32_t* v, int64_t loc) {
  const int n = corner_count(e);
  bool distinct = true;
  for (int k = 1; k < n && distinct; ++k)
    for (int j = 0; j < k; ++j) distinct = distinct && v[j] != v[k];
  if (distinct) {
    // The common case: the corners themselves; the builder reads the faces from the template.
    in_.cells.items.insert(in_.cells.items.end(), v, v + n);
    end_cell(e, loc);
    return;
  }
  const ShapeFaces& sf = shape_faces(e);
  sets_.clear();
  for (int j = 0; j < sf.nfaces; ++j) {
    loop_.clear();
    for (int i = 0; i < sf.size[j]; ++i) {
      const int32_t x = v[sf.corner[j][i]];
      if (std::find(loop_.begin(), loop_.end(), x) == loop_.end()) loop_.push_back(x);
    }
    if (loop_.size() < 3) continue;
    std::array<int32_t, 8> sorted;
    sorted.fill(-1);
    std::copy(loop_.begin(), loop_.end(), sorted.begin());
    sort_small(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(loop_.size()));
    if (std::find(sets_.begin(), sets_.end(), sorted) != sets_.end()) continue;
    sets_.push_back(sorted);
    in_.cells.items.push_back(static_cast<int32_t>(2 * in_.faces.rows()));
    in_.faces.push_row(loop_.begin(), loop_.end());
  }
  end_cell(CellShape::Faces, loc);
}

void CellAppender::polyhedron(const std::vector<int32_t>& face_sizes, const std::vector<int32_t>& ids, int64_t loc) {
  size_t at = 0;
  for (int32_t n : face_sizes) {
    in_.cells.items.push_back(static_cast<int32_t>(2 * in_.faces.rows()));
    in_.faces.push_row(ids.begin() + static_cast<std::ptrdiff_t>(at), ids.begin() + static_cast<std::ptrdiff_t>(at + n));
    at += static_cast<size_t>(n);
  }
  end_cell(CellShape::Faces, loc);
}

void CellAppender::midside(int32_t v) {
  if (midside_.size() <= static_cast<size_t>(v)) midside_.resize(static_cast<size_t>(v) + 1, 0);
  midside_[static_cast<size_t>(v)] = 1;
}

void CellAppender::finish() {
  if (midside_.empty()) return;
  // Every vertex a cell uses is a corner, whatever else named it.
  auto corner = [&](int32_t v) {
    if (static_cast<size_t>(v) < midside_.size()) midside_[static_cast<size_t>(v)] = 0;
  };
  for (int32_t v : in_.faces.items) corner(v);
  for (size_t c = 0; c < in_.cells.rows(); ++c)
    if (in_.shape(c) != CellShape::Faces)
      for (int32_t v : in_.cells[c]) corner(v);
  const size_t nv = in_.points.size() / 3;
  std::vector<int32_t> new_id(nv, -1);
  size_t kept = 0;
  for (size_t v = 0; v < nv; ++v) {
    if (v < midside_.size() && midside_[v]) continue;
    new_id[v] = static_cast<int32_t>(kept);
    for (int k = 0; k < 3; ++k) in_.points[3 * kept + k] = in_.points[3 * v + k];
    if (v < in_.vertex_loc.size()) in_.vertex_loc[kept] = in_.vertex_loc[v];
    ++kept;
  }
  if (kept == nv) return;
  in_.points.resize(3 * kept);
  if (in_.vertex_loc.size() == nv) in_.vertex_loc.resize(kept);
  for (int32_t& v : in_.faces.items) v = new_id[static_cast<size_t>(v)];
  for (size_t c = 0; c < in_.cells.rows(); ++c)
    if (in_.shape(c) != CellShape::Faces)
      for (int32_t& v : in_.cells.row(c)) v = new_id[static_cast<size_t>(v)];
}

}  // namespace detail

MeshInput with_face_soup(MeshInput in) {
  if (in.cell_shape.empty()) return in;
  Csr<int32_t> cells;
  cells.reserve(in.cells.rows(), in.cells.items.size());
  for (size_t c = 0; c < in.cells.rows(); ++c) {
    const auto row = in.cells[c];
    const CellShape s = in.cell_shape[c];
    if (s == CellShape::Faces) {
      cells.push_row(row);
      continue;
    }
    const detail::ShapeFaces& sf = detail::shape_faces(s);
    for (int j = 0; j < sf.nfaces; ++j) {
      cells.items.push_back(static_cast<int32_t>(2 * in.faces.rows()));
      for (int i = 0; i < sf.size[j]; ++i) in.faces.items.push_back(row[sf.corner[j][i]]);
      in.faces.offsets.push_back(static_cast<int32_t>(in.faces.items.size()));
    }
    cells.offsets.push_back(static_cast<int32_t>(cells.items.size()));
  }
  in.cells = std::move(cells);
  in.cell_shape.clear();
  return in;
}

}  // namespace hbc
