// The element-list readers (.msh, .vtk, .vtu): one real hex-dominant mesh written by gmsh and
// meshio in every format must give the same analysis; hand-drawn cells check corner orders,
// degenerate hexahedra, node tags and higher-order elements; binary variants that no tool here
// writes (big-endian Gmsh, appended VTU, UInt64 headers) are encoded field by field below.
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "hbc/vtu_export.hpp"
#include "io/detail/base64.hpp"
#include "format_samples.hpp"
#include "test_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

std::string formats_path(const std::string& rel) { return std::string(HBC_FORMATS_DIR) + "/" + rel; }
std::string formats_file(const std::string& rel) { return read_file_bytes(formats_path(rel)); }

using test::signed_volume;


// ---------------------------------------------------------------------------------------------
// One real mesh in every format.

// The same mesh as real/slab.mesh, written by gmsh or meshio (make_real_files.py).
const char* const kRealFiles[] = {"slab_22.msh", "slab_22_bin.msh", "slab_41.msh", "slab_41_bin.msh",
                                  "slab_41_order2.msh", "slab_gmsh.vtk", "slab_42_ascii.vtk", "slab_42_bin.vtk",
                                  "slab_51_ascii.vtk", "slab_51_bin.vtk", "slab_poly.vtk", "slab_poly_bin.vtk",
                                  "slab_ascii.vtu", "slab_zlib.vtu", "slab_b64.vtu"};

TEST(FormatsRealTools, EveryFormatGivesTheSameAnalysisAsMedit) {
  const Mesh ref_mesh = load_mesh(formats_path("real/slab.mesh"));
  // slab.geo: 41 quadrangles and 14 triangles extruded in 2 layers; the counts pin the file down.
  ASSERT_EQ(ref_mesh.num_cells(), 110u);
  ASSERT_EQ(ref_mesh.num_hex_cells(), 82u);
  const Stats ref = compute_stats(ref_mesh, analyze(ref_mesh));
  for (const char* f : kRealFiles) {
    SCOPED_TRACE(f);
    const Mesh m = load_mesh(formats_path(std::string("real/") + f));
    EXPECT_EQ(m.num_vertices(), ref_mesh.num_vertices());
    EXPECT_EQ(m.num_edges(), ref_mesh.num_edges());
    EXPECT_EQ(m.num_faces(), ref_mesh.num_faces());
    test::expect_same_counts(compute_stats(m, analyze(m)), ref);
  }
}

TEST(FormatsRealTools, EveryCellFacesOutAsReadButMirroredWedges) {
  // The slab is untangled, so each tool's corner order, read by that format's convention, gives
  // outward loops before build_mesh orients anything, but for the wedges of the VTK files: meshio
  // and Gmsh's VTK writer write the mirror image of VTK's wedge (after VTK's older documentation),
  // and VTK 9.7 itself finds those 28 wedges inverted (vtkCellSizeFilter: negative volumes; the
  // hexahedra positive). build_mesh turns them with their neighbours: every cell comes out positive.
  for (const char* f : kRealFiles) {
    SCOPED_TRACE(f);
    const std::string path = formats_path(std::string("real/") + f);
    const std::string name = f;
    const bool vtk_elements = name.find(".vt") != std::string::npos && name.find("poly") == std::string::npos;
    const MeshInput read = read_input(path);
    const MeshInput in = with_face_soup(read);
    ASSERT_EQ(in.cells.rows(), 110u);
    size_t mirrored = 0;
    for (size_t c = 0; c < in.cells.rows(); ++c) {
      const bool wedge = in.cells.count(c) == 5;  // the slab has hexahedra and wedges only
      const double vol = signed_volume(in, c);
      if (vtk_elements && wedge) {
        ASSERT_LT(vol, 0) << "cell " << c;
        ++mirrored;
      } else {
        ASSERT_GT(vol, 0) << "cell " << c;
      }
    }
    EXPECT_EQ(mirrored, vtk_elements ? 28u : 0u);
    EXPECT_EQ(check_input(read)[Defect::Inverted].count, 0);
  }
}

