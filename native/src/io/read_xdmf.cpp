// XDMF3 (.xdmf, .xmf: FEniCS/dolfinx, meshio): the XML (pugixml) names a Grid's Topology and
// Geometry, whose DataItems hold their numbers inline (Format="XML") or in an HDF5 file beside it
// (Format="HDF", "file.h5:/path" relative to the .xdmf), read through HDF5's C library. The first
// Grid of the Domain is read (of a collection, its first Grid: a warning says so). Topologies:
// Hexahedron, Wedge, Pyramid, Tetrahedron, their second-order forms by their corners (XDMF's
// corner orders are VTK's, and so MEDIT's), and Mixed by XDMF's type ids; points, lines and
// surfaces are skipped and counted. Messages name the .xdmf line for XML problems and the HDF5
// dataset for data problems. Builds without HDF5 (and the WebAssembly core) read inline data only.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/element_tally.hpp"
#include "io/detail/text_scanner.hpp"
#include "mesh/cell_templates.hpp"
#include "platform/charconv.hpp"

#if HBC_HDF5
#include <hdf5.h>

#include <mutex>

#include "io/detail/hdf5_lock.hpp"
#endif

namespace hbc {
namespace {

struct XdmfType {
  std::string_view name;  // TopologyType, lower case
  int mixed_id;           // its id in a Mixed topology
  int dim;
  CellShape shape;
  int nodes;
};
constexpr XdmfType kTypes[] = {
    {"tetrahedron", 6, 3, CellShape::Tet, 4},      {"pyramid", 7, 3, CellShape::Pyramid, 5},
    {"wedge", 8, 3, CellShape::Prism, 6},          {"hexahedron", 9, 3, CellShape::Hex, 8},
    {"tetrahedron_10", 38, 3, CellShape::Tet, 10}, {"pyramid_13", 39, 3, CellShape::Pyramid, 13},
    {"wedge_15", 40, 3, CellShape::Prism, 15},     {"wedge_18", 41, 3, CellShape::Prism, 18},
    {"hexahedron_20", 48, 3, CellShape::Hex, 20},  {"hexahedron_24", 49, 3, CellShape::Hex, 24},
    {"hexahedron_27", 50, 3, CellShape::Hex, 27},  {"triangle", 4, 2, CellShape::Faces, 3},
    {"quadrilateral", 5, 2, CellShape::Faces, 4},  {"triangle_6", 36, 2, CellShape::Faces, 6},
    {"quadrilateral_8", 37, 2, CellShape::Faces, 8}, {"quadrilateral_9", 35, 2, CellShape::Faces, 9},
    {"edge_3", 34, 1, CellShape::Faces, 3},
};

class XdmfReader {
 public:
  XdmfReader(std::string_view xml, const std::string& source) : xml_(xml), cells_(in_) { in_.source = source; }
  MeshInput read();

 private:
  int64_t line_of(const pugi::xml_node& n) const {
    const size_t at = std::min(static_cast<size_t>(std::max<ptrdiff_t>(n.offset_debug(), 0)), xml_.size());
    return 1 + std::count(xml_.begin(), xml_.begin() + static_cast<ptrdiff_t>(at), '\n');
  }
  [[noreturn]] void fail(const pugi::xml_node& n, const std::string& expected) const {
    throw InputError(in_.source, SourceLoc::at_line(line_of(n)), "expected " + expected);
  }
  [[noreturn]] void fail_data(const std::string& dataset, const std::string& expected) const {
    throw InputError(in_.source, {}, "expected " + expected + " in HDF5 dataset " + dataset);
  }
  pugi::xml_node grid(const pugi::xml_node& domain);
  pugi::xml_node included(const pugi::xml_node& domain, const pugi::xml_node& g);
  // A DataItem's values: `count` of them when >= 0, else as many as its Dimensions say.
  std::vector<double> numbers(const pugi::xml_node& item, int64_t count, bool integers);
  std::vector<double> inline_numbers(const pugi::xml_node& item, int64_t count) const;
  std::vector<double> hdf_numbers(const pugi::xml_node& item, int64_t count, bool integers) const;
  void geometry(const pugi::xml_node& g);
  void topology(const pugi::xml_node& t);
  void element(const XdmfType& t, const double* ids, const pugi::xml_node& where);

