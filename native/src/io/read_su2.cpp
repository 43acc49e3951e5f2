// SU2 native mesh (.su2, su2code.github.io "Mesh File"): "KEY= value" lines, '%' comments.
// NDIME= 3; NELEM= n, then n lines "type v0 .. vk [index]" with VTK's type ids and corner orders
// (10 tet, 12 hex, 13 prism, 14 pyramid) and 0-based point ids; NPOIN= n [ndomain], then n lines
// "x y z [index]" (the first line says whether the index column is there); NMARK= m, and per
// marker MARKER_TAG= name and MARKER_ELEMS= k lines of boundary elements, skipped and counted.
// SU2's prism is the mirror image of MEDIT's (SU2's CPrismConnectivity lists the outward faces
// 0-1-2 and 5-4-3, as VTK's older documentation had it; gmsh's SU2 writer writes that), so its
// corners 1 and 2, 4 and 5 swap; the other cells have MEDIT's orders.
// NELEM usually comes before NPOIN, so element ids are checked once the zone's points are known.
// Several zones (NZONE= z, each opened by IZONE= i) are read one after the other into one mesh,
// each zone's ids offset by the points of the zones before it: the zones stay apart (their shared
// interface points are not merged), as SU2 keeps them.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/element_tally.hpp"
#include "mesh/cell_templates.hpp"
#include "platform/charconv.hpp"

