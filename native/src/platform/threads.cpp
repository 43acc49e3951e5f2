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
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

Threads resolved(const Threads& threads) {
  Threads r = threads;
  r.count = resolve_threads(threads);
  r.grain = std::max(1, threads.grain);
  return r;
}

}  // namespace hbc
