// Readers and writers on the real meshes of ../shared/data (counts from its SOURCES.md), the
// OVM/OVMB pairs, round trips through the writers, format detection and the CLI's --format.
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <unistd.h>

#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

using test::data_path;

struct RealFile {
  const char* path;
  size_t vertices, cells;
  std::array<size_t, 5> types;  // hex, tet, prism, pyramid, polyhedron
};

// SOURCES.md: #V, #cells and the cell-type breakdown of every file.
const RealFile kRealFiles[] = {
    {"hybrid-base-complex/test_2.HYBRID", 64, 24, {21, 0, 3, 0, 0}},
    {"hybrid-base-complex/cube_twist-comp.obj.HYBRID", 705, 493, {475, 0, 1, 0, 17}},
    {"hybrid-base-complex/teapot.hedra", 2976, 2404, {2380, 0, 0, 0, 24}},
    // 66 prisms, 2 tets, 1 pyramid, 44 + 31 other closed polyhedra.
    {"hybrid-base-complex/twistcube_s.mesh", 1603, 1301, {1157, 2, 66, 1, 75}},
    {"openvolumemesh/Cube_with_props.ovm", 8, 1, {1, 0, 0, 0, 0}},
    {"openvolumemesh/Cube_with_props.ovmb", 8, 1, {1, 0, 0, 0, 0}},
    {"openvolumemesh/Cylinder.ovm", 399, 288, {288, 0, 0, 0, 0}},
    {"openvolumemesh/Cylinder.ovmb", 399, 288, {288, 0, 0, 0, 0}},
    {"openvolumemesh/NonManifold.ovm", 12, 2, {1, 0, 0, 1, 0}},
    {"openvolumemesh/NonManifold.ovmb", 12, 2, {1, 0, 0, 1, 0}},
    {"cinolib/eight_voronoi.hedra", 18341, 2162, {1, 0, 0, 0, 2161}},
    {"cinolib/ellipsoid.mesh", 7293, 6816, {6816, 0, 0, 0, 0}},
    {"cinolib/rockerarm.mesh", 12751, 10600, {10600, 0, 0, 0, 0}},
    {"hexalab-edge-cone-rectification/block_out.mesh", 3180, 2520, {2520, 0, 0, 0, 0}},
    {"hexalab-edge-cone-rectification/cap_out.mesh", 5449, 4420, {4420, 0, 0, 0, 0}},
    {"hexalab-edge-cone-rectification/bust_out.mesh", 6314, 5258, {5258, 0, 0, 0, 0}},
    {"hexalab-edge-cone-rectification/hanger_stresstest_out.mesh", 6633, 4539, {4539, 0, 0, 0, 0}},
    {"hexalab-edge-cone-rectification/dragon_out.mesh", 18147, 14009, {14009, 0, 0, 0, 0}},
    {"hexalab-edge-cone-rectification/armadillo_out.mesh", 34726, 29935, {29935, 0, 0, 0, 0}},
};

std::array<size_t, 5> type_counts(const Mesh& m) {
  std::array<size_t, 5> t{};
  for (CellType c : m.cell_type) ++t[static_cast<size_t>(c)];
  return t;
}

bool has_polyhedra(const Mesh& m) {
  return std::count(m.cell_type.begin(), m.cell_type.end(), CellType::Polyhedron) > 0;
}

template <class T>
void expect_same_csr(const Csr<T>& a, const Csr<T>& b, const char* what) {
  EXPECT_EQ(a.offsets, b.offsets) << what;
  EXPECT_EQ(a.items, b.items) << what;
}

// Files written and read back hold what was kept, not what was dropped.
void expect_same_mesh(const Mesh& a, const Mesh& b) { test::expect_same_mesh(a, b, false); }

// A cell as the sorted list of its faces, each a sorted vertex set.
std::vector<std::vector<int32_t>> cell_face_sets(const Mesh& m, size_t c) {
  std::vector<std::vector<int32_t>> sig;
  for (int32_t f : m.cell_faces[c]) {
    std::vector<int32_t> s(m.face_verts[f].begin(), m.face_verts[f].end());
    std::sort(s.begin(), s.end());
    sig.push_back(std::move(s));
  }
  std::sort(sig.begin(), sig.end());
  return sig;
}

