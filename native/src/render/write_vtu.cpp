// VTU export (vtu_export.hpp): cells in VTK's corner orders, per-cell and per-point analysis
// arrays, and the singularity graph as line cells in a second file.
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "io/detail/base64.hpp"
#include "hbc/region.hpp"
#include "hbc/vtu_export.hpp"

namespace hbc {
namespace {

template <class T>
const char* vtk_type_name() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, int64_t>) return "Int64";
  else if constexpr (std::is_same_v<T, int32_t>) return "Int32";
  else return "UInt8";
}

// One XML document; DataArrays in ascii or as VTK's compressed base64 (header: block count,
// block size, last block size, compressed sizes, all UInt64).
class VtuDoc {
 public:
  explicit VtuDoc(bool ascii) : ascii_(ascii) {
    x_ << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
       << (std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\""
       << (ascii ? "" : " compressor=\"vtkZLibDataCompressor\"") << ">\n<UnstructuredGrid>\n";
  }
  std::ostringstream& xml() { return x_; }
  template <class T>
  void array(const char* name, const std::vector<T>& v, int components = 1) {
    // NumberOfComponents only when more than 1: meshio reshapes every array that states it.
    x_ << "<DataArray type=\"" << vtk_type_name<T>() << "\" Name=\"" << name << "\"";
    if (components > 1) x_ << " NumberOfComponents=\"" << components << "\"";
    x_ << " format=\"" << (ascii_ ? "ascii" : "binary") << "\">\n";
    if (ascii_) {
      char buf[32];
      for (size_t i = 0; i < v.size(); ++i) {
        if constexpr (std::is_same_v<T, double>) std::snprintf(buf, sizeof buf, "%.17g", v[i]);
        else std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v[i]));
        x_ << buf << ((i + 1) % 12 == 0 || i + 1 == v.size() ? '\n' : ' ');
      }
    } else {
      x_ << compressed(std::string_view(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T))) << "\n";
    }
    x_ << "</DataArray>\n";
  }
  std::string finish() {
    x_ << "</UnstructuredGrid>\n</VTKFile>\n";
    return x_.str();
  }

 private:
  static std::string compressed(std::string_view data) {
    constexpr size_t kBlock = 1 << 16;
    const size_t nb = (data.size() + kBlock - 1) / kBlock;
    std::vector<uint64_t> head = {nb, kBlock, data.size() % kBlock};
    std::string body;
    for (size_t k = 0; k < nb; ++k) {
      const std::string_view part = data.substr(k * kBlock, kBlock);
      uLongf n = compressBound(static_cast<uLong>(part.size()));
      std::string z(n, '\0');
      if (compress2(reinterpret_cast<Bytef*>(z.data()), &n, reinterpret_cast<const Bytef*>(part.data()),
                    static_cast<uLong>(part.size()), 6) != Z_OK)
        throw std::runtime_error("zlib compression failed");
      head.push_back(n);
      body.append(z.data(), n);
    }
    return detail::base64_encode({reinterpret_cast<const char*>(head.data()), head.size() * 8}) +
           detail::base64_encode(body);
  }
  bool ascii_;
  std::ostringstream x_;
};

// The loop of the i-th face of cell c as the cell sees it: outward (build_mesh orients cells).
void cell_face_loop(const Mesh& m, size_t c, size_t i, std::vector<int32_t>& loop) {
  const int32_t slot = m.cell_faces.offsets[c] + static_cast<int32_t>(i);
  auto l = m.face_verts[static_cast<size_t>(m.cell_faces.items[slot])];
  loop.assign(l.begin(), l.end());
  if (m.cell_face_flip[slot]) std::reverse(loop.begin(), loop.end());
}

