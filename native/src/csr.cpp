#include "hbc/csr.hpp"

namespace hbc {
namespace {

// Row offsets of a counting sort: how many items fall into each of n rows, then prefix sums.
template <class KeyOf>
std::vector<int32_t> counted_offsets(size_t nitems, size_t nrows, KeyOf&& key_of) {
  std::vector<int32_t> offsets(nrows + 1, 0);
  for (size_t i = 0; i < nitems; ++i) ++offsets[static_cast<size_t>(key_of(i)) + 1];
  for (size_t r = 0; r < nrows; ++r) offsets[r + 1] += offsets[r];
  return offsets;
}

}  // namespace

Csr<int32_t> transpose(const Csr<int32_t>& a, size_t ncols) {
  Csr<int32_t> t;
  t.offsets = counted_offsets(a.items.size(), ncols, [&](size_t i) { return a.items[i]; });
  t.items.resize(a.items.size());
  std::vector<int32_t> fill(t.offsets.begin(), t.offsets.end() - 1);
  for (size_t r = 0; r < a.rows(); ++r)
    for (int32_t c : a[r]) t.items[fill[c]++] = static_cast<int32_t>(r);
  return t;
}

Csr<int32_t> group_by(std::span<const int32_t> keys, size_t nkeys) {
  Csr<int32_t> g;
  g.offsets = counted_offsets(keys.size(), nkeys, [&](size_t i) { return keys[i]; });
  g.items.resize(keys.size());
  std::vector<int32_t> fill(g.offsets.begin(), g.offsets.end() - 1);
  for (size_t i = 0; i < keys.size(); ++i) g.items[fill[keys[i]]++] = static_cast<int32_t>(i);
  return g;
}

}  // namespace hbc
