// Salome MED (.med, MED-fichier 3.x/4.x), read through HDF5's C library from memory (a core-driver
// file image), so that it parses from bytes like the other readers. MED has no lines: messages name
// the HDF5 group or dataset. The first mesh of /ENS_MAA at its first time step: NOE/COO holds the
// coordinates by component (all x, then all y, then all z), MAI/<type>/NOD each type's nodes by
// node column (1-based); volume types (TE4/T10, PY5/P13, PE6/P15/P18, HE8/H20/H27) become cells by
// their corners, points, edges and faces (PO1, SE*, TR*, QU*, POG) are skipped and counted.
//
// Corner order: MED's reference volume elements are the mirror images of MEDIT's (Salome's
// "nodal connectivity of elements"; SMESH converts with the self-inverse permutations of
// kMedToMedit). meshio 5.3.5 writes and reads MED without converting, so its files hold VTK's
// (MEDIT's) order. A file is read in MED's order unless most of its volume cells would then be
// inverted and are upright in MEDIT's: then it was written in VTK's order, and a warning says so.
// The choice is per file, so a real inverted cell still shows as one.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "hbc/io.hpp"

#if HBC_HDF5
#include <hdf5.h>

#include "io/detail/element_tally.hpp"
#include "io/detail/hdf5_lock.hpp"
#include "mesh/cell_templates.hpp"
#endif

namespace hbc {

#if HBC_HDF5
namespace {

struct MedType {
  std::string_view name;  // the HDF5 group under MAI (MED's 3-letter geometry names)
  int dim;
  CellShape shape;
  int nodes;
  std::array<int8_t, 8> to_medit;  // MEDIT corner k is MED node to_medit[k]
};
constexpr std::array<int8_t, 8> kHex{0, 3, 2, 1, 4, 7, 6, 5}, kPrism{0, 2, 1, 3, 5, 4}, kPyramid{0, 3, 2, 1, 4},
    kTet{0, 2, 1, 3};
constexpr MedType kTypes[] = {
    {"HE8", 3, CellShape::Hex, 8, kHex},        {"H20", 3, CellShape::Hex, 20, kHex},
    {"H27", 3, CellShape::Hex, 27, kHex},       {"PE6", 3, CellShape::Prism, 6, kPrism},
    {"P15", 3, CellShape::Prism, 15, kPrism},   {"P18", 3, CellShape::Prism, 18, kPrism},
    {"PY5", 3, CellShape::Pyramid, 5, kPyramid}, {"P13", 3, CellShape::Pyramid, 13, kPyramid},
    {"TE4", 3, CellShape::Tet, 4, kTet},        {"T10", 3, CellShape::Tet, 10, kTet},
    {"PO1", 0, CellShape::Faces, 1, {}},        {"SE2", 1, CellShape::Faces, 2, {}},
    {"SE3", 1, CellShape::Faces, 3, {}},        {"SE4", 1, CellShape::Faces, 4, {}},
    {"TR3", 2, CellShape::Faces, 3, {}},        {"TR6", 2, CellShape::Faces, 6, {}},
    {"TR7", 2, CellShape::Faces, 7, {}},        {"QU4", 2, CellShape::Faces, 4, {}},
    {"QU8", 2, CellShape::Faces, 8, {}},        {"QU9", 2, CellShape::Faces, 9, {}},
};

// An HDF5 id closed by its own function when it goes out of scope.
class Hid {
 public:
  Hid(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  ~Hid() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// HDF5 prints its error stack on stderr unless told not to; the reader's messages say it instead.
class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* out) {
  auto* names = static_cast<std::vector<std::string>*>(out);
  names->emplace_back(name);
  return names->size() < 100000 ? 0 : 1;  // a bound on what a damaged file can list
}

// One MAI/<type> group's elements: their nodes (0-based), element after element.
struct Block {
  const MedType* type;
  int64_t count;
  std::vector<int32_t> nodes;
};

class MedReader {
 public:
  MedReader(std::string_view bytes, const std::string& source) : bytes_(bytes), cells_(in_) { in_.source = source; }
  MeshInput read();

