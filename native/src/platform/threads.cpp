#include "hbc/threads.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace hbc {

int resolve_threads(const Threads& threads) {
  if (threads.count > 0) return threads.count;
  if (const char* env = std::getenv("HBC_THREADS")) {
    int n = 0;
    const char* end = env + std::strlen(env);
    if (std::from_chars(env, end, n).ptr == end && n > 0) return n;
  }
#if defined(HBC_SINGLE_THREADED)
  return 1;  // an explicit count above still splits the ranges as it would with threads
#else
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
#endif
}

Threads resolved(const Threads& threads) {
  Threads r = threads;
  r.count = resolve_threads(threads);
  r.grain = std::max(1, threads.grain);
  return r;
}

}  // namespace hbc