// The loops the cell sees, each rotated to start at its smallest vertex, sorted: equal for two
// cells with the same faces seen the same way round.
std::vector<std::vector<int32_t>> cell_seen_loops(const Mesh& m, size_t c) {
  std::vector<std::vector<int32_t>> sig;
  for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) {
    auto loop = m.face_verts[m.cell_faces.items[i]];
    std::vector<int32_t> seen(loop.begin(), loop.end());
    if (m.cell_face_flip[i]) std::reverse(seen.begin(), seen.end());
    std::rotate(seen.begin(), std::min_element(seen.begin(), seen.end()), seen.end());
    sig.push_back(std::move(seen));
  }
  std::sort(sig.begin(), sig.end());
  return sig;
}

// Whether the cell's seen loops run through each of its edges once in each direction. Some
// files carry no orientation (test_2.HYBRID has all flags 0, teapot.hedra all face ids
// positive), so their cells are not.
bool consistently_oriented(const Mesh& m, size_t c) {
  std::vector<std::pair<int32_t, int32_t>> dirs;
  for (const auto& loop : cell_seen_loops(m, c))
    for (size_t k = 0; k < loop.size(); ++k) dirs.push_back({loop[k], loop[(k + 1) % loop.size()]});
  std::sort(dirs.begin(), dirs.end());
  if (std::adjacent_find(dirs.begin(), dirs.end()) != dirs.end()) return false;
  for (auto [a, b] : dirs)
    if (!std::binary_search(dirs.begin(), dirs.end(), std::pair{b, a})) return false;
  return true;
}

TEST(IoRealData, EveryFileLoadsWithTheDocumentedCounts) {
  for (const RealFile& f : kRealFiles) {
    SCOPED_TRACE(f.path);
    HBC_REQUIRE_DATA(f.path);
    const Mesh m = test::load_data(f.path);
    EXPECT_EQ(m.num_vertices(), f.vertices);
    EXPECT_EQ(m.num_cells(), f.cells);
    EXPECT_EQ(m.num_hex_cells(), f.types[0]);
    EXPECT_EQ(type_counts(m), f.types);
  }
}

TEST(IoRealData, OvmFilesHaveTheDocumentedEdgesAndFaces) {
  // SOURCES.md: #V/#E/#F/#C = 8/12/6/1 and 399/1070/960/288.
  for (const char* name : {"Cube_with_props", "Cylinder"}) {
    for (const char* ext : {".ovm", ".ovmb"}) {
      const std::string rel = std::string("openvolumemesh/") + name + ext;
      SCOPED_TRACE(rel);
      HBC_REQUIRE_DATA(rel);
      const MeshInput in = read_input(data_path(rel));
      const Mesh m = build_mesh(read_input(data_path(rel)));
      const bool cube = std::string(name) == "Cube_with_props";
      EXPECT_EQ(in.declared_edges.size(), cube ? 12u : 1070u);
      EXPECT_EQ(in.faces.rows(), cube ? 6u : 960u);
      EXPECT_EQ(m.num_edges(), cube ? 12u : 1070u);
      EXPECT_EQ(m.num_faces(), cube ? 6u : 960u);
      EXPECT_EQ(m.dropped_faces, 0);
      EXPECT_EQ(m.dropped_edges, 0);
    }
  }
}

TEST(IoRealData, NonManifoldDropsTheDanglingFaceAndEdges) {
  // The file lists 12/20/11/2. Face 6 (half-edges 24 26 28 21: vertices 2 8 9 6) is in no cell;
  // edges 12 (2 8), 13 (8 9), 14 (9 6) are only in that face and edge 15 (9 10) is in none, so
  // 1 face and 4 edges are dropped, leaving 16 edges and 10 faces. Vertices 8, 9, 10 stay
  // (unused), as the vertex count of SOURCES.md says.
  for (const char* rel : {"openvolumemesh/NonManifold.ovm", "openvolumemesh/NonManifold.ovmb"}) {
    SCOPED_TRACE(rel);
    HBC_REQUIRE_DATA(rel);
    const MeshInput in = read_input(data_path(rel));
    EXPECT_EQ(in.points.size(), 3u * 12);
    EXPECT_EQ(in.declared_edges.size(), 20u);
    EXPECT_EQ(in.faces.rows(), 11u);
    EXPECT_EQ(in.cells.rows(), 2u);
    const Mesh m = build_mesh(in);
    EXPECT_EQ(m.dropped_faces, 1);
    EXPECT_EQ(m.dropped_edges, 4);
    EXPECT_EQ(m.num_edges(), 16u);
    EXPECT_EQ(m.num_faces(), 10u);
    EXPECT_EQ(m.warnings.size(), 2u);
    // The pyramid is glued on the hex's face x = 0 (vertices 0 3 7 4): one interior face.
    EXPECT_EQ(std::count(m.face_boundary.begin(), m.face_boundary.end(), 0), 1);
    EXPECT_EQ(m.cell_type[0], CellType::Hex);
    EXPECT_EQ(m.cell_type[1], CellType::Pyramid);
    EXPECT_EQ(test::cell_verts(m, 1).size(), 5u);
    EXPECT_EQ(test::cell_verts(m, 1).back(), 11);
  }
}

