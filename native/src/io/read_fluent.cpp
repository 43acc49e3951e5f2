// Fluent mesh (.msh; Ansys Fluent User's Guide, appendix "Mesh File Format"): sections
// "(index ...)" with a decimal index. (2 3) the dimension; (10 (zone first last type nd)(x y z
// ...)) nodes; (12 (zone first last type elemtype)[(types)]) cells; (13 (zone first last bc
// facetype)(n0 .. c0 c1 ...)) faces, a mixed zone (facetype 0) or a polygonal one (5) giving each
// face's node count first. Header numbers and ids are hexadecimal, coordinates decimal; ids count
// from 1 and a cell id 0 is "no cell" (the boundary). Zone 0 declares the totals. Binary sections
// (index 2010/2012/2013 and 3010/3012/3013) hold the same items as 4-byte little-endian integers
// and 4-byte (20xx) or 8-byte (30xx) reals between "(" and ")End of Binary Section index)".
// Every other section (names 39/45, periodic shadows 18, trees 58/59, ...) is read past.
// Fluent's faces are ordered so that the right-hand normal points into c0 and out of c1
// (foamMeshToFluent writes OpenFOAM's neighbour as c0, its owner as c1): c1 sees the loop as
// written, c0 reversed. Cells are made from their faces as OpenFOAM's are (detail::cells_from_sides).
// A file with binary sections reports byte offsets everywhere, an ASCII file lines.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/face_cells.hpp"
#include "platform/charconv.hpp"

namespace hbc {
namespace {

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

class FluentReader {
 public:
  FluentReader(std::string_view bytes, const std::string& source) : t_(bytes) {
    in_.source = source;
    in_.binary = bytes.find("End of Binary Section") != std::string_view::npos;
  }
  MeshInput read();

