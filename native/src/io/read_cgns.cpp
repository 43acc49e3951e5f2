// CGNS (.cgns: Pointwise, ICEM, CFD solvers), read through the CGNS library (Debian's 3.4, ADF
// or HDF5 files). Its API opens files only, so this reader takes a path, not bytes. Every zone of
// the first base is read and the zones are joined with their vertices numbered on (no merge of
// the vertices zones share: a zone interface becomes boundary, and a warning says so).
// Unstructured zones: volume sections (TETRA, PYRA, PENTA, HEXA of any order, by their corners;
// CGNS's corner orders are MEDIT's), MIXED, and NFACE_n polyhedra over the NGON_n faces (both in
// the offsets form CGNS 3.4 and 4.x read); points, bars and surface sections (boundary QUAD_4,
// TRI_3, ...) are skipped and counted. Structured zones are read as their (i-1)(j-1)(k-1) hexahedra.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "hbc/io.hpp"

#if HBC_CGNS
#include <cgnslib.h>

#include "io/detail/element_tally.hpp"
#include "io/detail/hdf5_lock.hpp"
#include "mesh/cell_templates.hpp"
#endif

namespace hbc {

#if HBC_CGNS
namespace {

struct Shape {
  int dim;  // < 3: skipped
  CellShape shape;
  int corners;
};

// By the type's name, so that every order of an element (HEXA_8 ... HEXA_125) reads by its corners.
Shape shape_of(CGNS_ENUMT(ElementType_t) type) {
  const std::string_view name = cg_ElementTypeName(type);
  auto is = [&](std::string_view p) { return name.substr(0, p.size()) == p; };
  if (is("HEXA_")) return {3, CellShape::Hex, 8};
  if (is("PENTA_")) return {3, CellShape::Prism, 6};
  if (is("PYRA_")) return {3, CellShape::Pyramid, 5};
  if (is("TETRA_")) return {3, CellShape::Tet, 4};
  if (is("TRI_") || is("QUAD_")) return {2, CellShape::Faces, 0};
  if (is("BAR_")) return {1, CellShape::Faces, 0};
  if (is("NODE")) return {0, CellShape::Faces, 0};
  return {-1, CellShape::Faces, 0};
}

class CgnsReader {
 public:
  explicit CgnsReader(const std::string& path) : cells_(in_) { in_.source = path; }
  ~CgnsReader() {
    if (fn_ >= 0) cg_close(fn_);
  }
  MeshInput read();

 private:
  [[noreturn]] void fail(const std::string& expected) const { throw InputError(in_.source, {}, "expected " + expected); }
  void check(int status, const std::string& expected) const {
    if (status != CG_OK) fail(expected + " (CGNS: " + cg_get_error() + ")");
  }
  // A count read from the file, checked against what the file's bytes could hold (1032:1 deflated).
  size_t checked(int64_t n, const std::string& what) const;
  void zone(int z);
  void structured(int z, const std::array<cgsize_t, 9>& size);
  void sections(int z);
  void fixed(const std::string& where, CGNS_ENUMT(ElementType_t) type, const cgsize_t* conn, int64_t count);
  void one_element(const std::string& where, CGNS_ENUMT(ElementType_t) type, const cgsize_t* nodes, int64_t npe);
  void nface(const std::string& where, const std::vector<cgsize_t>& conn, const std::vector<cgsize_t>& offsets);
  int32_t vertex(int64_t id, const std::string& where) const;

