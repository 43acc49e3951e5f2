// The Exodus II and CGNS readers on files written here by the formats' own libraries (libexodus,
// the CGNS library), cell by cell against the MEDIT reader on the same mesh; the real-tool twins
// of tests/data/formats/real (meshio's Exodus writer, CGNS's aflr3_to_cgns and adf2hdf) against
// their MEDIT original; malformed and truncated files. Builds without a library check the refusal.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <vector>

#include "hbc/analysis.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

#if HBC_TEST_EXODUS
#include <exodusII.h>
#endif
#if HBC_TEST_CGNS
#include <cgnslib.h>
#endif

namespace hbc {
namespace {

namespace fs = std::filesystem;

// A hexahedron (0-7, the unit cube), a prism on its face x = 1 (triangles 1 8 5 at y = 0 and
// 2 9 6 at y = 1), a pyramid on its top (apex 10 above the top's centre) and a tetrahedron on the
// pyramid's face 5 6 10 (apex 11): 12 vertices, one cell of each type, faces shared pairwise.
constexpr double kPoints[12][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1},     {1, 0, 1},
                                   {1, 1, 1}, {0, 1, 1}, {2, 0, 0}, {2, 1, 0}, {.5, .5, 1.5}, {1.5, .5, 1.5}};
// 1-based, in MEDIT's corner orders (Exodus's and CGNS's are the same).
const std::vector<int> kHex{1, 2, 3, 4, 5, 6, 7, 8}, kPrism{2, 9, 6, 3, 10, 7}, kPyramid{5, 6, 7, 8, 11}, kTet{6, 7, 11, 12};

std::string medit_mixed4() {
  std::string s = "MeshVersionFormatted 2\nDimension 3\nVertices\n12\n";
  for (const auto& p : kPoints) s += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + " 0\n";
  auto section = [&](const char* name, const std::vector<int>& v) {
    s += std::string(name) + "\n1\n";
    for (int id : v) s += std::to_string(id) + " ";
    s += "0\n";
  };
  section("Hexahedra", kHex);
  section("Prisms", kPrism);
  section("Pyramids", kPyramid);
  section("Tetrahedra", kTet);
  return s + "End\n";
}

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() / ("hbc_exo_cgns_" + std::to_string(::getpid()) + "_" + name);
}

using test::read_error;
using test::write_bytes;
using test::expect_refused_without_library;

#if HBC_TEST_EXODUS
struct ExoBlock {
  const char* type;
  int per;                // nodes per element
  std::vector<int> conn;  // 1-based
};

// `blocks` written by libexodus (netCDF-4/HDF5 when `hdf5`, else 64-bit offset netCDF).
void write_exodus(const fs::path& path, const std::vector<ExoBlock>& blocks, bool hdf5, int npoints = 12) {
  int cpu = 8, io = 8;
  const int exo = ex_create(path.c_str(), EX_CLOBBER | (hdf5 ? EX_NETCDF4 : EX_LARGE_MODEL), &cpu, &io);
  ASSERT_GE(exo, 0);
  int nel = 0;
  for (const ExoBlock& b : blocks) nel += static_cast<int>(b.conn.size()) / b.per;
  ASSERT_EQ(ex_put_init(exo, "hbc test", 3, npoints, nel, static_cast<int>(blocks.size()), 0, 0), 0);
  std::vector<double> x, y, z;
  for (int v = 0; v < npoints; ++v) {
    x.push_back(kPoints[v % 12][0] + v / 12);
    y.push_back(kPoints[v % 12][1]);
    z.push_back(kPoints[v % 12][2]);
  }
  ASSERT_EQ(ex_put_coord(exo, x.data(), y.data(), z.data()), 0);
  int id = 10;
  for (const ExoBlock& b : blocks) {
    ASSERT_EQ(ex_put_elem_block(exo, id, b.type, static_cast<int>(b.conn.size()) / b.per, b.per, 0), 0);
    ASSERT_EQ(ex_put_elem_conn(exo, id, b.conn.data()), 0);
    id += 10;
  }
  ASSERT_EQ(ex_close(exo), 0);
}