// VTK's corners of a hex, tet, prism or pyramid, from its faces; false for other cells.
bool vtk_corners(const Mesh& m, size_t c, std::vector<int64_t>& conn, uint8_t& vtk_type) {
  const CellType t = m.cell_type[c];
  if (t == CellType::Polyhedron) return false;
  // Base: hex and tet any face, prism a triangle, pyramid the quadrangle.
  const size_t nf = static_cast<size_t>(m.cell_faces.count(c));
  const size_t want = t == CellType::Prism ? 3 : t == CellType::Pyramid ? 4 : 0;
  std::vector<int32_t> base;
  for (size_t i = 0; i < nf; ++i) {
    cell_face_loop(m, c, i, base);
    if (want == 0 || base.size() == want) break;
  }
  // In VTK the base of every type faces into the cell: hexahedron 0-1-2-3 towards 4-5-6-7, tetra
  // 0-1-2 and pyramid 0-1-2-3 towards the apex, wedge 0-1-2 towards 3-4-5 (vtkWedge's reference
  // cell; VTK 9.7's vtkMeshQuality and vtkCellSizeFilter rate the mirror image as inverted, though
  // older VTK documentation and meshio say the wedge's triangle faces out). A wedge keeps its first
  // corner: its corners differ from the mirror image written before only by swapping 1 with 2 and
  // 4 with 5, and they read back into the same face loops as those did.
  std::reverse(base.begin() + (t == CellType::Prism ? 1 : 0), base.end());
  conn.assign(base.begin(), base.end());
  if (t == CellType::Tet || t == CellType::Pyramid) {
    std::vector<int32_t> vs;
    cell_vertices(m, c, vs);
    for (int32_t v : vs)
      if (std::find(base.begin(), base.end(), v) == base.end()) conn.push_back(v);
    vtk_type = t == CellType::Tet ? 10 : 14;
    return conn.size() == base.size() + 1;
  }
  // Hex and prism: above each base corner the corner joined to it by an edge off the base.
  std::vector<int32_t> es;
  cell_edges(m, c, es);
  for (int32_t b : base)
    for (int32_t e : es) {
      const auto& ev = m.edge_verts[static_cast<size_t>(e)];
      if (ev[0] != b && ev[1] != b) continue;
      const int32_t u = m.other_vertex(e, b);
      if (std::find(base.begin(), base.end(), u) == base.end()) conn.push_back(u);
    }
  vtk_type = t == CellType::Hex ? 12 : 13;
  return conn.size() == 2 * base.size();
}

void write_points(VtuDoc& d, const Mesh& m) {
  d.xml() << "<Points>\n";
  d.array("Points", m.points, 3);
  d.xml() << "</Points>\n";
}

// Per cell: the lowest row of `rows` that lists it, and how many do.
void first_and_count(const Csr<int32_t>& rows, size_t nc, std::vector<int32_t>& first, std::vector<int32_t>& count) {
  first.assign(nc, -1);
  count.assign(nc, 0);
  for (size_t r = 0; r < rows.rows(); ++r)
    for (int32_t c : rows[r]) {
      if (first[c] < 0) first[c] = static_cast<int32_t>(r);
      ++count[c];
    }
}

void write_cell_data(VtuDoc& d, const Mesh& m, const Analysis& a, const VtuExportOptions& o) {
  const size_t nc = m.num_cells();
  std::vector<uint8_t> is_hex(nc), type(nc);
  for (size_t c = 0; c < nc; ++c) {
    is_hex[c] = m.is_hex(c) ? 1 : 0;
    type[c] = static_cast<uint8_t>(m.cell_type[c]);
  }
  d.xml() << "<CellData Scalars=\"component\">\n";
  d.array("component", a.complex.cell_component);
  d.array("is_hex", is_hex);
  d.array("cell_type", type);
  if (a.sheet_stage) {
    std::vector<int32_t> first, count;
    first_and_count(a.sheet_stage->sheets.sheet_cells, nc, first, count);
    d.array("sheet", first);
    d.array("sheet_count", count);
  }
  if (o.sheet) {
    const SheetStage& st = require_sheet(a, *o.sheet);
    std::vector<uint8_t> in(nc, 0);
    for (int32_t c : st.sheets.sheet_cells[static_cast<size_t>(*o.sheet)]) in[c] = 1;
    d.array("in_sheet", in);
    std::vector<int32_t> first(nc, -1), count(nc, 0);
    if (const Subsheets* s = st.subsheets_of(*o.sheet)) first_and_count(s->cells, nc, first, count);
    d.array("subsheet", first);
    d.array("subsheet_count", count);
  }
  d.xml() << "</CellData>\n";
}

void write_point_data(VtuDoc& d, const Mesh& m, const Analysis& a) {
  std::vector<uint8_t> singular(m.num_vertices(), 0);
  for (int32_t v : a.graph.singular_vertices) singular[v] = 1;
  d.xml() << "<PointData>\n";
  d.array("singular", singular);
  d.array("pseudo_singular", a.graph.vert_pseudo_singular);
  d.array("corner", a.complex.vert_corner);
  d.xml() << "</PointData>\n";
}

}  // namespace

