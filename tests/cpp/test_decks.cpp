// The finite-element deck readers (Abaqus .inp, Nastran .bdf/.nas, LS-DYNA .k/.key): the real
// slab written by gmsh's and meshio's writers (and, LS-DYNA having no writer installable here, by
// tests/data/formats/make_deck_files.py after the manual) must give slab.mesh's analysis; small
// hand-written decks check parts and instances, includes, field formats, labels and degenerate
// hexahedra, with their answers derived in the comments.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

std::string formats_path(const std::string& rel) { return std::string(HBC_FORMATS_DIR) + "/" + rel; }

// Cells of each type, in CellType order.
std::array<size_t, 5> type_counts(const Mesh& m) {
  std::array<size_t, 5> n{};
  for (CellType t : m.cell_type) ++n[static_cast<size_t>(t)];
  return n;
}

// Twins of real/slab.mesh (make_deck_files.py) and the surface elements each writer adds: gmsh
// writes the 41 quadrangles and 14 triangles of the physical surface "bottom", meshio none.
const std::pair<const char*, const char*> kDecks[] = {
    {"slab_gmsh.inp", "55 surface"},        {"slab_gmsh_order2.inp", "55 surface"},
    {"slab_meshio.inp", nullptr},           {"slab_gmsh_free.bdf", "55 surface"},
    {"slab_gmsh_small.bdf", "55 surface"},  {"slab_gmsh_large.bdf", "55 surface"},
    {"slab_gmsh_order2.bdf", "55 surface"}, {"slab_meshio.bdf", nullptr},
    {"slab_standard.k", nullptr},           {"slab_long.k", nullptr},
    {"slab_twocard.k", nullptr},            {"slab_free.k", nullptr},
    {"slab_i10.key", nullptr}};

TEST(DecksRealTools, EveryDeckGivesTheSameCellsAndAnalysisAsMedit) {
  const Mesh ref_mesh = load_mesh(formats_path("real/slab.mesh"));
  ASSERT_EQ(ref_mesh.num_cells(), 110u);  // 82 hexahedra and 28 prisms (test_formats.cpp)
  const Stats ref = compute_stats(ref_mesh, analyze(ref_mesh));
  for (const auto& [f, skipped] : kDecks) {
    SCOPED_TRACE(f);
    const Mesh m = load_mesh(formats_path(std::string("real/") + f));
    EXPECT_EQ(m.num_vertices(), ref_mesh.num_vertices());  // second-order nodes dropped
    EXPECT_EQ(m.num_edges(), ref_mesh.num_edges());
    EXPECT_EQ(m.num_faces(), ref_mesh.num_faces());
    EXPECT_EQ(type_counts(m), type_counts(ref_mesh));
    test::expect_same_counts(compute_stats(m, analyze(m)), ref);
    if (skipped) {
      ASSERT_EQ(m.warnings.size(), 1u);
      EXPECT_NE(m.warnings[0].find(skipped), std::string::npos) << m.warnings[0];
    } else {
      EXPECT_TRUE(m.warnings.empty());
    }
  }
}

TEST(DecksRealTools, TheSameVertexPositionsAsMedit) {
  // Labels are not positions in the file: gmsh numbers nodes 1..n in slab.mesh's order, the .k
  // files label node i as 1000 + 7 i and list them backwards. Sorted point lists must agree (to the
  // 9 significant digits the .k writer keeps).
  auto sorted_points = [](const Mesh& m) {
    std::vector<std::array<double, 3>> p(m.num_vertices());
    for (size_t v = 0; v < p.size(); ++v) p[v] = {m.points[3 * v], m.points[3 * v + 1], m.points[3 * v + 2]};
    std::sort(p.begin(), p.end());
    return p;
  };
  const auto ref = sorted_points(load_mesh(formats_path("real/slab.mesh")));
  for (const char* f : {"slab_gmsh.inp", "slab_meshio.bdf", "slab_gmsh_large.bdf", "slab_standard.k", "slab_long.k"}) {
    SCOPED_TRACE(f);
    const auto p = sorted_points(load_mesh(formats_path(std::string("real/") + f)));
    ASSERT_EQ(p.size(), ref.size());
    for (size_t i = 0; i < p.size(); ++i)
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[i][k], ref[i][k], 1e-6);
  }
}

