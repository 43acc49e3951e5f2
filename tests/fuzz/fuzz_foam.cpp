// libFuzzer harness: read_foam + build_mesh on arbitrary bytes, cut into the four polyMesh files
// (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::read_and_build(hbc::Format::Foam, {reinterpret_cast<const char*>(data), size});
  return 0;
}
