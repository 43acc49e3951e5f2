// libFuzzer harness: read_ugrid (AFLR3 UGRID, the first byte picking the encoding (ASCII, b8, lb8, r8, lr8)) + build_mesh on arbitrary bytes (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::read_and_build(hbc::Format::Ugrid, {reinterpret_cast<const char*>(data), size});
  return 0;
}
