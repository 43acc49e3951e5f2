#pragma once
// The one version of hbc: library, CLI (`hbc --version`), Python package (hbc.__version__) and
// Blender add-on all report the project(VERSION ...) of the top-level CMakeLists.txt, which the
// build writes into hbc/version_number.hpp (HBC_VERSION, HBC_VERSION_MAJOR/_MINOR/_PATCH).
#include "hbc/version_number.hpp"

namespace hbc {

// "MAJOR.MINOR.PATCH", the same string as HBC_VERSION.
const char* version();

}  // namespace hbc
