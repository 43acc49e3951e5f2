// OpenFOAM polyMesh (constant/polyMesh: points, faces, owner, neighbour). Each file is a FoamFile
// header dictionary ("format ascii|binary;", "class ...;", "arch "LSB;label=32;scalar=64";")
// followed by lists: a count, then "(" items ")" (or "{" one value "}" for a list whose items are
// all equal, written so in ASCII). ASCII items are numbers, points "(x y z)", faces "n(v0 .. vn-1)";
// binary items are the raw labels and scalars of the arch's sizes and byte order between "(" and
// ")". faces is a faceList (ASCII) or a faceCompactList: a list of nFaces+1 offsets and a list
// of the vertex labels (binary, and possible in ASCII). Comments (// and /* */) may stand wherever
// whitespace may. Face f belongs to cell owner[f], its normal pointing out of it, and for f below
// the length of neighbour (the internal faces, listed first; old files pad neighbour with -1) to
// cell neighbour[f] too, seeing it reversed. Messages name the file and the line, or the byte
// offset once the header says binary (offsets of the inflated data for a .gz file).
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "hbc/io.hpp"
#include "io/detail/face_cells.hpp"
#include "io/detail/text_scanner.hpp"
#include "platform/charconv.hpp"

namespace hbc {
namespace {

constexpr int64_t kMaxId = std::numeric_limits<int32_t>::max();

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string shown(std::string_view t) {
  std::string out(1, '\'');
  out.append(t.substr(0, 30));
  out.append(t.size() > 30 ? "...'" : "'");
  return out;
}

// One file: its header, then a cursor over its lists.
class FoamText {
 public:
  FoamText(std::string_view bytes, std::string source) : t_(bytes), source_(std::move(source)) { header(); }

  bool binary() const { return binary_; }
  const std::string& cls() const { return class_; }
  const std::string& source() const { return source_; }
  int64_t loc() {
    skip_space();
    return binary_ ? static_cast<int64_t>(pos_) : line_;
  }

  [[noreturn]] void fail_at(int64_t loc, const std::string& expected) const {
    throw InputError(source_, binary_ ? SourceLoc::at_byte(loc) : SourceLoc::at_line(loc), "expected " + expected);
  }
  [[noreturn]] void fail(const std::string& expected) { fail_at(loc(), expected + ", found " + found()); }

  // A list's count and its opening "(" or "{" (a uniform list: one value stands for all). The
  // count must fit in what is left of the file at `min_bytes` an item (uniform lists excepted).
  struct List {
    int64_t n = 0;
    bool uniform = false;
    bool parens = true;  // false for binary's bare "0" of an empty list
  };
  List open_list(const char* what, int64_t min_bytes) {
    List l;
    const int64_t at = loc();  // the count's place names the list in messages
    l.n = integer(what);
    if (l.n < 0 || l.n > kMaxId) fail_at(at, std::string(what) + " in [0, 2^31), found " + std::to_string(l.n));
    skip_space();
    if (pos_ < t_.size() && t_[pos_] == '{') {
      ++pos_;
      l.uniform = true;
      return l;
    }
    if (l.n == 0 && (pos_ >= t_.size() || t_[pos_] != '(')) {
      l.parens = false;
      return l;
    }
    expect('(', "'(' opening the list of " + std::to_string(l.n));
    const int64_t room = static_cast<int64_t>(t_.size() - pos_) / min_bytes + 1;
    if (l.n > room)
      fail_at(at, std::string(what) + " that the rest of the file can hold (at most " + std::to_string(room) +
                         "), found " + std::to_string(l.n));
    return l;
  }
  void close_list(const List& l) {
    if (l.uniform) expect('}', "'}' closing the uniform list");
    else if (l.parens) expect(')', "')' closing the list of " + std::to_string(l.n));
  }

  void expect(char c, const std::string& what) {
    skip_space();
    if (pos_ >= t_.size() || t_[pos_] != c) fail(what);
    ++pos_;
  }