std::string vtu_cells_text(const Mesh& m, const Analysis& a, const VtuExportOptions& o) {
  if (o.sheet) require_sheet(a, *o.sheet);  // before any work
  const size_t nc = m.num_cells();
  std::vector<int64_t> conn, offsets, faces, faceoffsets, corners, loop64;
  std::vector<uint8_t> types(nc);
  std::vector<int32_t> loop, scratch;
  // Each cell as its own VTK type, so that ParaView's filters treat hexahedra as hexahedra; only
  // general polyhedra (and a standard type whose corners cannot be found) as VTK_POLYHEDRON, whose
  // face stream VTK's format puts beside the others (faceoffsets -1 for the standard cells).
  // meshio 5 refuses a file mixing VTK_POLYHEDRON with other types; VTK and ParaView read it.
  bool any_poly = false;
  for (size_t c = 0; c < nc; ++c) {
    if (vtk_corners(m, c, corners, types[c])) {
      conn.insert(conn.end(), corners.begin(), corners.end());
      faceoffsets.push_back(-1);
    } else {
      any_poly = true;
      // Face stream: face count, then each outward loop with its length.
      types[c] = 42;
      cell_vertices(m, c, scratch);
      conn.insert(conn.end(), scratch.begin(), scratch.end());
      const size_t nf = static_cast<size_t>(m.cell_faces.count(c));
      faces.push_back(static_cast<int64_t>(nf));
      for (size_t i = 0; i < nf; ++i) {
        cell_face_loop(m, c, i, loop);
        faces.push_back(static_cast<int64_t>(loop.size()));
        faces.insert(faces.end(), loop.begin(), loop.end());
      }
      faceoffsets.push_back(static_cast<int64_t>(faces.size()));
    }
    offsets.push_back(static_cast<int64_t>(conn.size()));
  }
  VtuDoc d(o.ascii);
  d.xml() << "<Piece NumberOfPoints=\"" << m.num_vertices() << "\" NumberOfCells=\"" << nc << "\">\n";
  write_point_data(d, m, a);
  write_cell_data(d, m, a, o);
  write_points(d, m);
  d.xml() << "<Cells>\n";
  d.array("connectivity", conn);
  d.array("offsets", offsets);
  d.array("types", types);
  if (any_poly) {
    d.array("faces", faces);
    d.array("faceoffsets", faceoffsets);
  }
  d.xml() << "</Cells>\n</Piece>\n";
  return d.finish();
}

std::string vtu_graph_text(const Mesh& m, const Analysis& a, const VtuExportOptions& o) {
  std::vector<int64_t> conn, offsets;
  std::vector<uint8_t> cls;
  std::vector<int32_t> valence, chain;
  for (size_t e = 0; e < m.num_edges(); ++e) {
    if (!a.graph.is_structural(static_cast<int32_t>(e))) continue;
    conn.push_back(m.edge_verts[e][0]);
    conn.push_back(m.edge_verts[e][1]);
    offsets.push_back(static_cast<int64_t>(conn.size()));
    cls.push_back(static_cast<uint8_t>(a.graph.edge_class[e]));
    valence.push_back(m.edge_valence(e));
    chain.push_back(a.graph.edge_chain[e]);
  }
  VtuDoc d(o.ascii);
  d.xml() << "<Piece NumberOfPoints=\"" << m.num_vertices() << "\" NumberOfCells=\"" << cls.size() << "\">\n";
  write_point_data(d, m, a);
  d.xml() << "<CellData Scalars=\"edge_class\">\n";
  d.array("edge_class", cls);
  d.array("valence", valence);
  d.array("singularity", chain);
  d.xml() << "</CellData>\n";
  write_points(d, m);
  d.xml() << "<Cells>\n";
  d.array("connectivity", conn);
  d.array("offsets", offsets);
  d.array("types", std::vector<uint8_t>(cls.size(), 3));  // VTK_LINE
  d.xml() << "</Cells>\n</Piece>\n";
  return d.finish();
}

std::string vtu_graph_path(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? path.substr(0, dot) : path) + "_graph.vtu";
}

void export_vtu(const Mesh& m, const Analysis& a, const std::string& path, const VtuExportOptions& o) {
  const std::pair<std::string, std::string> files[] = {{path, vtu_cells_text(m, a, o)},
                                                       {vtu_graph_path(path), vtu_graph_text(m, a, o)}};
  for (const auto& [p, text] : files) {
    std::ofstream f(p, std::ios::binary);
    if (!f) throw std::runtime_error("cannot write " + p);
    f << text;
    if (!f) throw std::runtime_error("write failed: " + p);
  }
}

}  // namespace hbc
