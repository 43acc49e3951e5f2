// OpenVolumeMesh ASCII (.ovm). Line oriented: a header line "OVM ASCII" (or just "OVM"), then the
// sections Vertices, Edges, Faces, Polyhedra, each a keyword line, a count line and one entity per
// line; blank lines and lines starting with '#' are skipped; keywords are case-insensitive.
//   Edges:     "a b"                      (0-based vertex ids)
//   Faces:     "n h0 .. h(n-1)"           half-edge h = 2*edge + 1 when the edge is run from b to a
//   Polyhedra: "n hf0 .. hf(n-1)"         half-face hf = 2*face + 1 when the cell sees it reversed
// Property blocks may follow: "VProp|EProp|HEProp|FProp|HFProp|CProp|MProp type "name"" and then
// one value line per entity of that kind (one line for MProp). They carry no topology and are
// read past, but their value counts are checked so that a damaged file is not taken as whole.
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/text_scanner.hpp"
#include "platform/charconv.hpp"

namespace hbc {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string shown(std::string_view t) {
  std::string out(1, '\'');  // appended piecewise: GCC 12 warns falsely on "'" + std::string
  out.append(t.substr(0, 40));
  out.append(t.size() > 40 ? "...'" : "'");
  return out;
}

// Walks the data lines of the text and cuts each into tokens (one reused buffer, no per-line
// allocation once it has grown).
class OvmLines {
 public:
  OvmLines(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  // Moves to the next line holding data. With strip_comment a '#' also ends the data on the line
  // (property values, which may be strings, keep theirs). False at the end of the text.
  bool next(bool strip_comment = true) {
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view l = trim(text_.substr(pos_, end - pos_));
      pos_ = end + 1;
      line_ = ++lines_read_;
      if (l.empty() || l.front() == '#') continue;
      if (strip_comment) l = trim(l.substr(0, l.find('#')));
      cur_ = l;
      toks_.clear();
      for (size_t i = 0; i < l.size();) {
        while (i < l.size() && is_space(l[i])) ++i;
        size_t j = i;
        while (j < l.size() && !is_space(l[j])) ++j;
        if (j > i) toks_.push_back(l.substr(i, j - i));
        i = j;
      }
      return true;
    }
    line_ = std::max<int64_t>(lines_read_, 1);
    cur_ = {};
    toks_.clear();
    return false;
  }
  void require_next(const std::string& expected) {
    if (!next()) fail(expected + ", found the end of the file");
  }

  int64_t line() const { return line_; }
  std::string_view text() const { return cur_; }
  const std::vector<std::string_view>& tokens() const { return toks_; }
  size_t remaining_bytes() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }

  [[noreturn]] void fail(const std::string& expected) const {
    throw InputError(source_, SourceLoc::at_line(line_), "expected " + expected);
  }

  void expect_tokens(size_t n, const std::string& what) const {
    if (toks_.size() != n)
      fail(what + " (" + std::to_string(n) + " number" + (n == 1 ? "" : "s") + " on the line), found " +
           std::to_string(toks_.size()) + " in " + shown(cur_));
  }

  int64_t integer(size_t i, const std::string& what) const {
    std::string_view t = toks_[i];
    int64_t v = 0;
    const char* b = t.data();
    const char* e = b + t.size();
    if (b != e && *b == '+') ++b;
    auto r = ::hbc::detail::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e) fail(what + " (an integer), found " + shown(t));
    return v;
  }
  int64_t integer_in(size_t i, int64_t lo, int64_t hi, const std::string& what) const {
    const int64_t v = integer(i, what);
    if (v < lo || v > hi)
      fail(what + " in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " + std::to_string(v));
    return v;
  }
  double real(size_t i, const std::string& what) const {
    std::string_view t = toks_[i];
    double v = 0;
    const char* b = t.data();
    const char* e = b + t.size();
    if (b != e && *b == '+') ++b;
    auto r = ::hbc::detail::from_chars(b, e, v);
    if (r.ec == std::errc() && r.ptr == e && std::isfinite(v)) return v;
    if (r.ptr == e && (r.ec == std::errc::result_out_of_range || !std::isfinite(v)))
      fail(what + " (a finite number), found " + shown(t));
    fail(what + " (a number), found " + shown(t));
  }

 private:
  std::string_view text_;
  const std::string& source_;
  size_t pos_ = 0;
  int64_t lines_read_ = 0;
  int64_t line_ = 1;
  std::string_view cur_;
  std::vector<std::string_view> toks_;
};

