// Robust Hex-Dominant Meshing .HYBRID: "nv nf 3*nc", vertices, faces "n v0..", then per cell a
// line "n f0.." and a line "n o0.." of face orientation flags, then nc lines with one cell
// orientation flag each (1: the normals are to be flipped). All ids are 0-based.
#include "hbc/io.hpp"
#include "io/detail/text_scanner.hpp"

namespace hbc {

MeshInput read_hybrid(std::string_view text, const std::string& source) {
  detail::TextScanner s(text, source, false);
  MeshInput in;
  in.source = source;
  const int64_t nv = s.count(6, "the number of vertices");
  const int64_t nf = s.count(8, "the number of faces");
  const int64_t n3 = s.count(2, "three times the number of cells");
  if (n3 % 3 != 0) s.fail("a multiple of 3 as the third header number (3 lines per cell), found " + std::to_string(n3));
  const int64_t nc = n3 / 3;
  detail::read_points(s, nv, in);
  detail::read_face_loops(s, nf, nv, 0, in);
  for (int64_t c = 0; c < nc; ++c) {
    in.cell_loc.push_back(s.next_line());
    const int64_t n = s.integer_in(0, 1 << 20, "the number of faces of a cell");  // fewer: build_mesh says why, hbc check lists them
    const size_t first = in.cells.items.size();
    for (int64_t k = 0; k < n; ++k)
      in.cells.items.push_back(static_cast<int32_t>(2 * s.integer_in(0, nf - 1, "a face index (0-based)")));
    const int64_t m = s.integer("the number of face orientation flags");
    if (m != n) s.fail("as many face orientation flags as faces (" + std::to_string(n) + "), found " + std::to_string(m));
    for (int64_t k = 0; k < n; ++k)
      in.cells.items[first + static_cast<size_t>(k)] |= static_cast<int32_t>(s.integer_in(0, 1, "a face orientation flag (0 or 1)"));
    in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
  }
  for (int64_t c = 0; c < nc; ++c) {
    if (s.integer_in(0, 1, "a cell orientation flag (0 or 1)") == 1)
      for (auto& r : in.cells.row(static_cast<size_t>(c))) r ^= 1;
  }
  std::string_view extra;
  if (s.next(extra)) s.fail("the end of the file after the cell orientation flags, found more data");
  return in;
}

}  // namespace hbc
