// Exodus II (.e, .exo, .g: Cubit/Coreform, MOOSE, SEACAS), read through netCDF-C from memory
// (nc_open_mem), so classic, 64-bit-offset and netCDF-4/HDF5 files all parse from the bytes like
// the other readers. Exodus has no lines: messages name the block and the netCDF variable.
// Element blocks (connect<i> with its elem_type attribute) become cells by their corners (Exodus's
// corner orders are MEDIT's); NFACED blocks are polyhedra over the face blocks' NSIDED faces;
// shells, bars, spheres and other lower-dimensional blocks are skipped and counted.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/text_scanner.hpp"

#if HBC_EXODUS
#include <netcdf.h>
#include <netcdf_mem.h>

#include "io/detail/element_tally.hpp"
#include "io/detail/hdf5_lock.hpp"
#include "mesh/cell_templates.hpp"
#endif

namespace hbc {

#if HBC_EXODUS
namespace {

// Exodus element type names (case-insensitive, by prefix as SEACAS compares them); `dim` < 3
// blocks are skipped. NFACED (polyhedra) is read apart.
struct ExoType {
  std::string_view prefix;
  int dim;
  CellShape shape;
  int corners;
};
constexpr ExoType kTypes[] = {
    {"hex", 3, CellShape::Hex, 8},       {"wedge", 3, CellShape::Prism, 6}, {"pyramid", 3, CellShape::Pyramid, 5},
    {"pyra", 3, CellShape::Pyramid, 5},  {"tetra", 3, CellShape::Tet, 4},   {"tet", 3, CellShape::Tet, 4},
    {"shell", 2, CellShape::Faces, 0},   {"quad", 2, CellShape::Faces, 0},  {"tri", 2, CellShape::Faces, 0},
    {"nsided", 2, CellShape::Faces, 0},  {"bar", 1, CellShape::Faces, 0},   {"beam", 1, CellShape::Faces, 0},
    {"truss", 1, CellShape::Faces, 0},   {"edge", 1, CellShape::Faces, 0},  {"spring", 1, CellShape::Faces, 0},
    {"sphere", 0, CellShape::Faces, 0},  {"circle", 0, CellShape::Faces, 0}, {"point", 0, CellShape::Faces, 0},
    {"super", 0, CellShape::Faces, 0},
};

const ExoType* exo_type(const std::string& lower) {
  for (const ExoType& t : kTypes)
    if (lower.rfind(t.prefix, 0) == 0) return &t;
  return nullptr;
}

class ExodusReader {
 public:
  ExodusReader(std::string_view bytes, const std::string& source) : bytes_(bytes), cells_(in_) { in_.source = source; }
  ~ExodusReader() {
    if (ncid_ >= 0) nc_close(ncid_);
  }
  MeshInput read();

 private:
  [[noreturn]] void fail(const std::string& expected) const { throw InputError(in_.source, {}, "expected " + expected); }
  void check(int status, const std::string& expected) const {
    if (status != NC_NOERR) fail(expected + " (netCDF: " + nc_strerror(status) + ")");
  }
  // The length of dimension `name`, or -1 when the file has none.
  int64_t dim(const std::string& name) const;
  int var(const std::string& name) const;  // -1 when absent
  // Variable `name` as integers, checked to hold `count` values.
  std::vector<int64_t> ints(const std::string& name, int64_t count, const std::string& what) const;
  void coordinates();
  void face_blocks();
  void element_block(int64_t b);
  void polyhedra(int64_t b, const std::string& block, int64_t n);
  int32_t node(int64_t id, const std::string& where) const;

