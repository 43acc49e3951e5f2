// Boundary surfaces through OpenMesh: counts, welding, closedness and outward orientation after a
// round trip through the files OpenMesh writes.
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "hbc/face_selection.hpp"
#include "hbc/surface.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() /
                     ("hbc_test_surface_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                      std::to_string(static_cast<long long>(::getpid())));
  fs::create_directories(d);
  return d;
}

// Enclosed volume of a closed surface (fan triangles per face, divergence theorem).
double enclosed_volume(const SurfaceMesh& s) {
  double vol = 0;
  for (auto fh : s.faces()) {
    std::vector<SurfaceMesh::Point> p;
    for (auto vh : s.fv_range(fh)) p.push_back(s.point(vh));
    for (size_t k = 1; k + 1 < p.size(); ++k) vol += static_cast<double>(p[0] | (p[k] % p[k + 1]));
  }
  return vol / 6.0;
}

void expect_closed(const SurfaceMesh& s) {
  for (auto eh : s.edges()) EXPECT_FALSE(s.is_boundary(eh)) << "edge " << eh.idx() << " has one face";
}

SurfaceMesh read_back(const fs::path& path, bool colors) {
  SurfaceMesh s;
  OpenMesh::IO::Options opt;
  if (colors) {
    s.request_face_colors();
    opt += OpenMesh::IO::Options::FaceColor;
  }
  EXPECT_TRUE(OpenMesh::IO::read_mesh(s, path.string(), opt)) << path;
  return s;
}

TEST(Surface, GridBoundaryRoundTrip) {
  // 2x3x4 grid: 2(2*3 + 2*4 + 3*4) = 52 boundary quads over 60 - 1*2*3 = 54 boundary vertices;
  // closed with 104 edges (Euler 54 - 104 + 52 = 2); encloses volume 24.
  const Mesh m = build_mesh(generate_grid(2, 3, 4));
  const FaceSelection sel = boundary_selection(m);
  ASSERT_EQ(sel.faces.size(), 52u);
  SurfaceStats stats;
  const SurfaceMesh s = build_surface(m, sel, &stats);
  EXPECT_EQ(stats.faces, 52);
  EXPECT_EQ(stats.unwelded_faces, 0);
  EXPECT_EQ(s.n_faces(), 52u);
  EXPECT_EQ(s.n_vertices(), 54u);
  EXPECT_EQ(s.n_edges(), 104u);
  expect_closed(s);
  EXPECT_NEAR(enclosed_volume(s), 24.0, 1e-4);

  const fs::path dir = temp_dir();
  for (const char* ext : {"off", "ply", "obj"}) {
    SCOPED_TRACE(ext);
    const fs::path path = dir / (std::string("grid.") + ext);
    write_surface(s, path.string());
    const SurfaceMesh r = read_back(path, false);
    EXPECT_EQ(r.n_faces(), 52u);
    EXPECT_EQ(r.n_vertices(), 54u);
    for (auto fh : r.faces()) EXPECT_EQ(r.valence(fh), 4u);
    expect_closed(r);
    EXPECT_NEAR(enclosed_volume(r), 24.0, 1e-4) << "outward orientation lost";
  }
  fs::remove_all(dir);
}

TEST(Surface, ColoursAndIdsFollowTheSelection) {
  // Corner cell of a 2x2x2 grid cut into tets: 27 boundary faces, 6 of them triangles of tets
  // (id Tet), the rest quads of hexes (id Hex) or of the 3 neighbouring polyhedra.
  const std::array<int32_t, 3> corner{0, 0, 0};
  const Mesh m = build_mesh(generate_split(2, 2, 2, SplitKind::Tets, {&corner, 1}));
  const FaceSelection sel = boundary_selection(m);
  ASSERT_EQ(sel.faces.size(), 27u);
  const SurfaceMesh s = build_surface(m, sel);
  expect_closed(s);
  EXPECT_NEAR(enclosed_volume(s), 8.0, 1e-4);
  OpenMesh::FPropHandleT<int> id_prop, face_prop;
  ASSERT_TRUE(s.get_property_handle(id_prop, kSurfaceIdProperty));
  ASSERT_TRUE(s.get_property_handle(face_prop, kSurfaceFaceProperty));
  int tets = 0;
  for (auto fh : s.faces()) {
    const int id = s.property(id_prop, fh);
    const int f = s.property(face_prop, fh);
    EXPECT_EQ(id, static_cast<int>(m.cell_type[m.face_cells[f][0]]));
    tets += id == static_cast<int>(CellType::Tet);
    const auto rgb = palette_color(id);
    EXPECT_EQ(s.color(fh), SurfaceMesh::Color(rgb[0], rgb[1], rgb[2]));
  }
  EXPECT_EQ(tets, 6);
  EXPECT_NE(palette_color(0), palette_color(1));
  EXPECT_EQ(palette_color(-3), (std::array<uint8_t, 3>{128, 128, 128}));

  // Colours survive in PLY and OFF.
  const fs::path dir = temp_dir();
  for (const char* ext : {"ply", "off"}) {
    SCOPED_TRACE(ext);
    const fs::path path = dir / (std::string("tets.") + ext);
    write_surface(s, path.string());
    const SurfaceMesh r = read_back(path, true);
    ASSERT_EQ(r.n_faces(), 27u);
    int tet_coloured = 0;
    const auto tet_rgb = palette_color(static_cast<int>(CellType::Tet));
    for (auto fh : r.faces())
      tet_coloured += r.color(fh) == SurfaceMesh::Color(tet_rgb[0], tet_rgb[1], tet_rgb[2]);
    EXPECT_EQ(tet_coloured, 6);
  }
  fs::remove_all(dir);
}

