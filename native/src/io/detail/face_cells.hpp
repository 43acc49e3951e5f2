#pragma once
// Cells from the two sides of each face, for the face-based formats (OpenFOAM's owner and
// neighbour, Fluent's c1 and c0): each cell lists its faces in face order, 2*f where it sees face
// f's loop as written and 2*f + 1 where it sees it reversed.
#include <cstdint>
#include <span>

#include "hbc/csr.hpp"

namespace hbc::detail {

// `written[f]`, `reversed[f]`: the cell (0-based, below nc) on that side of face f, or -1 for none;
// `reversed` may be shorter than `written` (its missing tail is -1). `empty` is set to the first
// cell with no face, or -1 when every cell has one.
Csr<int32_t> cells_from_sides(std::span<const int32_t> written, std::span<const int32_t> reversed, int32_t nc,
                              int32_t& empty);

}  // namespace hbc::detail