// ---------------------------------------------------------------------------------------------
// Abaqus

// One part, a unit cube [0,1]^3 (labels 10..17) with a shell on its bottom, placed twice: C1 as
// it is, C2 moved by (1,0,0) and then turned 90 degrees about the z axis through the origin, which
// takes (x, y) to (-y, x): C2 spans x in [-1, 0], y in [1, 2]. Instances keep their labels apart,
// so the 16 nodes stay 16 vertices. Everything after *Step is history data, not read.
const char* const kInstances = R"(** two placed instances of one part
*Heading
 cubes
*Part, name=Cube
*Node
 10, 0., 0., 0.
 11, 1., 0., 0.
 12, 1., 1., 0.
 13, 0., 1., 0.
 14, 0., 0., 1.
 15, 1., 0., 1.
 16, 1., 1., 1.
 17, 0., 1., 1.
*element, TYPE=c3d8r, elset=all
 1, 10, 11, 12, 13, 14, 15, 16, 17
*Element, type=S4R
 2, 10, 11, 12, 13
*End Part
*Assembly, name=A
*Instance, name=C1, part=Cube
*End Instance
*Instance, name=C2, part=CUBE
 1., 0., 0.
 0., 0., 0., 0., 0., 1., 90.
*End Instance
*End Assembly
*Step
*Node
 99, 5., 5., 5.
)";

TEST(DecksAbaqus, InstancesOfAPartArePlacedWithTheirOwnLabels) {
  const MeshInput in = read_abaqus(kInstances, "cubes.inp");
  ASSERT_EQ(in.points.size(), 3u * 16);
  const Mesh m = build_mesh(in);
  ASSERT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.num_hex_cells(), 2u);
  EXPECT_EQ(m.num_faces(), 12u);  // apart: no face shared
  for (size_t v = 8; v < 16; ++v) {
    EXPECT_GE(m.points[3 * v], -1 - 1e-12);
    EXPECT_LE(m.points[3 * v], 1e-12);
    EXPECT_GE(m.points[3 * v + 1], 1 - 1e-12);
    EXPECT_LE(m.points[3 * v + 1], 2 + 1e-12);
  }
  // Label 10 of C2: (0,0,0) + (1,0,0) turned to (0,1,0).
  EXPECT_NEAR(m.points[3 * 8], 0, 1e-12);
  EXPECT_NEAR(m.points[3 * 8 + 1], 1, 1e-12);
  ASSERT_EQ(m.warnings.size(), 1u);  // one S4R per instance
  EXPECT_NE(m.warnings[0].find("2 surface element(s)"), std::string::npos) << m.warnings[0];
}

// A 20-node hexahedron over two lines (the first ending in a comma), a 10-node tetrahedron on its
// top edge 5-6 (corners 5 6 30 31), a truss: 8 + 2 corners are vertices, the 12 + 6 mid-edge nodes
// (100..111, 200..205) are dropped.
const char* const kSecondOrder = R"(*NODE, NSET=all
1,0,0,0
2,1,0,0
3,1,1,0
4,0,1,0
5,0,0,1
6,1,0,1
7,1,1,1
8,0,1,1
30,0.5,0.5,2
31,0.5,-0.5,1.5
100,.5,0,0
101,1,.5,0
102,.5,1,0
103,0,.5,0
104,.5,0,1
105,1,.5,1
106,.5,1,1
107,0,.5,1
108,0,0,.5
109,1,0,.5
110,1,1,.5
111,0,1,.5
200,.5,0,1
201,1,.5,1
202,.5,.5,1
203,.25,.25,1.5
204,.75,.25,1.5
205,.75,.75,1.5
*ELEMENT, TYPE=C3D20R
1, 1, 2, 3, 4, 5, 6, 7, 8, 100, 101, 102, 103, 104, 105, 106,
107, 108, 109, 110, 111
*ELEMENT, TYPE=C3D10
2, 5, 6, 30, 31, 200, 201, 202, 203, 204, 205
*ELEMENT, TYPE=T3D2
3, 1, 2
)";

