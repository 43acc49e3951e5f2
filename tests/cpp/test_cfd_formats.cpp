// The CFD readers (SU2, AFLR3 UGRID, Fluent .msh): the slab written by the real tools (gmsh's and
// meshio's SU2, meshio's UGRID in all five encodings, OpenFOAM's foamMeshToFluent; made by
// tests/data/formats/make_cfd_files.py) must give slab.mesh's analysis; hand-written cells check
// corner orders, zones, markers and Fluent's face sides and binary sections.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "format_samples.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

constexpr bool kLittle = std::endian::native == std::endian::little;

std::string formats_path(const std::string& rel) { return std::string(HBC_FORMATS_DIR) + "/" + rel; }

using test::signed_volume;

const char* const kCfdFiles[] = {"slab_gmsh.su2",  "slab_meshio.su2", "slab.ugrid",     "slab.b8.ugrid",
                                 "slab.lb8.ugrid", "slab.r8.ugrid",   "slab.lr8.ugrid", "slab_fluent.msh"};

TEST(CfdFormatsRealTools, EveryFileGivesTheAnalysisOfItsMeditTwin) {
  const Mesh ref_mesh = load_mesh(formats_path("real/slab.mesh"));
  ASSERT_EQ(ref_mesh.num_cells(), 110u);
  const Stats ref = compute_stats(ref_mesh, analyze(ref_mesh));
  for (const char* f : kCfdFiles) {
    SCOPED_TRACE(f);
    const Mesh m = load_mesh(formats_path(std::string("real/") + f));
    EXPECT_EQ(m.num_vertices(), ref_mesh.num_vertices());
    EXPECT_EQ(m.num_edges(), ref_mesh.num_edges());
    EXPECT_EQ(m.num_faces(), ref_mesh.num_faces());
    EXPECT_EQ(m.num_hex_cells(), 82u);
    EXPECT_EQ(std::count(m.cell_type.begin(), m.cell_type.end(), CellType::Prism), 28);
    test::expect_same_counts(compute_stats(m, analyze(m)), ref);
  }
}

TEST(CfdFormatsRealTools, EveryCellFacesOutAsRead) {
  // The slab is untangled: read by each format's convention (SU2's mirrored prism, UGRID's
  // pyramid, Fluent's c0/c1 sides), every cell's loops face out before build_mesh orients anything,
  // but for meshio's SU2: meshio writes its wedges (Gmsh's order) without the swap SU2's prism
  // needs (its VTK writer makes it), so its 28 wedges are inverted for SU2 too (SU2's
  // CPrismConnectivity faces, gmsh's SU2 writer); build_mesh turns them with their neighbours, and
  // the analysis is the same (above).
  for (const char* f : kCfdFiles) {
    SCOPED_TRACE(f);
    const MeshInput read = read_input(formats_path(std::string("real/") + f));
    const MeshInput in = with_face_soup(read);
    ASSERT_EQ(in.cells.rows(), 110u);
    size_t negative = 0;
    for (size_t c = 0; c < in.cells.rows(); ++c) negative += signed_volume(in, c) < 0;
    EXPECT_EQ(negative, std::string(f) == "slab_meshio.su2" ? 28u : 0u);
    EXPECT_EQ(check_input(read)[Defect::Inverted].count, 0);
  }
}

TEST(CfdFormatsRealTools, BoundaryElementsAreSkippedAndCounted) {
  // The 41 quadrangles and 14 triangles of the slab's bottom: gmsh's SU2 marker "bottom" and
  // meshio's UGRID boundary faces; meshio's SU2 was written without them; Fluent's faces are cells'.
  for (const char* f : {"slab_gmsh.su2", "slab.ugrid", "slab.b8.ugrid"}) {
    SCOPED_TRACE(f);
    const Mesh m = load_mesh(formats_path(std::string("real/") + f));
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("55 surface element(s)"), std::string::npos) << m.warnings[0];
  }
  EXPECT_TRUE(load_mesh(formats_path("real/slab_meshio.su2")).warnings.empty());
}

