// libFuzzer harness: join_foam_processors + build_mesh on arbitrary bytes, cut into up to four
// processors' polyMesh, addressing and boundary files (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::join_and_build({reinterpret_cast<const char*>(data), size});
  return 0;
}