TEST(DecksAbaqus, SecondOrderElementsByTheirCornersAndContinuationLines) {
  const Mesh m = build_mesh(read_abaqus(kSecondOrder, "second.inp"));
  EXPECT_EQ(m.num_vertices(), 10u);
  ASSERT_EQ(m.num_cells(), 2u);
  EXPECT_EQ(m.cell_type[0], CellType::Hex);
  EXPECT_EQ(m.cell_type[1], CellType::Tet);
  EXPECT_EQ(m.num_faces(), 6u + 4u);  // sharing an edge, no face
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("1 line"), std::string::npos) << m.warnings[0];
}

TEST(DecksAbaqus, IncludesAreFetchedRelativeToTheIncludingFile) {
  // The nodes in one file, the element in another, both included; cells and vertices are located
  // at the line of the top file that includes them.
  const std::map<std::string, std::string> files = {
      {"decks/nodes.inp", "1, 0,0,0\n2, 1,0,0\n3, 0,1,0\n4, 0,0,1\n"},
      {"decks/more/tet.inp", "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n"}};
  std::vector<std::pair<std::string, std::string>> asked;
  const IncludeReader fetch = [&](const std::string& from, const std::string& path, std::string& name) {
    asked.emplace_back(from, path);
    name = "decks/" + path;
    return files.at(name);
  };
  const std::string top = "** top\n*NODE\n*INCLUDE, INPUT=nodes.inp\n*Include, input=\"more/tet.inp\"\n";
  const MeshInput in = read_abaqus(top, "decks/top.inp", fetch);
  ASSERT_EQ(asked.size(), 2u);
  EXPECT_EQ(asked[0], (std::pair<std::string, std::string>("decks/top.inp", "nodes.inp")));
  EXPECT_EQ(asked[1].second, "more/tet.inp");
  ASSERT_EQ(in.cells.rows(), 1u);
  EXPECT_EQ(in.vertex_loc, (std::vector<int64_t>{3, 3, 3, 3}));
  EXPECT_EQ(in.cell_loc, (std::vector<int64_t>{4}));
  EXPECT_EQ(build_mesh(in).cell_type[0], CellType::Tet);
  // An error inside an included file names that file and its line.
  const std::map<std::string, std::string> bad = {{"decks/nodes.inp", "1, 0,0,0\n2, x,0,0\n"}};
  try {
    read_abaqus(top, "decks/top.inp", [&](const std::string&, const std::string& path, std::string& name) {
      name = "decks/" + path;
      return bad.count(name) ? bad.at(name) : files.at(name);
    });
    ADD_FAILURE() << "accepted a bad coordinate";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "decks/nodes.inp");
    EXPECT_EQ(e.loc().line, 2);
  }
  // Read from memory without a way to fetch: the include is refused where it stands.
  try {
    read_abaqus(top, "top.inp");
    ADD_FAILURE() << "accepted an include it cannot read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 3);
  }
}

TEST(DecksAbaqus, ReadInputFetchesIncludesFromDisk) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hbc_test_decks";
  std::filesystem::create_directories(dir / "sub");
  std::ofstream(dir / "top.inp") << "*NODE, INPUT=sub/nodes.inp\n*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n";
  std::ofstream(dir / "sub" / "nodes.inp") << "1, 0,0,0\n2, 1,0,0\n3, 0,1,0\n4, 0,0,1\n";
  const Mesh m = load_mesh((dir / "top.inp").string());
  EXPECT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.num_vertices(), 4u);
  std::filesystem::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// Nastran

