// libFuzzer harness: read_lsdyna (LS-DYNA keyword; includes fetched as a fixed small file) + build_mesh on arbitrary bytes (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::read_and_build(hbc::Format::LsDyna, {reinterpret_cast<const char*>(data), size});
  return 0;
}