TEST(CfdFormatsDispatch, MshIsGmshOrFluentByContent) {
  // By extension and by --format msh, a Fluent file is read as Fluent; --format fluent names it.
  const std::string fluent = formats_path("real/slab_fluent.msh");
  EXPECT_EQ(format_from_path(fluent), Format::Msh);
  EXPECT_EQ(format_from_name("fluent"), Format::Fluent);
  EXPECT_EQ(format_from_path("a/b.b8.ugrid"), Format::Ugrid);
  EXPECT_EQ(ugrid_encoding_of("a/B.LB8.UGRID"), UgridEncoding::LittleEndian);
  EXPECT_EQ(ugrid_encoding_of("a/b.r8.ugrid"), UgridEncoding::FortranBigEndian);
  EXPECT_EQ(ugrid_encoding_of("a/b.ugrid"), UgridEncoding::Ascii);
  EXPECT_EQ(read_input(fluent).cells.rows(), 110u);
  EXPECT_EQ(read_input(fluent, Format::Fluent).cells.rows(), 110u);
  EXPECT_EQ(read_input(formats_path("real/slab_41.msh"), Format::Msh).cells.rows(), 110u);
  EXPECT_THROW(read_input(formats_path("real/slab_41.msh"), Format::Fluent), InputError);
}

// ---------------------------------------------------------------------------------------------
// Hand-written files.

// Two unit cubes side by side along x, in VTK's hexahedron order (SU2's, MEDIT's): points
// 0..5 at z = 0 (x = 0, 1, 2 for y = 0, then for y = 1), 6..11 the same at z = 1.
const std::string kSu2Zone =
    "NDIME= 3\n"
    "NELEM= 2\n"
    "12 0 1 4 3 6 7 10 9 0\n"
    "12 1 2 5 4 7 8 11 10   % no index column on this line\n"
    "NPOIN= 12\n"
    "0 0 0 0\n1 0 0 1\n2 0 0 2\n0 1 0 3\n1 1 0 4\n2 1 0 5\n"
    "0 0 1 6\n1 0 1 7\n2 0 1 8\n0 1 1 9\n1 1 1 10\n2 1 1 11\n"
    "NMARK= 1\n"
    "MARKER_TAG= bottom\n"
    "MARKER_ELEMS= 2\n"
    "9 0 3 4 1\n9 1 4 5 2\n";

TEST(CfdFormatsSu2, TwoHexahedraWithIndexColumnsCommentsAndAMarker) {
  const MeshInput in = read_su2("% written by hand\n" + kSu2Zone, "two.su2");
  ASSERT_EQ(in.cells.rows(), 2u);
  const MeshInput soup = with_face_soup(in);
  EXPECT_DOUBLE_EQ(signed_volume(soup, 0), 1.0);
  EXPECT_DOUBLE_EQ(signed_volume(soup, 1), 1.0);
  // The element on line 5 of the file (a comment line first).
  EXPECT_EQ(in.cell_loc[1], 5);
  const Mesh m = build_mesh(in);
  EXPECT_EQ(m.num_hex_cells(), 2u);
  EXPECT_EQ(m.num_faces(), 11u);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("2 surface element(s)"), std::string::npos) << m.warnings[0];
}

TEST(CfdFormatsSu2, ZonesAreJoinedApart) {
  // Two zones of the same two cubes: 24 points, 4 cells, 22 faces (no shared face between zones:
  // their points are distinct), the second zone's ids offset by the first zone's 12 points.
  const MeshInput in = read_su2("NZONE= 2\nIZONE= 1\n" + kSu2Zone + "IZONE= 2\n" + kSu2Zone, "zones.su2");
  ASSERT_EQ(in.cells.rows(), 4u);
  EXPECT_EQ(in.points.size(), 3u * 24);
  EXPECT_EQ(in.cells[2][0], 12);
  const Mesh m = build_mesh(in);
  EXPECT_EQ(m.num_faces(), 22u);
}