TEST(IoRealData, OvmAndOvmbPairsBuildTheSameMesh) {
  for (const char* name : {"Cube_with_props", "Cylinder", "NonManifold"}) {
    SCOPED_TRACE(name);
    const std::string a = std::string("openvolumemesh/") + name + ".ovm";
    const std::string b = std::string("openvolumemesh/") + name + ".ovmb";
    HBC_REQUIRE_DATA(a);
    HBC_REQUIRE_DATA(b);
    const MeshInput ia = read_input(data_path(a)), ib = read_input(data_path(b));
    EXPECT_EQ(ia.points, ib.points);
    EXPECT_EQ(ia.declared_edges, ib.declared_edges);
    expect_same_csr(ia.faces, ib.faces, "faces");
    expect_same_csr(ia.cells, ib.cells, "cells");
    const Mesh ma = build_mesh(ia), mb = build_mesh(ib);
    expect_same_mesh(ma, mb);
    EXPECT_EQ(ma.dropped_faces, mb.dropped_faces);
    EXPECT_EQ(ma.dropped_edges, mb.dropped_edges);
  }
}

TEST(IoRealData, OvmbRecordsByteOffsets) {
  // Cube_with_props.ovmb: vertex data at 0xe0 (24 bytes each), face handles at 0x208 (4 one-byte
  // half-edges each), the cell's half-faces at 0x248.
  HBC_REQUIRE_DATA("openvolumemesh/Cube_with_props.ovmb");
  const MeshInput in = read_input(data_path("openvolumemesh/Cube_with_props.ovmb"));
  EXPECT_TRUE(in.binary);
  ASSERT_EQ(in.vertex_loc.size(), 8u);
  EXPECT_EQ(in.vertex_loc[0], 0xe0);
  EXPECT_EQ(in.vertex_loc[3], 0xe0 + 3 * 24);
  ASSERT_EQ(in.face_loc.size(), 6u);
  EXPECT_EQ(in.face_loc[0], 0x208);
  EXPECT_EQ(in.face_loc[5], 0x208 + 5 * 4);
  ASSERT_EQ(in.cell_loc.size(), 1u);
  EXPECT_EQ(in.cell_loc[0], 0x248);
  EXPECT_EQ(in.points[0], -1.0);
  EXPECT_EQ(in.points[3 * 6 + 2], 1.0);
}

