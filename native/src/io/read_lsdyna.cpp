// LS-DYNA keyword files (.k, .key; LS-DYNA Keyword User's Manual, "General card format",
// *NODE, *ELEMENT_SOLID): a keyword line starting with '*', then its cards; '$' starts a comment
// line; *END ends the input. Cards are fixed-width unless they hold a comma (free format, fields
// between commas). Widths: standard (*NODE: NID i8, X Y Z e16; elements: i8 fields), I10 (a
// keyword ending in " %": integers i10, reals e16) and long (a keyword ending in " +", or every
// keyword after *KEYWORD LONG=Y: every field 20 wide). *ELEMENT_SOLID has two forms: one card
// "EID PID N1..N8", or a card "EID PID" and a card N1..N10 (the 10-node tetrahedron when N9, N10
// are set: corners N1..N4). Its tetrahedra, pyramids and prisms are hexahedra with repeated nodes:
// N4=N5=N6=N7=N8 a tetrahedron N1..N4 (or N5..N8 left blank), N5=N6=N7=N8 a pyramid, N5=N6 and
// N7=N8 a prism; the last two are what collapsing the hexahedron's faces gives, as MEDIT's are.
// _ORTHO and _DOF take two and one card more per element, read past. *ELEMENT_SHELL, _BEAM,
// _TSHELL, _DISCRETE, _MASS (one card an element) are skipped and counted.
#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/labelled_mesh.hpp"

namespace hbc {
namespace {

using detail::DeckLoc;

enum class Width { Standard, I10, Long };

class LsDynaReader {
 public:
  LsDynaReader(const std::string& source, const IncludeReader& include) : files_(source), include_(include) {}
  MeshInput read(std::string_view text) {
    lines(text, 0, 0);
    if (pending_) files_.fail(card1_at_, "the node card of the *ELEMENT_SOLID element above, found none");
    return mesh_.finish(files_, "*NODE", "*ELEMENT_SOLID", end_);
  }

 private:
  enum class Mode { Other, Node, Solid, Skip, Include };
  void lines(std::string_view text, int32_t file, int depth);
  void keyword(std::string_view line, const DeckLoc& at);
  // The card's fields: between commas, else `n` fixed fields of the widths `w` (the last repeated).
  void fields(std::string_view line, std::initializer_list<size_t> w, size_t n);
  void node(const DeckLoc& at);
  void solid(std::string_view line, const DeckLoc& at);
  void solid_nodes(size_t first, const DeckLoc& at);
  int64_t label(size_t i, const DeckLoc& at, const char* what, bool blank_ok) const {
    const std::string_view f = i < f_.size() ? f_[i] : std::string_view();
    int64_t v = 0;
    if (blank_ok && (f.empty() || (detail::parse_int(f, v) && v == 0))) return 0;
    if (!detail::parse_int(f, v) || v < 1 || v > 0xffffffffLL)
      files_.fail(at, std::string(what) + " (an integer from 1 to 2^32 - 1), found " + detail::shown_field(f));
    return v;
  }
  size_t int_width() const { return width_ == Width::Long ? 20 : width_ == Width::I10 ? 10 : 8; }

