// Legacy VTK (.vtk, DataFile versions 2.0 to 5.1), DATASET UNSTRUCTURED_GRID, ASCII or BINARY
// (binary numbers are big-endian). Cells come as "CELLS n size" with each cell's count before its
// point ids (versions before 5), or as "CELLS noffsets nconn" with OFFSETS and CONNECTIVITY arrays
// (5.x). POINT_DATA, CELL_DATA and FIELD data follow the cells and are read past.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "io/detail/byte_cursor.hpp"
#include "hbc/io.hpp"
#include "io/detail/text_scanner.hpp"
#include "io/detail/vtk_cells.hpp"

namespace hbc {
namespace {

// Byte size of a legacy VTK data type name, 0 for a name we do not know.
int type_size(const std::string& t) {
  if (t == "float") return 4;
  if (t == "double") return 8;
  if (t == "int" || t == "unsigned_int") return 4;
  if (t == "long" || t == "unsigned_long" || t == "vtktypeint64" || t == "vtktypeuint64" || t == "vtkidtype") return 8;
  if (t == "short" || t == "unsigned_short") return 2;
  if (t == "char" || t == "unsigned_char" || t == "bit") return 1;
  return 0;
}

class VtkReader {
 public:
  VtkReader(std::string_view bytes, const std::string& source) : c_(bytes, source) { in_.source = source; }
  MeshInput read();

 private:
  void header();
  // `n` numbers of the named data type; `locs` (if given) gets where each one is.
  template <class T>
  void numbers(const std::string& type, int64_t n, std::vector<T>& out, std::vector<int64_t>* locs);
  std::string type_word(bool integer);
  void points();
  void cells_old(int64_t n, int64_t size);
  void cells_new(int64_t noffsets, int64_t nconn);
  void field();