  std::string_view xml_;
  MeshInput in_;
  detail::CellAppender cells_;
  detail::ElementTally tally_;
  int64_t nv_ = 0;
  int64_t topology_line_ = -1;  // the cells' location: their DataItem's line (counted once, not per cell)
};

std::string attr(const pugi::xml_node& n, const char* a, const char* b = nullptr) {
  if (const pugi::xml_attribute x = n.attribute(a)) return x.value();
  return b && n.attribute(b) ? n.attribute(b).value() : "";
}

pugi::xml_node XdmfReader::grid(const pugi::xml_node& domain) {
  pugi::xml_node g = domain.child("Grid");
  if (!g) fail(domain, "a Grid in the Domain");
  while (detail::lower(attr(g, "GridType")) == "collection" || detail::lower(attr(g, "GridType")) == "tree") {
    const pugi::xml_node first = g.child("Grid");
    if (!first) fail(g, "a Grid in the collection '" + attr(g, "Name") + "'");
    const auto n = std::distance(g.children("Grid").begin(), g.children("Grid").end());
    in_.warnings.push_back("read the first of " + std::to_string(n) + " grids of the " + detail::lower(attr(g, "CollectionType")) +
                           " collection '" + attr(g, "Name") + "' (" + attr(first, "Name") + ")");
    g = first;
  }
  return g;
}

// meshio's time series: each step's Grid includes the mesh's Topology and Geometry from a Grid
// named in an xi:include's xpointer ("//Grid[@Name="mesh"]/..."); that Grid is read.
pugi::xml_node XdmfReader::included(const pugi::xml_node& domain, const pugi::xml_node& g) {
  for (const pugi::xml_node c : g.children()) {
    const std::string_view name = c.name();
    if (name != "include" && (name.size() < 8 || name.substr(name.size() - 8) != ":include")) continue;
    const std::string xp = attr(c, "xpointer");
    const size_t at = xp.find("@Name=\"");
    const size_t end = at == std::string::npos ? at : xp.find('"', at + 7);
    if (end == std::string::npos) fail(c, "an xpointer naming a Grid (//Grid[@Name=\"...\"]), found '" + xp + "'");
    const std::string target = xp.substr(at + 7, end - at - 7);
    const pugi::xml_node found = domain.find_node([&](const pugi::xml_node& n) {
      return std::string_view(n.name()) == "Grid" && target == n.attribute("Name").value() && n.child("Topology") && n.child("Geometry");
    });
    if (!found) fail(c, "a Grid named '" + target + "' with a Topology and a Geometry (the xpointer's)");
    in_.warnings.push_back("the grid's Topology and Geometry are those of grid '" + target + "' (xi:include)");
    return found;
  }
  if (!g.child("Geometry")) fail(g, "a Geometry in the Grid");
  fail(g, "a Topology in the Grid");
}

std::vector<double> XdmfReader::numbers(const pugi::xml_node& item, int64_t count, bool integers) {
  if (!item) fail(item, "a DataItem");
  if (item.attribute("Reference") || detail::lower(attr(item, "ItemType")) == "function")
    fail(item, "a DataItem holding its numbers (references and functions are not read)");
  int64_t dims = 1;
  const std::string d = attr(item, "Dimensions");
  size_t at = 0;
  int parts = 0;
  while (at < d.size()) {
    const size_t end = d.find_first_of(" \t\r\n", at);
    const std::string w = d.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos ? d.size() : end + 1;
    if (w.empty()) continue;
    int64_t v = -1;
    const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size() || v < 0 || (v > 0 && dims > INT32_MAX / v)) fail(item, "Dimensions of non-negative integers, found '" + d + "'");
    dims *= v;
    ++parts;
  }
  if (parts == 0) fail(item, "a Dimensions attribute on the DataItem");
  if (count >= 0 && dims != count) fail(item, std::to_string(count) + " values (Dimensions), found " + std::to_string(dims));
  const std::string format = detail::lower(attr(item, "Format").empty() ? "XML" : attr(item, "Format"));
  if (format == "xml") return inline_numbers(item, dims);
  if (format == "hdf") return hdf_numbers(item, dims, integers);
  fail(item, "Format XML or HDF, found '" + attr(item, "Format") + "'");
}

std::vector<double> XdmfReader::inline_numbers(const pugi::xml_node& item, int64_t count) const {
  const std::string_view text = item.text().get();
  std::vector<double> out;
  out.reserve(static_cast<size_t>(std::min<int64_t>(count, static_cast<int64_t>(text.size() / 2 + 1))));
  size_t at = 0;
  while (at < text.size()) {
    at = text.find_first_not_of(" \t\r\n", at);
    if (at == std::string_view::npos) break;
    const size_t end = std::min(text.find_first_of(" \t\r\n", at), text.size());
    double v = 0;
    const auto r = detail::from_chars(text.data() + at, text.data() + end, v);
    if (r.ec != std::errc() || r.ptr != text.data() + end) fail(item, "numbers in the DataItem, found '" + std::string(text.substr(at, std::min<size_t>(end - at, 40))) + "'");
    out.push_back(v);
    at = end;
  }
  if (static_cast<int64_t>(out.size()) != count) fail(item, std::to_string(count) + " numbers in the DataItem (Dimensions), found " + std::to_string(out.size()));
  return out;
}

// "file.h5:/path/in/file", the file relative to the .xdmf's folder.
std::vector<double> XdmfReader::hdf_numbers(const pugi::xml_node& item, int64_t count, bool integers) const {
  std::string ref(item.text().get());
  ref.erase(0, ref.find_first_not_of(" \t\r\n"));
  ref.erase(ref.find_last_not_of(" \t\r\n") + 1);
  const size_t colon = ref.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == ref.size()) fail(item, "FILE:/DATASET in the HDF DataItem, found '" + ref.substr(0, 80) + "'");
  const std::filesystem::path file(ref.substr(0, colon));
  const std::string path = (file.is_absolute() ? file : std::filesystem::path(in_.source).parent_path() / file).string();
  const std::string dataset = path + ":" + ref.substr(colon + 1);
#if HBC_HDF5
  const std::lock_guard<std::mutex> lock(detail::hdf5_library_lock());
  // HDF5 prints its error stack on stderr unless told not to; the message says it instead.
  H5E_auto2_t func = nullptr;
  void* data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::vector<double> out;
  std::string problem;
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = f >= 0 ? H5Dopen2(f, ref.substr(colon + 1).c_str(), H5P_DEFAULT) : -1;
  const hid_t type = d >= 0 ? H5Dget_type(d) : -1;
  const hid_t space = d >= 0 ? H5Dget_space(d) : -1;
  const H5T_class_t cls = type >= 0 ? H5Tget_class(type) : H5T_NO_CLASS;
  const hssize_t n = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
  if (f < 0) problem = "a readable HDF5 file";
  else if (d < 0 || type < 0 || space < 0) problem = "the dataset";
  else if (cls != H5T_INTEGER && cls != H5T_FLOAT) problem = "numbers";
  else if (integers && cls != H5T_INTEGER) problem = "integers";
  else if (n != count) problem = std::to_string(count) + " values (the DataItem's Dimensions), found " + std::to_string(n) + ",";
  else {
    out.resize(static_cast<size_t>(count));
    if (count > 0 && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0) problem = "readable numbers";
  }
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  if (d >= 0) H5Dclose(d);
  if (f >= 0) H5Fclose(f);
  H5Eset_auto2(H5E_DEFAULT, func, data);
  if (!problem.empty()) fail_data(dataset, problem);
  return out;
#else
  (void)count;
  (void)integers;
#ifdef __EMSCRIPTEN__
  throw InputError(in_.source, SourceLoc::at_line(line_of(item)), "XDMF data in HDF5 files (" + dataset + ") need the desktop tool (the hbc command, its Python module or the Blender add-on): the web viewer has no HDF5 library to read them");
#else
  throw InputError(in_.source, SourceLoc::at_line(line_of(item)), "XDMF data in HDF5 files (" + dataset + ") need HDF5: this hbc was built without it (HBC_MED=OFF; install libhdf5-dev and build again)");
#endif
#endif
}