TEST(Exodus, EveryVolumeBlockAsMeditReadsTheSameMeshAndShellsAreCounted) {
  // Lower-case and long type names as Cubit and SEACAS spell them; a 2-element shell block between.
  const std::vector<ExoBlock> blocks{{"HEX8", 8, kHex},
                                     {"SHELL4", 4, {1, 2, 3, 4, 5, 6, 7, 8}},
                                     {"wedge6", 6, kPrism},
                                     {"PYRAMID", 5, kPyramid},
                                     {"TETRA4", 4, kTet}};
  const MeshInput ref = read_medit(medit_mixed4(), "mixed4.mesh");
  for (bool hdf5 : {false, true}) {
    SCOPED_TRACE(hdf5 ? "netCDF-4/HDF5" : "64-bit offset");
    const fs::path p = temp_file(hdf5 ? "mixed4_h5.exo" : "mixed4.exo");
    write_exodus(p, blocks, hdf5);
    const MeshInput in = read_input(p.string());
    test::expect_same_cells(in, ref);
    ASSERT_EQ(in.warnings.size(), 1u);
    EXPECT_EQ(in.warnings[0], "read past 0 point, 0 line and 2 surface element(s); only volume elements are cells");
    const Mesh m = build_mesh(in);
    EXPECT_EQ(m.num_cells(), 4u);
    fs::remove(p);
  }
}

TEST(Exodus, SecondOrderAndDegenerateHexahedraReadByTheirCorners) {
  // HEX20 over the unit cube and 12 edge nodes (vertices 12-23 of the written file): the nodes past
  // the eighth are dropped, leaving the cube. A HEX8 with corners 1 2 3 3 5 6 7 7 (a prism written
  // as a hexahedron) gives what MEDIT's reader makes of the same hexahedron.
  std::vector<int> hex20{1, 2, 3, 4, 5, 6, 7, 8};
  for (int k = 13; k <= 24; ++k) hex20.push_back(k);
  const fs::path p = temp_file("hex20.e");
  write_exodus(p, {{"HEX20", 20, hex20}}, false, 24);
  const MeshInput in = read_input(p.string());
  ASSERT_EQ(in.cells.rows(), 1u);
  // 24 nodes written, the 12 edge nodes dropped; nodes 9-12 belong to no element and stay.
  EXPECT_EQ(in.points.size(), 3u * 12);
  EXPECT_EQ(in.shape(0), CellShape::Hex);

  write_exodus(p, {{"HEX", 8, {1, 2, 3, 3, 5, 6, 7, 7}}}, false);
  const std::string medit = "MeshVersionFormatted 2\nDimension 3\nVertices\n12\n" + [] {
    std::string s;
    for (const auto& q : kPoints) s += std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " 0\n";
    return s;
  }() + "Hexahedra\n1\n1 2 3 3 5 6 7 7 0\nEnd\n";
  test::expect_same_cells(read_input(p.string()), read_medit(medit, "degenerate.mesh"));
  fs::remove(p);
}