  detail::ByteCursor c_;
  MeshInput in_;
  bool binary_ = false;
  int major_ = 0;
  int64_t nv_ = -1;
  std::vector<int64_t> offsets_, conn_, cell_locs_;
};

void VtkReader::header() {
  const std::string_view first = c_.line_text();
  if (first.substr(0, 5) != "# vtk") c_.fail_at(1, "'# vtk DataFile Version x.y' on the first line of a legacy VTK file");
  const size_t at = first.rfind(' ');
  const std::string_view version = first.substr(at + 1);
  if (version.size() < 3 || version[0] < '2' || version[0] > '5' || version[1] != '.')
    c_.fail_at(1, "a DataFile version 2.0 to 5.1, found '" + std::string(version.substr(0, 20)) + "'");
  major_ = version[0] - '0';
  c_.line_text();  // the title, free text
  const std::string kind = detail::lower(c_.word("ASCII or BINARY"));
  if (kind != "ascii" && kind != "binary") c_.fail("ASCII or BINARY, found '" + kind.substr(0, 40) + "'");
  binary_ = kind == "binary";
  // From here on messages give byte offsets in a binary file (its numbers have no lines).
  c_.set_binary(binary_);
  in_.binary = binary_;
  if (detail::lower(c_.word("DATASET")) != "dataset") c_.fail("DATASET UNSTRUCTURED_GRID");
  const std::string ds = detail::lower(c_.word("the data set type"));
  if (ds != "unstructured_grid") c_.fail("DATASET UNSTRUCTURED_GRID, found DATASET " + ds.substr(0, 40));
}

std::string VtkReader::type_word(bool integer) {
  const std::string t = detail::lower(c_.word("a data type"));
  const bool real = t == "float" || t == "double";
  if (type_size(t) == 0 || t == "bit" || (integer && real))
    c_.fail(std::string(integer ? "an integer" : "a numeric") + " data type (int, vtktypeint64, float, double, ...), found '" + t.substr(0, 40) + "'");
  return t;
}

template <class T>
void VtkReader::numbers(const std::string& type, int64_t n, std::vector<T>& out, std::vector<int64_t>* locs) {
  const int sz = type_size(type);
  c_.checked_count(n, binary_ ? sz : 2, "a number of values");
  out.resize(static_cast<size_t>(n));
  if (locs) locs->resize(static_cast<size_t>(n));
  if (!binary_) {
    for (int64_t i = 0; i < n; ++i) {
      if (locs) (*locs)[i] = c_.loc();
      if constexpr (std::is_integral_v<T>) out[i] = c_.integer("an integer value");
      else out[i] = c_.real("a number");
    }
    return;
  }
  c_.end_line();
  const bool swap = detail::kLittleEndian;  // legacy binary VTK is big-endian
  const bool uns = type.rfind("unsigned", 0) == 0 || type == "vtktypeuint64";
  for (int64_t i = 0; i < n; ++i) {
    if (locs) (*locs)[i] = static_cast<int64_t>(c_.pos());
    const char* what = "a binary value";
    double v = 0;
    switch (sz) {
      case 1: v = uns ? static_cast<double>(c_.bin<uint8_t>(false, what)) : c_.bin<int8_t>(false, what); break;
      case 2: v = uns ? static_cast<double>(c_.bin<uint16_t>(swap, what)) : c_.bin<int16_t>(swap, what); break;
      case 4:
        if (type == "float") v = c_.bin<float>(swap, what);
        else v = uns ? static_cast<double>(c_.bin<uint32_t>(swap, what)) : c_.bin<int32_t>(swap, what);
        break;
      default:
        if (type == "double") v = c_.bin<double>(swap, what);
        else if constexpr (std::is_integral_v<T>) {
          out[i] = uns ? static_cast<int64_t>(c_.bin<uint64_t>(swap, what) & INT64_MAX) : c_.bin<int64_t>(swap, what);
          continue;
        }
        else v = static_cast<double>(c_.bin<int64_t>(swap, what));
    }
    if constexpr (std::is_integral_v<T>) out[i] = static_cast<int64_t>(v);
    else {
      if (!std::isfinite(v)) c_.fail_at(static_cast<int64_t>(c_.pos()) - sz, "a finite coordinate");
      out[i] = v;
    }
  }
}

void VtkReader::points() {
  if (nv_ >= 0) c_.fail("one POINTS section, found a second");
  nv_ = c_.integer_in(0, INT32_MAX, "the number of points");
  const std::string type = type_word(false);
  std::vector<int64_t> locs;
  numbers(type, 3 * nv_, in_.points, &locs);
  in_.vertex_loc.resize(static_cast<size_t>(nv_));
  for (int64_t i = 0; i < nv_; ++i) in_.vertex_loc[i] = locs[3 * i];
}

void VtkReader::cells_old(int64_t n, int64_t size) {
  std::vector<int64_t> flat, locs;
  numbers("int", size, flat, &locs);
  offsets_.assign(1, 0);
  conn_.clear();
  cell_locs_.clear();
  size_t at = 0;
  for (int64_t c = 0; c < n; ++c) {
    if (at >= flat.size()) c_.fail(std::to_string(n) + " cells in the " + std::to_string(size) + " CELLS entries, found " + std::to_string(c));
    const int64_t k = flat[at];
    if (k < 0 || static_cast<uint64_t>(k) > flat.size() - at - 1)
      c_.fail_at(locs[at], "a cell size that fits in the CELLS entries, found " + std::to_string(k));
    cell_locs_.push_back(locs[at]);
    conn_.insert(conn_.end(), flat.begin() + static_cast<std::ptrdiff_t>(at + 1), flat.begin() + static_cast<std::ptrdiff_t>(at + 1 + k));
    offsets_.push_back(static_cast<int64_t>(conn_.size()));
    at += 1 + static_cast<size_t>(k);
  }
  if (at != flat.size()) c_.fail(std::to_string(size) + " CELLS entries for " + std::to_string(n) + " cells, found " + std::to_string(at));
}

void VtkReader::cells_new(int64_t noffsets, int64_t nconn) {
  if (noffsets < 1) c_.fail("at least one offset (the CELLS count is cells + 1), found " + std::to_string(noffsets));
  if (detail::lower(c_.word("OFFSETS")) != "offsets") c_.fail("OFFSETS");
  numbers(type_word(true), noffsets, offsets_, nullptr);
  if (detail::lower(c_.word("CONNECTIVITY")) != "connectivity") c_.fail("CONNECTIVITY");
  std::vector<int64_t> locs;
  numbers(type_word(true), nconn, conn_, &locs);
  if (offsets_[0] != 0 || offsets_.back() != nconn)
    c_.fail("offsets from 0 to the connectivity size " + std::to_string(nconn) + ", found " + std::to_string(offsets_[0]) + " to " + std::to_string(offsets_.back()));
  cell_locs_.clear();
  for (size_t c = 0; c + 1 < offsets_.size(); ++c) {
    if (offsets_[c + 1] < offsets_[c]) c_.fail("non-decreasing OFFSETS, found " + std::to_string(offsets_[c + 1]) + " after " + std::to_string(offsets_[c]));
    cell_locs_.push_back(offsets_[c] < nconn ? locs[static_cast<size_t>(offsets_[c])] : c_.loc());
  }
}

void VtkReader::field() {
  c_.word("the name of the field data");
  const int64_t n = c_.integer_in(0, 1 << 20, "the number of field arrays");
  std::vector<double> skipped;
  for (int64_t i = 0; i < n; ++i) {
    c_.word("the name of a field array");
    const int64_t comps = c_.integer_in(1, 1 << 20, "the number of components of a field array");
    const int64_t tuples = c_.integer_in(0, INT32_MAX, "the number of tuples of a field array");
    const std::string type = detail::lower(c_.word("a data type"));
    if (type == "string" || type_size(type) == 0 || type == "bit")
      c_.fail("a numeric field array type (int, float, double, ...), found '" + type.substr(0, 40) + "'");
    numbers(type, comps * tuples, skipped, nullptr);
  }
}

MeshInput VtkReader::read() {
  header();
  bool have_cells = false, have_types = false;
  std::vector<int64_t> types;
  int64_t types_loc = 0;
  std::string_view t;
  while (c_.token(t)) {
    const std::string kw = detail::lower(t);
    if (kw == "points") points();
    else if (kw == "cells") {
      if (have_cells) c_.fail("one CELLS section, found a second");
      const int64_t a = c_.integer("the number of cells"), b = c_.integer("the size of the cell list");
      if (major_ >= 5) cells_new(a, b);
      else cells_old(c_.checked_count(a, 2, "the number of cells"), b);
      have_cells = true;
    } else if (kw == "cell_types") {
      types_loc = c_.loc();
      numbers("int", c_.integer("the number of cell types"), types, nullptr);
      have_types = true;
    } else if (kw == "metadata") {
      // VTK 9 writes array metadata blocks ended by an empty line.
      c_.line_text();
      while (c_.remaining() > 0 && !c_.line_text().empty()) {
      }
    } else if (kw == "field") {
      field();  // data-set field data (ParaView writes TimeValue here), before or after the cells
    } else if (kw == "point_data" || kw == "cell_data") {
      break;  // attributes follow the geometry; none of them is needed
    } else {
      c_.fail("POINTS, CELLS, CELL_TYPES, POINT_DATA or CELL_DATA, found '" + std::string(t.substr(0, 40)) + "'");
    }
  }
  if (nv_ < 0) c_.fail("a POINTS section");
  if (!have_cells) c_.fail("a CELLS section");
  if (!have_types) c_.fail("a CELL_TYPES section");
  if (types.size() != cell_locs_.size())
    c_.fail_at(types_loc, std::to_string(cell_locs_.size()) + " cell types, one per cell, found " + std::to_string(types.size()));
  detail::VtkCells cells(in_, nv_);
  for (size_t c = 0; c < types.size(); ++c)
    cells.add(types[c], conn_.data() + offsets_[c], static_cast<size_t>(offsets_[c + 1] - offsets_[c]), cell_locs_[c]);
  cells.finish(c_.loc());
  return std::move(in_);
}

}  // namespace

MeshInput read_vtk(std::string_view bytes, const std::string& source) { return VtkReader(bytes, source).read(); }

}  // namespace hbc
