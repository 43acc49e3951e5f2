// MEDIT .mesh (INRIA): keyword sections in any order, counts on the same or the next line,
// 1-based vertex ids, a reference number after each entry. Degenerate hexahedra (repeated ids,
// as At-Most-Hexa writes prisms, pyramids and tets) become the polyhedron they stand for.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cctype>

#include "hbc/io.hpp"
#include "cell_templates.hpp"
#include "text_scanner.hpp"

namespace hbc {
namespace {

using detail::Element;

const Element kTet = Element::Tet, kPyramid = Element::Pyramid, kPrism = Element::Prism, kHex = Element::Hex;

const Element* element_of(const std::string& kw) {
  if (kw == "tetrahedra") return &kTet;
  if (kw == "pyramids") return &kPyramid;
  if (kw == "prisms") return &kPrism;
  if (kw == "hexahedra") return &kHex;
  return nullptr;
}

bool looks_like_keyword(std::string_view t) {
  return !t.empty() && std::isalpha(static_cast<unsigned char>(t[0]));
}

}  // namespace

MeshInput read_medit(std::string_view text, const std::string& source) {
  detail::TextScanner s(text, source, true);
  MeshInput in;
  in.source = source;
  int64_t nv = -1;
  // Elements as read, validated once the vertex count is known (sections come in any order).
  std::vector<const Element*> raw_el;
  std::vector<int64_t> raw_line;
  std::vector<int32_t> raw_ids;  // 1-based as in the file; 0 stands for anything outside int32
  int64_t wide_line = -1, wide_value = 0;  // the first id too large for int32, for the message
  bool seen_version = false, seen_end = false;
  std::string_view tok;
  bool have_tok = s.next(tok);
  while (have_tok) {
    if (!looks_like_keyword(tok)) s.fail("a MEDIT keyword, found '" + std::string(tok.substr(0, 40)) + "'");
    const std::string kw = detail::lower(tok);
    const int64_t kw_line = s.line();
    if (kw == "meshversionformatted") {
      s.integer_in(1, 4, "the MEDIT version");
      seen_version = true;
    } else if (kw == "dimension") {
      s.integer_in(3, 3, "dimension 3");
    } else if (kw == "vertices") {
      if (nv >= 0) s.fail("one Vertices section, found a second");
      nv = s.count(8, "the number of vertices");
      in.points.reserve(static_cast<size_t>(3 * nv));
      in.vertex_loc.reserve(static_cast<size_t>(nv));
      for (int64_t i = 0; i < nv; ++i) {
        const int64_t l = s.next_line();
        for (int k = 0; k < 3; ++k) in.points.push_back(s.real("a vertex coordinate"));
        s.integer("a vertex reference number");
        in.vertex_loc.push_back(l);
      }
    } else if (const Element* el = element_of(kw)) {
      const int64_t n = s.count(2 * (detail::corner_count(*el) + 1), (std::string("the number of ") + kw).c_str());
      raw_el.reserve(raw_el.size() + static_cast<size_t>(n));
      raw_line.reserve(raw_line.size() + static_cast<size_t>(n));
      raw_ids.reserve(raw_ids.size() + static_cast<size_t>(n * detail::corner_count(*el)));
      for (int64_t i = 0; i < n; ++i) {
        raw_el.push_back(el);
        raw_line.push_back(s.next_line());
        for (int k = 0; k < detail::corner_count(*el); ++k) {
          const int64_t id = s.integer("a vertex index");
          const bool fits = id >= 1 && id <= INT32_MAX;
          if (!fits && wide_line < 0) {
            wide_line = raw_line.back();
            wide_value = id;
          }
          raw_ids.push_back(fits ? static_cast<int32_t>(id) : 0);
        }
        s.integer("an element reference number");
      }
    } else if (kw == "end") {
      seen_end = true;
      break;
    } else {
      // Surface elements and other data are read past: everything up to the next keyword.
      while ((have_tok = s.next(tok)) && !looks_like_keyword(tok)) {
      }
      continue;
    }
    (void)kw_line;
    have_tok = s.next(tok);
  }
  (void)seen_end;
  if (!seen_version && text.size() > 0 && nv < 0) s.fail("a MEDIT file (MeshVersionFormatted, Vertices, ...)");
  if (nv < 0) s.fail("a Vertices section");
  if (raw_el.empty()) s.fail("at least one volume element (Tetrahedra, Pyramids, Prisms or Hexahedra)");

  // Cells: every element through the shared templates (degenerate hexahedra included).
  in.faces.offsets.reserve(raw_el.size() * 6 + 1);
  in.faces.items.reserve(raw_ids.size() * 3);
  in.cells.offsets.reserve(raw_el.size() + 1);
  in.cells.items.reserve(raw_el.size() * 6);
  in.cell_loc.reserve(raw_el.size());
  detail::CellAppender cells(in);
  size_t next_id = 0;
  for (size_t e = 0; e < raw_el.size(); ++e) {
    const int64_t line = raw_line[e];
    std::array<int32_t, 8> v{};
    for (int k = 0; k < detail::corner_count(*raw_el[e]); ++k) {
      const int64_t id = raw_ids[next_id++];
      if (id < 1 || id > nv) {
        const int64_t shown = (id == 0 && line == wide_line) ? wide_value : id;
        s.fail_at(line, "a vertex index in [1, " + std::to_string(nv) + "], found " + std::to_string(shown));
      }
      v[k] = static_cast<int32_t>(id - 1);
    }
    cells.element(*raw_el[e], v.data(), line);
  }
  return in;
}

}  // namespace hbc
