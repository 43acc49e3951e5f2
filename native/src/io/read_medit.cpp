// MEDIT .mesh (INRIA): keyword sections in any order, counts on the same or the next line,
// 1-based vertex ids, a reference number after each entry. Degenerate hexahedra (repeated ids,
// as At-Most-Hexa writes prisms, pyramids and tets) become the polyhedron they stand for.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cctype>

#include "hbc/io.hpp"
#include "mesh/cell_templates.hpp"
#include "io/detail/line_table.hpp"
#include "platform/huge_pages.hpp"
#include "parallel/parallel.hpp"
#include "io/detail/text_scanner.hpp"

namespace hbc {
namespace {

using detail::Element;

// The element kind of a section keyword, or nullptr.
const Element* element_of(const std::string& kw) {
  static constexpr Element kTet = Element::Tet, kPyramid = Element::Pyramid, kPrism = Element::Prism,
                           kHex = Element::Hex;
  if (kw == "tetrahedra") return &kTet;
  if (kw == "pyramids") return &kPyramid;
  if (kw == "prisms") return &kPrism;
  if (kw == "hexahedra") return &kHex;
  return nullptr;
}

bool looks_like_keyword(std::string_view t) {
  return !t.empty() && std::isalpha(static_cast<unsigned char>(t[0]));
}

// Elements as read, validated once the vertex count is known (sections come in any order).
struct RawElements {
  std::vector<Element> el;
  std::vector<int64_t> line;
  std::vector<int32_t> ids;                // 1-based as in the file; 0 stands for anything outside int32
  int64_t wide_line = -1, wide_value = 0;  // the first id too large for int32, for the message
};

void read_vertices(detail::TextScanner& s, int64_t nv, MeshInput& in, const Threads& par) {
  detail::reserve_huge(in.points, static_cast<size_t>(3 * nv));
  detail::reserve_huge(in.vertex_loc, static_cast<size_t>(nv));
  if (detail::fast_vertex_lines(s, nv, in.points, in.vertex_loc, par)) return;
  for (int64_t i = 0; i < nv; ++i) {
    const int64_t l = s.next_line();
    for (int k = 0; k < 3; ++k) in.points.push_back(s.real("a vertex coordinate"));
    s.integer("a vertex reference number");
    in.vertex_loc.push_back(l);
  }
}

void read_elements(detail::TextScanner& s, Element el, int64_t n, RawElements& raw, const Threads& par) {
  const int nverts = detail::corner_count(el);
  raw.el.resize(raw.el.size() + static_cast<size_t>(n), el);
  detail::reserve_huge(raw.line, raw.line.size() + static_cast<size_t>(n));
  detail::reserve_huge(raw.ids, raw.ids.size() + static_cast<size_t>(n * nverts));
  if (detail::fast_element_lines(s, n, nverts, raw.ids, raw.line, par)) return;
  for (int64_t i = 0; i < n; ++i) {
    raw.line.push_back(s.next_line());
    for (int k = 0; k < nverts; ++k) {
      const int64_t id = s.integer("a vertex index");
      const bool fits = id >= 1 && id <= INT32_MAX;
      if (!fits && raw.wide_line < 0) {
        raw.wide_line = raw.line.back();
        raw.wide_value = id;
      }
      raw.ids.push_back(fits ? static_cast<int32_t>(id) : 0);
    }
    s.integer("an element reference number");
  }
}

// Cells from the elements read, once the vertex count nv is known, through the templates shared
// with the other element-list readers (degenerate hexahedra included).
void cells_through_templates(const RawElements& raw, int64_t nv, const detail::TextScanner& s, MeshInput& in) {
  in.cells.reserve(raw.el.size(), raw.ids.size());
  in.cell_shape.reserve(raw.el.size());
  in.cell_loc.reserve(raw.el.size());
  detail::CellAppender cells(in);
  size_t next_id = 0;
  for (size_t e = 0; e < raw.el.size(); ++e) {
    const int64_t line = raw.line[e];
    std::array<int32_t, 8> v{};
    for (int k = 0; k < detail::corner_count(raw.el[e]); ++k) {
      const int64_t id = raw.ids[next_id++];
      if (id < 1 || id > nv) {
        const int64_t shown = (id == 0 && line == raw.wide_line) ? raw.wide_value : id;
        s.fail_at(line, "a vertex index in [1, " + std::to_string(nv) + "], found " + std::to_string(shown));
      }
      v[k] = static_cast<int32_t>(id - 1);
    }
    cells.element(raw.el[e], v.data(), line);
  }
}

// The common case, in parallel and without copies: every element's corners in range and
// distinct, so the ids (made 0-based) are the cells' rows as they stand. False, touching nothing,
// when some element is out of range or degenerate (the template path then reads them in order).
bool cells_as_read(RawElements& raw, int64_t nv, MeshInput& in, const Threads& par) {
  const size_t n = raw.el.size();
  if (raw.ids.size() > static_cast<size_t>(INT32_MAX)) return false;  // validate_input names the limit
  // The first id of each element in raw.ids: the cells' offsets if all is well.
  std::vector<int32_t> first;
  detail::resize_touched(first, n + 1, par);
  first[0] = 0;
  for (size_t e = 0; e < n; ++e) first[e + 1] = first[e] + detail::corner_count(raw.el[e]);
  const int nr = detail::range_count(n, par);
  std::vector<uint8_t> plain(static_cast<size_t>(nr), 1);
  detail::parallel_ranges(n, par, [&](size_t b, size_t e, int r) {
    for (size_t i = b; i < e && plain[static_cast<size_t>(r)]; ++i) {
      const int32_t* v = raw.ids.data() + first[i];
      const int k = detail::corner_count(raw.el[i]);
      for (int a = 0; a < k; ++a) {
        bool ok = v[a] >= 1 && v[a] <= nv;
        for (int c = 0; c < a; ++c) ok = ok && v[c] != v[a];
        if (!ok) plain[static_cast<size_t>(r)] = 0;
      }
    }
  });
  if (std::find(plain.begin(), plain.end(), 0) != plain.end()) return false;
  detail::parallel_ranges(raw.ids.size(), par, [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i) --raw.ids[i];
  });
  in.cells.offsets = std::move(first);
  in.cells.items = std::move(raw.ids);
  in.cell_shape = std::move(raw.el);
  in.cell_loc = std::move(raw.line);
  return true;
}

}  // namespace