// A unit cube (small field, continued on a '+' line), a pyramid on its top (apex 9 at z = 1.5,
// free field) and a tetrahedron on the pyramid's face 5 6 9 (apex 10 at (0.5, -0.5, 1.5), large
// field), grids in every format with Nastran's reals (5.-1 = 0.5, 1.5+0 = 1.5, 15.-1 = 1.5); a
// quadrangle and a bar skipped. Nothing before BEGIN BULK or after ENDDATA is read.
const char* const kNastran = R"(SOL 101
CEND
GRID    99              junk
BEGIN BULK
$ comment
GRID    1               0.      0.      0.
GRID    2               1.      0.      0.
GRID    3               1.      1.      0.
GRID    4               0.      1.      0.
GRID*   5                               0.              0.
*       1.
GRID,6,,1.,0.,1.
GRID,7,0,1.,1.,1.
GRID,8,,0.,1.,1.
GRID    9               5.-1    .5      1.5+0
GRID*   10              0               .5              -5.-1
*       15.-1
CHEXA   1       1       1       2       3       4       5       6       +C1
+C1     7       8
CPYRAM,2,1,5,6,7,8,9
CTETRA* 3               1               5               6
*       9               10
CQUAD4  4       1       1       2       3       4
CBAR    5       1       1       2
ENDDATA
GRID    11              0.      0.      0.
)";

TEST(DecksNastran, SmallLargeAndFreeFieldsAndNastransReals) {
  const MeshInput in = read_nastran(kNastran, "mixed.bdf");
  ASSERT_EQ(in.points.size(), 3u * 10);
  EXPECT_DOUBLE_EQ(in.points[3 * 8], 0.5);
  EXPECT_DOUBLE_EQ(in.points[3 * 8 + 2], 1.5);
  EXPECT_DOUBLE_EQ(in.points[3 * 9 + 1], -0.5);
  EXPECT_DOUBLE_EQ(in.points[3 * 9 + 2], 1.5);
  EXPECT_EQ(in.cell_loc, (std::vector<int64_t>{18, 20, 21}));
  const Mesh m = build_mesh(in);
  ASSERT_EQ(m.num_cells(), 3u);
  EXPECT_EQ(m.cell_type[0], CellType::Hex);
  EXPECT_EQ(m.cell_type[1], CellType::Pyramid);
  EXPECT_EQ(m.cell_type[2], CellType::Tet);
  EXPECT_EQ(m.num_faces(), 6u + 4u + 3u);  // the pyramid shares the cube's top, the tet the pyramid's face
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("1 line and 1 surface"), std::string::npos) << m.warnings[0];
}

TEST(DecksNastran, MidEdgeGridsMayBeLeftBlank) {
  // A 10-node CTETRA with only G5 and G8 of its six mid-edge grids: the four corners are the cell,
  // grids 5 and 6 (mid-edge only) are dropped.
  const std::string t = "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.,1.,0.\nGRID,4,,0.,0.,1.\nGRID,5,,.5,0.,0.\n"
                        "GRID,6,,0.,0.,.5\nCTETRA,1,1,1,2,3,4,5,,+\n+,,6\n";
  const Mesh m = build_mesh(read_nastran(t, "tet10.bdf"));
  EXPECT_EQ(m.num_vertices(), 4u);
  ASSERT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.cell_type[0], CellType::Tet);
}

