#pragma once
// What the finite-element decks (Abaqus .inp, Nastran .bdf, LS-DYNA .k) share: nodes named by
// labels (any positive integers, gaps and any order, defined before or after the elements that
// use them), every node of a second-order element listed, line-based records with fields, and
// files included by others. LabelledMesh collects nodes and elements as read and resolves the
// labels once at the end, so that a reader is only its record syntax.
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/element_tally.hpp"
#include "mesh/cell_templates.hpp"

namespace hbc::detail {

// Where a record is: a file of the deck (0 the file read, then each included one) and its line.
struct DeckLoc {
  int32_t file = 0;
  int64_t line = 0;
};

// The files of a deck: their names for messages, and for each included file the line of the top
// file that (through any chain of includes) brought it in, which is what cell_loc can hold.
class DeckFiles {
 public:
  explicit DeckFiles(std::string top) { add(std::move(top), 0); }
  int32_t add(std::string name, int64_t top_line);
  const std::string& name(int32_t f) const { return names_[static_cast<size_t>(f)]; }
  int64_t top_line(const DeckLoc& at) const { return at.file == 0 ? at.line : top_line_[static_cast<size_t>(at.file)]; }
  [[noreturn]] void fail(const DeckLoc& at, const std::string& expected) const;
  // The bytes of an included file `path` as written in file `from` (kept alive here), through
  // `fetch`; InputError at `at` when there is no fetch or the nesting is deeper than 16.
  std::string_view include(const IncludeReader& fetch, const DeckLoc& at, const std::string& path, int depth, int32_t& file);

 private:
  std::vector<std::string> names_;
  std::vector<int64_t> top_line_;
  std::deque<std::string> bytes_;  // a deque: views of its strings stay valid as it grows
};

class LabelledMesh {
 public:
  // A node with key `key`: its label, or for Abaqus (instance << 32 | label).
  void node(int64_t key, const double* xyz, const DeckLoc& at);
  // A volume element: `n` node keys, its corners first in MEDIT's order.
  void element(CellShape shape, const int64_t* keys, int n, const DeckLoc& at);
  void skip(int dim) { tally_.skip(dim); }
  // The nodes and elements of `part` added with keys (scope << 32 | key), points moved by `place`
  // (Abaqus instances; `place` maps one point in place).
  template <class Place>
  void add_instance(const LabelledMesh& part, int64_t scope, Place place) {
    for (size_t i = 0; i < part.keys_.size(); ++i) {
      double p[3] = {part.points_[3 * i], part.points_[3 * i + 1], part.points_[3 * i + 2]};
      place(p);
      node((scope << 32) | part.keys_[i], p, part.node_at_[i]);
    }
    for (size_t e = 0; e < part.shape_.size(); ++e) {
      const int32_t b = part.start_[e], n = part.start_[e + 1] - b;
      scratch_.assign(part.el_keys_.begin() + b, part.el_keys_.begin() + b + n);
      for (int64_t& k : scratch_) k |= scope << 32;
      element(part.shape_[e], scratch_.data(), n, part.el_at_[e]);
    }
    tally_.add(part.tally_);
  }
  size_t elements() const { return shape_.size(); }
  // Labels to vertex ids (InputError naming an element's file and line for a label no node has,
  // or the second node of a label), corners through the shared templates, the other nodes of
  // second-order elements dropped, skipped elements reported. `what` names the node records
  // ("*NODE", "GRID") and `volume` the element records for the messages.
  MeshInput finish(const DeckFiles& files, const char* what, const char* volume, const DeckLoc& end) const;

 private:
  std::vector<int64_t> keys_;
  std::vector<double> points_;
  std::vector<DeckLoc> node_at_;
  std::vector<CellShape> shape_;
  std::vector<int32_t> start_{0};
  std::vector<int64_t> el_keys_;
  std::vector<DeckLoc> el_at_;
  std::vector<int64_t> scratch_;
  ElementTally tally_;
};

// One text line at a time, '\r' dropped, with its 1-based number.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  bool next(std::string_view& line);
  int64_t line() const { return line_; }
  // Back to the start of the line last returned, so that the next call returns it again.
  void unread() { pos_ = last_, --line_; }

 private:
  std::string_view text_;
  size_t pos_ = 0, last_ = 0;
  int64_t line_ = 0;
};

// Spaces and tabs off both ends (inline: every field of every line goes through it).
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}
// The whole (trimmed) field as a number; false when it is not one (an empty field is not).
bool parse_int(std::string_view field, int64_t& v);
bool parse_real(std::string_view field, double& v);
// A field shown in a message: quoted, at most 40 characters.
std::string shown_field(std::string_view field);
// Fields split at commas (Abaqus, and the free formats of LS-DYNA and Nastran), trimmed.
void split_commas(std::string_view line, std::vector<std::string_view>& fields);

}  // namespace hbc::detail
