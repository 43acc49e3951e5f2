#include "cell_templates.hpp"

#include <algorithm>

namespace hbc::detail {
namespace {

struct Template {
  int nverts;
  std::vector<std::vector<int>> faces;  // local vertex loops
};

// Loops are outward for elements of positive orientation in MEDIT's convention.
const Template kTemplates[4] = {
    {4, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}},
    {5, {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}},
    {6, {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}},
    {8, {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}},
};

}  // namespace

int corner_count(Element e) { return kTemplates[static_cast<int>(e)].nverts; }

void CellAppender::end_cell(size_t first_face, int64_t loc) {
  for (size_t f = first_face; f < in_.faces.rows(); ++f) in_.cells.items.push_back(static_cast<int32_t>(2 * f));
  in_.cells.offsets.push_back(static_cast<int32_t>(in_.cells.items.size()));
  in_.cell_loc.push_back(loc);
}

void CellAppender::element(Element e, const int32_t* v, int64_t loc) {
  const Template& el = kTemplates[static_cast<int>(e)];
  bool distinct = true;
  for (int k = 1; k < el.nverts && distinct; ++k)
    for (int j = 0; j < k; ++j) distinct = distinct && v[j] != v[k];
  const size_t first_face = in_.faces.rows();
  if (distinct) {
    // The common case: the template as it is.
    for (const auto& tf : el.faces) {
      for (int k : tf) in_.faces.items.push_back(v[k]);
      in_.faces.offsets.push_back(static_cast<int32_t>(in_.faces.items.size()));
    }
    end_cell(first_face, loc);
    return;
  }
  sets_.clear();
  for (const auto& tf : el.faces) {
    loop_.clear();
    for (int k : tf)
      if (std::find(loop_.begin(), loop_.end(), v[k]) == loop_.end()) loop_.push_back(v[k]);
    if (loop_.size() < 3) continue;
    std::array<int32_t, 8> sorted;
    sorted.fill(-1);
    std::copy(loop_.begin(), loop_.end(), sorted.begin());
    for (size_t i = 1; i < loop_.size(); ++i)  // at most 4 ids: insertion sort
      for (size_t j = i; j > 0 && sorted[j - 1] > sorted[j]; --j) std::swap(sorted[j - 1], sorted[j]);
    if (std::find(sets_.begin(), sets_.end(), sorted) != sets_.end()) continue;
    sets_.push_back(sorted);
    in_.faces.push_row(loop_.begin(), loop_.end());
  }
  end_cell(first_face, loc);
}

void CellAppender::polyhedron(const std::vector<int32_t>& face_sizes, const std::vector<int32_t>& ids, int64_t loc) {
  const size_t first_face = in_.faces.rows();
  size_t at = 0;
  for (int32_t n : face_sizes) {
    in_.faces.push_row(ids.begin() + static_cast<std::ptrdiff_t>(at), ids.begin() + static_cast<std::ptrdiff_t>(at + n));
    at += static_cast<size_t>(n);
  }
  end_cell(first_face, loc);
}

void CellAppender::midside(int32_t v) {
  if (midside_.size() <= static_cast<size_t>(v)) midside_.resize(static_cast<size_t>(v) + 1, 0);
  midside_[static_cast<size_t>(v)] = 1;
}

void CellAppender::finish() {
  if (midside_.empty()) return;
  for (int32_t v : in_.faces.items)
    if (static_cast<size_t>(v) < midside_.size()) midside_[static_cast<size_t>(v)] = 0;
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
}

}  // namespace hbc::detail