TEST(CfdFormatsSkipInvalid, ThreeCopiesOfAHexahedronLoseTheDuplicates) {
  // The unit cube three times: each face in three cells, which build_mesh refuses; --skip-invalid
  // drops one duplicate (the second copy: SU2 line 4, UGRID line 11), and the two cells left
  // share all their faces, which a face in two cells allows.
  const std::string hex = "0 1 2 3 4 5 6 7";
  const std::string pts = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
  const std::string su2 = "NDIME= 3\nNELEM= 3\n12 " + hex + "\n12 " + hex + "\n12 " + hex + "\nNPOIN= 8\n" + pts;
  const std::string ugrid = "8 0 0 0 0 0 3\n" + pts + "1 2 3 4 5 6 7 8\n1 2 3 4 5 6 7 8\n1 2 3 4 5 6 7 8\n";
  const MeshInput inputs[2] = {read_su2(su2, "three.su2"), read_ugrid(ugrid, "three.ugrid", UgridEncoding::Ascii)};
  const int64_t first_dropped_line[2] = {4, 11};
  for (int i = 0; i < 2; ++i) {
    EXPECT_THROW(build_mesh(inputs[i]), InputError);
    std::vector<DroppedCell> dropped;
    const Mesh m = build_mesh_skipping_invalid(inputs[i], dropped);
    EXPECT_EQ(m.num_cells(), 2u);
    ASSERT_EQ(dropped.size(), 1u);
    EXPECT_EQ(dropped[0].reason, Defect::DuplicateCells);
    EXPECT_EQ(dropped[0].loc.line, first_dropped_line[i]);
  }
}

TEST(CfdFormatsUgrid, APyramidInAflr3sOrder) {
  // The pyramid over the unit square with its apex at (0.5, 0.5, 1): volume 1/3. UGRID lists the
  // base as 1-2-5-4 around the apex 3 (meshio's permutation [1, 0, 3, 4, 2] to VTK's order): here
  // node 1 (1,0,0), 2 (0,0,0), 3 the apex, 4 (1,1,0), 5 (0,1,0), so MEDIT's base 0-1-2-3 is
  // (0,0,0) (1,0,0) (1,1,0) (0,1,0), counter-clockwise seen from the apex.
  const std::string text = "5 0 0 0 1 0 0\n1 0 0\n0 0 0\n0.5 0.5 1\n1 1 0\n0 1 0\n1 2 3 4 5\n";
  const MeshInput in = read_ugrid(text, "pyramid.ugrid", UgridEncoding::Ascii);
  EXPECT_DOUBLE_EQ(signed_volume(with_face_soup(in), 0), 1.0 / 3);
  EXPECT_EQ(build_mesh(in).cell_type[0], CellType::Pyramid);
  // The same big-endian and as little-endian Fortran records: the same cell.
  for (const UgridEncoding enc : {UgridEncoding::BigEndian, UgridEncoding::FortranLittleEndian}) {
    const bool fortran = enc == UgridEncoding::FortranLittleEndian;
    test::Bytes b{"", enc == UgridEncoding::BigEndian ? kLittle : !kLittle};
    if (fortran) b.put<int32_t>(28);
    for (int32_t v : {5, 0, 0, 0, 1, 0, 0}) b.put<int32_t>(v);
    if (fortran) b.put<int32_t>(28).put<int32_t>(5 * 24 + 5 * 4);
    for (double x : {1., 0., 0., 0., 0., 0., 0.5, 0.5, 1., 1., 1., 0., 0., 1., 0.}) b.put<double>(x);
    for (int32_t v : {1, 2, 3, 4, 5}) b.put<int32_t>(v);
    if (fortran) b.put<int32_t>(5 * 24 + 5 * 4);
    test::expect_same_cells(read_ugrid(b.s, "pyramid.b8.ugrid", enc), in);
  }
}

