#include "hbc/csr.hpp"

namespace hbc {

Csr<int32_t> transpose(const Csr<int32_t>& a, size_t ncols) {
  Csr<int32_t> t;
  t.offsets.assign(ncols + 1, 0);
  for (int32_t c : a.items) ++t.offsets[static_cast<size_t>(c) + 1];
  for (size_t i = 0; i < ncols; ++i) t.offsets[i + 1] += t.offsets[i];
  t.items.resize(a.items.size());
  std::vector<int32_t> fill(t.offsets.begin(), t.offsets.end() - 1);
  for (size_t r = 0; r < a.rows(); ++r)
    for (int32_t c : a[r]) t.items[fill[c]++] = static_cast<int32_t>(r);
  return t;
}

}  // namespace hbc