  int fn_ = -1;
  uint64_t file_size_ = 0;
  MeshInput in_;
  detail::CellAppender cells_;
  detail::ElementTally tally_;
  int64_t base_ = 0, nv_ = 0;  // this zone's first vertex id, and its vertex count
  // This zone's NGON_n faces (as vertex loops) and the element number each section starts at.
  Csr<int32_t> faces_;
  std::vector<std::array<int64_t, 3>> ngon_ranges_;  // first element, last element, first face row
  std::vector<int32_t> sizes_, ids_;
};

size_t CgnsReader::checked(int64_t n, const std::string& what) const {
  if (n < 0 || n > INT32_MAX || static_cast<uint64_t>(n) > 1032 * file_size_)
    fail(what + " of a size the file can hold, found " + std::to_string(n));
  return static_cast<size_t>(n);
}

int32_t CgnsReader::vertex(int64_t id, const std::string& where) const {
  if (id < 1 || id > nv_) fail("vertex ids in [1, " + std::to_string(nv_) + "] in " + where + ", found " + std::to_string(id));
  return static_cast<int32_t>(base_ + id - 1);
}

void CgnsReader::one_element(const std::string& where, CGNS_ENUMT(ElementType_t) type, const cgsize_t* nodes, int64_t npe) {
  const Shape s = shape_of(type);
  if (s.dim < 0) fail("a TETRA, PYRA, PENTA, HEXA, MIXED, NFACE_n or lower-dimensional section in " + where + ", found " + cg_ElementTypeName(type));
  std::array<int32_t, 8> v{};
  for (int64_t k = 0; k < npe; ++k) {
    const int32_t id = vertex(nodes[k], where);
    if (k < s.corners) v[static_cast<size_t>(k)] = id;
    else if (s.dim == 3) cells_.midside(id);
  }
  if (s.dim < 3) tally_.skip(s.dim);
  else cells_.element(s.shape, v.data(), -1);
}

void CgnsReader::fixed(const std::string& where, CGNS_ENUMT(ElementType_t) type, const cgsize_t* conn, int64_t count) {
  int npe = 0;
  check(cg_npe(type, &npe), "the node count of " + std::string(cg_ElementTypeName(type)) + " in " + where);
  if (npe <= 0) fail("a fixed-size element type in " + where + ", found " + cg_ElementTypeName(type));
  for (int64_t e = 0; e < count; ++e) one_element(where, type, conn + e * npe, npe);
}

void CgnsReader::nface(const std::string& where, const std::vector<cgsize_t>& conn, const std::vector<cgsize_t>& offsets) {
  for (size_t e = 0; e + 1 < offsets.size(); ++e) {
    sizes_.clear();
    ids_.clear();
    if (offsets[e + 1] - offsets[e] < 4) fail("polyhedra of 4 or more faces in " + where + ", found " + std::to_string(offsets[e + 1] - offsets[e]));
    for (cgsize_t i = offsets[e]; i < offsets[e + 1]; ++i) {
      const int64_t f = std::abs(static_cast<int64_t>(conn[static_cast<size_t>(i)]));  // negative: seen reversed
      const auto range = std::find_if(ngon_ranges_.begin(), ngon_ranges_.end(), [&](const auto& r) { return f >= r[0] && f <= r[1]; });
      if (range == ngon_ranges_.end()) fail("face numbers of the zone's NGON_n sections in " + where + ", found " + std::to_string(f));
      const auto loop = faces_[static_cast<size_t>((*range)[2] + f - (*range)[0])];
      sizes_.push_back(static_cast<int32_t>(loop.size()));
      if (conn[static_cast<size_t>(i)] < 0) ids_.insert(ids_.end(), loop.rbegin(), loop.rend());
      else ids_.insert(ids_.end(), loop.begin(), loop.end());
    }
    cells_.polyhedron(sizes_, ids_, -1);
  }
}

void CgnsReader::structured(int z, const std::array<cgsize_t, 9>& size) {
  const int64_t ni = size[0], nj = size[1], nk = size[2];
  if (ni < 2 || nj < 2 || nk < 2) fail("a structured zone of at least 2 x 2 x 2 vertices in zone " + std::to_string(z) + ", found " +
                                       std::to_string(ni) + " x " + std::to_string(nj) + " x " + std::to_string(nk));
  checked((ni - 1) * (nj - 1) * (nk - 1), "a structured zone " + std::to_string(z));
  // Vertices run i fastest, then j, then k: a cell's bottom loop at k, its top at k + 1.
  auto at = [&](int64_t i, int64_t j, int64_t k) { return static_cast<int32_t>(base_ + i + ni * (j + nj * k)); };
  std::array<int32_t, 8> v{};
  for (int64_t k = 0; k + 1 < nk; ++k)
    for (int64_t j = 0; j + 1 < nj; ++j)
      for (int64_t i = 0; i + 1 < ni; ++i) {
        v = {at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k),
             at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1)};
        cells_.element(CellShape::Hex, v.data(), -1);
      }
}

