#pragma once
// Helpers shared by the core tests: where the real data is, and building meshes from text.
#include <gtest/gtest.h>

#include <filesystem>
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

}  // namespace hbc::test