  detail::DeckFiles files_;
  const IncludeReader& include_;
  detail::LabelledMesh mesh_;
  DeckLoc end_;
  Mode mode_ = Mode::Other;
  Width width_ = Width::Standard;
  bool long_all_ = false, done_ = false;
  int skip_dim_ = 2, extra_cards_ = 0, to_skip_ = 0;
  bool pending_ = false;  // an "EID PID" card read, its node card next
  DeckLoc card1_at_;
  std::vector<std::string_view> f_;
};

void LsDynaReader::lines(std::string_view text, int32_t file, int depth) {
  detail::LineCursor c(text);
  std::string_view line;
  while (!done_ && c.next(line)) {
    const DeckLoc at{file, c.line()};
    if (file == 0) end_ = at;
    if (line.empty() || line[0] == '$') continue;
    if (line[0] == '*') {
      if (pending_) files_.fail(card1_at_, "the node card of the *ELEMENT_SOLID element above, found " + detail::shown_field(line));
      keyword(line, at);
      continue;
    }
    if (detail::trim(line).empty()) continue;
    switch (mode_) {
      case Mode::Node:
        fields(line, {int_width(), width_ == Width::Long ? size_t{20} : size_t{16}}, 4);
        node(at);
        break;
      case Mode::Solid: solid(line, at); break;
      case Mode::Skip: mesh_.skip(skip_dim_); break;
      case Mode::Include: {
        int32_t f = 0;
        const std::string_view bytes = files_.include(include_, at, std::string(detail::trim(line)), depth, f);
        lines(bytes, f, depth + 1);
        mode_ = Mode::Other;
        break;
      }
      case Mode::Other: break;
    }
  }
  if (file == 0) end_.line = std::max<int64_t>(1, c.line());
}

void LsDynaReader::keyword(std::string_view line, const DeckLoc& at) {
  std::string k;
  for (char ch : detail::trim(line.substr(1))) k += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  width_ = long_all_ ? Width::Long : Width::Standard;
  if (!k.empty() && (k.back() == '+' || k.back() == '%' || k.back() == '-')) {
    width_ = k.back() == '+' ? Width::Long : k.back() == '%' ? Width::I10 : Width::Standard;
    k.pop_back();
    while (!k.empty() && k.back() == ' ') k.pop_back();
  }
  const std::string name = k.substr(0, k.find(' '));
  mode_ = Mode::Other;
  if (name == "KEYWORD") {
    long_all_ = k.find("LONG=Y") != std::string::npos;
  } else if (name == "END") {
    done_ = true;
  } else if (name == "INCLUDE") {
    mode_ = Mode::Include;
  } else if (name == "NODE") {
    mode_ = Mode::Node;
  } else if (name == "ELEMENT_SOLID" || name == "ELEMENT_SOLID_ORTHO" || name == "ELEMENT_SOLID_DOF") {
    mode_ = Mode::Solid;
    extra_cards_ = name == "ELEMENT_SOLID_ORTHO" ? 2 : name == "ELEMENT_SOLID_DOF" ? 1 : 0;
    to_skip_ = 0;
  } else if (name.rfind("ELEMENT_SOLID", 0) == 0) {
    files_.fail(at, "*ELEMENT_SOLID, _ORTHO or _DOF (the forms hbc reads), found *" + name);
  } else {
    const std::pair<const char*, int> skipped[] = {{"ELEMENT_SHELL", 2}, {"ELEMENT_TSHELL", 2}, {"ELEMENT_BEAM", 1},
                                                   {"ELEMENT_DISCRETE", 1}, {"ELEMENT_MASS", 0}};
    for (const auto& [s, dim] : skipped)
      if (name == s) mode_ = Mode::Skip, skip_dim_ = dim;
  }
}

void LsDynaReader::fields(std::string_view line, std::initializer_list<size_t> w, size_t n) {
  if (line.find(',') != std::string_view::npos) return detail::split_commas(line, f_);
  f_.clear();
  size_t b = 0;
  for (size_t i = 0; i < n; ++i) {
    const size_t wi = *(w.begin() + std::min(i, w.size() - 1));
    f_.push_back(b < line.size() ? detail::trim(line.substr(b, wi)) : std::string_view());
    b += wi;
  }
}

void LsDynaReader::node(const DeckLoc& at) {
  const int64_t id = label(0, at, "a node id", false);
  double p[3] = {0, 0, 0};
  for (size_t k = 0; k < 3; ++k) {
    const std::string_view f = k + 1 < f_.size() ? f_[k + 1] : std::string_view();
    if (!f.empty() && !detail::parse_real(f, p[k]))
      files_.fail(at, "a coordinate of node " + std::to_string(id) + " (a number), found " + detail::shown_field(f));
  }
  mesh_.node(id, p, at);
}

void LsDynaReader::solid(std::string_view line, const DeckLoc& at) {
  if (to_skip_ > 0) {
    --to_skip_;
    return;
  }
  fields(line, {int_width()}, 10);
  if (pending_) {
    pending_ = false;
    solid_nodes(0, card1_at_);
    return;
  }
  label(0, at, "an element id", false);
  const bool nodes_here = std::any_of(f_.begin() + std::min<size_t>(2, f_.size()), f_.end(), [](std::string_view f) { return !f.empty(); });
  if (!nodes_here) {
    pending_ = true;
    card1_at_ = at;
    return;
  }
  solid_nodes(2, at);
}

void LsDynaReader::solid_nodes(size_t first, const DeckLoc& at) {
  std::array<int64_t, 10> n{};
  for (size_t k = 0; k < 10; ++k) n[k] = label(first + k, at, "a node id of the element", true);
  to_skip_ = extra_cards_;
  for (size_t k = 0; k < 4; ++k)
    if (n[k] == 0) files_.fail(at, "node ids N1 to N4 of the element, found a blank N" + std::to_string(k + 1));
  if (first == 0 && n[8] != 0 && n[9] != 0) return mesh_.element(CellShape::Tet, n.data(), 10, at);
  const bool tet = std::all_of(n.begin() + 4, n.begin() + 8, [&](int64_t v) { return v == n[3]; }) ||
                   std::all_of(n.begin() + 4, n.begin() + 8, [](int64_t v) { return v == 0; });
  if (tet) return mesh_.element(CellShape::Tet, n.data(), 4, at);
  for (size_t k = 4; k < 8; ++k)
    if (n[k] == 0) files_.fail(at, "node ids N5 to N8 of the element (all set, or all blank for a tetrahedron), found a blank N" + std::to_string(k + 1));
  mesh_.element(CellShape::Hex, n.data(), 8, at);
}

}  // namespace

MeshInput read_lsdyna(std::string_view text, const std::string& source, const IncludeReader& include) {
  return LsDynaReader(source, include).read(text);
}

}  // namespace hbc