// "Keyword" alone on its line, then the count (on the same line or the next one). The count is
// checked against what is left of the file (each entity needs at least min_bytes of text) before
// anything is allocated.
int64_t section(OvmLines& in, const char* keyword, int64_t min_bytes) {
  const std::string kw = detail::lower(keyword);
  in.require_next(std::string("the section keyword ") + keyword);
  const auto& t = in.tokens();
  if (detail::lower(t[0]) != kw || t.size() > 2)
    in.fail(std::string("the section keyword ") + keyword + ", found " + shown(in.text()));
  if (t.size() == 1) {
    in.require_next(std::string("the number of ") + kw);
    in.expect_tokens(1, std::string("the number of ") + kw);
  }
  const size_t i = in.tokens().size() - 1;
  const int64_t n = in.integer(i, std::string("the number of ") + kw);
  if (n < 0) in.fail("the number of " + kw + " (a count >= 0), found " + std::to_string(n));
  const int64_t room = static_cast<int64_t>(in.remaining_bytes()) / min_bytes + 1;
  if (n > room)
    in.fail("a number of " + kw + " that the rest of the file can hold (at most " +
            std::to_string(room) + "), found " + std::to_string(n));
  return n;
}

// Property blocks: which entity count each kind refers to, and how many numbers a value of a
// known numeric type has (0: type not checked, e.g. strings and vectors of handles).
int property_kind(std::string_view tok) {
  static constexpr std::array<std::string_view, 7> kinds{"vprop", "eprop", "heprop", "fprop",
                                                         "hfprop", "cprop", "mprop"};
  const std::string t = detail::lower(tok);
  for (size_t k = 0; k < kinds.size(); ++k)
    if (t == kinds[k]) return static_cast<int>(k);
  return -1;
}

int numbers_per_value(const std::string& type) {
  static constexpr std::array<std::string_view, 9> scalars{"int", "uint", "short", "long", "ulong",
                                                           "bool", "float", "double", "size_t"};
  for (auto s : scalars)
    if (type == s) return 1;
  // vec2f, vec3d, vec4ui, ...
  if (type.size() >= 5 && type.compare(0, 3, "vec") == 0 && type[3] >= '2' && type[3] <= '9') {
    const std::string_view rest = std::string_view(type).substr(4);
    if (rest == "f" || rest == "d" || rest == "i" || rest == "ui") return type[3] - '0';
  }
  return 0;
}

void skip_properties(OvmLines& in, const std::array<int64_t, 7>& counts) {
  const char* kExpected = "a property block header (VProp, EProp, HEProp, FProp, HFProp, CProp or MProp "
                          "followed by a type and a quoted name)";
  std::string after;  // names the previous block, for a clearer message when it had too many values
  while (in.next(false)) {
    const auto& t = in.tokens();
    const int kind = property_kind(t[0]);
    if (kind < 0 || t.size() < 3) in.fail(std::string(kExpected) + after + ", found " + shown(in.text()));
    const std::string type = detail::lower(t[1]);
    const std::string_view text = in.text();
    const size_t q0 = text.find('"'), q1 = text.rfind('"');
    if (q0 == std::string_view::npos || q1 == q0)
      in.fail("a quoted property name in " + shown(text));
    const std::string name(text.substr(q0 + 1, q1 - q0 - 1));
    const int64_t n = counts[static_cast<size_t>(kind)];
    const int per = numbers_per_value(type);
    for (int64_t i = 0; i < n; ++i) {
      const std::string what = std::to_string(n) + " values of property \"" + name + "\"";
      if (!in.next(false)) in.fail(what + ", found " + std::to_string(i) + " before the end of the file");
      if (property_kind(in.tokens()[0]) >= 0 && in.text().find('"') != std::string_view::npos)
        in.fail(what + ", found " + std::to_string(i) + " before the next property block");
      if (per > 0) {
        in.expect_tokens(static_cast<size_t>(per), "a " + type + " value of property \"" + name + "\"");
        for (int k = 0; k < per; ++k) in.real(static_cast<size_t>(k), "a " + type + " value of property \"" + name + "\"");
      }
    }
    after = " after the " + std::to_string(n) + " values of property \"" + name + "\"";
  }
}

}  // namespace

