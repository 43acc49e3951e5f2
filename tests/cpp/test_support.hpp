#pragma once
// Helpers shared by the core tests: where the real data is, and building meshes from text.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>
#include <vector>
#include <string>

#include "hbc/io.hpp"
#include "hbc/mesh.hpp"

namespace hbc::test {

inline std::string data_dir() { return HBC_DATA_DIR; }
inline std::string data_path(const std::string& rel) { return data_dir() + "/" + rel; }

// Skips nothing silently: a missing data folder fails the test with a clear message.
#define HBC_REQUIRE_DATA(rel)                                                              \
  do {                                                                                     \
    if (!std::filesystem::exists(::hbc::test::data_path(rel)))                            \
      FAIL() << "real mesh data missing: " << ::hbc::test::data_path(rel)                  \
             << " (tests read ../shared/data; set -DHBC_DATA_DIR=... to point elsewhere)"; \
  } while (0)

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

// The same points, faces and cells (numbering included) in two reader or generator outputs.
inline void expect_same_cells(const MeshInput& a, const MeshInput& b) {
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.faces.offsets, b.faces.offsets);
  EXPECT_EQ(a.faces.items, b.faces.items);
  EXPECT_EQ(a.cells.offsets, b.cells.offsets);
  EXPECT_EQ(a.cells.items, b.cells.items);
}

}  // namespace hbc::test
