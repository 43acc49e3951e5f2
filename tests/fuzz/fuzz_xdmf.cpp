// libFuzzer harness: read_xdmf (XDMF3: the XML with inline data; HDF references resolve from the working folder) + build_mesh on arbitrary bytes
// (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::read_and_build(hbc::Format::Xdmf, {reinterpret_cast<const char*>(data), size});
  return 0;
}
