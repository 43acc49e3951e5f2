// LoopyCuts / cinolib .hedra: "nv nf nc", vertices, faces "n v1..vn" (1-based), cells
// "n f1..fn" with 1-based signed face ids (a negative id: the cell sees the face reversed).
#include "hbc/io.hpp"
#include "io/detail/text_scanner.hpp"

namespace hbc {

MeshInput read_hedra(std::string_view text, const std::string& source) {
  detail::TextScanner s(text, source, false);
  MeshInput in;
  in.source = source;
  const int64_t nv = s.count(6, "the number of vertices");
  const int64_t nf = s.count(8, "the number of faces");
  const int64_t nc = s.count(4, "the number of cells");
  detail::read_points(s, nv, in);
  detail::read_face_loops(s, nf, nv, 1, in);
  for (int64_t c = 0; c < nc; ++c) {
    in.cell_loc.push_back(s.next_line());
    const int64_t n = s.integer_in(0, 1 << 20, "the number of faces of a cell");  // fewer: build_mesh says why, hbc check lists them
    for (int64_t k = 0; k < n; ++k) {
      const int64_t id = s.integer_in(-nf, nf, "a signed face index (1-based)");
      if (id == 0) s.fail("a signed face index (1-based, never 0), found 0");
      const int64_t f = (id < 0 ? -id : id) - 1;
      in.cells.items.push_back(static_cast<int32_t>(2 * f + (id < 0 ? 1 : 0)));
    }
    in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
  }
  std::string_view extra;
  if (s.next(extra)) s.fail("the end of the file after " + std::to_string(nc) + " cells, found more data");
  return in;
}

}  // namespace hbc