 private:
  int64_t loc() {
    skip_space();
    return in_.binary ? static_cast<int64_t>(pos_) : line_;
  }
  [[noreturn]] void fail_at(int64_t loc, const std::string& expected) const {
    throw InputError(in_.source, in_.binary ? SourceLoc::at_byte(loc) : SourceLoc::at_line(loc), "expected " + expected);
  }
  [[noreturn]] void fail(const std::string& expected) {
    int64_t at = loc();
    // "Found the end of the file" points at the last line, not the empty one after its newline.
    if (!in_.binary && pos_ >= t_.size() && at > 1 && !t_.empty() && t_.back() == '\n') --at;
    std::string found = "the end of the file";
    if (pos_ < t_.size()) {
      size_t e = pos_;
      while (e < t_.size() && e - pos_ < 30 && !is_space(t_[e])) ++e;
      found = "'" + std::string(t_.substr(pos_, std::max<size_t>(e - pos_, 1))) + "'";
    }
    fail_at(at, expected + ", found " + found);
  }
  void skip_space() {
    while (pos_ < t_.size() && is_space(t_[pos_])) line_ += t_[pos_++] == '\n';
  }
  bool peek(char c) {
    skip_space();
    return pos_ < t_.size() && t_[pos_] == c;
  }
  void expect(char c, const char* what) {
    if (!peek(c)) fail(what);
    ++pos_;
  }
  // A number token; `base` 16 for ids and counts, 10 for the section index.
  int64_t integer(int base, const char* what) {
    skip_space();
    int64_t v = 0;
    const char* b = t_.data() + pos_;
    const auto r = std::from_chars(b, t_.data() + t_.size(), v, base);
    if (r.ec != std::errc() || (r.ptr < t_.data() + t_.size() && !is_space(*r.ptr) && *r.ptr != ')' && *r.ptr != '('))
      fail(std::string(what) + (base == 16 ? " (a hexadecimal integer)" : " (an integer)"));
    pos_ += static_cast<size_t>(r.ptr - b);
    return v;
  }
  double real(const char* what) {
    skip_space();
    double v = 0;
    const char* b = t_.data() + pos_;
    const auto r = ::hbc::detail::from_chars(b, t_.data() + t_.size(), v);
    if (r.ec != std::errc() || !std::isfinite(v) || (r.ptr < t_.data() + t_.size() && !is_space(*r.ptr) && *r.ptr != ')'))
      fail(std::string(what) + " (a finite number)");
    pos_ += static_cast<size_t>(r.ptr - b);
    return v;
  }
  template <class T>
  T bin(const char* what) {
    if (t_.size() - pos_ < sizeof(T))
      fail_at(static_cast<int64_t>(pos_), std::string(what) + " (" + std::to_string(sizeof(T)) + " bytes), found the end of the file");
    T v;
    std::memcpy(&v, t_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  // An item of a section body: binary (4-byte little-endian) or hexadecimal text.
  int64_t id(bool binary, const char* what) { return binary ? bin<int32_t>(what) : integer(16, what); }
  struct Header {
    int64_t zone = 0, first = 0, last = 0, type = 0, kind = -1;
  };
  Header header(const char* what);
  void check_range(const Header& h, int64_t at, int64_t min_bytes, const char* what);
  void end_binary(int64_t index);
  void skip_section(int64_t index);
  void skip_list(int64_t at, int64_t index);
  // Lists after a section's body (foamMeshToFluent ends a cell zone with "()"), then its ")".
  void end_section(int64_t index) {
    while (peek('(')) {
      const int64_t at = loc();
      ++pos_;
      skip_list(at, index);
    }
    expect(')', "')' closing the section");
  }
  void nodes(int64_t index);
  void cells(int64_t index);
  void faces(int64_t index);
  void cell_count(int64_t n, int64_t at) {
    if (n > nc_) nc_ = n, nc_loc_ = at;
  }

  std::string_view t_;
  size_t pos_ = 0;
  int64_t line_ = 1;
  MeshInput in_;
  std::vector<uint8_t> have_node_;
  std::vector<int32_t> written_, reversed_;  // per face: the cell seeing the loop as written / reversed, or -1
  int64_t nc_ = 0, nc_loc_ = 0;  // the number of cells, and where the highest cell id was read
};

// "(zone first last type [kind])", all hexadecimal.
FluentReader::Header FluentReader::header(const char* what) {
  Header h;
  expect('(', what);
  h.zone = integer(16, "a zone id");
  h.first = integer(16, "the first index of the zone");
  h.last = integer(16, "the last index of the zone");
  h.type = integer(16, "the zone type");
  if (!peek(')')) h.kind = integer(16, "the element type or dimension of the zone");
  expect(')', "')' closing the zone header");
  return h;
}

// A zone's ids from first to last, each item at least `min_bytes` long in what is left of the file.
void FluentReader::check_range(const Header& h, int64_t at, int64_t min_bytes, const char* what) {
  if (h.first < 1 || h.last < h.first - 1 || h.last >= INT32_MAX)
    fail_at(at, std::string(what) + " with 1 <= first <= last + 1 < 2^31, found " + std::to_string(h.first) + " to " +
                    std::to_string(h.last));
  const int64_t room = static_cast<int64_t>(t_.size() - pos_) / min_bytes + 1;
  if (h.last - h.first + 1 > room)
    fail_at(at, std::string(what) + " that the rest of the file can hold (at most " + std::to_string(room) + " items), found " +
                    std::to_string(h.last - h.first + 1));
}

void FluentReader::end_binary(int64_t index) {
  expect(')', "')' closing the binary data");
  const std::string end = "End of Binary Section";
  skip_space();
  if (t_.substr(pos_, end.size()) != end) fail("'End of Binary Section " + std::to_string(index) + "'");
  pos_ += end.size();
  if (integer(10, "the section index after End of Binary Section") != index)
    fail("'End of Binary Section " + std::to_string(index) + "'");
}

// Past a section's ")" : strings and nested lists in text, up to "End of Binary Section" in binary.
void FluentReader::skip_section(int64_t index) {
  const int64_t at = loc();
  if (index >= 1000) {
    const size_t e = t_.find("End of Binary Section", pos_);
    if (e == std::string_view::npos) fail_at(at, "'End of Binary Section' closing section " + std::to_string(index));
    line_ += std::count(t_.begin() + static_cast<ptrdiff_t>(pos_), t_.begin() + static_cast<ptrdiff_t>(e), '\n');
    pos_ = e + 21;
    integer(10, "the section index after End of Binary Section");
  } else {
    skip_list(at, index);
    return;
  }
  expect(')', "')' closing the section");
}

// Past the ")" closing a text list whose "(" is behind: nested lists and strings skipped.
void FluentReader::skip_list(int64_t at, int64_t index) {
  for (int depth = 0;;) {
    if (pos_ >= t_.size()) fail_at(at, "')' closing section " + std::to_string(index) + ", found the end of the file");
    const char c = t_[pos_++];
    if (c == '\n') ++line_;
    else if (c == '(') ++depth;
    else if (c == ')' && depth-- == 0) return;
    else if (c == '"') {
      const size_t e = t_.find('"', pos_);
      if (e == std::string_view::npos) fail_at(at, "a closing '\"' in section " + std::to_string(index));
      line_ += std::count(t_.begin() + static_cast<ptrdiff_t>(pos_), t_.begin() + static_cast<ptrdiff_t>(e), '\n');
      pos_ = e + 1;
    }
  }
}

void FluentReader::nodes(int64_t index) {
  const int64_t at = loc();
  const Header h = header("'(' opening the node zone header");
  if (h.zone == 0 || peek(')')) {
    // The declaration of the total: no coordinates.
    expect(')', "')' closing the node declaration");
    return;
  }
  const int64_t nd = h.kind < 0 ? 3 : h.kind;
  if (nd != 3) fail_at(at, "nodes of dimension 3, found " + std::to_string(nd));
  const bool binary = index != 10;
  const int64_t bytes = binary ? (index == 2010 ? 12 : 24) : 6;
  check_range(h, at, bytes, "a node zone");
  // Every node from 1 to the highest id must be in the file: bounds the arrays sized by that id.
  if (h.last > static_cast<int64_t>(t_.size()) / 6) fail_at(at, "node ids that a file of this size can hold, found " + std::to_string(h.last));
  const size_t n_before = have_node_.size();
  if (static_cast<size_t>(h.last) > n_before) {
    have_node_.resize(static_cast<size_t>(h.last), 0);
    in_.points.resize(3 * static_cast<size_t>(h.last), 0.0);
    in_.vertex_loc.resize(static_cast<size_t>(h.last), 0);
  }
  expect('(', "'(' opening the node coordinates");
  for (int64_t i = h.first - 1; i < h.last; ++i) {
    const int64_t where = binary ? static_cast<int64_t>(pos_) : loc();
    if (have_node_[static_cast<size_t>(i)]) fail_at(where, "each node once, found node " + std::to_string(i + 1) + " again");
    have_node_[static_cast<size_t>(i)] = 1;
    in_.vertex_loc[static_cast<size_t>(i)] = where;
    for (int a = 0; a < 3; ++a) {
      double x = index == 10 ? real("a node coordinate") : index == 2010 ? bin<float>("a node coordinate") : bin<double>("a node coordinate");
      if (!std::isfinite(x)) fail_at(where, "a node coordinate (a finite number)");
      in_.points[3 * static_cast<size_t>(i) + static_cast<size_t>(a)] = x;
    }
  }
  if (binary) end_binary(index);
  else expect(')', "')' closing the node coordinates");
  end_section(index);
}

// Cells are made from faces: a zone's range only says how many there are.
void FluentReader::cells(int64_t index) {
  const int64_t at = loc();
  const Header h = header("'(' opening the cell zone header");
  check_range(h, at, 1, "a cell zone");
  cell_count(h.last, at);
  if (peek('(')) {
    ++pos_;
    const bool binary = index != 12;
    // The type of each cell of a mixed zone (0..7); checked, not needed.
    for (int64_t i = h.first; i <= h.last; ++i) {
      const int64_t where = binary ? static_cast<int64_t>(pos_) : loc();
      const int64_t type = id(binary, "a cell type");
      if (type < 0 || type > 7) fail_at(where, "a Fluent cell type in [0, 7], found " + std::to_string(type));
    }
    if (binary) end_binary(index);
    else expect(')', "')' closing the cell types");
  }
  end_section(index);
}

void FluentReader::faces(int64_t index) {
  const int64_t at = loc();
  const Header h = header("'(' opening the face zone header");
  if (h.zone == 0 || peek(')')) {
    expect(')', "')' closing the face declaration");
    return;
  }
  const bool binary = index != 13;
  const int64_t kind = h.kind < 0 ? 0 : h.kind;
  if (kind != 0 && kind != 3 && kind != 4 && kind != 5) fail_at(at, "a 3D face type (0 mixed, 3 triangle, 4 quadrilateral, 5 polygon), found " + std::to_string(kind));
  check_range(h, at, binary ? 20 : 10, "a face zone");
  expect('(', "'(' opening the faces");
  if (in_.face_loc.size() + static_cast<size_t>(h.last - h.first + 1) > static_cast<size_t>(INT32_MAX)) fail_at(at, "fewer than 2^31 faces");
  for (int64_t f = h.first; f <= h.last; ++f) {
    const int64_t where = binary ? static_cast<int64_t>(pos_) : loc();
    const int64_t n = kind == 0 || kind == 5 ? id(binary, "the number of nodes of a face") : kind;
    if (n < 3 || n > (1 << 20)) fail_at(where, "a face of 3 or more nodes (at most 2^20), found " + std::to_string(n));
    for (int64_t k = 0; k < n; ++k) {
      const int64_t v = id(binary, "a node id of a face");
      if (v < 1 || v > static_cast<int64_t>(have_node_.size()) || !have_node_[static_cast<size_t>(v - 1)])
        fail_at(where, "a node id of a node section (1 to " + std::to_string(have_node_.size()) + "), found " + std::to_string(v));
      in_.faces.items.push_back(static_cast<int32_t>(v - 1));
    }
    int64_t c[2];
    for (int64_t& ci : c) {
      ci = id(binary, "a cell id of a face (0 for none)");
      if (ci < 0 || ci >= INT32_MAX) fail_at(where, "a cell id in [0, 2^31 - 1), found " + std::to_string(ci));
      cell_count(ci, where);
    }
    if (c[0] == 0 && c[1] == 0) fail_at(where, "a face with a cell on at least one side, found 0 0");
    written_.push_back(static_cast<int32_t>(c[1] - 1));
    reversed_.push_back(static_cast<int32_t>(c[0] - 1));
    in_.faces.offsets.push_back(static_cast<int32_t>(in_.faces.items.size()));
    in_.face_loc.push_back(where);
  }
  if (binary) end_binary(index);
  else expect(')', "')' closing the faces");
  end_section(index);
}

MeshInput FluentReader::read() {
  for (skip_space(); pos_ < t_.size(); skip_space()) {
    expect('(', "'(' opening a Fluent section");
    const int64_t at = loc();
    const int64_t index = integer(10, "a section index");
    switch (index) {
      case 2:
        if (integer(10, "the dimension") != 3) fail_at(at, "a 3D mesh, (2 3)");
        expect(')', "')' closing the dimension");
        break;
      case 10: case 2010: case 3010: nodes(index); break;
      case 12: case 2012: case 3012: cells(index); break;
      case 13: case 2013: case 3013: faces(index); break;
      default: skip_section(index);
    }
  }
  if (in_.faces.rows() == 0) fail("a face section (13) in a Fluent mesh");
  const auto gap = std::find(have_node_.begin(), have_node_.end(), 0);
  if (gap != have_node_.end())
    throw InputError(in_.source, {}, "expected every node from 1 to " + std::to_string(have_node_.size()) + " in a node section, node " +
                                         std::to_string(gap - have_node_.begin() + 1) + " is in none");
  // Each cell has a face side: checked before the cells' offsets are allocated.
  if (nc_ > 2 * static_cast<int64_t>(written_.size()))
    fail_at(nc_loc_, "cell ids up to twice the number of faces (" + std::to_string(2 * written_.size()) + "), found " + std::to_string(nc_));
  int32_t empty = -1;
  in_.cells = detail::cells_from_sides(written_, reversed_, static_cast<int32_t>(nc_), empty);
  if (empty >= 0)
    fail_at(nc_loc_, "every cell from 1 to " + std::to_string(nc_) + " to have faces, cell " + std::to_string(empty + 1) + " has none");
  return std::move(in_);
}

}  // namespace

MeshInput read_fluent(std::string_view bytes, const std::string& source) { return FluentReader(bytes, source).read(); }

}  // namespace hbc