void XdmfReader::element(const XdmfType& t, const double* ids, const pugi::xml_node& where) {
  if (t.dim < 3) return tally_.skip(t.dim);
  std::array<int32_t, 8> v{};
  for (int k = 0; k < t.nodes; ++k) {
    const double id = ids[k];
    if (!(id >= 0 && id < static_cast<double>(nv_)) || id != std::floor(id))
      fail(where, "node ids in [0, " + std::to_string(nv_ - 1) + "] in the Topology, found " + std::to_string(id));
    if (k < corner_count(t.shape)) v[static_cast<size_t>(k)] = static_cast<int32_t>(id);
    else cells_.midside(static_cast<int32_t>(id));
  }
  cells_.element(t.shape, v.data(), topology_line_);
}

void XdmfReader::topology(const pugi::xml_node& top) {
  const std::string type = detail::lower(attr(top, "TopologyType", "Type"));
  const pugi::xml_node item = top.child("DataItem");
  const std::vector<double> ids = numbers(item, -1, true);
  topology_line_ = line_of(item);
  const int64_t n = ids.size();
  if (type == "mixed") {
    for (int64_t at = 0; at < n;) {
      const double id = ids[static_cast<size_t>(at++)];
      if (id == 1 || id == 2 || id == 3) {  // polyvertex, polyline, polygon: a node count follows
        const double k = at < n ? ids[static_cast<size_t>(at)] : -1;
        if (!(k >= 0 && k <= static_cast<double>(n - at - 1))) fail(item, "a node count within the Topology after type " + std::to_string(static_cast<int>(id)));
        tally_.skip(id == 1 ? 0 : id == 2 ? 1 : 2);
        at += 1 + static_cast<int64_t>(k);
        continue;
      }
      const XdmfType* t = nullptr;
      for (const XdmfType& x : kTypes)
        if (x.mixed_id == id) t = &x;
      if (!t) fail(item, "an XDMF cell type id (4-9, 34-41, 48-50; 16 polyhedra are not read) in the Mixed Topology, found " + std::to_string(id));
      if (t->nodes > n - at) fail(item, std::to_string(t->nodes) + " node ids after type " + std::to_string(t->mixed_id) + ", found the end of the Topology");
      element(*t, ids.data() + at, item);
      at += t->nodes;
    }
    return;
  }
  const XdmfType* t = nullptr;
  for (const XdmfType& x : kTypes)
    if (x.name == type) t = &x;
  if (!t) fail(top, "a TopologyType Hexahedron, Wedge, Pyramid, Tetrahedron (or their second-order forms), Mixed, Triangle or Quadrilateral, found '" + attr(top, "TopologyType", "Type") + "'");
  if (n % t->nodes != 0) fail(item, "a multiple of " + std::to_string(t->nodes) + " node ids for " + attr(top, "TopologyType", "Type") + ", found " + std::to_string(n));
  for (int64_t e = 0; e < n / t->nodes; ++e) element(*t, ids.data() + e * t->nodes, item);
}

