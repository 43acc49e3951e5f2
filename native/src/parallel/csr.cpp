#include "hbc/csr.hpp"

#include "parallel/parallel.hpp"

namespace hbc {

// The counting sort is written once, in parallel.hpp; these are its one-thread forms for callers
// without a thread count.

Csr<int32_t> transpose(const Csr<int32_t>& a, size_t ncols) {
  return detail::transpose(a, ncols, Threads{.count = 1});
}

Csr<int32_t> group_by(std::span<const int32_t> keys, size_t nkeys) {
  return detail::group_by_key(keys.size(), nkeys, Threads{.count = 1}, [&](size_t i) { return keys[i]; });
}

}  // namespace hbc