TEST(Exodus, NfacedPolyhedraTakeTheirFacesFromTheFaceBlock) {
  // The unit cube as one NFACED element over an NSIDED face block of its six quadrangles, written
  // with libexodus's polyhedra calls: one Faces cell over 8 vertices and 6 faces.
  const fs::path p = temp_file("nfaced.exo");
  int cpu = 8, io = 8;
  const int exo = ex_create(p.c_str(), EX_CLOBBER, &cpu, &io);
  ASSERT_GE(exo, 0);
  ex_init_params par{};
  std::snprintf(par.title, sizeof par.title, "cube");
  par.num_dim = 3;
  par.num_nodes = 8;
  par.num_elem = 1;
  par.num_elem_blk = 1;
  par.num_face = 6;
  par.num_face_blk = 1;
  ASSERT_EQ(ex_put_init_ext(exo, &par), 0);
  std::vector<double> x, y, z;
  for (int v = 0; v < 8; ++v) {
    x.push_back(kPoints[v][0]);
    y.push_back(kPoints[v][1]);
    z.push_back(kPoints[v][2]);
  }
  ASSERT_EQ(ex_put_coord(exo, x.data(), y.data(), z.data()), 0);
  const std::vector<int> nodes{1, 4, 3, 2, 5, 6, 7, 8, 1, 2, 6, 5, 2, 3, 7, 6, 3, 4, 8, 7, 4, 1, 5, 8}, per_face(6, 4);
  ASSERT_EQ(ex_put_block(exo, EX_FACE_BLOCK, 1, "nsided", 6, 24, 0, 0, 0), 0);
  ASSERT_EQ(ex_put_entity_count_per_polyhedra(exo, EX_FACE_BLOCK, 1, per_face.data()), 0);
  ASSERT_EQ(ex_put_conn(exo, EX_FACE_BLOCK, 1, nodes.data(), nullptr, nullptr), 0);
  const std::vector<int> faces{1, 2, 3, 4, 5, 6}, per_elem{6};
  ASSERT_EQ(ex_put_block(exo, EX_ELEM_BLOCK, 1, "NFACED", 1, 0, 0, 6, 0), 0);
  ASSERT_EQ(ex_put_entity_count_per_polyhedra(exo, EX_ELEM_BLOCK, 1, per_elem.data()), 0);
  ASSERT_EQ(ex_put_conn(exo, EX_ELEM_BLOCK, 1, nullptr, nullptr, faces.data()), 0);
  ASSERT_EQ(ex_close(exo), 0);
  const Mesh m = build_mesh(read_input(p.string()));
  EXPECT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.num_vertices(), 8u);
  EXPECT_EQ(m.num_faces(), 6u);
  EXPECT_EQ(m.num_edges(), 12u);
  fs::remove(p);
}

TEST(Exodus, MalformedFilesNameTheFileAndWhatWasWrong) {
  const fs::path p = temp_file("bad.exo");
  write_exodus(p, {{"HEX8", 8, {1, 2, 3, 4, 5, 6, 7, 99}}}, false);  // node 99 of 12
  EXPECT_NE(read_error(p).find("node ids in [1, 12] in connect1 (element block 1), found 99"), std::string::npos) << read_error(p);
  write_exodus(p, {{"FOO8", 8, kHex}}, false);
  EXPECT_NE(read_error(p).find("an Exodus element type (HEX8, WEDGE6, PYRAMID5, TETRA4, NFACED, SHELL4, ...) for element block 1, found 'FOO8'"),
            std::string::npos) << read_error(p);
  write_exodus(p, {{"SHELL4", 4, {1, 2, 3, 4}}}, false);
  EXPECT_NE(read_error(p).find("at least one volume element block"), std::string::npos) << read_error(p);
  // Every truncation of a classic file and of an HDF5 one, and text: InputError, never a crash.
  for (bool hdf5 : {false, true}) {
    write_exodus(p, {{"HEX8", 8, kHex}, {"TETRA4", 4, kTet}}, hdf5);
    const std::string bytes = test::slurp(p);
    for (size_t cut = 0; cut < bytes.size(); cut += 1 + bytes.size() / 97) {
      write_bytes(p, std::string_view(bytes).substr(0, cut));
      EXPECT_NE(read_error(p), "") << "cut at " << cut;
    }
  }
  write_bytes(p, "MeshVersionFormatted 2\n");
  EXPECT_NE(read_error(p).find("expected an Exodus II file (netCDF classic, 64-bit offset or netCDF-4/HDF5; netCDF: "), std::string::npos);
  fs::remove(p);
}
#else
TEST(Exodus, ABuildWithoutNetcdfListsTheFormatAndRefusesItsFiles) {
  expect_refused_without_library(temp_file("any.exo"), "CDF\x01", "Exodus II", "netCDF-C");
  EXPECT_EQ(format_from_name("exo"), Format::Exodus);
}
#endif