TEST(IoRealData, OvmCellsSeeTheirFacesOutward) {
  // OVM cells list outward half-faces; the unit cube's bottom face 0 (z = -1, loop 0 1 2 3
  // counter-clockwise seen from above, normal +z) must be seen reversed by the cell.
  HBC_REQUIRE_DATA("openvolumemesh/Cube_with_props.ovm");
  const Mesh m = test::load_data("openvolumemesh/Cube_with_props.ovm");
  ASSERT_EQ(m.cell_faces[0][0], 0);
  EXPECT_EQ(std::vector<int32_t>(m.face_verts[0].begin(), m.face_verts[0].end()),
            (std::vector<int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(m.cell_face_flip[0], 1);
}

TEST(IoRoundTrip, OvmReproducesEveryRealMesh) {
  for (const RealFile& f : kRealFiles) {
    SCOPED_TRACE(f.path);
    HBC_REQUIRE_DATA(f.path);
    const Mesh m = test::load_data(f.path);
    const std::string text = ovm_text(m);
    const Mesh back = build_mesh(read_ovm(text, "roundtrip.ovm"));
    expect_same_mesh(m, back);
    EXPECT_EQ(back.dropped_faces, 0);
    EXPECT_EQ(back.dropped_edges, 0);
    // Written twice, the text is the same: the writer is a function of the mesh alone.
    EXPECT_EQ(ovm_text(back), text);
  }
}

TEST(IoRoundTrip, MeditReproducesEveryRealMeshWithoutPolyhedra) {
  int tested = 0;
  for (const RealFile& f : kRealFiles) {
    SCOPED_TRACE(f.path);
    HBC_REQUIRE_DATA(f.path);
    const Mesh m = test::load_data(f.path);
    if (has_polyhedra(m)) {
      EXPECT_THROW(medit_text(m), std::invalid_argument);
      continue;
    }
    ++tested;
    const Mesh back = build_mesh(read_medit(medit_text(m), "roundtrip.mesh"));
    EXPECT_EQ(back.points, m.points);
    EXPECT_EQ(back.num_edges(), m.num_edges());
    EXPECT_EQ(back.num_faces(), m.num_faces());
    ASSERT_EQ(back.num_cells(), m.num_cells());
    // MEDIT groups cells by type (hex, tet, prism, pyramid), keeping their order within a type.
    std::vector<size_t> order;
    for (CellType t : {CellType::Hex, CellType::Tet, CellType::Prism, CellType::Pyramid})
      for (size_t c = 0; c < m.num_cells(); ++c)
        if (m.cell_type[c] == t) order.push_back(c);
    ASSERT_EQ(order.size(), m.num_cells());
    size_t set_mismatches = 0, oriented = 0, orientation_mismatches = 0;
    for (size_t i = 0; i < order.size(); ++i) {
      EXPECT_EQ(back.cell_type[i], m.cell_type[order[i]]);
      set_mismatches += cell_face_sets(back, i) != cell_face_sets(m, order[i]);
      // Where the input says which way each face is seen, the written element keeps it.
      if (consistently_oriented(m, order[i])) {
        ++oriented;
        orientation_mismatches += cell_seen_loops(back, i) != cell_seen_loops(m, order[i]);
      }
    }
    EXPECT_EQ(set_mismatches, 0u);
    EXPECT_EQ(orientation_mismatches, 0u) << "of " << oriented << " consistently oriented cells";
    // build_mesh orients every cell outward, whatever the file said (test_2 lists all faces one way).
    EXPECT_EQ(oriented, m.num_cells());
  }
  // test_2, 3 OVM pairs, ellipsoid, rockerarm, 6 HexaLab meshes.
  EXPECT_EQ(tested, 15);
}

TEST(IoWriters, MeditKeepsTheVertexOrderOfEveryElementType) {
  // One element of each type on vertices of its own, so that each is rebuilt from its own faces.
  const std::string text =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n23\n"
      "0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n1 1 1 0\n0 1 1 0\n"
      "3 0 0 0\n4 0 0 0\n3 1 0 0\n3 0 1 0\n"
      "6 0 0 0\n7 0 0 0\n6 1 0 0\n6 0 1 0\n7 0 1 0\n6 1 1 0\n"
      "9 0 0 0\n10 0 0 0\n10 1 0 0\n9 1 0 0\n9.5 0.5 1 0\n"
      "Hexahedra\n1\n1 2 3 4 5 6 7 8 0\n"
      "Tetrahedra\n1\n9 10 11 12 0\n"
      "Prisms\n1\n13 14 15 16 17 18 0\n"
      "Pyramids\n1\n19 20 21 22 23 0\n"
      "End\n";
  MeshInput in = read_medit(text, "elements.mesh");
  const Mesh m = build_mesh(std::move(in));
  EXPECT_EQ(type_counts(m), (std::array<size_t, 5>{1, 1, 1, 1, 0}));
  EXPECT_EQ(medit_text(m), text);
}

TEST(IoWriters, MeditRejectsAPolyhedronNamingTheCell) {
  // Cell 1 is a hexagonal prism (8 faces).
  const char* hedra =
      "12 8 1\n"
      "1 0 0\n0.5 0.9 0\n-0.5 0.9 0\n-1 0 0\n-0.5 -0.9 0\n0.5 -0.9 0\n"
      "1 0 1\n0.5 0.9 1\n-0.5 0.9 1\n-1 0 1\n-0.5 -0.9 1\n0.5 -0.9 1\n"
      "6 6 5 4 3 2 1\n6 7 8 9 10 11 12\n"
      "4 1 2 8 7\n4 2 3 9 8\n4 3 4 10 9\n4 4 5 11 10\n4 5 6 12 11\n4 6 1 7 12\n"
      "8 1 2 3 4 5 6 7 8\n";
  const Mesh m = build_mesh(read_hedra(hedra, "hexprism.hedra"));
  ASSERT_EQ(m.cell_type[0], CellType::Polyhedron);
  try {
    medit_text(m);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("polyhedron"), std::string::npos) << e.what();
  }
  // OVM stores it.
  expect_same_mesh(build_mesh(read_ovm(ovm_text(m), "hexprism.ovm")), m);
}

TEST(IoReaders, OvmAcceptsCommentsCaseAndPropertyBlocks) {
  const char* text =
      "# a tetrahedron\n"
      "ovm ascii\n\n"
      "VERTICES 4\n"
      "0 0 0\n1 0 0 # comment after data\n0 1 0\n0 0 1\n"
      "edges\n6\n0 1\n1 2\n2 0\n0 3\n1 3\n2 3\n"
      "Faces\n4\n3 0 2 4\n3 0 8 7\n3 2 10 9\n3 4 6 11\n"
      "Polyhedra\n1\n4 1 2 4 6\n"
      "VProp vec3d \"normals\"\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"
      "HEProp int \"he\"\n0\n1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n11\n"
      "CProp string \"name # not a comment\"\nthe only cell # with a hash\n"
      "MProp double \"scale\"\n2.5\n";
  const MeshInput in = read_ovm(text, "tet.ovm");
  EXPECT_EQ(in.vertex_loc, (std::vector<int64_t>{5, 6, 7, 8}));
  EXPECT_EQ(in.face_loc, (std::vector<int64_t>{19, 20, 21, 22}));
  EXPECT_EQ(in.cell_loc, (std::vector<int64_t>{25}));
  const Mesh m = build_mesh(in);
  EXPECT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.cell_type[0], CellType::Tet);
  // Face 1 is 0 -> 1 -> 3 (half-edges 0, 8 = edge 4 forward, 7 = edge 3 reversed).
  EXPECT_EQ(std::vector<int32_t>(m.face_verts[1].begin(), m.face_verts[1].end()),
            (std::vector<int32_t>{0, 1, 3}));
}