MeshInput read_medit(std::string_view text, const std::string& source, const Threads& threads) {
  const detail::RunOptions run(threads);
  const Threads& par = run.get();
  detail::TextScanner s(text, source, true);
  MeshInput in;
  in.source = source;
  int64_t nv = -1;
  RawElements raw;
  bool seen_version = false;
  std::string_view tok;
  bool have_tok = s.next(tok);
  while (have_tok) {
    if (!looks_like_keyword(tok)) s.fail("a MEDIT keyword, found '" + std::string(tok.substr(0, 40)) + "'");
    const std::string kw = detail::lower(tok);
    if (kw == "meshversionformatted") {
      s.integer_in(1, 4, "the MEDIT version");
      seen_version = true;
    } else if (kw == "dimension") {
      s.integer_in(3, 3, "dimension 3");
    } else if (kw == "vertices") {
      if (nv >= 0) s.fail("one Vertices section, found a second");
      nv = s.count(8, "the number of vertices");
      read_vertices(s, nv, in, par);
    } else if (const Element* el = element_of(kw)) {
      const int64_t n = s.count(2 * (detail::corner_count(*el) + 1), (std::string("the number of ") + kw).c_str());
      read_elements(s, *el, n, raw, par);
    } else if (kw == "end") {
      break;
    } else {
      // Surface elements and other data are read past: everything up to the next keyword.
      have_tok = s.next_word(tok);
      continue;
    }
    have_tok = s.next(tok);
  }
  if (!seen_version && text.size() > 0 && nv < 0) s.fail("a MEDIT file (MeshVersionFormatted, Vertices, ...)");
  if (nv < 0) s.fail("a Vertices section");
  if (raw.el.empty()) s.fail("at least one volume element (Tetrahedra, Pyramids, Prisms or Hexahedra)");
  if (!cells_as_read(raw, nv, in, par)) cells_through_templates(raw, nv, s, in);
  return in;
}

}  // namespace hbc
