// MEDIT .mesh writer: Hexahedra, Tetrahedra, Prisms and Pyramids in MEDIT's vertex order, which
// is rebuilt from each cell's faces. The order matches the face templates of mesh/cell_templates
// (hex bottom 0 3 2 1 and top 4 5 6 7, tet 0 2 1 + apex 3, prism 0 2 1 / 3 4 5, pyramid base
// 0 3 2 1 + apex 4), so reading the text back gives every cell the same faces. The element's
// handedness follows the cell's view of the face used as its base: a cell whose faces are seen
// consistently (each edge run once each way) comes back with every face seen the same way round;
// files that carry no orientation (test_2.HYBRID, teapot.hedra) give elements of either
// handedness. MEDIT has no general polyhedra: such a cell is a std::invalid_argument.
#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>

#include "hbc/io.hpp"
#include "io/detail/text_writer.hpp"

namespace hbc {
namespace {

using detail::append_int;
using detail::append_real;

// Vertices of one cell in MEDIT order, up to 8.
struct Element {
  std::array<int32_t, 8> v{};
  int n = 0;
};

class ElementBuilder {
 public:
  explicit ElementBuilder(const Mesh& m) : m_(m) {}

  Element build(size_t c) const {
    Element el;
    switch (m_.cell_type[c]) {
      case CellType::Hex: {
        // Bottom: the first face, seen by the cell as MEDIT's 0 3 2 1; the top vertex above
        // each bottom vertex is its neighbor along the one cell edge leaving the bottom.
        const auto b = seen_loop(first_face_with(c, 4));
        el = {{b[0], b[3], b[2], b[1]}, 8};
        for (int k = 0; k < 4; ++k) el.v[4 + k] = up(c, el.v[k], el.v.data(), 4);
        break;
      }
      case CellType::Tet: {
        const auto b = seen_loop(first_face_with(c, 3));
        el = {{b[0], b[2], b[1]}, 4};
        el.v[3] = apex(c, el.v.data(), 3);
        break;
      }
      case CellType::Prism: {
        const auto b = seen_loop(first_face_with(c, 3));
        el = {{b[0], b[2], b[1]}, 6};
        for (int k = 0; k < 3; ++k) el.v[3 + k] = up(c, el.v[k], el.v.data(), 3);
        break;
      }
      case CellType::Pyramid: {
        const auto b = seen_loop(first_face_with(c, 4));
        el = {{b[0], b[3], b[2], b[1]}, 5};
        el.v[4] = apex(c, el.v.data(), 4);
        break;
      }
      case CellType::Polyhedron:
        throw std::invalid_argument("MEDIT cannot store cell " + std::to_string(c) + " of " + m_.source +
                                    ", a general polyhedron with " + std::to_string(m_.cell_faces.count(c)) +
                                    " faces (write .ovm instead)");
    }
    return el;
  }

 private:
  // Index into cell_faces.items of the cell's first face with n vertices (the cell type
  // guarantees there is one).
  int32_t first_face_with(size_t c, int32_t n) const {
    for (int32_t i = m_.cell_faces.offsets[c]; i < m_.cell_faces.offsets[c + 1]; ++i)
      if (m_.face_verts.count(m_.cell_faces.items[i]) == n) return i;
    throw std::logic_error("cell type does not match its faces");
  }
  // The face's loop as the cell sees it (reversed when the cell's flip says so), up to 4 ids.
  std::array<int32_t, 4> seen_loop(int32_t slot) const {
    auto loop = m_.face_verts[m_.cell_faces.items[slot]];
    std::array<int32_t, 4> r{};
    const size_t n = loop.size();
    for (size_t k = 0; k < n; ++k) r[k] = m_.cell_face_flip[slot] ? loop[(n - k) % n] : loop[k];
    return r;
  }
  // The neighbor of x along a cell edge whose other end is not among base[0..nb).
  int32_t up(size_t c, int32_t x, const int32_t* base, int nb) const {
    for (int32_t f : m_.cell_faces[c])  // the edges of the cell's faces; the answer is unique
      for (int32_t e : m_.face_edges(static_cast<size_t>(f))) {
        const auto& ev = m_.edge_verts[static_cast<size_t>(e)];
        if (ev[0] != x && ev[1] != x) continue;
        const int32_t y = ev[0] == x ? ev[1] : ev[0];
        if (std::find(base, base + nb, y) == base + nb) return y;
      }
    throw std::logic_error("cell type does not match its edges");
  }
  // The one cell vertex not among base[0..nb).
  int32_t apex(size_t c, const int32_t* base, int nb) const {
    for (int32_t f : m_.cell_faces[c])
      for (int32_t v : m_.face_verts[static_cast<size_t>(f)])
        if (std::find(base, base + nb, v) == base + nb) return v;
    throw std::logic_error("cell type does not match its vertices");
  }

  const Mesh& m_;
};

}  // namespace

std::string medit_text(const Mesh& m) {
  ElementBuilder builder(m);
  // Sections in MEDIT's usual order; cells keep their relative order within a section.
  constexpr std::array<std::pair<CellType, const char*>, 4> kSections{{{CellType::Hex, "Hexahedra"},
                                                                        {CellType::Tet, "Tetrahedra"},
                                                                        {CellType::Prism, "Prisms"},
                                                                        {CellType::Pyramid, "Pyramids"}}};
  // Fail before writing anything when a cell cannot be expressed.
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (m.cell_type[c] == CellType::Polyhedron) builder.build(c);

  std::string out;
  out.reserve(48 * m.num_vertices() + 40 * m.num_cells() + 128);
  out += "MeshVersionFormatted 2\nDimension 3\nVertices\n";
  append_int(out, static_cast<int64_t>(m.num_vertices()));
  out += '\n';
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) {
      append_real(out, m.points[3 * v + k]);
      out += ' ';
    }
    out += "0\n";
  }
  for (const auto& [type, keyword] : kSections) {
    const auto n = std::count(m.cell_type.begin(), m.cell_type.end(), type);
    if (n == 0) continue;
    out += keyword;
    out += '\n';
    append_int(out, n);
    out += '\n';
    for (size_t c = 0; c < m.num_cells(); ++c) {
      if (m.cell_type[c] != type) continue;
      const Element el = builder.build(c);
      for (int k = 0; k < el.n; ++k) {
        append_int(out, el.v[k] + 1);
        out += ' ';
      }
      out += "0\n";
    }
  }
  out += "End\n";
  return out;
}

}  // namespace hbc