void CgnsReader::sections(int z) {
  int ns = 0;
  check(cg_nsections(fn_, 1, z, &ns), "the element sections of zone " + std::to_string(z));
  faces_ = {};
  ngon_ranges_.clear();
  // NGON_n first: the NFACE_n sections, wherever they are, refer to its faces by element number.
  for (int pass = 0; pass < 2; ++pass)
    for (int s = 1; s <= ns; ++s) {
      char name[64] = {};
      CGNS_ENUMT(ElementType_t) type;
      cgsize_t start = 0, end = 0;
      int nbndry = 0, parent = 0;
      const std::string where = "zone " + std::to_string(z) + " section " + std::to_string(s);
      check(cg_section_read(fn_, 1, z, s, name, &type, &start, &end, &nbndry, &parent), "an element section in " + where);
      const std::string named = where + " (" + name + ")";
      if ((type == CGNS_ENUMV(NGON_n)) != (pass == 0)) continue;
      const size_t count = checked(int64_t{end} - start + 1, "an element range in " + named);
      cgsize_t data_size = 0;
      check(cg_ElementDataSize(fn_, 1, z, s, &data_size), "the connectivity size of " + named);
      std::vector<cgsize_t> conn(checked(data_size, "a connectivity in " + named));
      const bool poly = type == CGNS_ENUMV(MIXED) || type == CGNS_ENUMV(NGON_n) || type == CGNS_ENUMV(NFACE_n);
      if (!poly) {
        if (count > 0) check(cg_elements_read(fn_, 1, z, s, conn.data(), nullptr), "the connectivity of " + named);
        int npe = 0;
        if (cg_npe(type, &npe) != CG_OK || npe <= 0 || conn.size() != count * static_cast<size_t>(npe))
          fail(std::to_string(count) + " elements of " + cg_ElementTypeName(type) + " in " + named + ", found " + std::to_string(conn.size()) + " ids");
        fixed(named, type, conn.data(), static_cast<int64_t>(count));
        continue;
      }
      std::vector<cgsize_t> offsets(count + 1);
      if (count > 0) check(cg_poly_elements_read(fn_, 1, z, s, conn.data(), offsets.data(), nullptr), "the connectivity of " + named);
      for (size_t e = 0; e < count; ++e)
        if (offsets[0] != 0 || offsets[e + 1] < offsets[e] || static_cast<size_t>(offsets[e + 1]) > conn.size())
          fail("non-decreasing ElementStartOffset within the connectivity in " + named);
      if (type == CGNS_ENUMV(NFACE_n)) {
        nface(named, conn, offsets);
      } else if (type == CGNS_ENUMV(NGON_n)) {
        ngon_ranges_.push_back({start, end, static_cast<int64_t>(faces_.rows())});
        for (size_t e = 0; e < count; ++e) {
          if (offsets[e + 1] - offsets[e] < 3) fail("faces of 3 or more vertices in " + named);
          for (cgsize_t i = offsets[e]; i < offsets[e + 1]; ++i) faces_.items.push_back(vertex(conn[static_cast<size_t>(i)], named));
          faces_.offsets.push_back(static_cast<int32_t>(faces_.items.size()));
        }
      } else {  // MIXED: each element's type, then its nodes
        for (size_t e = 0; e < count; ++e) {
          const int64_t n = offsets[e + 1] - offsets[e];
          const auto t = static_cast<CGNS_ENUMT(ElementType_t)>(n > 0 ? conn[static_cast<size_t>(offsets[e])] : 0);
          int npe = 0;
          if (n < 1 || cg_npe(t, &npe) != CG_OK || npe <= 0 || npe != n - 1)
            fail("an element type and its nodes for element " + std::to_string(start + static_cast<cgsize_t>(e)) + " of MIXED " + named);
          one_element(named, t, conn.data() + offsets[e] + 1, npe);
        }
      }
    }
}