TEST(FormatsRealTools, SurfaceElementsAreSkippedAndCounted) {
  // gmsh writes the 41 quadrangles and 14 triangles of the physical surface "bottom" (the
  // 82 hexahedra and 28 prisms stand on them in two layers); they are counted in one warning.
  const Mesh m = load_mesh(formats_path("real/slab_41.msh"));
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("55 surface element(s)"), std::string::npos) << m.warnings[0];
  EXPECT_TRUE(load_mesh(formats_path("real/slab.mesh")).warnings.empty());
}

// ---------------------------------------------------------------------------------------------
// Hand-drawn cells.

TEST(FormatsCorners, APrismInEachFormatsOwnOrderFacesOutward) {
  // The prism over the unit right triangle, height 1: volume 1/2 when every loop faces out. VTK's
  // wedge has MEDIT's and Gmsh's corner order (vtkWedge's reference cell in VTK 9.7: triangle
  // 0-1-2 faces into the cell), so all three files give the same cell.
  const MeshInput medit = with_face_soup(read_medit(formats_file("prism.mesh"), "prism.mesh"));
  const MeshInput msh = with_face_soup(read_msh(formats_file("prism_gmsh.msh"), "prism_gmsh.msh"));
  const MeshInput vtk = with_face_soup(read_vtk(formats_file("prism_vtk.vtk"), "prism_vtk.vtk"));
  EXPECT_DOUBLE_EQ(signed_volume(medit, 0), 0.5);
  EXPECT_DOUBLE_EQ(signed_volume(msh, 0), 0.5);
  EXPECT_DOUBLE_EQ(signed_volume(vtk, 0), 0.5);
  test::expect_same_cells(msh, medit);
  test::expect_same_cells(vtk, medit);
  // The mirror image (VTK's older documentation, meshio's VTK writer) is the prism turned inside
  // out: VTK 9.7's vtkCellSizeFilter gives this wedge the volume -0.5 too.
  std::string mirrored = formats_file("prism_vtk.vtk");
  mirrored.replace(mirrored.find("6 0 1 2 3 4 5"), 13, "6 0 2 1 3 5 4");
  EXPECT_DOUBLE_EQ(signed_volume(with_face_soup(read_vtk(mirrored, "mirrored.vtk")), 0), -0.5);
  // The same in the XML format and for the quadratic wedges, whose corners come first: VTK 9.7's
  // reference cells of types 26, 31 and 32 have these corners and a positive volume too.
  const std::string head = "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"18\" "
                           "NumberOfCells=\"1\"><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                           "format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1";
  for (int type : {13, 26, 31, 32}) {
    SCOPED_TRACE(type);
    const int n = type == 13 ? 6 : type == 26 ? 15 : type == 31 ? 12 : 18;
    std::string xml = head;
    for (int i = 6; i < 18; ++i) xml += " 0.5 0.5 0.5";  // mid-edge nodes: only the corners count
    xml += "</DataArray></Points><Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">";
    for (int i = 0; i < n; ++i) xml += " " + std::to_string(i);
    xml += "</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">" + std::to_string(n) +
           "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" + std::to_string(type) +
           "</DataArray></Cells></Piece></UnstructuredGrid></VTKFile>";
    const MeshInput in = with_face_soup(read_vtu(xml, "wedge.vtu"));
    EXPECT_DOUBLE_EQ(signed_volume(in, 0), 0.5);
  }
}