TEST(Surface, NonManifoldEdgeFacesAreKeptUnwelded) {
  // Two unit cubes sharing only the edge x = 1, y = 1: the boundary has 4 faces at that edge,
  // which an OpenMesh surface cannot hold; two of them get their own corners, none is lost.
  MeshInput in = generate_grid(2, 2, 1);
  // Keep cells (0,0,0) and (1,1,0) of the 2x2x1 grid: they meet along one vertical edge.
  Csr<int32_t> cells;
  for (size_t c : {size_t{0}, size_t{3}}) cells.push_row(in.cells[c]);
  in.cells = cells;
  const Mesh m = build_mesh(std::move(in));
  ASSERT_EQ(m.num_cells(), 2u);
  const FaceSelection sel = boundary_selection(m);
  ASSERT_EQ(sel.faces.size(), 12u);
  SurfaceStats stats;
  const SurfaceMesh s = build_surface(m, sel, &stats);
  EXPECT_EQ(s.n_faces(), 12u);
  EXPECT_GT(stats.unwelded_faces, 0);
  EXPECT_NEAR(enclosed_volume(s), 2.0, 1e-4);
}

TEST(Surface, RejectsUnknownExtension) {
  const Mesh m = build_mesh(generate_grid(1, 1, 1));
  const SurfaceMesh s = build_surface(m, boundary_selection(m));
  EXPECT_THROW(write_surface(s, "/tmp/x.stl"), std::invalid_argument);
  FaceSelection bad = boundary_selection(m);
  bad.ids.pop_back();
  EXPECT_THROW(build_surface(m, bad), std::invalid_argument);
}


TEST(SurfaceCli, ExportsTheBoundary) {
  ASSERT_TRUE(fs::exists(HBC_CLI)) << HBC_CLI;
  const fs::path dir = temp_dir();
  write_mesh(build_mesh(generate_grid(2, 3, 4)), (dir / "g.mesh").string());
  auto run = [](const std::string& args) { return test::run_cli(args).status; };
  const std::string in = "'" + (dir / "g.mesh").string() + "'";
  ASSERT_EQ(run("export-surface " + in + " -o '" + (dir / "g.ply").string() + "' --what boundary"), 0);
  const SurfaceMesh r = read_back(dir / "g.ply", true);
  EXPECT_EQ(r.n_faces(), 52u);
  EXPECT_EQ(r.n_vertices(), 54u);
  expect_closed(r);
  EXPECT_NEAR(enclosed_volume(r), 24.0, 1e-4);
  const auto hex = palette_color(static_cast<int>(CellType::Hex));
  for (auto fh : r.faces()) EXPECT_EQ(r.color(fh), SurfaceMesh::Color(hex[0], hex[1], hex[2]));

  EXPECT_EQ(run("export-surface " + in + " -o '" + (dir / "x.off").string() + "' --what volumes"), 2);  // not a --what
  EXPECT_EQ(run("export-surface " + in + " -o '" + (dir / "x.stl").string() + "'"), 1);
  EXPECT_EQ(run("export-surface " + in), 1);
  EXPECT_EQ(run("export-surface '" + (dir / "missing.mesh").string() + "' -o '" + (dir / "x.off").string() + "'"), 2);
  EXPECT_FALSE(fs::exists(dir / "x.off"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hbc

namespace hbc {
namespace {

// The structure surfaces: each patch / component / sheet is a piece of its own, oriented out of
// the owner it bounds. On a 3×3×3 grid with the centre cell split into pyramids every piece is a
// box (or a flat rectangle for patches), so every exported piece is welded: nothing unwelded.
TEST(StructureSurfaces, SplitGridPiecesAreClean) {
  const std::array<int32_t, 3> centre{1, 1, 1};
  const Mesh m = build_mesh(generate_split(3, 3, 3, SplitKind::Pyramids, std::span(&centre, 1)));
  AnalysisOptions opt;
  opt.wireframe = false;
  const Analysis a = analyze(m, opt);
  for (const FaceSelection& sel :
       {patch_selection(m, a.complex), component_selection(m, a.complex), sheet_selection(m, a.sheet_stage->sheets)}) {
    SurfaceStats st;
    const SurfaceMesh s = build_surface(m, sel, &st);
    EXPECT_EQ(st.unwelded_faces, 0);
    EXPECT_EQ(st.faces, static_cast<int64_t>(sel.faces.size()));
  }
  // Components: 26 boxes + 6 pyramids, each closed: faces = sum over components of their faces.
  const FaceSelection comps = component_selection(m, a.complex);
  EXPECT_EQ(comps.faces.size(), 26u * 6u + 6u * 5u);
}

}  // namespace
}  // namespace hbc