namespace hbc {
namespace {

using detail::Element;

// SU2's element types are VTK's; dim < 3 types are read past.
struct Su2Type {
  int type, dim, nodes;
  Element element;
};
constexpr Su2Type kTypes[] = {{3, 1, 2, Element::Tet},   {5, 2, 3, Element::Tet},  {9, 2, 4, Element::Tet},
                              {10, 3, 4, Element::Tet},  {12, 3, 8, Element::Hex}, {13, 3, 6, Element::Prism},
                              {14, 3, 5, Element::Pyramid}};

// MEDIT's prism corner k is SU2's corner kPrism[k].
constexpr int kPrism[6] = {0, 2, 1, 3, 5, 4};

const Su2Type* su2_type(int64_t t) {
  for (const Su2Type& s : kTypes)
    if (s.type == t) return &s;
  return nullptr;
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string shown(std::string_view t) {
  return "'" + std::string(t.substr(0, 40)) + (t.size() > 40 ? "...'" : "'");
}

// The numbers of one line.
struct Fields {
  std::string_view rest;
  bool empty() {
    while (!rest.empty() && blank(rest.front())) rest.remove_prefix(1);
    return rest.empty();
  }
  std::string_view token() {
    empty();
    size_t e = 0;
    while (e < rest.size() && !blank(rest[e])) ++e;
    const std::string_view t = rest.substr(0, e);
    rest.remove_prefix(e);
    return t;
  }
  template <class T>
  bool number(T& v) {
    const std::string_view t = token();
    const char* b = t.data();
    const char* e = b + t.size();
    if (b != e && *b == '+') ++b;
    auto r = ::hbc::detail::from_chars(b, e, v);
    return !t.empty() && r.ec == std::errc() && r.ptr == e;
  }
  // The line's numbers in one pass, up to `max` into `out`: how many the line holds (max + 1 for
  // more), or -1 - i when token i is not a number of type T.
  template <class T>
  int numbers(T* out, int max) {
    const char* p = rest.data();
    const char* e = p + rest.size();
    for (int n = 0;; ++n) {
      while (p < e && blank(*p)) ++p;
      if (p == e) return n;
      if (n == max) return max + 1;
      const auto r = ::hbc::detail::from_chars(p + (*p == '+'), e, out[n]);
      if (r.ec != std::errc() || (r.ptr < e && !blank(*r.ptr))) return -1 - n;
      p = r.ptr;
    }
  }
};

class Su2Reader {
 public:
  Su2Reader(std::string_view text, const std::string& source) : t_(text), cells_(in_) { in_.source = source; }
  MeshInput read();

 private:
  [[noreturn]] void fail_at(int64_t line, const std::string& expected) const {
    throw InputError(in_.source, SourceLoc::at_line(line), "expected " + expected);
  }
  [[noreturn]] void fail(const std::string& expected) const { fail_at(std::max<int64_t>(line_, 1), expected); }
  // The next line with something on it, its '%' comment cut; false at the end of the text.
  bool next_line(Fields& f);
  Fields line(const char* what) {
    Fields f;
    if (!next_line(f)) fail(std::string(what) + ", found the end of the file");
    return f;
  }
  int64_t count_value(Fields& f, const char* what, int64_t min_bytes);
  void points(int64_t n);
  void elements(int64_t n, bool volume);
  void end_zone();

  std::string_view t_;
  size_t pos_ = 0;
  int64_t line_ = 0;
  MeshInput in_;
  detail::CellAppender cells_;
  detail::ElementTally tally_;
  // The zone being read: its elements wait for its points.
  int64_t zone_base_ = 0, zone_points_ = -1;
  std::vector<Element> el_;
  std::vector<int64_t> el_line_, ids_;
};

bool Su2Reader::next_line(Fields& f) {
  while (pos_ < t_.size()) {
    size_t e = t_.find('\n', pos_);
    if (e == std::string_view::npos) e = t_.size();
    std::string_view l = t_.substr(pos_, e - pos_);
    pos_ = e + 1;
    ++line_;
    if (const size_t c = l.find('%'); c != std::string_view::npos) l = l.substr(0, c);
    f.rest = l;
    if (!f.empty()) return true;
  }
  return false;
}

int64_t Su2Reader::count_value(Fields& f, const char* what, int64_t min_bytes) {
  int64_t n = 0;
  if (!f.number(n) || n < 0) fail(std::string(what) + " (a count >= 0)");
  const int64_t room = static_cast<int64_t>(t_.size() - std::min(pos_, t_.size())) / min_bytes + 1;
  if (n > room)
    fail(std::string(what) + " that the rest of the file can hold (at most " + std::to_string(room) + "), found " +
         std::to_string(n));
  return n;
}

void Su2Reader::points(int64_t n) {
  if (zone_points_ >= 0) fail("one NPOIN= section in the zone, found a second");
  zone_points_ = n;
  in_.points.reserve(in_.points.size() + static_cast<size_t>(3 * n));
  int columns = 0;
  double x[4];
  for (int64_t i = 0; i < n; ++i) {
    Fields f = line("a point line (x y z [index])");
    const int k = f.numbers(x, 4);
    if (k < 0) fail("a point coordinate (a finite number)");
    // The first line says whether an index column follows the coordinates.
    if (i == 0) columns = k;
    if (k != columns || (k != 3 && k != 4))
      fail("a point line of " + (i == 0 ? std::string("3 or 4") : std::to_string(columns)) + " numbers (x y z [index]), found " +
           std::to_string(k));
    for (int a = 0; a < 3; ++a) {
      if (!std::isfinite(x[a])) fail("a point coordinate (a finite number)");
      in_.points.push_back(x[a]);
    }
    in_.vertex_loc.push_back(line_);
  }
}

void Su2Reader::elements(int64_t n, bool volume) {
  for (int64_t i = 0; i < n; ++i) {
    Fields f = line("an element line (type ids [index])");
    int64_t v[11];
    const int k = f.numbers(v, 10);
    if (k < 0) fail(k == -1 ? "an element type (an integer)" : "a point id (an integer)");
    if (k == 0) fail("an element type (an integer)");
    const Su2Type* t = su2_type(v[0]);
    if (!t) fail("an SU2 element type (3 line, 5 triangle, 9 quadrilateral, 10, 12, 13, 14), found " + std::to_string(v[0]));
    if (k - 1 != t->nodes && k - 1 != t->nodes + 1)
      fail(std::to_string(t->nodes) + " point ids (and an optional index) for type " + std::to_string(v[0]) + ", found " +
           (k > 10 ? std::string("more") : std::to_string(k - 1)) + " numbers");
    if (t->dim == 3 && volume) ids_.insert(ids_.end(), v + 1, v + 1 + t->nodes);
    if (t->dim < 3 || !volume) {
      tally_.skip(t->dim);
      continue;
    }
    el_.push_back(t->element);
    el_line_.push_back(line_);
  }
}

// The zone's elements, once its points are known.
void Su2Reader::end_zone() {
  if (zone_points_ < 0) fail("an NPOIN= section in the zone");
  size_t next = 0;
  for (size_t e = 0; e < el_.size(); ++e) {
    std::array<int32_t, 8> v{};
    const int n = detail::corner_count(el_[e]);
    for (int k = 0; k < n; ++k) {
      const int64_t id = ids_[next + static_cast<size_t>(el_[e] == Element::Prism ? kPrism[k] : k)];
      if (id < 0 || id >= zone_points_)
        fail_at(el_line_[e], "a point id in [0, " + std::to_string(zone_points_ - 1) + "], found " + std::to_string(id));
      v[k] = static_cast<int32_t>(zone_base_ + id);
    }
    next += static_cast<size_t>(n);
    cells_.element(el_[e], v.data(), el_line_[e]);
  }
  el_.clear();
  el_line_.clear();
  ids_.clear();
  zone_base_ += zone_points_;
  zone_points_ = -1;
}

MeshInput Su2Reader::read() {
  int64_t zones = 1, zone = 0;
  bool seen = false;
  Fields f;
  while (next_line(f)) {
    const size_t eq = f.rest.find('=');
    if (eq == std::string_view::npos) fail("a KEYWORD= line (NDIME=, NELEM=, NPOIN=, NMARK=, ...), found " + shown(f.rest));
    std::string_view key = f.rest.substr(0, eq);
    while (!key.empty() && blank(key.back())) key.remove_suffix(1);
    Fields value{f.rest.substr(eq + 1)};
    if (key == "NZONE") {
      zones = count_value(value, "the number of zones", 1);
    } else if (key == "IZONE") {
      if (zone > 0) end_zone();
      if (++zone > zones) fail(std::to_string(zones) + " zones as NZONE= says, found more");
    } else if (key == "NDIME") {
      int64_t d = 0;
      if (!value.number(d) || d != 3) fail("NDIME= 3 (hbc reads volume meshes)");
      seen = true;
    } else if (key == "NELEM") {
      elements(count_value(value, "the number of elements", 6), true);
    } else if (key == "NPOIN") {
      points(count_value(value, "the number of points", 6));
    } else if (key == "MARKER_ELEMS") {
      elements(count_value(value, "the number of marker elements", 4), false);
    } else if (key != "NMARK" && key != "MARKER_TAG") {
      fail("an SU2 keyword (NDIME=, NELEM=, NPOIN=, NMARK=, MARKER_TAG=, MARKER_ELEMS=, NZONE=, IZONE=), found " + shown(key));
    }
  }
  if (!seen) fail("NDIME= 3 in an SU2 file");
  end_zone();
  if (in_.cells.rows() == 0) fail("at least one volume element (type 10, 12, 13 or 14)");
  tally_.report(in_);
  cells_.finish();
  return std::move(in_);
}

}  // namespace

MeshInput read_su2(std::string_view text, const std::string& source) { return Su2Reader(text, source).read(); }

}  // namespace hbc