  // One label: text, or the arch's binary size.
  int64_t label(const char* what) {
    if (!binary_) return integer(what);
    int64_t v = 0;
    if (label_bytes_ == 4) {
      int32_t x;
      std::memcpy(&x, raw(4, what), 4);
      v = swap_ ? static_cast<int32_t>(__builtin_bswap32(static_cast<uint32_t>(x))) : x;
    } else {
      std::memcpy(&v, raw(8, what), 8);
      if (swap_) v = static_cast<int64_t>(__builtin_bswap64(static_cast<uint64_t>(v)));
    }
    return v;
  }
  double scalar(const char* what) {
    if (!binary_) return real(what);
    if (scalar_bytes_ == 4) {
      uint32_t x;
      std::memcpy(&x, raw(4, what), 4);
      if (swap_) x = __builtin_bswap32(x);
      float f;
      std::memcpy(&f, &x, 4);
      return f;
    }
    uint64_t x;
    std::memcpy(&x, raw(8, what), 8);
    if (swap_) x = __builtin_bswap64(x);
    double d;
    std::memcpy(&d, &x, 8);
    return d;
  }
  int label_bytes() const { return label_bytes_; }
  int scalar_bytes() const { return scalar_bytes_; }
  // Where the next binary item starts (no whitespace skipped inside binary data).
  int64_t raw_loc() const { return static_cast<int64_t>(pos_); }

  // Text: an integer token.
  int64_t integer(const char* what) {
    skip_space();
    const char* b = t_.data() + pos_;
    const char* e = t_.data() + t_.size();
    int64_t v = 0;
    auto r = ::hbc::detail::from_chars(b, e, v);
    if (r.ec != std::errc() || (r.ptr != e && !ends_number(*r.ptr))) fail(std::string(what) + " (an integer)");
    pos_ += static_cast<size_t>(r.ptr - b);
    return v;
  }
  double real(const char* what) {
    skip_space();
    const char* b = t_.data() + pos_;
    const char* e = t_.data() + t_.size();
    double v = 0;
    auto r = ::hbc::detail::from_chars(b, e, v);
    if (r.ptr == b || (r.ptr != e && !ends_number(*r.ptr))) fail(std::string(what) + " (a number)");
    if (r.ec != std::errc() || !std::isfinite(v)) fail(std::string(what) + " (a finite number)");
    pos_ += static_cast<size_t>(r.ptr - b);
    return v;
  }

  // Only comments and whitespace may follow the last list.
  void expect_end(const std::string& after) {
    skip_space();
    if (pos_ < t_.size()) fail("the end of the file after " + after);
  }

 private:
  static bool ends_number(char c) { return is_space(c) || c == ')' || c == '(' || c == '{' || c == '}' || c == '/' || c == ';'; }

  const char* raw(size_t n, const char* what) {
    if (t_.size() - pos_ < n)
      fail_at(static_cast<int64_t>(pos_), std::string(what) + " (" + std::to_string(n) + " bytes), found the end of the file");
    const char* p = t_.data() + pos_;
    pos_ += n;
    return p;
  }

  std::string found() {
    if (pos_ >= t_.size()) return "the end of the file";
    size_t e = pos_;
    while (e < t_.size() && e - pos_ < 30 && !is_space(t_[e])) ++e;
    return shown(t_.substr(pos_, std::max<size_t>(e - pos_, 1)));
  }

  void skip_space() {
    while (pos_ < t_.size()) {
      const char c = t_[pos_];
      if (c == '\n') ++line_, ++pos_;
      else if (is_space(c)) ++pos_;
      else if (c == '/' && pos_ + 1 < t_.size() && t_[pos_ + 1] == '/') {
        while (pos_ < t_.size() && t_[pos_] != '\n') ++pos_;
      } else if (c == '/' && pos_ + 1 < t_.size() && t_[pos_ + 1] == '*') {
        const size_t end = t_.find("*/", pos_ + 2);
        const size_t stop = end == std::string_view::npos ? t_.size() : end + 2;
        line_ += std::count(t_.begin() + static_cast<ptrdiff_t>(pos_), t_.begin() + static_cast<ptrdiff_t>(stop), '\n');
        pos_ = stop;
      } else break;
    }
  }