MeshInput read_ovm(std::string_view text, const std::string& source) {
  OvmLines in(text, source);
  MeshInput out;
  out.source = source;

  const char* kHeader = "the header line 'OVM ASCII'";
  in.require_next(kHeader);
  {
    const auto& t = in.tokens();
    if (detail::lower(t[0]) != "ovm") in.fail(std::string(kHeader) + ", found " + shown(in.text()));
    if (t.size() >= 2 && detail::lower(t[1]) == "binary")
      in.fail("an ASCII OVM file ('OVM BINARY' is not supported; OVMB files end in .ovmb)");
    if (t.size() > 2 || (t.size() == 2 && detail::lower(t[1]) != "ascii"))
      in.fail(std::string(kHeader) + ", found " + shown(in.text()));
  }

  constexpr int64_t kMax = std::numeric_limits<int32_t>::max();
  const int64_t nv = section(in, "Vertices", 6);
  out.points.reserve(static_cast<size_t>(3 * nv));
  out.vertex_loc.reserve(static_cast<size_t>(nv));
  for (int64_t i = 0; i < nv; ++i) {
    in.require_next("vertex " + std::to_string(i) + " of " + std::to_string(nv));
    in.expect_tokens(3, "the coordinates of vertex " + std::to_string(i));
    for (size_t k = 0; k < 3; ++k) out.points.push_back(in.real(k, "a vertex coordinate"));
    out.vertex_loc.push_back(in.line());
  }

  const int64_t ne = section(in, "Edges", 4);
  if (ne > kMax / 2) in.fail("fewer than 2^30 edges");
  out.declared_edges.reserve(static_cast<size_t>(ne));
  for (int64_t i = 0; i < ne; ++i) {
    in.require_next("edge " + std::to_string(i) + " of " + std::to_string(ne));
    in.expect_tokens(2, "the two vertices of edge " + std::to_string(i));
    const auto a = static_cast<int32_t>(in.integer_in(0, 0, nv - 1, "a vertex index"));
    const auto b = static_cast<int32_t>(in.integer_in(1, 0, nv - 1, "a vertex index"));
    out.declared_edges.push_back({a, b});
  }

  const int64_t nf = section(in, "Faces", 8);
  if (nf > kMax / 2) in.fail("fewer than 2^30 faces");
  out.face_loc.reserve(static_cast<size_t>(nf));
  for (int64_t f = 0; f < nf; ++f) {
    in.require_next("face " + std::to_string(f) + " of " + std::to_string(nf));
    const int64_t n = in.integer_in(0, 3, kMax, "the number of half-edges of face " + std::to_string(f));
    in.expect_tokens(static_cast<size_t>(n) + 1,
                     "the half-edge count and " + std::to_string(n) + " half-edges of face " + std::to_string(f));
    // A half-edge runs from one end of its edge to the other; consecutive ones must chain.
    auto ends = [&](int64_t h) {
      const auto& e = out.declared_edges[static_cast<size_t>(h >> 1)];
      return (h & 1) ? std::array<int32_t, 2>{e[1], e[0]} : e;
    };
    std::array<int32_t, 2> first{}, prev{};
    for (int64_t k = 0; k < n; ++k) {
      const int64_t h = in.integer_in(static_cast<size_t>(k) + 1, 0, 2 * ne - 1, "a half-edge index");
      const auto cur = ends(h);
      if (k == 0) first = cur;
      else if (cur[0] != prev[1])
        in.fail("half-edges of face " + std::to_string(f) + " that chain end to start, half-edge " +
                std::to_string(h) + " starts at vertex " + std::to_string(cur[0]) +
                " but the previous one ends at " + std::to_string(prev[1]));
      out.faces.items.push_back(cur[0]);
      prev = cur;
    }
    if (prev[1] != first[0])
      in.fail("a closed loop of half-edges in face " + std::to_string(f) + ", it ends at vertex " +
              std::to_string(prev[1]) + " but starts at " + std::to_string(first[0]));
    out.faces.offsets.push_back(static_cast<int32_t>(out.faces.items.size()));
    out.face_loc.push_back(in.line());
  }

  const int64_t nc = section(in, "Polyhedra", 6);
  out.cell_loc.reserve(static_cast<size_t>(nc));
  for (int64_t c = 0; c < nc; ++c) {
    in.require_next("polyhedron " + std::to_string(c) + " of " + std::to_string(nc));
    const int64_t n = in.integer_in(0, 1, kMax, "the number of half-faces of polyhedron " + std::to_string(c));
    in.expect_tokens(static_cast<size_t>(n) + 1, "the half-face count and " + std::to_string(n) +
                                                     " half-faces of polyhedron " + std::to_string(c));
    for (int64_t k = 0; k < n; ++k)
      out.cells.items.push_back(
          static_cast<int32_t>(in.integer_in(static_cast<size_t>(k) + 1, 0, 2 * nf - 1, "a half-face index")));
    out.cells.offsets.push_back(static_cast<int32_t>(out.cells.items.size()));
    out.cell_loc.push_back(in.line());
  }

  skip_properties(in, {nv, ne, 2 * ne, nf, 2 * nf, nc, 1});
  return out;
}

}  // namespace hbc
