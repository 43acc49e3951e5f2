#include "io/detail/face_cells.hpp"

#include <vector>

namespace hbc::detail {

Csr<int32_t> cells_from_sides(std::span<const int32_t> written, std::span<const int32_t> reversed, int32_t nc,
                              int32_t& empty) {
  Csr<int32_t> cells;
  cells.offsets.assign(static_cast<size_t>(nc) + 1, 0);
  for (int32_t c : written)
    if (c >= 0) ++cells.offsets[static_cast<size_t>(c) + 1];
  for (int32_t c : reversed)
    if (c >= 0) ++cells.offsets[static_cast<size_t>(c) + 1];
  empty = -1;
  for (size_t c = 0; c < static_cast<size_t>(nc); ++c) {
    if (cells.offsets[c + 1] == 0 && empty < 0) empty = static_cast<int32_t>(c);
    cells.offsets[c + 1] += cells.offsets[c];
  }
  cells.items.resize(static_cast<size_t>(cells.offsets.back()));
  std::vector<int32_t> fill(cells.offsets.begin(), cells.offsets.end() - 1);
  for (size_t f = 0; f < written.size(); ++f) {
    if (written[f] >= 0) cells.items[static_cast<size_t>(fill[static_cast<size_t>(written[f])]++)] = static_cast<int32_t>(2 * f);
    if (f < reversed.size() && reversed[f] >= 0)
      cells.items[static_cast<size_t>(fill[static_cast<size_t>(reversed[f])]++)] = static_cast<int32_t>(2 * f + 1);
  }
  return cells;
}

}  // namespace hbc::detail