TEST(IoReaders, MeditReadsPastOtherSectionsKeepingLinesAndTokens) {
  // A section we do not read (quadrangles here) is passed token by token up to the next token
  // that starts with a letter, eight bytes at a time where no letter or '#' is. Shifting it by
  // 0-16 bytes puts every part of it at every place in those eight. "777...Tetrahedra" is one
  // token, not a keyword (taken for one, the section after would read tetrahedra from the
  // comment's line and fail); a word in a comment after numbers is no keyword; one after numbers
  // on a line is. The tetrahedron is on line 16 whatever the shift: 1-2 header, 3-8 vertices,
  // 9-10 the section and its count, 11-14 its lines, 15 the count of tetrahedra.
  for (int shift = 0; shift <= 16; ++shift) {
    SCOPED_TRACE("shift " + std::to_string(shift));
    const std::string head =
        "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
        "Quadrilaterals\n2\n" + std::string(static_cast<size_t>(shift), ' ') +
        "1 2 3 4 0\n"
        "2 3 4 1 1e-5 " + std::string(static_cast<size_t>(8 + shift), '7') + "Tetrahedra 0\n"
        "#" + std::string(static_cast<size_t>(shift), ' ') + "1 2 3 4 5 6 7 8 9 Hexahedra\n"
        "3 4 1 2 0 Tetrahedra\n1\n";
    const MeshInput in = read_medit(head + "1 2 3 4 0\nEnd\n", "past.mesh");
    EXPECT_EQ(in.cell_loc, (std::vector<int64_t>{16}));
    EXPECT_EQ(build_mesh(in).num_cells(), 1u);
    try {
      build_mesh(read_medit(head + "1 2 3 9 0\nEnd\n", "past.mesh"));
      ADD_FAILURE() << "accepted vertex 9 of 4";
    } catch (const InputError& e) {
      EXPECT_EQ(e.loc().line, 16) << e.what();
    }
  }
}

