// The Salome MED reader: meshio's twins of tests/data/formats/real (make_med_files.py) cell for cell
// and by analysis against their MEDIT originals, in meshio's VTK corner order and in MED's own;
// files written here through HDF5's C library (the layout MED-fichier gives: /ENS_MAA/<mesh>/<step>
// with NOE/COO and MAI/<type>/NOD) for second-order and lower-dimensional elements, and malformed
// and truncated ones. A build without HDF5 checks the refusal.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hbc/analysis.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

#if HBC_TEST_MED
#include <hdf5.h>
#endif

namespace hbc {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) { return fs::temp_directory_path() / ("hbc_med_" + std::to_string(::getpid()) + "_" + name); }

using test::read_error;
using test::write_bytes;
using test::expect_refused_without_library;

#if HBC_TEST_MED
const std::string kDir = HBC_FORMATS_DIR;

// meshio writes VTK's (MEDIT's) corner order into MED files, mixed4_med_order.med holds MED's own
// (the mirror images): both read as the MEDIT original, point for point and cell for cell (the
// types come in MAI's name order HE8, PE6, PY5, TE4, MEDIT's section order here), with no defect;
// only meshio's files say that they were read in VTK's order.
TEST(MedRealTools, MeshioTwinsReadCellForCellAsTheirMedit) {
  const std::vector<std::pair<std::string, std::string>> twins = {
      {"real/slab_meshio.med", "real/slab.mesh"}, {"real/mixed4_meshio.med", "mixed4.mesh"}, {"real/mixed4_med_order.med", "mixed4.mesh"}};
  for (const auto& [twin, original] : twins) {
    SCOPED_TRACE(twin);
    const MeshInput in = read_input(kDir + "/" + twin), ref = read_input(kDir + "/" + original);
    test::expect_same_cells(in, ref);
    const bool vtk_order = twin.find("meshio") != std::string::npos;
    const std::string note = "volume elements stored in VTK's corner order (as meshio writes MED), not MED's: read as VTK's";
    EXPECT_EQ(std::count(in.warnings.begin(), in.warnings.end(), note), vtk_order ? 1 : 0);
    EXPECT_TRUE(check_input(in).clean());
    const Mesh m = build_mesh(in), r = build_mesh(ref);
    test::expect_same_counts(compute_stats(m, analyze(m)), compute_stats(r, analyze(r)));
  }
}

// A MED file as MED-fichier lays it out, written through HDF5: `points` (x y z each), and per
// element type its elements' 1-based nodes, element after element (stored by node column, int32).
struct MedBlock {
  std::string type;
  int per;
  std::vector<int> nodes;
  int64_t nbr = -1;  // the NBR attribute when not nodes.size() / per
};

void int_attr(hid_t at, const char* name, int64_t v) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(at, name, H5T_NATIVE_INT64, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_INT64, &v);
  H5Aclose(a);
  H5Sclose(space);
}

template <class T>
void dataset(hid_t at, const char* name, hid_t type, const std::vector<T>& v, int64_t nbr) {
  const hsize_t n = v.size();
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t d = H5Dcreate2(at, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (!v.empty()) H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  int_attr(d, "NBR", nbr);
  H5Dclose(d);
  H5Sclose(space);
}

void write_med(const fs::path& path, const std::vector<std::array<double, 3>>& points, const std::vector<MedBlock>& blocks, int64_t esp = 3) {
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  auto group = [](hid_t at, const char* name) { return H5Gcreate2(at, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT); };
  const hid_t ens = group(f, "ENS_MAA"), mesh = group(ens, "mesh");
  int_attr(mesh, "ESP", esp);
  int_attr(mesh, "DIM", esp);
  const hid_t step = group(mesh, "-0000000000000000001-0000000000000000001");
  const hid_t noe = group(step, "NOE"), mai = group(step, "MAI");
  std::vector<double> coo;
  for (size_t k = 0; k < 3; ++k)
    for (const auto& p : points) coo.push_back(p[k]);
  dataset(noe, "COO", H5T_NATIVE_DOUBLE, coo, static_cast<int64_t>(points.size()));
  for (const MedBlock& b : blocks) {
    const size_t n = b.nodes.size() / static_cast<size_t>(b.per);
    std::vector<int> by_column(b.nodes.size());
    for (size_t e = 0; e < n; ++e)
      for (size_t k = 0; k < static_cast<size_t>(b.per); ++k) by_column[k * n + e] = b.nodes[e * static_cast<size_t>(b.per) + k];
    const hid_t g = group(mai, b.type.c_str());
    dataset(g, "NOD", H5T_NATIVE_INT, by_column, b.nbr >= 0 ? b.nbr : static_cast<int64_t>(n));
    H5Gclose(g);
  }
  for (hid_t g : {mai, noe, step, mesh, ens}) H5Gclose(g);
  H5Fclose(f);
}

// The unit tetrahedron and its six edge midpoints (MED's T10: corners, then midpoints).
const std::vector<std::array<double, 3>> kTet10 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},   {.5, 0, 0},
                                                  {.5, .5, 0}, {0, .5, 0}, {0, 0, .5}, {.5, 0, .5}, {0, .5, .5}};

