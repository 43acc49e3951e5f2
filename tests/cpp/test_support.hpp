#pragma once
// Helpers shared by the core tests: where the real data is, and building meshes from text.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <vector>
#include <string>
#include <string_view>
#include <tuple>

#include "hbc/analysis.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/io.hpp"
#include "hbc/mesh.hpp"

namespace hbc::test {

inline std::string data_dir() { return HBC_DATA_DIR; }
inline std::string data_path(const std::string& rel) { return data_dir() + "/" + rel; }

// Shared meshes of every reader and cell mix (hex-dominant, polyhedral, non-manifold), for the
// tests that compare one thread against several.
inline constexpr const char* kVariedMeshes[] = {
    "hexalab-edge-cone-rectification/armadillo_out.mesh", "cinolib/rockerarm.mesh",
    "hybrid-base-complex/twistcube_s.mesh", "cinolib/eight_voronoi.hedra",
    "hybrid-base-complex/cube_twist-comp.obj.HYBRID", "openvolumemesh/NonManifold.ovm",
    "openvolumemesh/Cylinder.ovmb"};

template <class T>
void expect_same_csr(const Csr<T>& a, const Csr<T>& b, const char* what) {
  EXPECT_EQ(a.offsets, b.offsets) << what;
  EXPECT_EQ(a.items, b.items) << what;
}

// Skips nothing silently: a missing data folder fails the test with a clear message.
#define HBC_REQUIRE_DATA(rel)                                                              \
  do {                                                                                     \
    if (!std::filesystem::exists(::hbc::test::data_path(rel)))                            \
      FAIL() << "real mesh data missing: " << ::hbc::test::data_path(rel)                  \
             << " (tests read ../shared/data; set -DHBC_DATA_DIR=... to point elsewhere)"; \
  } while (0)

// Signed volume of cell c of a reader's output, with each face loop as the cell sees it: positive
// when the loops face out of the cell. `in` holds a face soup (see with_face_soup).
inline double signed_volume(const MeshInput& in, size_t c) {
  EXPECT_TRUE(in.cell_shape.empty()) << "element cells: take with_face_soup of the reader's output";
  double vol = 0;
  for (int32_t hf : in.cells[c]) {
    auto loop = in.faces[static_cast<size_t>(hf / 2)];
    std::vector<int32_t> l(loop.begin(), loop.end());
    if (hf % 2) std::reverse(l.begin(), l.end());
    auto p = [&](size_t i, int a) { return in.points[3 * static_cast<size_t>(l[i]) + static_cast<size_t>(a)]; };
    for (size_t t = 1; t + 1 < l.size(); ++t)
      vol += p(0, 0) * (p(t, 1) * p(t + 1, 2) - p(t, 2) * p(t + 1, 1)) -
             p(0, 1) * (p(t, 0) * p(t + 1, 2) - p(t, 2) * p(t + 1, 0)) +
             p(0, 2) * (p(t, 0) * p(t + 1, 1) - p(t, 1) * p(t + 1, 0));
  }
  return vol / 6;
}

// Writes `bytes` to `p` as they are (the readers' tests make their files).
inline void write_bytes(const std::filesystem::path& p, std::string_view bytes) {
  std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The message of the InputError that reading `path` raises (naming that file), or "" when it reads.
inline std::string read_error(const std::filesystem::path& path) {
  try {
    read_input(path.string());
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    return e.what();
  }
  return "";
}

// A build without the library a format needs still lists the format and refuses its files (`bytes`
// written to `p`), saying which library it lacks; the WebAssembly core, which has none of them,
// sends the user to the desktop tool instead.
inline void expect_refused_without_library(const std::filesystem::path& p, std::string_view bytes, std::string_view what,
                                           [[maybe_unused]] std::string_view library) {
  write_bytes(p, bytes);
#ifdef __EMSCRIPTEN__
  const std::string why = std::string(what) + " files need the desktop tool";
#else
  const std::string why = std::string(what) + " files need " + std::string(library);
#endif
  const std::string got = read_error(p);
  EXPECT_NE(got.find(why), std::string::npos) << got;
  std::filesystem::remove(p);
}

inline Mesh load_data(const std::string& rel) { return load_mesh(data_path(rel)); }

// `mesh` renumbered by random permutations drawn from rng (vertices first, then cells): vertex v
// becomes vert[v], cell c becomes cell[c].
struct Renumbering {
  std::vector<int32_t> vert, cell;
  Mesh mesh;
};
inline Renumbering random_renumbering(const Mesh& m, std::mt19937& rng) {
  Renumbering out{std::vector<int32_t>(m.num_vertices()), std::vector<int32_t>(m.num_cells()), {}};
  std::iota(out.vert.begin(), out.vert.end(), 0);
  std::iota(out.cell.begin(), out.cell.end(), 0);
  std::shuffle(out.vert.begin(), out.vert.end(), rng);
  std::shuffle(out.cell.begin(), out.cell.end(), rng);
  out.mesh = build_mesh(renumbered(m, out.vert, out.cell));
  return out;
}

// The derived incidences of a Mesh as values, for assertions.
inline std::vector<int32_t> cell_verts(const Mesh& m, size_t c) {
  std::vector<int32_t> v;
  cell_vertices(m, c, v);
  return v;
}
inline std::vector<int32_t> cell_edge_ids(const Mesh& m, size_t c) {
  std::vector<int32_t> v;
  cell_edges(m, c, v);
  return v;
}
inline EdgeFan fan_of(const Mesh& m, size_t e) {
  EdgeFan f;
  edge_fan(m, static_cast<int32_t>(e), f);
  return f;
}
// The edge joining vertices a and b, or -1.
inline int32_t edge_between(const Mesh& m, int32_t a, int32_t b) {
  for (size_t e = 0; e < m.num_edges(); ++e)
    if (m.edge_verts[e] == std::array<int32_t, 2>{std::min(a, b), std::max(a, b)}) return static_cast<int32_t>(e);
  return -1;
}

// Every array of two meshes is equal, numbering included, and so is every incidence derived from
// them (edge fans in their order, the vertices and edges of each cell); with `counts`, also what
// was dropped and the warnings.
inline void expect_same_mesh(const Mesh& a, const Mesh& b, bool counts = true) {
#define HBC_SAME(x) EXPECT_EQ(a.x, b.x) << #x
  HBC_SAME(points); HBC_SAME(edge_verts);
  HBC_SAME(face_verts.offsets); HBC_SAME(face_verts.items); HBC_SAME(face_edge_ids); HBC_SAME(face_cells);
  HBC_SAME(cell_faces.offsets); HBC_SAME(cell_faces.items); HBC_SAME(cell_face_flip);
  HBC_SAME(fan_start); HBC_SAME(odd_fan_faces.offsets); HBC_SAME(odd_fan_faces.items); HBC_SAME(valence_small);
  HBC_SAME(vert_boundary); HBC_SAME(edge_boundary); HBC_SAME(face_boundary);
  HBC_SAME(cell_type); HBC_SAME(vert_non_manifold);
  if (counts) {
    HBC_SAME(dropped_faces); HBC_SAME(dropped_edges); HBC_SAME(warnings);
  }
#undef HBC_SAME
  if (a.num_edges() != b.num_edges() || a.num_cells() != b.num_cells()) return;
  for (size_t e = 0; e < a.num_edges(); ++e) {
    const EdgeFan fa = fan_of(a, e), fb = fan_of(b, e);
    ASSERT_EQ(fa.faces, fb.faces) << "edge " << e;
    ASSERT_EQ(fa.cells, fb.cells) << "edge " << e;
  }
  for (size_t c = 0; c < a.num_cells(); ++c) {
    ASSERT_EQ(cell_verts(a, c), cell_verts(b, c)) << "cell " << c;
    ASSERT_EQ(cell_edge_ids(a, c), cell_edge_ids(b, c)) << "cell " << c;
  }
}

// The same points, faces and cells (numbering included) in two reader or generator outputs.
inline void expect_same_cells(const MeshInput& a, const MeshInput& b) {
  EXPECT_EQ(a.cell_shape, b.cell_shape);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.faces.offsets, b.faces.offsets);
  EXPECT_EQ(a.faces.items, b.faces.items);
  EXPECT_EQ(a.cells.offsets, b.cells.offsets);
  EXPECT_EQ(a.cells.items, b.cells.items);
}

// Stage outputs whose meaning does not depend on numbering, compared between two analyses of the
// same mesh (renumbered, or read from another format). Counts that depend on a "lowest index"
// choice are left out (see docs/reliability.md): subsheet counts and the simplified wireframe.
inline void expect_same_counts(const Stats& a, const Stats& b) {
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.hex_cells, b.hex_cells);
  EXPECT_EQ(a.singular_edges, b.singular_edges);
  EXPECT_EQ(a.singularities, b.singularities);
  EXPECT_EQ(a.pseudo_singular_edges, b.pseudo_singular_edges);
  EXPECT_EQ(a.non_manifold_edges, b.non_manifold_edges);
  EXPECT_EQ(a.singular_vertices, b.singular_vertices);
  EXPECT_EQ(a.components, b.components);
  EXPECT_EQ(a.hex_components, b.hex_components);
  EXPECT_EQ(a.patches, b.patches);
  EXPECT_EQ(a.curves, b.curves);
  EXPECT_EQ(a.corners, b.corners);
  EXPECT_EQ(a.self_adjacent_faces, b.self_adjacent_faces);
  EXPECT_EQ(a.sheets, b.sheets);
  EXPECT_EQ(a.sheets_perfect, b.sheets_perfect);
  EXPECT_EQ(a.sheets_type1, b.sheets_type1);
  EXPECT_EQ(a.sheets_type2, b.sheets_type2);
  EXPECT_EQ(a.sheets_type3, b.sheets_type3);
  EXPECT_EQ(a.vsg_edges, b.vsg_edges);
  EXPECT_EQ(a.wireframe_edges, b.wireframe_edges);
}