void CgnsReader::zone(int z) {
  char name[64] = {};
  std::array<cgsize_t, 9> size{};
  check(cg_zone_read(fn_, 1, z, name, size.data()), "zone " + std::to_string(z) + " of base 1");
  CGNS_ENUMT(ZoneType_t) type;
  check(cg_zone_type(fn_, 1, z, &type), "the type of zone " + std::to_string(z));
  const bool structured_zone = type == CGNS_ENUMV(Structured);
  nv_ = structured_zone ? int64_t{size[0]} * size[1] * size[2] : size[0];
  const size_t nv = checked(nv_, "a vertex count in zone " + std::to_string(z) + " (" + name + ")");
  base_ = static_cast<int64_t>(in_.points.size() / 3);
  if (base_ + nv_ > INT32_MAX) fail("at most 2^31 vertices in all zones together");
  std::vector<double> xyz(nv);
  in_.points.resize(in_.points.size() + 3 * nv);
  for (int k = 0; k < 3; ++k) {
    const std::string coord = std::string("Coordinate") + "XYZ"[k];
    cgsize_t lo[3] = {1, 1, 1}, hi[3] = {size[0], structured_zone ? size[1] : 1, structured_zone ? size[2] : 1};
    check(cg_coord_read(fn_, 1, z, coord.c_str(), CGNS_ENUMV(RealDouble), lo, hi, xyz.data()),
          coord + " in zone " + std::to_string(z) + " (" + name + "; Cartesian coordinates)");
    for (size_t v = 0; v < nv; ++v) {
      if (!std::isfinite(xyz[v])) fail("finite coordinates in zone " + std::to_string(z) + ", found " + std::to_string(xyz[v]) + " in " + coord);
      in_.points[3 * (static_cast<size_t>(base_) + v) + static_cast<size_t>(k)] = xyz[v];
    }
  }
  if (structured_zone) structured(z, size);
  else if (type == CGNS_ENUMV(Unstructured)) sections(z);
  else fail("a structured or unstructured zone " + std::to_string(z) + " (" + name + ")");
}

MeshInput CgnsReader::read() {
  std::error_code ec;
  file_size_ = std::filesystem::file_size(in_.source, ec);
  if (ec) throw InputError(in_.source, {}, "a readable file (cannot open it)");
  if (cg_open(in_.source.c_str(), CG_MODE_READ, &fn_) != CG_OK) {
    fn_ = -1;
    fail(std::string("a CGNS file (ADF or HDF5; CGNS: ") + cg_get_error() + ")");
  }
  int nbases = 0, cell_dim = 0, phys_dim = 0, nzones = 0;
  check(cg_nbases(fn_, &nbases), "a CGNS base");
  if (nbases < 1) fail("a CGNS base (CGNSBase_t), found none");
  char name[64] = {};
  check(cg_base_read(fn_, 1, name, &cell_dim, &phys_dim), "base 1");
  if (cell_dim != 3 || phys_dim != 3) fail("a base of cell and physical dimension 3, found " + std::to_string(cell_dim) + " and " + std::to_string(phys_dim));
  check(cg_nzones(fn_, 1, &nzones), "the zones of base 1");
  if (nzones < 1) fail("a zone in base 1 (" + std::string(name) + "), found none");
  for (int z = 1; z <= nzones; ++z) zone(z);
  if (in_.cells.rows() == 0) fail("at least one volume element (TETRA, PYRA, PENTA, HEXA, MIXED or NFACE_n) in base 1");
  if (nbases > 1) in_.warnings.push_back("read base 1 (" + std::string(name) + ") of " + std::to_string(nbases) + "; the other bases are left out");
  if (nzones > 1)
    in_.warnings.push_back("joined " + std::to_string(nzones) + " zones without merging the vertices they share: zone interfaces are boundary");
  tally_.report(in_);
  cells_.finish();
  return std::move(in_);
}

}  // namespace

MeshInput read_cgns(const std::string& path) {
  // The CGNS library keeps its open files in a table of its own and is not thread-safe: one reader
  // at a time in this process.
  // Both sit on HDF5, as the MED reader does: one lock for all three.
  const std::lock_guard<std::mutex> lock(detail::hdf5_library_lock());
  return CgnsReader(path).read();
}
#else
MeshInput read_cgns(const std::string& path) {
#ifdef __EMSCRIPTEN__
  throw InputError(path, {}, "CGNS files need the desktop tool (the hbc command, its Python module or the Blender add-on): "
                             "the web viewer has no CGNS library to read them");
#else
  throw InputError(path, {}, "CGNS files need the CGNS library: this hbc was built without it (HBC_CGNS=OFF; "
                             "install libcgns-dev and build again)");
#endif
}
#endif

}  // namespace hbc