// MEDIT's upright tetrahedron 1 2 3 4 is MED's 1 3 2 4 (kTet: corners 1 and 2 swapped). As T10 its
// midpoints are dropped (the vertices left are the corners, renumbered 1-4); a quadrangle and a
// segment over its corners are skipped and counted in one warning.
TEST(Med, SecondOrderElementsByTheirCornersAndFacesCounted) {
  const fs::path p = temp_file("t10.med");
  write_med(p, kTet10, {{"T10", 10, {1, 3, 2, 4, 7, 6, 5, 8, 10, 9}}, {"QU4", 4, {1, 2, 3, 4}}, {"SE2", 2, {1, 2}}});
  const MeshInput in = read_input(p.string());
  const std::string medit = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";
  test::expect_same_cells(in, read_medit(medit, "tet.mesh"));
  EXPECT_EQ(std::count(in.warnings.begin(), in.warnings.end(),
                       "read past 0 point, 1 line and 1 surface element(s); only volume elements are cells"), 1);
  EXPECT_TRUE(check_input(in).clean());
  fs::remove(p);
}

TEST(Med, MalformedFilesNameTheFileTheDatasetAndWhatWasWrong) {
  const fs::path p = temp_file("bad.med");
  const std::string step = "/ENS_MAA/mesh/-0000000000000000001-0000000000000000001";
  const std::vector<std::array<double, 3>> corners(kTet10.begin(), kTet10.begin() + 4);
  write_med(p, corners, {{"TE4", 4, {1, 3, 2, 99}}});
  EXPECT_NE(read_error(p).find("node numbers in [1, 4] in " + step + "/MAI/TE4/NOD, found 99 for element 1"), std::string::npos) << read_error(p);
  write_med(p, corners, {{"XX4", 4, {1, 3, 2, 4}}});
  EXPECT_NE(read_error(p).find("a MED element type (HE8, PE6, PY5, TE4, H20, ..., QU4, TR3, SE2, PO1) in " + step + "/MAI, found XX4"), std::string::npos) << read_error(p);
  write_med(p, corners, {{"QU4", 4, {1, 2, 3, 4}}});
  EXPECT_NE(read_error(p).find("at least one volume element type"), std::string::npos) << read_error(p);
  write_med(p, corners, {{"TE4", 4, {1, 3, 2, 4}, 2}});  // NBR says 2 elements, NOD holds 1
  EXPECT_NE(read_error(p).find("8 values in dataset " + step + "/MAI/TE4/NOD, found 4"), std::string::npos) << read_error(p);
  write_med(p, corners, {{"TE4", 4, {1, 3, 2, 4}}}, 2);
  EXPECT_NE(read_error(p).find("a mesh in 3-dimensional space (attribute ESP of /ENS_MAA/mesh = 3), found 2"), std::string::npos) << read_error(p);
  write_bytes(p, "MeshVersionFormatted 2\n");
  EXPECT_NE(read_error(p).find("expected a MED file (HDF5; the file is no HDF5 file or is damaged)"), std::string::npos) << read_error(p);
  // Every truncation of meshio's file: InputError, never a crash.
  const std::string bytes = test::slurp(kDir + "/real/mixed4_med_order.med");
  for (size_t cut = 0; cut < bytes.size(); cut += 1 + bytes.size() / 97) {
    write_bytes(p, std::string_view(bytes).substr(0, cut));
    EXPECT_NE(read_error(p), "") << "cut at " << cut;
  }
  fs::remove(p);
}
#else
TEST(Med, ABuildWithoutHdf5ListsTheFormatAndRefusesItsFiles) {
  expect_refused_without_library(temp_file("any.med"), "\x89HDF\r\n\x1a\n", "MED", "HDF5");
  EXPECT_EQ(format_from_name("med"), Format::Med);
}
#endif

}  // namespace
}  // namespace hbc