#if HBC_TEST_CGNS
// A CGNS file of one base, written by the CGNS library: zones made by `zones` (file, base) -> ().
template <class Zones>
void write_cgns(const fs::path& path, Zones zones) {
  int fn = 0, base = 0;
  ASSERT_EQ(cg_open(path.c_str(), CG_MODE_WRITE, &fn), CG_OK) << cg_get_error();
  ASSERT_EQ(cg_base_write(fn, "Base", 3, 3, &base), CG_OK);
  zones(fn, base);
  ASSERT_EQ(cg_close(fn), CG_OK);
}

// An unstructured zone over the 12 points of kPoints.
int mixed4_zone(int fn, int base, int ncells) {
  cgsize_t size[3] = {12, ncells, 0};
  int zone = 0, c = 0;
  EXPECT_EQ(cg_zone_write(fn, base, "Zone", size, CGNS_ENUMV(Unstructured), &zone), CG_OK);
  std::array<std::vector<double>, 3> xyz;
  for (const auto& p : kPoints)
    for (int k = 0; k < 3; ++k) xyz[static_cast<size_t>(k)].push_back(p[k]);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(cg_coord_write(fn, base, zone, CGNS_ENUMV(RealDouble), (std::string("Coordinate") + "XYZ"[k]).c_str(), xyz[static_cast<size_t>(k)].data(), &c), CG_OK);
  return zone;
}

void section(int fn, int base, int zone, const char* name, CGNS_ENUMT(ElementType_t) type, cgsize_t first, const std::vector<int>& v, int n = 1) {
  int s = 0;
  const std::vector<cgsize_t> conn(v.begin(), v.end());
  EXPECT_EQ(cg_section_write(fn, base, zone, name, type, first, first + n - 1, 0, conn.data(), &s), CG_OK) << cg_get_error();
}

TEST(Cgns, SectionsOfEveryTypeAndMixedReadAsMeditReadsTheSameMesh) {
  const MeshInput ref = read_medit(medit_mixed4(), "mixed4.mesh");
  const fs::path p = temp_file("mixed4.cgns");
  write_cgns(p, [](int fn, int base) {
    const int z = mixed4_zone(fn, base, 4);
    section(fn, base, z, "Hex", CGNS_ENUMV(HEXA_8), 1, kHex);
    section(fn, base, z, "Prism", CGNS_ENUMV(PENTA_6), 2, kPrism);
    section(fn, base, z, "Pyramid", CGNS_ENUMV(PYRA_5), 3, kPyramid);
    section(fn, base, z, "Tet", CGNS_ENUMV(TETRA_4), 4, kTet);
    section(fn, base, z, "Wall", CGNS_ENUMV(QUAD_4), 5, {1, 4, 3, 2, 1, 2, 6, 5}, 2);  // boundary faces
  });
  MeshInput in = read_input(p.string());
  test::expect_same_cells(in, ref);
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_EQ(in.warnings[0], "read past 0 point, 0 line and 2 surface element(s); only volume elements are cells");

  // The same cells in one MIXED section (each element's type before its nodes), written through
  // the library's offsets form.
  write_cgns(p, [](int fn, int base) {
    const int z = mixed4_zone(fn, base, 4);
    std::vector<cgsize_t> conn, offsets{0};
    auto add = [&](CGNS_ENUMT(ElementType_t) t, const std::vector<int>& v) {
      conn.push_back(t);
      conn.insert(conn.end(), v.begin(), v.end());
      offsets.push_back(static_cast<cgsize_t>(conn.size()));
    };
    add(CGNS_ENUMV(HEXA_8), kHex);
    add(CGNS_ENUMV(PENTA_6), kPrism);
    add(CGNS_ENUMV(PYRA_5), kPyramid);
    add(CGNS_ENUMV(TETRA_4), kTet);
    int s = 0;
    EXPECT_EQ(cg_poly_section_write(fn, base, z, "Mixed", CGNS_ENUMV(MIXED), 1, 4, 0, conn.data(), offsets.data(), &s), CG_OK) << cg_get_error();
  });
  test::expect_same_cells(read_input(p.string()), ref);
  fs::remove(p);
}

