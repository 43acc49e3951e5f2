// The platform layer's choices that a user can observe from outside the results.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "platform/huge_pages.hpp"

namespace {

#if defined(__linux__)
// The VmFlags line of the mapping holding address p in /proc/self/smaps ("hg" marks a range the
// process advised MADV_HUGEPAGE), or nothing when no mapping holds it.
std::optional<std::string> vm_flags_at(const void* p) {
  const auto at = reinterpret_cast<uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return std::nullopt;
}

bool advised_huge(const std::vector<int32_t>& v) {
  // The advice covers the whole 2 MiB pages inside the array: look at the first one.
  constexpr uintptr_t kHuge = uintptr_t{2} << 20;
  const auto first = (reinterpret_cast<uintptr_t>(v.data()) + kHuge - 1) & ~(kHuge - 1);
  const auto flags = vm_flags_at(reinterpret_cast<const void*>(first));
  EXPECT_TRUE(flags.has_value()) << "no mapping holds the array";
  return flags && flags->find(" hg") != std::string::npos;
}

// Restores HBC_HUGE_PAGES as the test found it.
struct SavedEnv {
  std::optional<std::string> value;
  SavedEnv() {
    if (const char* v = std::getenv("HBC_HUGE_PAGES")) value = v;
  }
  ~SavedEnv() {
    if (value) ::setenv("HBC_HUGE_PAGES", value->c_str(), 1);
    else ::unsetenv("HBC_HUGE_PAGES");
  }
};

// The 2 MiB page advice cost a third to a half of a cold run on the project's machine kind and
// won 4-5 % elsewhere (docs/performance.md), so a user gets the kernel's own paging unless they
// set HBC_HUGE_PAGES=1. The mapping's flags in /proc/self/smaps show whether the loader's arrays
// were advised: 32 MiB, so the array has its own mapping with whole 2 MiB pages inside.
TEST(Platform, HugePageAdviceIsOffUnlessAskedFor) {
  SavedEnv saved;
  constexpr size_t kCount = size_t{8} << 20;
  for (const char* setting : {static_cast<const char*>(nullptr), "", "0", "1"}) {
    if (setting) ::setenv("HBC_HUGE_PAGES", setting, 1);
    else ::unsetenv("HBC_HUGE_PAGES");
    std::vector<int32_t> v;
    hbc::detail::resize_huge(v, kCount, int32_t{0});
    const bool want = setting != nullptr && std::string(setting) == "1";
    EXPECT_EQ(advised_huge(v), want) << "HBC_HUGE_PAGES=" << (setting ? setting : "(unset)");
  }
}
#endif

}  // namespace
