#pragma once
// The process's CPU seconds so far (every thread), user and system apart, and its minor page
// faults, for the load benchmarks: on a VM the kernel's zeroing of fresh pages can cost more than
// a step's own work, at a cost per page that the host sets, so the two are reported apart.
// Header-only and outside the library: scripts/bench.sh compiles bench_load.cpp against a
// baseline build as well.
#include <sys/resource.h>

namespace hbc_bench {

struct Usage {
  double user = 0, sys = 0, faults = 0;
  double cpu() const { return user + sys; }
};

inline Usage usage_now() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  auto sec = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return {sec(u.ru_utime), sec(u.ru_stime), static_cast<double>(u.ru_minflt)};
}

}  // namespace hbc_bench