  std::string_view bytes_;
  int ncid_ = -1;
  MeshInput in_;
  detail::CellAppender cells_;
  detail::ElementTally tally_;
  int64_t nv_ = 0;
  Csr<int32_t> faces_;  // the face blocks' faces in file order (0-based node ids), for NFACED
};

int64_t ExodusReader::dim(const std::string& name) const {
  int id = 0;
  if (nc_inq_dimid(ncid_, name.c_str(), &id) != NC_NOERR) return -1;
  size_t len = 0;
  check(nc_inq_dimlen(ncid_, id, &len), "the length of dimension " + name);
  return static_cast<int64_t>(len);
}

int ExodusReader::var(const std::string& name) const {
  int id = -1;
  return nc_inq_varid(ncid_, name.c_str(), &id) == NC_NOERR ? id : -1;
}

std::vector<int64_t> ExodusReader::ints(const std::string& name, int64_t count, const std::string& what) const {
  const int id = var(name);
  if (id < 0) fail("variable " + name + " (" + what + ")");
  // Sizes come from the file: no more values than its bytes could hold even deflated (1032:1).
  if (count < 0 || count > INT32_MAX || static_cast<uint64_t>(count) > 1032 * static_cast<uint64_t>(bytes_.size()))
    fail(what + " of a size the file can hold, found " + std::to_string(count) + " values in " + name);
  int ndims = 0;
  check(nc_inq_varndims(ncid_, id, &ndims), "the shape of variable " + name);
  std::array<int, NC_MAX_VAR_DIMS> dims{};
  check(nc_inq_vardimid(ncid_, id, dims.data()), "the shape of variable " + name);
  uint64_t total = 1;
  for (int d = 0; d < ndims; ++d) {
    size_t len = 0;
    check(nc_inq_dimlen(ncid_, dims[static_cast<size_t>(d)], &len), "the shape of variable " + name);
    total *= len;
  }
  if (total != static_cast<uint64_t>(count))
    fail(std::to_string(count) + " values in variable " + name + " (" + what + "), found " + std::to_string(total));
  std::vector<int64_t> out(static_cast<size_t>(count));
  static_assert(sizeof(long long) == sizeof(int64_t));
  if (count > 0) check(nc_get_var_longlong(ncid_, id, reinterpret_cast<long long*>(out.data())), "integer values in variable " + name + " (" + what + ")");
  return out;
}

int32_t ExodusReader::node(int64_t id, const std::string& where) const {
  if (id < 1 || id > nv_) fail("node ids in [1, " + std::to_string(nv_) + "] in " + where + ", found " + std::to_string(id));
  return static_cast<int32_t>(id - 1);
}

void ExodusReader::coordinates() {
  const int64_t ndim = dim("num_dim");
  if (ndim != 3) fail("a 3-dimensional mesh (dimension num_dim = 3), found " + (ndim < 0 ? std::string("no num_dim") : std::to_string(ndim)));
  nv_ = dim("num_nodes");
  if (nv_ <= 0 || nv_ > INT32_MAX || static_cast<uint64_t>(nv_) > 1032 * static_cast<uint64_t>(bytes_.size()))
    fail("a number of nodes (dimension num_nodes) the file can hold, found " + std::to_string(nv_));
  const size_t nv = static_cast<size_t>(nv_);
  std::vector<double> xyz(3 * nv);
  const int joint = var("coord");  // the old layout: coord[num_dim][num_nodes]
  for (int k = 0; k < 3; ++k) {
    const std::string name = std::string("coord") + "xyz"[k];
    const int id = var(name);
    if (id < 0 && joint < 0) fail("variable " + name + " (or coord) with the nodes' coordinates");
    const size_t start[2] = {static_cast<size_t>(k), 0}, count[2] = {1, nv};
    double* out = xyz.data() + k * nv;
    if (id >= 0) check(nc_get_var_double(ncid_, id, out), "numbers in variable " + name + " (" + std::to_string(nv) + " node coordinates)");
    else check(nc_get_vara_double(ncid_, joint, start, count, out), "numbers in variable coord (3 x " + std::to_string(nv) + " node coordinates)");
  }
  in_.points.resize(3 * nv);
  for (size_t v = 0; v < nv; ++v)
    for (size_t k = 0; k < 3; ++k) {
      const double c = xyz[k * nv + v];
      if (!std::isfinite(c)) fail("finite node coordinates, found " + std::to_string(c) + " for node " + std::to_string(v + 1));
      in_.points[3 * v + k] = c;
    }
}

// Face blocks (NSIDED, or fixed-size TRI/QUAD faces) give NFACED elements their faces; face ids
// run through the blocks in file order.
void ExodusReader::face_blocks() {
  const int64_t nblocks = std::max<int64_t>(dim("num_fa_blk"), 0);
  for (int64_t b = 1; b <= nblocks; ++b) {
    const std::string s = std::to_string(b), block = "face block " + s;
    const int64_t n = dim("num_fa_in_blk" + s), per = dim("num_nod_per_fa" + s);
    if (n <= 0) continue;
    const int64_t stored = per < 0 ? -1 : var("fbepecnt" + s) >= 0 ? per : n * per;
    std::vector<int64_t> sizes(static_cast<size_t>(n), per);
    if (var("fbepecnt" + s) >= 0) sizes = ints("fbepecnt" + s, n, "the node count of each face of " + block);
    const std::vector<int64_t> conn = ints("fbconn" + s, stored, "the nodes of " + block);
    size_t at = 0;
    for (int64_t f = 0; f < n; ++f) {
      const int64_t k = sizes[static_cast<size_t>(f)];
      if (k < 3 || static_cast<uint64_t>(k) > conn.size() - at)
        fail("faces of 3 or more nodes within fbconn" + s + " (" + block + "), found " + std::to_string(k) + " for face " + std::to_string(f + 1));
      faces_.items.reserve(faces_.items.size() + static_cast<size_t>(k));
      for (int64_t i = 0; i < k; ++i) faces_.items.push_back(node(conn[at + static_cast<size_t>(i)], "fbconn" + s + " (" + block + ")"));
      faces_.offsets.push_back(static_cast<int32_t>(faces_.items.size()));
      at += static_cast<size_t>(k);
    }
  }
}

void ExodusReader::polyhedra(int64_t b, const std::string& block, int64_t n) {
  const std::string s = std::to_string(b);
  const std::vector<int64_t> counts = ints("ebepecnt" + s, n, "the face count of each element of " + block);
  const std::vector<int64_t> conn = ints("facconn" + s, dim("num_fac_per_el" + s), "the faces of each element of " + block);
  std::vector<int32_t> sizes, ids;
  size_t at = 0;
  for (int64_t e = 0; e < n; ++e) {
    const int64_t k = counts[static_cast<size_t>(e)];
    if (k < 4 || static_cast<uint64_t>(k) > conn.size() - at)
      fail("polyhedra of 4 or more faces within facconn" + s + " (" + block + "), found " + std::to_string(k) + " for element " + std::to_string(e + 1));
    sizes.clear();
    ids.clear();
    for (int64_t i = 0; i < k; ++i) {
      const int64_t f = conn[at + static_cast<size_t>(i)];
      if (f < 1 || static_cast<size_t>(f) > faces_.rows())
        fail("face ids in [1, " + std::to_string(faces_.rows()) + "] (the face blocks' faces) in facconn" + s + " (" + block + "), found " + std::to_string(f));
      const auto loop = faces_[static_cast<size_t>(f - 1)];
      sizes.push_back(static_cast<int32_t>(loop.size()));
      ids.insert(ids.end(), loop.begin(), loop.end());
    }
    cells_.polyhedron(sizes, ids, -1);
    at += static_cast<size_t>(k);
  }
}

void ExodusReader::element_block(int64_t b) {
  const std::string s = std::to_string(b), block = "element block " + s;
  const int64_t n = dim("num_el_in_blk" + s);
  if (n <= 0) return;  // an empty block may have no connectivity at all
  // The type is an attribute of the connectivity: connect<i>, or facconn<i> for NFACED.
  const std::string conn_name = var("connect" + s) >= 0 ? "connect" + s : var("facconn" + s) >= 0 ? "facconn" + s : "";
  if (conn_name.empty()) fail("variable connect" + s + " with the nodes of " + block);
  size_t len = 0;
  check(nc_inq_attlen(ncid_, var(conn_name), "elem_type", &len), "attribute elem_type of " + conn_name + " (" + block + ")");
  std::string type(std::min<size_t>(len, 64), '\0');
  if (len > 64) fail("an element type name of at most 64 characters in " + conn_name + " (" + block + ")");
  check(nc_get_att_text(ncid_, var(conn_name), "elem_type", type.data()), "attribute elem_type of " + conn_name + " (" + block + ")");
  type.erase(std::find(type.begin(), type.end(), '\0'), type.end());
  const std::string lower = detail::lower(type);
  if (lower.rfind("nfaced", 0) == 0) return polyhedra(b, block, n);
  const ExoType* t = exo_type(lower);
  if (!t) fail("an Exodus element type (HEX8, WEDGE6, PYRAMID5, TETRA4, NFACED, SHELL4, ...) for " + block + ", found '" + type + "'");
  const int64_t per = dim("num_nod_per_el" + s);
  if (per < t->corners || (t->dim == 3 && per > 64)) fail(std::to_string(t->corners) + " to 64 nodes per element for " + type + " (num_nod_per_el" + s + ", " + block + "), found " + std::to_string(per));
  if (t->dim < 3) {
    for (int64_t e = 0; e < n; ++e) tally_.skip(t->dim);
    return;
  }
  const std::vector<int64_t> conn = ints(conn_name, n * per, "the nodes of each element of " + block);
  const std::string where = conn_name + " (" + block + ")";
  std::array<int32_t, 8> v{};
  for (int64_t e = 0; e < n; ++e) {
    const int64_t* row = conn.data() + e * per;
    for (int64_t k = 0; k < per; ++k) {
      const int32_t id = node(row[k], where);
      if (k < t->corners) v[static_cast<size_t>(k)] = id;
      else cells_.midside(id);
    }
    cells_.element(t->shape, v.data(), -1);
  }
}

MeshInput ExodusReader::read() {
  // NC_NOWRITE: netCDF only reads the buffer (nc_open_mem locks it), which may be a read-only map.
  const int status = nc_open_mem(in_.source.c_str(), NC_NOWRITE, bytes_.size(), const_cast<char*>(bytes_.data()), &ncid_);
  if (status != NC_NOERR) {
    ncid_ = -1;
    fail(std::string("an Exodus II file (netCDF classic, 64-bit offset or netCDF-4/HDF5; netCDF: ") + nc_strerror(status) + ")");
  }
  in_.binary = true;
  coordinates();
  face_blocks();
  const int64_t nblocks = dim("num_el_blk");
  if (nblocks < 1) fail("element blocks (dimension num_el_blk)");
  for (int64_t b = 1; b <= nblocks; ++b) element_block(b);
  if (in_.cells.rows() == 0) fail("at least one volume element block (HEX, WEDGE, PYRAMID, TETRA or NFACED)");
  tally_.report(in_);
  cells_.finish();
  return std::move(in_);
}

}  // namespace

MeshInput read_exodus(std::string_view bytes, const std::string& source) {
  // netCDF-C (as Debian builds it) keeps its open files in a table of its own without a lock: one
  // reader at a time in this process (the Python module reads without the GIL).
  // Both sit on HDF5, as the CGNS and MED readers do: one lock for all three.
  const std::lock_guard<std::mutex> lock(detail::hdf5_library_lock());
  return ExodusReader(bytes, source).read();
}
#else
MeshInput read_exodus(std::string_view, const std::string& source) {
#ifdef __EMSCRIPTEN__
  throw InputError(source, {}, "Exodus II files need the desktop tool (the hbc command, its Python module or the Blender add-on): "
                               "the web viewer has no netCDF-C library to read them");
#else
  throw InputError(source, {}, "Exodus II files need netCDF-C: this hbc was built without it (HBC_EXODUS=OFF; "
                               "install libnetcdf-dev and build again)");
#endif
}
#endif

}  // namespace hbc
