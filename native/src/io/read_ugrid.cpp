// AFLR3 UGRID (simcenter.msstate.edu/software/documentation/ug_io, "ugrid"): the counts
// nnodes ntri nquad ntet npyr nprz nhex, the node coordinates, the boundary triangles and
// quadrilaterals and then one surface tag each (read past, counted), then the tetrahedra,
// pyramids, prisms and hexahedra; ids are 1-based. What follows the hexahedra (volume tags,
// boundary-layer counts) is not needed. The encoding is in the file name: .ugrid ASCII,
// .b8.ugrid big-endian and .lb8.ugrid little-endian 4-byte integers and 8-byte reals,
// .r8.ugrid/.lr8.ugrid the same as Fortran unformatted records (a 4-byte length before and after
// the header's record and around the record of everything else).
// Corner orders are MEDIT's but for the pyramid: UGRID's base is 1-2-5-4 around the apex 3
// (1-based), MEDIT's 0-1-2-3 under 4; meshio 5.3 reads UGRID pyramids with the same permutation.
#include <array>
#include <cmath>
#include <cstdint>

#include "hbc/io.hpp"
#include "io/detail/byte_cursor.hpp"
#include "io/detail/element_tally.hpp"
#include "io/detail/text_scanner.hpp"
#include "mesh/cell_templates.hpp"

namespace hbc {
namespace {

using detail::Element;

class UgridReader {
 public:
  UgridReader(std::string_view bytes, const std::string& source, UgridEncoding enc)
      : c_(bytes, source), enc_(enc), cells_(in_) {
    in_.source = source;
    in_.binary = enc != UgridEncoding::Ascii;
    c_.set_binary(in_.binary);
    swap_ = (enc == UgridEncoding::BigEndian || enc == UgridEncoding::FortranBigEndian) == detail::kLittleEndian;
  }
  MeshInput read();

 private:
  int64_t integer(const char* what) { return in_.binary ? c_.bin<int32_t>(swap_, what) : c_.integer(what); }
  double real(const char* what) {
    if (!in_.binary) return c_.real(what);
    const int64_t at = c_.loc();
    const double x = c_.bin<double>(swap_, what);
    if (!std::isfinite(x)) c_.fail_at(at, std::string(what) + " (a finite number)");
    return x;
  }
  bool fortran() const { return enc_ == UgridEncoding::FortranBigEndian || enc_ == UgridEncoding::FortranLittleEndian; }
  void record_mark(const char* what) {
    if (fortran()) integer(what);
  }
  void elements(Element e, int64_t n);

  detail::ByteCursor c_;
  UgridEncoding enc_;
  bool swap_ = false;
  MeshInput in_;
  detail::CellAppender cells_;
  int64_t nv_ = 0;
};

// UGRID corner k of an element as MEDIT's corner k: only the pyramid differs.
constexpr std::array<int8_t, 8> kId{0, 1, 2, 3, 4, 5, 6, 7};
constexpr std::array<int8_t, 8> kPyramid{1, 0, 3, 4, 2, 5, 6, 7};

void UgridReader::elements(Element e, int64_t n) {
  const int k = detail::corner_count(e);
  const auto& perm = e == Element::Pyramid ? kPyramid : kId;
  std::array<int32_t, 8> raw{}, v{};
  for (int64_t i = 0; i < n; ++i) {
    const int64_t loc = c_.loc();
    for (int a = 0; a < k; ++a) {
      const int64_t at = c_.loc();
      const int64_t id = integer("a node id of a volume element");
      if (id < 1 || id > nv_) c_.fail_at(at, "a node id in [1, " + std::to_string(nv_) + "], found " + std::to_string(id));
      raw[a] = static_cast<int32_t>(id - 1);
    }
    for (int a = 0; a < k; ++a) v[a] = raw[perm[a]];
    cells_.element(e, v.data(), loc);
  }
}

MeshInput UgridReader::read() {
  record_mark("the Fortran record length of the header");
  std::array<int64_t, 7> n{};
  static const char* const kWhat[7] = {"the number of nodes", "the number of boundary triangles",
                                       "the number of boundary quadrilaterals", "the number of tetrahedra",
                                       "the number of pyramids", "the number of prisms", "the number of hexahedra"};
  // Each item takes at least 2 bytes of text (a digit and a space) or 4 of binary per number.
  static const int64_t kNumbers[7] = {3, 4, 5, 4, 5, 6, 8};
  const int64_t per = in_.binary ? 4 : 2;
  for (int i = 0; i < 7; ++i) n[i] = c_.checked_count(integer(kWhat[i]), kNumbers[i] * per, kWhat[i]);
  record_mark("the Fortran record length after the header");
  record_mark("the Fortran record length of the mesh");
  nv_ = n[0];
  if (nv_ > INT32_MAX) c_.fail("fewer than 2^31 nodes");
  in_.points.reserve(static_cast<size_t>(3 * nv_));
  in_.vertex_loc.reserve(static_cast<size_t>(nv_));
  for (int64_t i = 0; i < nv_; ++i) {
    in_.vertex_loc.push_back(c_.loc());
    for (int a = 0; a < 3; ++a) in_.points.push_back(real("a node coordinate"));
  }
  // Boundary faces and their tags: read past, ids checked all the same.
  for (int64_t i = 0; i < 3 * n[1] + 4 * n[2]; ++i) {
    const int64_t at = c_.loc();
    const int64_t id = integer("a node id of a boundary face");
    if (id < 1 || id > nv_) c_.fail_at(at, "a node id in [1, " + std::to_string(nv_) + "], found " + std::to_string(id));
  }
  for (int64_t i = 0; i < n[1] + n[2]; ++i) integer("a boundary face tag");
  elements(Element::Tet, n[3]);
  elements(Element::Pyramid, n[4]);
  elements(Element::Prism, n[5]);
  elements(Element::Hex, n[6]);
  if (in_.cells.rows() == 0) c_.fail("at least one volume element (the header counts none)");
  if (n[1] + n[2] > 0) {
    detail::ElementTally tally;
    for (int64_t i = 0; i < n[1] + n[2]; ++i) tally.skip(2);
    tally.report(in_);
  }
  cells_.finish();
  return std::move(in_);
}

}  // namespace

UgridEncoding ugrid_encoding_of(const std::string& path) {
  const std::string p = detail::lower(path);
  auto ends = [&](std::string_view s) { return p.size() >= s.size() && p.compare(p.size() - s.size(), s.size(), s) == 0; };
  if (ends(".lb8.ugrid")) return UgridEncoding::LittleEndian;
  if (ends(".b8.ugrid")) return UgridEncoding::BigEndian;
  if (ends(".lr8.ugrid")) return UgridEncoding::FortranLittleEndian;
  if (ends(".r8.ugrid")) return UgridEncoding::FortranBigEndian;
  return UgridEncoding::Ascii;
}

MeshInput read_ugrid(std::string_view bytes, const std::string& source, UgridEncoding encoding) {
  return UgridReader(bytes, source, encoding).read();
}

}  // namespace hbc