TEST(Cgns, NfacePolyhedraOverNgonFacesAndStructuredZonesAsHexahedra) {
  // The unit cube as one NFACE_n cell over six NGON_n quadrangles (elements 1-6; the cell is 7),
  // face 2 referred to reversed (-2): one cell, 8 vertices, 6 faces, 12 edges.
  const fs::path p = temp_file("poly.cgns");
  write_cgns(p, [](int fn, int base) {
    cgsize_t size[3] = {8, 1, 0};
    int z = 0, c = 0, s = 0;
    ASSERT_EQ(cg_zone_write(fn, base, "Cube", size, CGNS_ENUMV(Unstructured), &z), CG_OK);
    for (int k = 0; k < 3; ++k) {
      std::vector<double> x;
      for (int v = 0; v < 8; ++v) x.push_back(kPoints[v][k]);
      ASSERT_EQ(cg_coord_write(fn, base, z, CGNS_ENUMV(RealDouble), (std::string("Coordinate") + "XYZ"[k]).c_str(), x.data(), &c), CG_OK);
    }
    std::vector<cgsize_t> faces{1, 4, 3, 2, 8, 7, 6, 5, 1, 2, 6, 5, 2, 3, 7, 6, 3, 4, 8, 7, 4, 1, 5, 8}, fo{0, 4, 8, 12, 16, 20, 24};
    ASSERT_EQ(cg_poly_section_write(fn, base, z, "Faces", CGNS_ENUMV(NGON_n), 1, 6, 0, faces.data(), fo.data(), &s), CG_OK) << cg_get_error();
    std::vector<cgsize_t> cell{1, -2, 3, 4, 5, 6}, co{0, 6};
    ASSERT_EQ(cg_poly_section_write(fn, base, z, "Cells", CGNS_ENUMV(NFACE_n), 7, 7, 0, cell.data(), co.data(), &s), CG_OK) << cg_get_error();
  });
  const Mesh m = build_mesh(read_input(p.string()));
  EXPECT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.num_vertices(), 8u);
  EXPECT_EQ(m.num_faces(), 6u);
  EXPECT_EQ(m.num_edges(), 12u);

  // A structured zone of 3 x 2 x 2 vertices: two hexahedra side by side along i, sharing one face
  // (12 vertices, 11 faces, 20 edges); a second zone, the same shifted by 5 along x, is joined
  // without merging: 4 cells, 24 vertices and a warning.
  write_cgns(p, [](int fn, int base) {
    for (int zi = 0; zi < 2; ++zi) {
      cgsize_t size[9] = {3, 2, 2, 2, 1, 1, 0, 0, 0};
      int z = 0, c = 0;
      ASSERT_EQ(cg_zone_write(fn, base, zi ? "B" : "A", size, CGNS_ENUMV(Structured), &z), CG_OK);
      std::array<std::vector<double>, 3> xyz;
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 3; ++i) {
            xyz[0].push_back(i + 5.0 * zi);
            xyz[1].push_back(j);
            xyz[2].push_back(k);
          }
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(cg_coord_write(fn, base, z, CGNS_ENUMV(RealDouble), (std::string("Coordinate") + "XYZ"[k]).c_str(), xyz[static_cast<size_t>(k)].data(), &c), CG_OK);
    }
  });
  const MeshInput in = read_input(p.string());
  EXPECT_EQ(in.cells.rows(), 4u);
  EXPECT_EQ(in.points.size(), 3u * 24);
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_EQ(in.warnings[0], "joined 2 zones without merging the vertices they share: zone interfaces are boundary");
  const Mesh two = build_mesh(in);
  EXPECT_EQ(two.num_faces(), 22u);
  EXPECT_EQ(two.num_edges(), 40u);
  EXPECT_EQ(two.num_hex_cells(), 4u);
  fs::remove(p);
}