// The two cubes of kSu2Zone as Fluent writes them (1-based hexadecimal node ids: node k + 1 is
// SU2's point k). Face loops turn so that their right-hand normal points into c0 and out of c1,
// as foamMeshToFluent writes OpenFOAM's faces (neighbour as c0, owner as c1); a boundary face's c0
// is its cell, c1 0, its loop facing into the cell. The interior face x = 1 is 2 5 b 8 (normal +x,
// into cell 2); cell 1's face x = 0 is 1 4 a 7 (normal +x, into cell 1).
const char* const kFluentFaces[11] = {"2 5 b 8 2 1",  // interior
                                      "1 4 a 7 1 0", "1 7 8 2 1 0", "4 5 b a 1 0", "1 2 5 4 1 0", "7 a b 8 1 0",
                                      "3 9 c 6 2 0", "2 8 9 3 2 0", "5 6 c b 2 0", "2 3 6 5 2 0", "8 b c 9 2 0"};

std::string fluent_ascii() {
  std::string s = "(0 \"two cubes\")\n(2 3)\n(10 (0 1 c 0 3))\n(12 (0 1 2 0 0))\n(13 (0 1 b 0 0))\n(10 (1 1 c 1 3)(\n";
  for (const char* p : {"0 0 0", "1 0 0", "2 0 0", "0 1 0", "1 1 0", "2 1 0", "0 0 1", "1 0 1", "2 0 1", "0 1 1", "1 1 1", "2 1 1"})
    s += std::string(p) + "\n";
  s += "))\n(12 (2 1 2 1 4))\n(13 (3 1 1 2 0)(\n4 " + std::string(kFluentFaces[0]) + "\n))\n(13 (4 2 b 3 4)(\n";
  for (int f = 1; f < 11; ++f) s += std::string(kFluentFaces[f]) + "\n";
  return s + "))\n(45 (2 fluid fluid)())\n(39 (3 interior int)())\n";
}

TEST(CfdFormatsFluent, TwoCubesFromTheirFacesFaceOut) {
  const MeshInput in = read_fluent(fluent_ascii(), "two.msh");
  ASSERT_EQ(in.cells.rows(), 2u);
  EXPECT_DOUBLE_EQ(signed_volume(in, 0), 1.0);
  EXPECT_DOUBLE_EQ(signed_volume(in, 1), 1.0);
  EXPECT_EQ(in.face_loc[0], 22);  // the interior face's line
  const Mesh m = build_mesh(in);
  EXPECT_EQ(m.num_hex_cells(), 2u);
  EXPECT_EQ(m.num_faces(), 11u);
  EXPECT_EQ(m.num_edges(), 20u);
}

TEST(CfdFormatsFluent, BinarySectionsReadAsTheAsciiFile) {
  // 3010 nodes (doubles), 2012 a mixed cell zone's types, 2013 faces (4-byte integers).
  test::Bytes b{"", !kLittle};
  b.text("(2 3)\n(3010 (1 1 c 1 3)(");
  for (double x : {0., 0., 0., 1., 0., 0., 2., 0., 0., 0., 1., 0., 1., 1., 0., 2., 1., 0.,
                   0., 0., 1., 1., 0., 1., 2., 0., 1., 0., 1., 1., 1., 1., 1., 2., 1., 1.})
    b.put<double>(x);
  b.text(")End of Binary Section 3010)\n(2012 (2 1 2 1 0)(").put<int32_t>(4).put<int32_t>(4);
  b.text(")End of Binary Section 2012)\n(2013 (3 1 b 2 0)(");
  for (const char* f : kFluentFaces) {
    b.put<int32_t>(4);
    for (size_t i = 0; i < std::strlen(f); i += 2) b.put<int32_t>(static_cast<int32_t>(std::stoi(std::string(1, f[i]), nullptr, 16)));
  }
  b.text(")End of Binary Section 2013)\n");
  const MeshInput bin = read_fluent(b.s, "two_bin.msh");
  const MeshInput ascii = read_fluent(fluent_ascii(), "two.msh");
  EXPECT_TRUE(bin.binary);
  EXPECT_EQ(bin.points, ascii.points);
  EXPECT_EQ(bin.faces.items, ascii.faces.items);
  EXPECT_EQ(bin.cells.items, ascii.cells.items);
  EXPECT_EQ(bin.face_loc[0], static_cast<int64_t>(b.s.find("(2013") + 18));  // just after "(2013 (3 1 b 2 0)("
}

}  // namespace
}  // namespace hbc
