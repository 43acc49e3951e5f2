// libFuzzer harness: the first byte picks a reader, the rest is the file; whatever parses goes
// through the whole analyze() pipeline (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hbc::fuzz::load_and_analyze({reinterpret_cast<const char*>(data), size});
  return 0;
}