TEST(IoFormats, FromPathAndName) {
  const std::pair<const char*, Format> by_path[] = {
      {"a/b/c.ovm", Format::Ovm},   {"c.OVMB", Format::Ovmb},   {"x.mesh", Format::Medit},
      {"cube_twist-comp.obj.HYBRID", Format::Hybrid},           {"t.hybrid", Format::Hybrid},
      {"teapot.hedra", Format::Hedra}, {"g.msh", Format::Msh},  {"model.VTK", Format::Vtk},
      {"p.vtu", Format::Vtu}};
  for (const auto& [path, f] : by_path) EXPECT_EQ(format_from_path(path), f) << path;
  for (const char* path : {"noextension", "dir.v2/noextension", "mesh.stl", "mesh.obj"})
    EXPECT_THROW(format_from_path(path), InputError) << path;
  try {
    format_from_path("model.ply");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "model.ply");
    EXPECT_NE(e.detail().find("--format"), std::string::npos);
  }
  const std::pair<const char*, Format> by_name[] = {{"ovm", Format::Ovm},       {"OVMB", Format::Ovmb},
                                                    {"mesh", Format::Medit},    {"Medit", Format::Medit},
                                                    {"HYBRID", Format::Hybrid}, {"hedra", Format::Hedra}};
  for (const auto& [name, f] : by_name) EXPECT_EQ(format_from_name(name), f) << name;
  for (const char* name : {"stl", ""}) EXPECT_THROW(format_from_name(name), std::invalid_argument) << name;
  for (Format f : {Format::Ovm, Format::Ovmb, Format::Medit, Format::Hybrid, Format::Hedra, Format::Msh, Format::Vtk,
                   Format::Vtu})
    EXPECT_EQ(format_from_name(format_name(f)), f);
}

TEST(IoFormats, WriteMeshPicksTheWriterByExtension) {
  HBC_REQUIRE_DATA("openvolumemesh/Cube_with_props.ovm");
  const Mesh m = test::load_data("openvolumemesh/Cube_with_props.ovm");
  const auto dir = std::filesystem::temp_directory_path() / ("hbc_io_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_mesh(m, (dir / "cube.ovm").string());
  write_mesh(m, (dir / "cube.mesh").string());
  write_mesh(m, (dir / "cube.txt").string(), Format::Ovm);
  expect_same_mesh(load_mesh((dir / "cube.ovm").string()), m);
  expect_same_mesh(load_mesh((dir / "cube.txt").string(), Format::Ovm), m);
  EXPECT_EQ(load_mesh((dir / "cube.mesh").string()).points, m.points);
  EXPECT_THROW(write_mesh(m, (dir / "cube.ovmb").string()), std::invalid_argument);
  std::filesystem::remove_all(dir);
}

using test::run_cli;

TEST(IoCli, FormatOverride) {
  HBC_REQUIRE_DATA("openvolumemesh/Cube_with_props.ovm");
  ASSERT_TRUE(std::filesystem::exists(HBC_CLI)) << "build the hbc_cli target: " << HBC_CLI;
  const auto dir = std::filesystem::temp_directory_path() / ("hbc_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  // The same OVM text under a name whose extension says nothing (or says something else).
  const auto plain = dir / "cube.dat";
  const auto lying = dir / "cube.mesh";
  std::filesystem::copy_file(data_path("openvolumemesh/Cube_with_props.ovm"), plain);
  std::filesystem::copy_file(data_path("openvolumemesh/Cube_with_props.ovm"), lying);

  test::CliRun r = run_cli("info '" + plain.string() + "' --json");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("cube.dat"), std::string::npos) << r.err;

  r = run_cli("info '" + plain.string() + "' --format ovm --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.json()["cells"], 1) << r.out;
  EXPECT_EQ(r.json()["hex_cells"], 1) << r.out;

  r = run_cli("info '" + lying.string() + "' --json");  // read as MEDIT: fails
  EXPECT_EQ(r.status, 2) << r.err;
  r = run_cli("info '" + lying.string() + "' --format OVM --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.json()["vertices"], 8) << r.out;

  r = run_cli("info '" + plain.string() + "' --format nonsense");  // a value --format cannot take
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("nonsense"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(IoCli, ThreadsOption) {
  // --threads changes how the load is split, never what it finds; a count below 1 is a usage
  // error naming the option.
  HBC_REQUIRE_DATA("cinolib/rockerarm.mesh");
  const std::string file = "'" + data_path("cinolib/rockerarm.mesh") + "'";
  const test::CliRun one = test::run_cli("info " + file + " --json --threads 1");
  const test::CliRun two = test::run_cli("info " + file + " --threads 2 --json");
  EXPECT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(one.out, two.out);
  EXPECT_EQ(one.json()["cells"], 10600) << one.out;
  // A value the option cannot take: exit 2 with CLI11's message naming it.
  const test::CliRun zero = test::run_cli("info " + file + " --threads 0");
  EXPECT_EQ(zero.status, 2);
  EXPECT_NE(zero.err.find("--threads"), std::string::npos) << zero.err;
}

}  // namespace
}  // namespace hbc