// The same component partition in the base complex `a` of a mesh and `b` of its renumbering
// (cell c became cell[c]): c and d share a component in a iff cell[c] and cell[d] do in b.
inline void expect_same_partition(const BaseComplex& a, const BaseComplex& b, const std::vector<int32_t>& cell) {
  ASSERT_EQ(a.num_components(), b.num_components());
  const size_t ncomp = a.num_components();
  std::vector<int32_t> fwd(ncomp, -1), back(ncomp, -1);
  for (size_t c = 0; c < cell.size(); ++c) {
    const int32_t ka = a.cell_component[c], kb = b.cell_component[static_cast<size_t>(cell[c])];
    if (fwd[ka] < 0 && back[kb] < 0) fwd[ka] = kb, back[kb] = ka;
    ASSERT_EQ(fwd[ka], kb) << "cell " << c;
    ASSERT_EQ(back[kb], ka) << "cell " << c;
  }
}

// Every array of two views, the whole-mesh adjacency of a proper region's included.
// Equal in every member, through the result structs' defaulted operator==, so that a member added
// to a struct later is compared too. gtest cannot print these structs: the message names the part.
template <class T>
void expect_same(const T& a, const T& b, const char* what) {
  EXPECT_TRUE(a == b) << what << " differs";
}

inline void expect_same_view(const CellComplex& a, const CellComplex& b) { expect_same(a, b, "the view"); }

}  // namespace hbc::test
