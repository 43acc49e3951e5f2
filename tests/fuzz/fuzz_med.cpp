// libFuzzer harness: read_med (Salome MED through HDF5, from memory) + build_mesh on arbitrary bytes
// (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::read_and_build(hbc::Format::Med, {reinterpret_cast<const char*>(data), size});
  return 0;
}