TEST(Cgns, MalformedFilesNameTheFileAndWhatWasWrong) {
  const fs::path p = temp_file("bad.cgns");
  write_cgns(p, [](int fn, int base) {
    const int z = mixed4_zone(fn, base, 1);
    section(fn, base, z, "Hex", CGNS_ENUMV(HEXA_8), 1, {1, 2, 3, 4, 5, 6, 7, 13});  // vertex 13 of 12
  });
  EXPECT_NE(read_error(p).find("vertex ids in [1, 12] in zone 1 section 1 (Hex), found 13"), std::string::npos) << read_error(p);
  write_cgns(p, [](int fn, int base) {
    const int z = mixed4_zone(fn, base, 1);
    section(fn, base, z, "Wall", CGNS_ENUMV(QUAD_4), 1, {1, 2, 3, 4});
  });
  EXPECT_NE(read_error(p).find("at least one volume element"), std::string::npos) << read_error(p);
  write_cgns(p, [](int fn, int base) {
    const int z = mixed4_zone(fn, base, 2);
    section(fn, base, z, "Hex", CGNS_ENUMV(HEXA_8), 1, kHex);
    section(fn, base, z, "Tet", CGNS_ENUMV(TETRA_4), 2, kTet);
  });
  const std::string bytes = test::slurp(p);
  for (size_t cut = 0; cut < bytes.size(); cut += 1 + bytes.size() / 97) {
    write_bytes(p, std::string_view(bytes).substr(0, cut));
    EXPECT_NE(read_error(p), "") << "cut at " << cut;
  }
  write_bytes(p, "MeshVersionFormatted 2\n");
  EXPECT_NE(read_error(p).find("expected a CGNS file (ADF or HDF5; CGNS: "), std::string::npos) << read_error(p);
  fs::remove(p);
}
#else
TEST(Cgns, ABuildWithoutTheLibraryListsTheFormatAndRefusesItsFiles) {
  expect_refused_without_library(temp_file("any.cgns"), "\x89HDF", "CGNS", "the CGNS library");
  EXPECT_EQ(format_from_name("cgns"), Format::Cgns);
}
#endif

#if HBC_TEST_EXODUS || HBC_TEST_CGNS
// The twins that meshio's Exodus writer, netCDF's nccopy and CGNS's aflr3_to_cgns and hdf2adf made
// of real/slab.mesh (gmsh's slab: 82 hexahedra, 28 prisms) and of mixed4.mesh
// (tests/data/formats/make_exodus_cgns_files.py): the same mesh, so the same analysis.
TEST(ExodusCgnsRealTools, EveryTwinGivesTheSameAnalysisAsItsMedit) {
  const std::string dir = HBC_FORMATS_DIR;
  std::vector<std::pair<std::string, std::string>> twins;
#if HBC_TEST_EXODUS
  twins.insert(twins.end(), {{"real/slab_hdf5.exo", "real/slab.mesh"}, {"real/slab_cdf5.e", "real/slab.mesh"}, {"real/mixed4.exo", "mixed4.mesh"}});
#endif
#if HBC_TEST_CGNS
  twins.insert(twins.end(), {{"real/slab.cgns", "real/slab.mesh"}, {"real/slab_adf.cgns", "real/slab.mesh"}, {"real/mixed4.cgns", "mixed4.mesh"}});
#endif
  for (const auto& [twin, original] : twins) {
    SCOPED_TRACE(twin);
    const Mesh ref = load_mesh(dir + "/" + original), m = load_mesh(dir + "/" + twin);
    EXPECT_EQ(m.num_vertices(), ref.num_vertices());
    EXPECT_EQ(m.num_edges(), ref.num_edges());
    EXPECT_EQ(m.num_faces(), ref.num_faces());
    // Cell for cell by type (aflr3_to_cgns writes tetrahedra first, MEDIT hexahedra first).
    auto types = [](const Mesh& x) {
      auto t = x.cell_type;
      std::sort(t.begin(), t.end());
      return t;
    };
    EXPECT_EQ(types(m), types(ref));
    test::expect_same_counts(compute_stats(m, analyze(m)), compute_stats(ref, analyze(ref)));
  }
}
#endif

}  // namespace
}  // namespace hbc
