// The XDMF3 reader: meshio's twins of tests/data/formats/real (make_xdmf_files.py: Mixed topologies
// with HDF5 or inline data, a temporal collection) cell for cell and by analysis against their MEDIT
// originals; single-type and dolfinx's second-order topologies and skipped lower-dimensional cells
// written here inline; malformed and truncated files naming the line or the HDF5 dataset.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hbc/analysis.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

namespace fs = std::filesystem;

const std::string kDir = HBC_FORMATS_DIR;

fs::path temp_file(const std::string& name) { return fs::temp_directory_path() / ("hbc_xdmf_" + std::to_string(::getpid()) + "_" + name); }

using test::read_error;
using test::write_bytes;

// An XDMF file of one Grid with inline data: the points (x y z each) and the topology's type and ids.
std::string xdmf(const std::string& points, int npoints, const std::string& type, const std::string& ids, int nids,
                 const std::string& geometry = "XYZ") {
  return "<?xml version=\"1.0\"?>\n<Xdmf Version=\"3.0\">\n<Domain>\n<Grid Name=\"g\">\n<Geometry GeometryType=\"" + geometry +
         "\">\n<DataItem Dimensions=\"" + std::to_string(npoints) + " 3\" Format=\"XML\">\n" + points +
         "\n</DataItem>\n</Geometry>\n<Topology TopologyType=\"" + type + "\">\n<DataItem Dimensions=\"" + std::to_string(nids) +
         "\" Format=\"XML\">\n" + ids + "\n</DataItem>\n</Topology>\n</Grid>\n</Domain>\n</Xdmf>\n";
}

// The unit tetrahedron and its six edge midpoints; 0 1 2 3 is upright in MEDIT's (and VTK's) order.
const std::string kTet10 = "0 0 0  1 0 0  0 1 0  0 0 1  .5 0 0  .5 .5 0  0 .5 0  0 0 .5  .5 0 .5  0 .5 .5";
const std::string kTetMedit = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";

#if HBC_TEST_MED
// meshio writes VTK's corner orders, which are MEDIT's: each twin reads point for point and cell for
// cell as its MEDIT original, with no defect and the same analysis. The time series' first step
// includes the mesh's grid through an xpointer: both are said in warnings.
TEST(XdmfRealTools, MeshioTwinsReadCellForCellAsTheirMedit) {
  const std::vector<std::pair<std::string, std::string>> twins = {{"real/slab_meshio.xdmf", "real/slab.mesh"},
                                                                  {"real/slab_inline.xdmf", "real/slab.mesh"},
                                                                  {"real/slab_series.xdmf", "real/slab.mesh"},
                                                                  {"real/mixed4_meshio.xdmf", "mixed4.mesh"}};
  for (const auto& [twin, original] : twins) {
    SCOPED_TRACE(twin);
    const MeshInput in = read_input(kDir + "/" + twin), ref = read_input(kDir + "/" + original);
    test::expect_same_cells(in, ref);
    EXPECT_TRUE(check_input(in).clean());
    const Mesh m = build_mesh(in), r = build_mesh(ref);
    test::expect_same_counts(compute_stats(m, analyze(m)), compute_stats(r, analyze(r)));
  }
  const MeshInput series = read_input(kDir + "/real/slab_series.xdmf");
  EXPECT_EQ(series.warnings, (std::vector<std::string>{"read the first of 2 grids of the temporal collection 'TimeSeries_meshio' ()",
                                                       "the grid's Topology and Geometry are those of grid 'mesh' (xi:include)"}));
}
#else
// Without HDF5 the inline twin reads as its MEDIT original and HDF data is refused saying why.
TEST(XdmfRealTools, WithoutHdf5InlineDataReadsAndHdfDataIsRefused) {
  test::expect_same_cells(read_input(kDir + "/real/slab_inline.xdmf"), read_input(kDir + "/real/slab.mesh"));
  // The WebAssembly core has none of these libraries: it sends the user to the desktop tool.
#ifdef __EMSCRIPTEN__
  const char* const kWhy = "need the desktop tool";
#else
  const char* const kWhy = "need HDF5: this hbc was built without it";
#endif
  EXPECT_NE(read_error(kDir + "/real/slab_meshio.xdmf").find(kWhy), std::string::npos);
}
#endif