TEST(DecksNastran, AGridInAnotherCoordinateSystemIsRefused) {
  std::string t = kNastran;
  t.replace(t.find("GRID    2               1."), 26, "GRID    2       3       1.");
  try {
    read_nastran(t, "cord.bdf");
    ADD_FAILURE() << "read a GRID in coordinate system 3 as if basic";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 7);
    EXPECT_NE(std::string(e.what()).find("basic coordinate system"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------------------------
// LS-DYNA

// Four cells as LS-DYNA writes them, each an 8-node card: a hexahedron (nodes 1..8), a prism
// (N5=N6, N7=N8: the quad 11 12 13 14, triangles 11 12 15 and 14 13 16), a pyramid (N5..N8 the apex)
// and a tetrahedron (N4..N8 equal). In the standard (i8), I10 (`%`) and free formats and the
// two-card form; '$' comments; *END ends the input.
const char* const kLsDyna = R"($ four cells
*KEYWORD
*NODE
$#   nid               x               y               z
       1             0.0             0.0             0.0
       2             1.0             0.0             0.0
       3             1.0             1.0             0.0
       4             0.0             1.0             0.0
       5             0.0             0.0             1.0
       6             1.0             0.0             1.0
       7             1.0             1.0             1.0
       8             0.0             1.0             1.0
*NODE %
        11             5.0             0.0             0.0
        12             6.0             0.0             0.0
        13             6.0             0.0             1.0
        14             5.0             0.0             1.0
        15             5.5             1.0             0.0
        16             5.5             1.0             1.0
21,10.,0.,0.
22,11.,0.,0.
23,11.,1.,0.
24,10.,1.,0.
25,10.5,.5,1.
31,20.,0.,0.
32,21.,0.,0.
33,20.,1.,0.
34,20.,0.,1.
*ELEMENT_SOLID
       1       1       1       2       3       4       5       6       7       8
       2       1
      11      12      13      14      15      15      16      16
*ELEMENT_SOLID %
         3         1        21        22        23        24        25        25        25        25
4,1,31,32,33,34,34,34,34,34
*ELEMENT_SHELL
       5       1       1       2       3       4
*END
*NODE
       9             0.0             0.0             0.0
)";

TEST(DecksLsDyna, DegenerateHexahedraAreThePrismPyramidAndTetTheyStandFor) {
  const MeshInput in = read_lsdyna(kLsDyna, "four.k");
  EXPECT_EQ(in.points.size(), 3u * 23);
  const Mesh m = build_mesh(in);
  ASSERT_EQ(m.num_cells(), 4u);
  EXPECT_EQ(m.cell_type[0], CellType::Hex);
  EXPECT_EQ(m.cell_type[1], CellType::Prism);
  EXPECT_EQ(m.cell_type[2], CellType::Pyramid);
  EXPECT_EQ(m.cell_type[3], CellType::Tet);
  EXPECT_EQ(m.num_faces(), 6u + 5u + 5u + 4u);
  EXPECT_EQ(in.cell_loc, (std::vector<int64_t>{30, 31, 34, 35}));
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("1 surface"), std::string::npos) << m.warnings[0];
}

TEST(DecksLsDyna, TheTenNodeTetrahedronByItsCorners) {
  // The two-card form with N9 and N10 set: corners N1..N4, the six mid-edge nodes dropped.
  const std::string k =
      "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,.5,0,0\n6,.5,.5,0\n7,0,.5,0\n8,0,0,.5\n9,.5,0,.5\n10,0,.5,.5\n"
      "*ELEMENT_SOLID\n       1       1\n       1       2       3       4       5       6       7       8       9      10\n*END\n";
  const Mesh m = build_mesh(read_lsdyna(k, "tet10.k"));
  EXPECT_EQ(m.num_vertices(), 4u);
  ASSERT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.cell_type[0], CellType::Tet);
}

TEST(Decks, SkipInvalidDropsTheCellsBuildMeshRefuses) {
  // A Nastran cube and a CHEXA whose top repeats its bottom (N5..N8 = N1..N4): its faces collapse
  // to one, no volume; build_mesh refuses the file, --skip-invalid drops that cell alone.
  const std::string t = std::string("GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n") +
                        "GRID,5,,0.,0.,1.\nGRID,6,,1.,0.,1.\nGRID,7,,1.,1.,1.\nGRID,8,,0.,1.,1.\n" +
                        "CHEXA,1,1,1,2,3,4,5,6,+\n+,7,8\nCHEXA,2,1,1,2,3,4,1,2,+\n+,3,4\n";
  const MeshInput in = read_nastran(t, "flat.bdf");
  std::vector<DroppedCell> dropped;
  const Mesh m = build_mesh_skipping_invalid(in, dropped);
  EXPECT_EQ(m.num_cells(), 1u);
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_THROW(build_mesh(read_nastran(t, "flat.bdf")), InputError);
}

}  // namespace
}  // namespace hbc
