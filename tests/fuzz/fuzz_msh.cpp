// libFuzzer harness: read_msh (Gmsh 2.2 / 4.1, ASCII or binary) + build_mesh on arbitrary bytes (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::read_and_build(hbc::Format::Msh, {reinterpret_cast<const char*>(data), size});
  return 0;
}