// dolfinx's Tetrahedron_10 reads by its corners (the midpoints dropped, the corners numbered 0-3);
// in a Mixed topology a triangle (id 4) and a polyline of 2 nodes (2, then its count) are skipped
// and counted beside the tetrahedron (id 6).
TEST(Xdmf, SecondOrderByCornersAndMixedSkipsLowerCells) {
  const fs::path p = temp_file("t10.xdmf");
  write_bytes(p, xdmf(kTet10, 10, "Tetrahedron_10", "0 1 2 3 4 5 6 7 8 9", 10));
  test::expect_same_cells(read_input(p.string()), read_medit(kTetMedit, "tet.mesh"));
  write_bytes(p, xdmf("0 0 0  1 0 0  0 1 0  0 0 1", 4, "Mixed", "4 0 1 2  2 2 0 1  6 0 1 2 3", 13));
  const MeshInput in = read_input(p.string());
  test::expect_same_cells(in, read_medit(kTetMedit, "tet.mesh"));
  EXPECT_EQ(in.warnings, (std::vector<std::string>{"read past 0 point, 1 line and 1 surface element(s); only volume elements are cells"}));
  fs::remove(p);
}

TEST(Xdmf, MalformedFilesNameTheLineOrTheDataset) {
  const fs::path p = temp_file("bad.xdmf");
  const std::string tet = "0 0 0  1 0 0  0 1 0  0 0 1";
  // The xdmf() layout: Geometry on line 5, its DataItem on 6, Topology on 10, its DataItem on 11.
  write_bytes(p, xdmf(tet, 4, "Tetrahedron", "0 1 2 7", 4));
  EXPECT_NE(read_error(p).find(":11: expected node ids in [0, 3] in the Topology, found 7"), std::string::npos) << read_error(p);
  write_bytes(p, xdmf(tet, 4, "Tetrahedron", "0 1 2 3", 4, "XY"));
  EXPECT_NE(read_error(p).find(":5: expected GeometryType XYZ (three coordinates a point), found XY"), std::string::npos) << read_error(p);
  write_bytes(p, xdmf(tet, 4, "Mixed", "16 0 1 2 3", 5));
  EXPECT_NE(read_error(p).find(":11: expected an XDMF cell type id (4-9, 34-41, 48-50; 16 polyhedra are not read)"), std::string::npos) << read_error(p);
  write_bytes(p, xdmf(tet, 4, "Tetrahedron", "0 1 2", 4));
  EXPECT_NE(read_error(p).find(":11: expected 4 numbers in the DataItem (Dimensions), found 3"), std::string::npos) << read_error(p);
  write_bytes(p, xdmf(tet, 4, "Triangle", "0 1 2", 3));
  EXPECT_NE(read_error(p).find(":10: expected at least one volume cell"), std::string::npos) << read_error(p);
  write_bytes(p, "<Xdmf>\n<Domain>\n<Grid>\n</Domain>\n");
  EXPECT_NE(read_error(p).find(":4: expected well-formed XML"), std::string::npos) << read_error(p);
#if HBC_TEST_MED
  // HDF5 data: a missing file and a dataset of the wrong size name the dataset.
  std::string text = test::slurp(kDir + "/real/mixed4_meshio.xdmf");
  const std::string missing = std::string(text).replace(text.find("mixed4_meshio.h5:/data0"), 16, "none.h5");
  write_bytes(p, missing);
  EXPECT_NE(read_error(p).find("expected a readable HDF5 file in HDF5 dataset " + (p.parent_path() / "none.h5").string() + ":/data0"), std::string::npos) << read_error(p);
  const std::string wrong = std::string(text).replace(text.find("Dimensions=\"12 3\""), 17, "Dimensions=\"11 3\"");
  const fs::path h5 = p.parent_path() / "mixed4_meshio.h5";  // beside the .xdmf, as it names it
  fs::copy_file(kDir + "/real/mixed4_meshio.h5", h5, fs::copy_options::overwrite_existing);
  write_bytes(p, wrong);
  EXPECT_NE(read_error(p).find("expected 33 values (the DataItem's Dimensions), found 36, in HDF5 dataset " + h5.string() + ":/data0"),
            std::string::npos) << read_error(p);
  fs::remove(h5);
#endif
  // Every truncation of meshio's inline file: InputError, never a crash.
  const std::string bytes = test::slurp(kDir + "/real/slab_inline.xdmf");
  for (size_t cut = 0; cut < bytes.size(); cut += 1 + bytes.size() / 97) {
    write_bytes(p, std::string_view(bytes).substr(0, cut));
    EXPECT_NE(read_error(p), "") << "cut at " << cut;
  }
  fs::remove(p);
}

}  // namespace
}  // namespace hbc
