#include "platform/huge_pages.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace hbc::detail {

namespace {

// HBC_HUGE_PAGES=0 leaves the kernel's default paging: the benchmark compares the two settings in
// cold processes (docs/performance.md), since whether the advice pays depends on the machine.
bool advice_wanted() {
  const char* env = std::getenv("HBC_HUGE_PAGES");
  return env == nullptr || std::strcmp(env, "0") != 0;
}

}  // namespace

void advise_huge_pages(const void* p, size_t bytes) {
  if (!advice_wanted()) return;
  constexpr uintptr_t kHuge = uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kHuge - 1);
#if defined(MADV_HUGEPAGE)
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)begin;
  (void)end;
#endif
}

}  // namespace hbc::detail