void XdmfReader::geometry(const pugi::xml_node& g) {
  const std::string type = attr(g, "GeometryType", "Type").empty() ? "XYZ" : attr(g, "GeometryType", "Type");
  if (type != "XYZ") fail(g, "GeometryType XYZ (three coordinates a point), found " + type);
  const pugi::xml_node item = g.child("DataItem");
  std::vector<double> xyz = numbers(item, -1, false);
  if (xyz.empty() || xyz.size() % 3 != 0) fail(item, "3 coordinates a point, found " + std::to_string(xyz.size()) + " numbers");
  for (double c : xyz)
    if (!std::isfinite(c)) fail(item, "finite coordinates, found " + std::to_string(c));
  nv_ = static_cast<int64_t>(xyz.size() / 3);
  in_.points = std::move(xyz);
}

MeshInput XdmfReader::read() {
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_buffer(xml_.data(), xml_.size());
  if (!r) {
    const int64_t line = 1 + std::count(xml_.begin(), xml_.begin() + std::min<ptrdiff_t>(std::max<ptrdiff_t>(r.offset, 0), static_cast<ptrdiff_t>(xml_.size())), '\n');
    throw InputError(in_.source, SourceLoc::at_line(line), std::string("expected well-formed XML (") + r.description() + ")");
  }
  const pugi::xml_node root = doc.child("Xdmf");
  if (!root) fail(doc.first_child(), "an Xdmf root element");
  const pugi::xml_node domain = root.child("Domain");
  if (!domain) fail(root, "a Domain in the Xdmf element");
  pugi::xml_node g = grid(domain);
  if (!g.child("Geometry") || !g.child("Topology")) g = included(domain, g);
  geometry(g.child("Geometry"));
  topology(g.child("Topology"));
  if (in_.cells.rows() == 0) fail(g.child("Topology"), "at least one volume cell (Hexahedron, Wedge, Pyramid or Tetrahedron)");
  tally_.report(in_);
  cells_.finish();
  return std::move(in_);
}

}  // namespace

MeshInput read_xdmf(std::string_view xml, const std::string& source) { return XdmfReader(xml, source).read(); }

}  // namespace hbc