 private:
  [[noreturn]] void fail(const std::string& expected) const { throw InputError(in_.source, {}, "expected " + expected); }
  // The links of group `path`, in name order (MED's own order); fails when it is no group.
  std::vector<std::string> children(const std::string& path, const std::string& what) const;
  int64_t int_attribute(hid_t object, const char* name, const std::string& where) const;
  // Dataset `path`: `count` values (checked against the file's size) of class `cls`, as `mem`.
  template <class T>
  std::vector<T> dataset(const std::string& path, int64_t count, H5T_class_t cls, hid_t mem) const;
  void coordinates(const std::string& step);
  void elements(const std::string& step);
  Block block(const std::string& path, const MedType& t);
  bool written_in_vtk_order() const;
  double volume(const Block& b, int64_t e, bool med_order) const;
  void append(bool med_order);

  std::string_view bytes_;
  hid_t file_ = -1;
  MeshInput in_;
  detail::CellAppender cells_;
  detail::ElementTally tally_;
  int64_t nv_ = 0;
  std::vector<Block> blocks_;
};

std::vector<std::string> MedReader::children(const std::string& path, const std::string& what) const {
  const Hid group(H5Gopen2(file_, path.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.ok()) fail("group " + path + " (" + what + ")");
  std::vector<std::string> names;
  hsize_t at = 0;
  if (H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_INC, &at, collect_name, &names) < 0)
    fail("a readable group " + path + " (" + what + ")");
  return names;
}

int64_t MedReader::int_attribute(hid_t object, const char* name, const std::string& where) const {
  if (H5Aexists(object, name) <= 0) fail("attribute " + std::string(name) + " of " + where);
  const Hid attr(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  const Hid type(attr.ok() ? H5Aget_type(attr.get()) : -1, H5Tclose);
  const Hid space(attr.ok() ? H5Aget_space(attr.get()) : -1, H5Sclose);
  int64_t value = 0;
  if (!type.ok() || !space.ok() || H5Tget_class(type.get()) != H5T_INTEGER || H5Sget_simple_extent_npoints(space.get()) != 1 ||
      H5Aread(attr.get(), H5T_NATIVE_INT64, &value) < 0)
    fail("one integer in attribute " + std::string(name) + " of " + where);
  return value;
}

template <class T>
std::vector<T> MedReader::dataset(const std::string& path, int64_t count, H5T_class_t cls, hid_t mem) const {
  // Sizes come from the file: no more values than its bytes could hold even deflated (1032:1).
  if (count < 0 || count > INT32_MAX || static_cast<uint64_t>(count) > 1032 * static_cast<uint64_t>(bytes_.size()))
    fail("a number of values the file can hold in " + path + ", found " + std::to_string(count));
  const Hid set(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail("dataset " + path);
  const Hid type(H5Dget_type(set.get()), H5Tclose);
  const Hid space(H5Dget_space(set.get()), H5Sclose);
  const char* kind = cls == H5T_FLOAT ? "numbers" : "integers";
  if (!type.ok() || H5Tget_class(type.get()) != cls) fail(std::string(kind) + " in dataset " + path);
  const hssize_t n = space.ok() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  if (n != count) fail(std::to_string(count) + " values in dataset " + path + ", found " + std::to_string(n));
  std::vector<T> out(static_cast<size_t>(count));
  if (count > 0 && H5Dread(set.get(), mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail(std::string("readable ") + kind + " in dataset " + path);
  return out;
}

void MedReader::coordinates(const std::string& step) {
  const std::string path = step + "/NOE/COO";
  const Hid set(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail("dataset " + path + " (the nodes' coordinates)");
  nv_ = int_attribute(set.get(), "NBR", path);
  if (nv_ <= 0 || nv_ > INT32_MAX / 3) fail("a positive number of nodes (attribute NBR of " + path + "), found " + std::to_string(nv_));
  const std::vector<double> xyz = dataset<double>(path, 3 * nv_, H5T_FLOAT, H5T_NATIVE_DOUBLE);
  const size_t nv = static_cast<size_t>(nv_);
  in_.points.resize(3 * nv);
  for (size_t v = 0; v < nv; ++v)
    for (size_t k = 0; k < 3; ++k) {
      const double c = xyz[k * nv + v];
      if (!std::isfinite(c)) fail("finite coordinates in " + path + ", found " + std::to_string(c) + " for node " + std::to_string(v + 1));
      in_.points[3 * v + k] = c;
    }
}

Block MedReader::block(const std::string& path, const MedType& t) {
  const std::string nod = path + "/NOD";
  const Hid set(H5Dopen2(file_, nod.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail("dataset " + nod + " (the nodes of each " + std::string(t.name) + " element)");
  const int64_t n = int_attribute(set.get(), "NBR", nod);
  if (n < 0 || n > INT32_MAX / t.nodes) fail("a number of elements (attribute NBR of " + nod + ") the file can hold, found " + std::to_string(n));
  const std::vector<int64_t> raw = dataset<int64_t>(nod, n * t.nodes, H5T_INTEGER, H5T_NATIVE_INT64);
  // By node column: node k of element e at k * n + e.
  Block b{&t, n, std::vector<int32_t>(raw.size())};
  for (int64_t k = 0; k < t.nodes; ++k)
    for (int64_t e = 0; e < n; ++e) {
      const int64_t id = raw[static_cast<size_t>(k * n + e)];
      if (id < 1 || id > nv_) fail("node numbers in [1, " + std::to_string(nv_) + "] in " + nod + ", found " + std::to_string(id) + " for element " + std::to_string(e + 1));
      b.nodes[static_cast<size_t>(e * t.nodes + k)] = static_cast<int32_t>(id - 1);
    }
  return b;
}

void MedReader::elements(const std::string& step) {
  const std::string mai = step + "/MAI";
  for (const std::string& name : children(mai, "the elements")) {
    const std::string path = mai + "/" + name;
    if (name == "POG") {  // polygons: a face index INN of count + 1 entries
      const Hid set(H5Dopen2(file_, (path + "/INN").c_str(), H5P_DEFAULT), H5Dclose);
      const int64_t n = set.ok() ? int_attribute(set.get(), "NBR", path + "/INN") - 1 : 0;
      for (int64_t e = 0; e < n && e < INT32_MAX; ++e) tally_.skip(2);
      continue;
    }
    if (name == "POE") fail("no polyhedra (" + path + "): MED polyhedra are not read yet");
    const MedType* t = nullptr;
    for (const MedType& m : kTypes)
      if (m.name == name) t = &m;
    if (!t) fail("a MED element type (HE8, PE6, PY5, TE4, H20, ..., QU4, TR3, SE2, PO1) in " + mai + ", found " + name);
    Block b = block(path, *t);
    if (t->dim < 3) {
      for (int64_t e = 0; e < b.count; ++e) tally_.skip(t->dim);
      continue;
    }
    blocks_.push_back(std::move(b));
  }
}

// The cell's signed volume through its template faces (outward for an upright MEDIT cell):
// the divergence theorem over each face's triangle fan, from the first corner.
double MedReader::volume(const Block& b, int64_t e, bool med_order) const {
  const int32_t* nodes = b.nodes.data() + e * b.type->nodes;
  std::array<std::array<double, 3>, 8> p{};
  for (int k = 0; k < corner_count(b.type->shape); ++k) {
    const int32_t v = nodes[med_order ? b.type->to_medit[static_cast<size_t>(k)] : k];
    for (size_t c = 0; c < 3; ++c) p[static_cast<size_t>(k)][c] = in_.points[3 * static_cast<size_t>(v) + c] - in_.points[3 * static_cast<size_t>(nodes[0]) + c];
  }
  const detail::ShapeFaces& f = detail::shape_faces(b.type->shape);
  double six = 0;
  for (int i = 0; i < f.nfaces; ++i)
    for (int j = 1; j + 1 < f.size[static_cast<size_t>(i)]; ++j) {
      const auto& a = p[static_cast<size_t>(f.corner[static_cast<size_t>(i)][0])];
      const auto& q = p[static_cast<size_t>(f.corner[static_cast<size_t>(i)][static_cast<size_t>(j)])];
      const auto& r = p[static_cast<size_t>(f.corner[static_cast<size_t>(i)][static_cast<size_t>(j + 1)])];
      six += a[0] * (q[1] * r[2] - q[2] * r[1]) - a[1] * (q[0] * r[2] - q[2] * r[0]) + a[2] * (q[0] * r[1] - q[1] * r[0]);
    }
  return six / 6;
}

bool MedReader::written_in_vtk_order() const {
  int64_t med_upright = 0, vtk_upright = 0;
  for (const Block& b : blocks_)
    for (int64_t e = 0; e < b.count; ++e) {
      med_upright += volume(b, e, true) > 0;
      vtk_upright += volume(b, e, false) > 0;
    }
  return vtk_upright > med_upright;
}

void MedReader::append(bool med_order) {
  std::array<int32_t, 8> v{};
  for (const Block& b : blocks_) {
    const int corners = corner_count(b.type->shape);
    for (int64_t e = 0; e < b.count; ++e) {
      const int32_t* nodes = b.nodes.data() + e * b.type->nodes;
      for (int k = 0; k < corners; ++k) v[static_cast<size_t>(k)] = nodes[med_order ? b.type->to_medit[static_cast<size_t>(k)] : k];
      for (int k = corners; k < b.type->nodes; ++k) cells_.midside(nodes[k]);
      cells_.element(b.type->shape, v.data(), -1);
    }
  }
}

MeshInput MedReader::read() {
  const QuietErrors quiet;
  // The core driver on a copy of the bytes (H5Pset_file_image copies them): nothing on disk.
  const Hid fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!fapl.ok() || H5Pset_fapl_core(fapl.get(), 1 << 16, 0) < 0 ||
      H5Pset_file_image(fapl.get(), const_cast<char*>(bytes_.data()), bytes_.size()) < 0)
    fail("memory for an HDF5 file image of " + std::to_string(bytes_.size()) + " bytes");
  // The core driver refuses an image whose name exists on disk (HDF5 1.10): a name that cannot.
  const Hid file(H5Fopen("/dev/null/hbc-med-image", H5F_ACC_RDONLY, fapl.get()), H5Fclose);
  if (!file.ok()) fail("a MED file (HDF5; the file is no HDF5 file or is damaged)");
  file_ = file.get();
  in_.binary = true;
  const std::vector<std::string> meshes = children("/ENS_MAA", "the meshes");
  if (meshes.empty()) fail("a mesh in group /ENS_MAA");
  const std::string mesh = "/ENS_MAA/" + meshes.front();
  const std::vector<std::string> steps = children(mesh, "the mesh's time steps");
  if (steps.empty()) fail("a time step in group " + mesh);
  const std::string step = mesh + "/" + steps.front();
  {
    const Hid group(H5Gopen2(file_, mesh.c_str(), H5P_DEFAULT), H5Gclose);
    if (!group.ok()) fail("group " + mesh);
    const int64_t dim = int_attribute(group.get(), "ESP", mesh);
    if (dim != 3) fail("a mesh in 3-dimensional space (attribute ESP of " + mesh + " = 3), found " + std::to_string(dim));
  }
  coordinates(step);
  elements(step);
  if (blocks_.empty()) fail("at least one volume element type (HE8, PE6, PY5, TE4, ...) in " + step + "/MAI");
  const bool vtk_order = written_in_vtk_order();
  append(!vtk_order);
  if (meshes.size() > 1) in_.warnings.push_back("read the first of " + std::to_string(meshes.size()) + " meshes (" + meshes.front() + ")");
  if (steps.size() > 1) in_.warnings.push_back("read the first of " + std::to_string(steps.size()) + " time steps of mesh " + meshes.front());
  if (vtk_order)
    in_.warnings.push_back("volume elements stored in VTK's corner order (as meshio writes MED), not MED's: read as VTK's");
  tally_.report(in_);
  cells_.finish();
  file_ = -1;
  return std::move(in_);
}

}  // namespace

MeshInput read_med(std::string_view bytes, const std::string& source) {
  const std::lock_guard<std::mutex> lock(detail::hdf5_library_lock());
  return MedReader(bytes, source).read();
}
#else
MeshInput read_med(std::string_view, const std::string& source) {
#ifdef __EMSCRIPTEN__
  throw InputError(source, {}, "MED files need the desktop tool (the hbc command, its Python module or the Blender add-on): "
                               "the web viewer has no HDF5 library to read them");
#else
  throw InputError(source, {}, "MED files need HDF5: this hbc was built without it (HBC_MED=OFF; "
                               "install libhdf5-dev and build again)");
#endif
}
#endif

}  // namespace hbc
