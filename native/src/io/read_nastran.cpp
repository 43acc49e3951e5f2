// Nastran bulk data (.bdf, .nas; MSC/NX Quick Reference Guide, "Bulk Data Entries"): an entry is
// a name and fields, over a first line and its continuations. Three formats, chosen line by line:
// small field (ten 8-character fields), large field (a name ending in '*', then four 16-character
// fields), free field (fields between commas; a name ending in '*' takes four data fields a line).
// Columns 1 and 10 of each line hold the name and the continuation marker; a line starting with
// '+', '*' or ',' or (small field) with a blank first field continues the entry above. What comes
// before BEGIN BULK (executive and case control) and after ENDDATA is not read; '$' starts a
// comment. Reals may drop the E of their exponent (1.-3, 1.5+2). Only the basic coordinate system
// is read: a GRID placed in another (CP) is refused rather than misplaced.
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/labelled_mesh.hpp"

namespace hbc {
namespace {

using detail::DeckLoc;

// ASCII upper case (std::toupper asks the locale for every character: a tenth of the read).
std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return r;
}

// A real in Nastran's forms: 1.0, -.5, 1.E3, 1.D-3, 1.-3, 1.5+2 (an integer is taken too).
bool nastran_real(std::string_view f, double& v) {
  f = detail::trim(f);
  char buf[64];
  if (f.empty() || f.size() >= sizeof buf - 2) return false;
  size_t n = 0;
  for (size_t i = 0; i < f.size(); ++i) {
    char c = f[i];
    if (c == 'D' || c == 'd') c = 'E';
    // A sign after a digit or point starts the exponent when no E does.
    if ((c == '+' || c == '-') && i > 0 && f[i - 1] != 'E' && f[i - 1] != 'e' && f[i - 1] != 'D' && f[i - 1] != 'd')
      buf[n++] = 'E';
    buf[n++] = c;
  }
  return detail::parse_real(std::string_view(buf, n), v);
}

struct EntryKind {
  const char* name;
  CellShape shape;  // Faces: skipped, counted in `dim`
  int corners, nodes, dim;
};

constexpr EntryKind kKinds[] = {
    {"CHEXA", CellShape::Hex, 8, 20, 3},      {"CPENTA", CellShape::Prism, 6, 15, 3},
    {"CPYRAM", CellShape::Pyramid, 5, 13, 3}, {"CTETRA", CellShape::Tet, 4, 10, 3},
    {"CQUAD4", CellShape::Faces, 0, 0, 2},    {"CQUAD8", CellShape::Faces, 0, 0, 2},
    {"CQUADR", CellShape::Faces, 0, 0, 2},    {"CQUAD", CellShape::Faces, 0, 0, 2},
    {"CTRIA3", CellShape::Faces, 0, 0, 2},    {"CTRIA6", CellShape::Faces, 0, 0, 2},
    {"CTRIAR", CellShape::Faces, 0, 0, 2},    {"CSHEAR", CellShape::Faces, 0, 0, 2},
    {"CBAR", CellShape::Faces, 0, 0, 1},      {"CBEAM", CellShape::Faces, 0, 0, 1},
    {"CROD", CellShape::Faces, 0, 0, 1},      {"CONROD", CellShape::Faces, 0, 0, 1},
    {"CTUBE", CellShape::Faces, 0, 0, 1},     {"CBUSH", CellShape::Faces, 0, 0, 1},
    {"CGAP", CellShape::Faces, 0, 0, 1},      {"CELAS1", CellShape::Faces, 0, 0, 1},
    {"CELAS2", CellShape::Faces, 0, 0, 1},    {"CDAMP1", CellShape::Faces, 0, 0, 1},
    {"RBE2", CellShape::Faces, 0, 0, 1},      {"RBE3", CellShape::Faces, 0, 0, 1},
    {"RBAR", CellShape::Faces, 0, 0, 1},      {"PLOTEL", CellShape::Faces, 0, 0, 1},
    {"CONM1", CellShape::Faces, 0, 0, 0},     {"CONM2", CellShape::Faces, 0, 0, 0},
    {"CMASS1", CellShape::Faces, 0, 0, 0},    {"CMASS2", CellShape::Faces, 0, 0, 0},
};

class NastranReader {
 public:
  NastranReader(const std::string& source, const IncludeReader& include) : files_(source), include_(include) {}
  MeshInput read(std::string_view text) {
    // Without BEGIN BULK the whole file is bulk data (an included deck, most converters' output).
    lines(text, 0, 0, text.find("BEGIN BULK") != std::string_view::npos || text.find("begin bulk") != std::string_view::npos);
    entry();
    return mesh_.finish(files_, "GRID", "CHEXA, CPENTA, CPYRAM or CTETRA", end_);
  }

 private:
  void lines(std::string_view text, int32_t file, int depth, bool skip_to_bulk);
  // The line's fields after its first (name or marker), up to its continuation marker.
  void data_fields(std::string_view line, bool free, bool large);
  void entry();
  void grid();
  void element(const EntryKind& k);
  int64_t label(size_t i, const char* what) const {
    int64_t v = 0;
    const std::string_view f = i < data_.size() ? data_[i] : std::string_view();
    if (!detail::parse_int(f, v) || v < 1 || v > 0xffffffffLL)
      files_.fail(at_, std::string(what) + " (an integer from 1 to 2^32 - 1), found " + detail::shown_field(f));
    return v;
  }