TEST(FormatsCorners, AHexahedronWithRepeatedCornersIsMeditsPolyhedron) {
  std::string medit_text = formats_file("prism.mesh");
  medit_text.replace(medit_text.find("Prisms\n1\n1 2 3 4 5 6 0"), 22, "Hexahedra\n1\n1 2 3 3 4 5 6 6 0");
  const MeshInput medit = read_medit(medit_text, "degenerate.mesh");
  ASSERT_EQ(medit.cells.count(0), 5);  // two triangles and three quadrangles
  test::expect_same_cells(read_msh(formats_file("degenerate_hex.msh"), "degenerate_hex.msh"), medit);
  test::expect_same_cells(read_vtk(formats_file("degenerate_hex.vtk"), "degenerate_hex.vtk"), medit);
  const Mesh m = build_mesh(medit);
  EXPECT_EQ(m.cell_type[0], CellType::Prism);
}

TEST(FormatsMsh, EntityBlocksTagGapsAndASecondOrderHexahedron) {
  const MeshInput in = read_msh(formats_file("two_hex_orders.msh"), "two_hex_orders.msh");
  // 16 nodes, of which 104, 105, 106 and 120 are only mid-edge nodes of the 20-node hexahedron.
  EXPECT_EQ(in.points.size(), 3u * 12);
  const Mesh m = build_mesh(in);
  ASSERT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.num_hex_cells(), 2u);
  EXPECT_EQ(m.num_faces(), 11u);  // two cubes sharing one face
  EXPECT_DOUBLE_EQ(signed_volume(with_face_soup(in), 1), 1.0);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("1 surface element(s)"), std::string::npos);
}