  // A word or a quoted string of the header.
  std::string_view header_word() {
    skip_space();
    const size_t b = pos_;
    if (pos_ < t_.size() && t_[pos_] == '"') {
      const size_t e = t_.find('"', pos_ + 1);
      if (e == std::string_view::npos) fail("a closing '\"' in the FoamFile header");
      pos_ = e + 1;
      return t_.substr(b + 1, e - b - 1);
    }
    while (pos_ < t_.size() && !is_space(t_[pos_]) && t_[pos_] != ';' && t_[pos_] != '}' && t_[pos_] != '{') ++pos_;
    return t_.substr(b, pos_ - b);
  }

  void header();
  void arch(std::string_view a);

  std::string_view t_;
  std::string source_;
  size_t pos_ = 0;
  int64_t line_ = 1;
  bool binary_ = false, swap_ = false;
  int label_bytes_ = 4, scalar_bytes_ = 8;
  std::string class_;
};

// "FoamFile { key value; ... }": format, class and arch matter here. A file without the header is
// read as ASCII.
void FoamText::header() {
  skip_space();
  if (t_.substr(pos_, 8) != "FoamFile") return;
  pos_ += 8;
  expect('{', "'{' opening the FoamFile header");
  bool binary = false;
  for (;;) {
    skip_space();
    if (pos_ < t_.size() && t_[pos_] == '}') break;
    const std::string_view key = header_word();
    if (key.empty()) fail("a FoamFile header entry or '}'");
    std::string value;
    for (std::string_view w = header_word(); !w.empty(); w = header_word()) {
      if (!value.empty()) value += ' ';
      value.append(w);
    }
    expect(';', "';' ending the header entry " + std::string(key));
    if (key == "format") {
      if (value != "ascii" && value != "binary") fail_at(line_, "format ascii or binary, found '" + value + "'");
      binary = value == "binary";
    } else if (key == "class") {
      class_ = value;
    } else if (key == "arch") {
      arch(value);
    }
  }
  ++pos_;
  skip_space();
  binary_ = binary;  // byte offsets from here on
}

// "LSB;label=32;scalar=64": byte order and sizes of binary labels and scalars.
void FoamText::arch(std::string_view a) {
  const auto size_of = [&](std::string_view key, int fallback) {
    const size_t at = a.find(key);
    if (at == std::string_view::npos) return fallback;
    const std::string_view v = a.substr(at + key.size(), 2);
    if (v == "32") return 4;
    if (v == "64") return 8;
    fail_at(line_, std::string(key) + "32 or 64 in the arch entry, found '" + std::string(a) + "'");
  };
  label_bytes_ = size_of("label=", 4);
  scalar_bytes_ = size_of("scalar=", 8);
  const bool msb = a.find("MSB") != std::string_view::npos;
  swap_ = msb == (std::endian::native == std::endian::little);
}

using List = FoamText::List;

void read_points(FoamText& f, MeshInput& in) {
  const List l = f.open_list("the number of points", f.binary() ? 3 * f.scalar_bytes() : 8);  // "(0 0 0)\n"
  if (l.uniform) f.fail("a list of distinct points, not a uniform list");
  in.points.reserve(static_cast<size_t>(3 * l.n));
  for (int64_t i = 0; i < l.n; ++i) {
    if (!f.binary()) f.expect('(', "'(' opening point " + std::to_string(i));
    for (int k = 0; k < 3; ++k) {
      const int64_t at = f.binary() ? f.raw_loc() : f.loc();
      const double x = f.scalar("a point coordinate");
      if (!std::isfinite(x)) f.fail_at(at, "a point coordinate (a finite number), found " + std::to_string(x));
      in.points.push_back(x);
    }
    if (!f.binary()) f.expect(')', "')' closing point " + std::to_string(i));
  }
  f.close_list(l);
  f.expect_end("the list of points");
}

// A vertex label of a face, checked against the points.
int32_t vertex_id(FoamText& f, int64_t nv) {
  const int64_t at = f.binary() ? f.raw_loc() : f.loc();
  const int64_t v = f.label("a point label");
  if (v < 0 || v >= nv) f.fail_at(at, "a point label in [0, " + std::to_string(nv - 1) + "], found " + std::to_string(v));
  return static_cast<int32_t>(v);
}

void end_face(FoamText& f, MeshInput& in) {
  if (in.faces.items.size() > static_cast<size_t>(kMaxId)) f.fail("fewer than 2^31 face corners in all");
  in.faces.offsets.push_back(static_cast<int32_t>(in.faces.items.size()));
}

// faceList: "n(v0 .. vn-1)" per face.
void read_face_list(FoamText& f, int64_t nv, MeshInput& in) {
  const List l = f.open_list("the number of faces", 10);
  if (l.uniform) f.fail("a list of faces, not a uniform list");
  in.faces.reserve(static_cast<size_t>(l.n), static_cast<size_t>(4 * l.n));
  in.face_loc.reserve(static_cast<size_t>(l.n));
  for (int64_t i = 0; i < l.n; ++i) {
    in.face_loc.push_back(f.loc());
    const List k = f.open_list("the number of points of a face", 2);
    if (k.uniform) f.fail("the point labels of face " + std::to_string(i) + ", not a uniform list");
    for (int64_t j = 0; j < k.n; ++j) in.faces.items.push_back(vertex_id(f, nv));
    f.close_list(k);
    end_face(f, in);
  }
  f.close_list(l);
}

// faceCompactList: nFaces+1 offsets rising from 0, then the labels.
void read_compact_faces(FoamText& f, int64_t nv, MeshInput& in) {
  const int64_t at = f.loc();
  const List l = f.open_list("the number of face offsets", f.binary() ? f.label_bytes() : 2);
  if (l.uniform) f.fail("a list of face offsets, not a uniform list");
  if (l.n == 0) f.fail_at(at, "at least one face offset (the number of faces + 1), found 0");
  std::vector<int64_t> offsets(static_cast<size_t>(l.n));
  for (size_t i = 0; i < offsets.size(); ++i) {
    const int64_t where = f.binary() ? f.raw_loc() : f.loc();
    offsets[i] = f.label("a face offset");
    const int64_t prev = i ? offsets[i - 1] : 0;
    if (offsets[i] < prev || (i == 0 && offsets[0] != 0) || offsets[i] > kMaxId)
      f.fail_at(where, "face offsets rising from 0, found " + std::to_string(offsets[i]) + " after " + std::to_string(prev));
  }
  f.close_list(l);
  const int64_t labels_at = f.loc();
  const List m = f.open_list("the number of face labels", f.binary() ? f.label_bytes() : 2);
  if (m.uniform) f.fail("a list of face labels, not a uniform list");
  if (m.n != offsets.back())
    f.fail_at(labels_at, std::to_string(offsets.back()) + " face labels as the last offset says, found " + std::to_string(m.n));
  in.faces.reserve(offsets.size() - 1, static_cast<size_t>(m.n));
  in.face_loc.reserve(offsets.size() - 1);
  for (size_t i = 0; i + 1 < offsets.size(); ++i) {
    in.face_loc.push_back(f.binary() ? f.raw_loc() : f.loc());
    for (int64_t j = offsets[i]; j < offsets[i + 1]; ++j) in.faces.items.push_back(vertex_id(f, nv));
    end_face(f, in);
  }
  f.close_list(m);
}

void read_faces(FoamText& f, int64_t nv, MeshInput& in) {
  if (f.cls() == "faceCompactList") read_compact_faces(f, nv, in);
  else if (f.cls().empty() || f.cls() == "faceList") read_face_list(f, nv, in);
  else f.fail_at(1, "class faceList or faceCompactList in the FoamFile header, found " + f.cls());
  f.expect_end("the faces");
  in.binary = f.binary();
}

// owner or neighbour: one cell label per face (owner: exactly nf; neighbour: at most nf).
std::vector<int32_t> read_cell_labels(FoamText& f, int64_t nf, bool is_owner) {
  const int64_t at = f.loc();
  const List l = f.open_list("the number of cell labels", f.binary() ? f.label_bytes() : 2);
  if (is_owner ? l.n != nf : l.n > nf)
    f.fail_at(at, (is_owner ? "one owner cell for each of the " : "at most one neighbour cell for each of the ") +
                      std::to_string(nf) + " faces, found " + std::to_string(l.n));
  std::vector<int32_t> cells(static_cast<size_t>(l.n));
  int64_t value = 0;
  for (size_t i = 0; i < cells.size(); ++i) {
    const int64_t where = f.binary() ? f.raw_loc() : f.loc();
    if (!l.uniform || i == 0) value = f.label("a cell label");
    // Old files pad neighbour with -1 for the boundary faces.
    if (value < (is_owner ? 0 : -1) || value >= kMaxId)
      f.fail_at(where, std::string("a cell label in [") + (is_owner ? "0" : "-1") + ", 2^31), found " + std::to_string(value));
    cells[i] = static_cast<int32_t>(value);
  }
  if (l.uniform && l.n == 0) f.label("the value of the uniform list");
  f.close_list(l);
  f.expect_end("the list of cell labels");
  return cells;
}

}  // namespace

MeshInput read_foam(const FoamFiles& files) {
  MeshInput in;
  FoamText points(files.points, files.points_name);
  read_points(points, in);
  FoamText faces(files.faces, files.faces_name);
  in.source = files.faces_name;
  read_faces(faces, static_cast<int64_t>(in.points.size() / 3), in);
  const int64_t nf = static_cast<int64_t>(in.faces.rows());
  FoamText owner_file(files.owner, files.owner_name);
  const std::vector<int32_t> owner = read_cell_labels(owner_file, nf, true);
  FoamText neighbour_file(files.neighbour, files.neighbour_name);
  std::vector<int32_t> neighbour = read_cell_labels(neighbour_file, nf, false);
  // The internal faces: the neighbour list up to its first -1 padding, which must run to its end.
  const auto pad = std::find(neighbour.begin(), neighbour.end(), -1);
  if (std::find_if(pad, neighbour.end(), [](int32_t c) { return c != -1; }) != neighbour.end())
    throw InputError(files.neighbour_name, {}, "expected the -1 padding of neighbour only after the internal faces");
  neighbour.erase(pad, neighbour.end());
  int32_t nc = 0;
  for (int32_t c : owner) nc = std::max(nc, c + 1);
  for (int32_t c : neighbour) nc = std::max(nc, c + 1);
  // Each cell's faces in face order: 2*f for its owned faces, 2*f + 1 for those it sees reversed.
  int32_t empty = -1;
  in.cells = detail::cells_from_sides(owner, neighbour, nc, empty);
  if (empty >= 0)
    throw InputError(files.owner_name, {}, "expected every cell below the highest label to own or neighbour a face, cell " +
                                               std::to_string(empty) + " has none");
  return in;
}

}  // namespace hbc

namespace hbc::detail {

// A labelList file (the processor addressing of a decomposed case): its labels, and with `locs`
// where each one stands (line, or byte offset when binary), for the message of a caller that finds
// one wrong only once every processor has been read.
std::vector<int64_t> read_foam_labels(std::string_view bytes, const std::string& source, std::vector<int64_t>* locs,
                                      bool* binary) {
  FoamText f(bytes, source);
  const List l = f.open_list("the number of labels", f.binary() ? f.label_bytes() : 2);
  std::vector<int64_t> out(static_cast<size_t>(l.n));
  if (locs) locs->resize(out.size());
  for (size_t i = 0; i < out.size(); ++i) {
    if (locs) (*locs)[i] = f.binary() ? f.raw_loc() : f.loc();
    if (!l.uniform || i == 0) out[i] = f.label("a label");
    else out[i] = out[0];
  }
  if (l.uniform && l.n == 0) f.label("the value of the uniform list");
  f.close_list(l);
  f.expect_end("the list of labels");
  if (binary) *binary = f.binary();
  return out;
}

}  // namespace hbc::detail