  detail::DeckFiles files_;
  const IncludeReader& include_;
  detail::LabelledMesh mesh_;
  DeckLoc end_, at_;
  bool done_ = false;  // ENDDATA read
  std::string name_;   // the open entry's name, upper case without '*'
  std::vector<std::string_view> data_, split_;
  std::vector<int64_t> ids_;
};

void NastranReader::data_fields(std::string_view line, bool free, bool large) {
  if (free) {
    detail::split_commas(line, split_);
    // Eight small or four large data fields a line; a longer line goes on past a marker field.
    const size_t per = large ? 4 : 8;
    for (size_t i = 1; i < split_.size(); ++i)
      if ((i - 1) % (per + 1) != per) data_.push_back(split_[i]);
    return;
  }
  const size_t w = large ? 16 : 8, n = large ? 4 : 8;
  for (size_t k = 0; k < n; ++k) {
    const size_t b = 8 + k * w;
    data_.push_back(b < line.size() ? detail::trim(line.substr(b, w)) : std::string_view());
  }
}

void NastranReader::lines(std::string_view text, int32_t file, int depth, bool skip_to_bulk) {
  detail::LineCursor c(text);
  std::string_view line;
  while (!done_ && c.next(line)) {
    const DeckLoc at{file, c.line()};
    if (file == 0) end_ = at;
    if (const size_t d = line.find('$'); d != std::string_view::npos) line = line.substr(0, d);
    if (detail::trim(line).empty()) continue;
    // Only BEGIN BULK, ENDDATA and INCLUDE are looked for by their words.
    const std::string_view tl = detail::trim(line);
    const char h = static_cast<char>(tl[0] & ~0x20);
    const std::string head = skip_to_bulk || h == 'E' || h == 'I' ? upper(tl.substr(0, 10)) : std::string();
    if (skip_to_bulk) {
      skip_to_bulk = head.rfind("BEGIN BULK", 0) != 0;
      continue;
    }
    const bool free = line.find(',') != std::string_view::npos;
    std::string_view first = free ? detail::trim(line.substr(0, line.find(','))) : detail::trim(line.substr(0, std::min<size_t>(8, line.size())));
    const char c0 = line[0];
    if (c0 == '+' || c0 == '*' || c0 == ',' || (!free && first.empty())) {
      if (name_.empty()) files_.fail(at, "a bulk data entry before its continuation line");
      data_fields(line, free, c0 == '*');
      continue;
    }
    entry();
    if (head.rfind("ENDDATA", 0) == 0) {
      done_ = true;
      break;
    }
    if (head.rfind("INCLUDE", 0) == 0) {
      std::string_view path = detail::trim(line.substr(7));
      if (path.size() >= 2 && path.front() == '\'' && path.back() == '\'') path = path.substr(1, path.size() - 2);
      int32_t f = 0;
      const std::string_view bytes = files_.include(include_, at, std::string(path), depth, f);
      lines(bytes, f, depth + 1, false);
      continue;
    }
    const bool large = !first.empty() && first.back() == '*';
    if (large) first.remove_suffix(1);
    name_ = upper(first);
    at_ = at;
    data_.clear();
    data_fields(line, free, large);
  }
  if (file == 0 && !done_) end_.line = std::max<int64_t>(1, c.line());
}

void NastranReader::entry() {
  if (name_.empty()) return;
  if (name_ == "GRID") {
    grid();
  } else {
    for (const EntryKind& k : kKinds)
      if (name_ == k.name) {
        if (k.shape == CellShape::Faces) mesh_.skip(k.dim);
        else element(k);
        break;
      }
  }
  name_.clear();
}

void NastranReader::grid() {
  const int64_t id = label(0, "a GRID's id");
  const std::string_view cp = data_.size() > 1 ? data_[1] : std::string_view();
  int64_t sys = 0;
  if (!cp.empty() && (!detail::parse_int(cp, sys) || sys != 0))
    files_.fail(at_, "GRID " + std::to_string(id) + " in the basic coordinate system (CP blank or 0), found CP " +
                         detail::shown_field(cp) + ": hbc reads no CORD frames");
  double p[3] = {0, 0, 0};
  for (size_t k = 0; k < 3; ++k) {
    const std::string_view f = k + 2 < data_.size() ? data_[k + 2] : std::string_view();
    if (!f.empty() && !nastran_real(f, p[k]))
      files_.fail(at_, "a coordinate of GRID " + std::to_string(id) + " (a real), found " + detail::shown_field(f));
  }
  mesh_.node(id, p, at_);
}

void NastranReader::element(const EntryKind& k) {
  label(0, "an element id");
  ids_.clear();
  // G1 .. from the third field: the corners, then any of the mid-edge grids (Nastran lets each be
  // left blank); trailing blanks are a first-order element's unused fields.
  size_t last = data_.size();
  while (last > 2 && data_[last - 1].empty()) --last;
  for (size_t i = 2; i < last; ++i)
    if (i < 2 + static_cast<size_t>(k.corners) || !data_[i].empty()) ids_.push_back(label(i, "a grid id of the element"));
  const int n = static_cast<int>(ids_.size());
  if (n < k.corners || n > k.nodes)
    files_.fail(at_, std::string("a ") + k.name + " with " + std::to_string(k.corners) + " to " + std::to_string(k.nodes) +
                         " grid ids, found " + std::to_string(n));
  mesh_.element(k.shape, ids_.data(), n, at_);
}

}  // namespace

MeshInput read_nastran(std::string_view text, const std::string& source, const IncludeReader& include) {
  return NastranReader(source, include).read(text);
}

}  // namespace hbc