TEST(FormatsVtk, FieldDataPointAndCellDataAreReadPast) {
  const MeshInput in = read_vtk(formats_file("field_data.vtk"), "field_data.vtk");
  ASSERT_EQ(in.cells.rows(), 2u);  // the triangle is skipped
  EXPECT_DOUBLE_EQ(signed_volume(with_face_soup(in), 0), 1.0 / 6);
  EXPECT_DOUBLE_EQ(signed_volume(with_face_soup(in), 1), 1.0 / 6);
  const Mesh m = build_mesh(in);
  EXPECT_EQ(m.num_faces(), 7u);  // two tets sharing a face
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("1 surface element(s)"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Binary Gmsh encoded here in either byte order.

TEST(FormatsMsh, BinaryInBothByteOrdersReadsAsTheAsciiFile) {
  const MeshInput ascii = read_msh(formats_file("prism_gmsh.msh"), "prism_gmsh.msh");
  for (bool swap : {false, true}) {
    SCOPED_TRACE(swap ? "byte-swapped" : "native order");
    const MeshInput bin = read_msh(test::prism_msh41_binary(swap), "prism.msh");
    EXPECT_TRUE(bin.binary);
    test::expect_same_cells(bin, ascii);
  }
}

// ---------------------------------------------------------------------------------------------
// VTU in every data encoding, encoded here from poly.vtu's arrays.

struct VtuArray {
  std::string name, type;
  int components;
  std::string raw;  // little-endian values
};

std::string base64(const std::string& in) { return detail::base64_encode(in); }

struct VtuMode {
  std::string format;   // binary or appended
  bool zlib = false, base64_appended = false, uint64 = false, big_endian = false;
};

std::string header_word(uint64_t v, const VtuMode& m) {
  test::Bytes b{"", m.big_endian};
  if (m.uint64) b.put<uint64_t>(v);
  else b.put<uint32_t>(static_cast<uint32_t>(v));
  return b.s;
}

// The bytes VTK writes for one array: a size header and the data, or zlib blocks of 40 bytes (so
// that arrays span several blocks) with the block header.
std::string vtk_block(const std::string& data, const VtuMode& m, bool separate_base64) {
  if (!m.zlib) {
    const std::string h = header_word(data.size(), m);
    return separate_base64 ? base64(h) + base64(data) : h + data;
  }
  const size_t bs = 40, nb = (data.size() + bs - 1) / bs;
  std::string head = header_word(nb, m) + header_word(bs, m) + header_word(data.size() % bs, m), body;
  for (size_t k = 0; k < nb; ++k) {
    const std::string part = data.substr(k * bs, bs);
    uLongf n = compressBound(part.size());
    std::string z(n, '\0');
    compress(reinterpret_cast<Bytef*>(z.data()), &n, reinterpret_cast<const Bytef*>(part.data()), part.size());
    z.resize(n);
    head += header_word(n, m);
    body += z;
  }
  return separate_base64 ? base64(head) + base64(body) : head + body;
}

std::string encode_vtu(const std::vector<VtuArray>& arrays, const VtuMode& m) {
  std::ostringstream x;
  std::string appended;
  x << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
    << (m.big_endian ? "BigEndian" : "LittleEndian") << "\" header_type=\"" << (m.uint64 ? "UInt64" : "UInt32") << "\""
    << (m.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") << ">\n<UnstructuredGrid>\n"
    << "<Piece NumberOfPoints=\"12\" NumberOfCells=\"2\">\n";
  for (const VtuArray& a : arrays) {
    if (a.name == "points") x << "<Points>\n";
    if (a.name == "connectivity") x << "<Cells>\n";
    // Values in the file's byte order.
    std::string raw = a.raw;
    const size_t w = a.type == "UInt8" ? 1 : a.type == "Int64" ? 8 : 4;
    if (m.big_endian)
      for (size_t i = 0; i < raw.size(); i += w) std::reverse(raw.begin() + static_cast<std::ptrdiff_t>(i), raw.begin() + static_cast<std::ptrdiff_t>(i + w));
    x << "<DataArray type=\"" << a.type << "\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components
      << "\" format=\"" << m.format << "\"";
    if (m.format == "binary") {
      x << ">\n" << vtk_block(raw, m, true) << "\n</DataArray>\n";
    } else {
      x << " offset=\"" << appended.size() << "\"/>\n";
      appended += m.base64_appended ? vtk_block(raw, m, true) : vtk_block(raw, m, false);
    }
    if (a.name == "points") x << "</Points>\n";
  }
  x << "</Cells>\n</Piece>\n</UnstructuredGrid>\n";
  if (m.format == "appended")
    x << "<AppendedData encoding=\"" << (m.base64_appended ? "base64" : "raw") << "\">\n_" << appended << "\n</AppendedData>\n";
  x << "</VTKFile>\n";
  return x.str();
}

template <class T>
std::string le(std::initializer_list<T> v) {
  std::string s;
  for (T x : v) s.append(reinterpret_cast<const char*>(&x), sizeof(T));
  return s;
}

// poly.vtu's arrays (a hexahedron and a polyhedral cube), with points as Float32 and the
// connectivity as Int32 so that several value types are read.
std::vector<VtuArray> poly_arrays() {
  return {{"points", "Float32", 3, le<float>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 2})},
          {"connectivity", "Int32", 1, le<int32_t>({0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 7, 8, 9, 10, 11})},
          {"offsets", "Int64", 1, le<int64_t>({8, 16})},
          {"types", "UInt8", 1, le<uint8_t>({12, 42})},
          {"faces", "Int64", 1, le<int64_t>({6, 4, 4, 7, 6, 5, 4, 8, 9, 10, 11, 4, 4, 5, 9, 8, 4, 5, 6, 10, 9, 4, 6, 7, 11, 10, 4, 7, 4, 8, 11})},
          {"faceoffsets", "Int64", 1, le<int64_t>({-1, 31})}};
}

TEST(FormatsVtu, EveryDataEncodingReadsAsTheAsciiFile) {
  const MeshInput ascii = read_vtu(formats_file("poly.vtu"), "poly.vtu");
  ASSERT_EQ(ascii.cells.rows(), 2u);
  EXPECT_DOUBLE_EQ(signed_volume(with_face_soup(ascii), 0), 1.0);
  EXPECT_DOUBLE_EQ(signed_volume(with_face_soup(ascii), 1), 1.0);  // the face list as written faces out
  const Mesh m = build_mesh(ascii);
  EXPECT_EQ(m.num_hex_cells(), 2u);  // the polyhedral cube is a hexahedron by its faces
  const std::vector<VtuMode> modes = {
      {"binary"}, {"binary", true}, {"binary", false, false, true}, {"binary", true, false, true, true},
      {"appended"}, {"appended", true}, {"appended", false, true}, {"appended", true, true, true},
      {"appended", true, false, false, true}};
  for (const VtuMode& mode : modes) {
    const std::string name = mode.format + (mode.zlib ? "_zlib" : "") + (mode.base64_appended ? "_b64" : "") +
                             (mode.uint64 ? "_u64" : "") + (mode.big_endian ? "_be" : "") + ".vtu";
    SCOPED_TRACE(name);
    test::expect_same_cells(read_vtu(encode_vtu(poly_arrays(), mode), name), ascii);
  }
}

// ---------------------------------------------------------------------------------------------
// Export: what vtu_cells_text writes reads back as the same mesh, every cell facing out in VTK's
// corner orders (hex, wedge, tet, pyramid) or as a polyhedron.

void expect_export_round_trip(const Mesh& m, bool ascii) {
  const Analysis a = analyze(m);
  VtuExportOptions o;
  o.ascii = ascii;
  const MeshInput back = with_face_soup(read_vtu(vtu_cells_text(m, a, o), "export.vtu"));
  ASSERT_EQ(back.cells.rows(), m.num_cells());
  for (size_t c = 0; c < m.num_cells(); ++c) ASSERT_GT(signed_volume(back, c), 0) << "cell " << c;
  const Mesh mb = build_mesh(back);
  EXPECT_EQ(mb.cell_type, m.cell_type);
  const Stats s = compute_stats(m, a), sb = compute_stats(mb, analyze(mb));
  EXPECT_EQ(sb.components, s.components);
  EXPECT_EQ(sb.sheets, s.sheets);
  EXPECT_EQ(sb.singular_edges, s.singular_edges);
  EXPECT_EQ(sb.pseudo_singular_edges, s.pseudo_singular_edges);
  // The graph file has only lines, which the reader skips and counts.
  try {
    read_vtu(vtu_graph_text(m, a, o), "graph.vtu");
    ADD_FAILURE() << "a graph of lines read as a volume mesh";
  } catch (const InputError& e) {
    EXPECT_NE(e.detail().find("at least one volume cell"), std::string::npos) << e.what();
  }
}

TEST(FormatsExport, HexPrismMeshReadsBackFacingOutInVtkCornerOrders) {
  const Mesh m = load_mesh(formats_path("real/slab.mesh"));
  expect_export_round_trip(m, false);
  expect_export_round_trip(m, true);
}

TEST(FormatsExport, EveryCellTypeAndPolyhedraReadBack) {
  HBC_REQUIRE_DATA("hybrid-base-complex/twistcube_s.mesh");
  expect_export_round_trip(test::load_data("hybrid-base-complex/twistcube_s.mesh"), false);
  HBC_REQUIRE_DATA("openvolumemesh/Cylinder.ovm");
  expect_export_round_trip(test::load_data("openvolumemesh/Cylinder.ovm"), false);
}

TEST(FormatsExport, GraphPathAndSheetRange) {
  EXPECT_EQ(vtu_graph_path("a/b.c/out.vtu"), "a/b.c/out_graph.vtu");
  EXPECT_EQ(vtu_graph_path("a.b/out"), "a.b/out_graph.vtu");
  const Mesh m = load_mesh(formats_path("real/slab.mesh"));
  const Analysis a = analyze(m);
  VtuExportOptions o;
  o.sheet = static_cast<int32_t>(a.sheet_stage->sheets.sheet_cells.rows());
  EXPECT_THROW(vtu_cells_text(m, a, o), std::invalid_argument);
}

}  // namespace
}  // namespace hbc
