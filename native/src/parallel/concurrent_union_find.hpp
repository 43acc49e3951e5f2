#pragma once
// Union-find over 0..n-1 that several threads may unite into at once. A root is only ever linked
// below a lower root (by compare-exchange), so every parent is at most its child and each class's
// root is its lowest member, whatever the order of the unions: class ids taken from the roots do
// not depend on the number of threads.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <vector>

#include "hbc/csr.hpp"
#include "parallel/parallel.hpp"
#include "platform/atomic_ref.hpp"

namespace hbc::detail {

class ConcurrentUnionFind {
 public:
  ConcurrentUnionFind(size_t n, const Threads& par) {
    resize_touched(parent_, n, par);  // the pages faulted in by every thread, not by resize alone
    parallel_ranges(n, par, [&](size_t b, size_t e, int) { std::iota(parent_.begin() + b, parent_.begin() + e, static_cast<int32_t>(b)); });
  }
  int32_t find(int32_t x) {
    for (;;) {
      const int32_t p = at(x).load(std::memory_order_acquire);
      if (p == x) return x;
      const int32_t gp = at(p).load(std::memory_order_acquire);
      // Path halving: x is no root, and gp is an ancestor of x for good, so any thread may store it.
      if (gp != p) at(x).store(gp, std::memory_order_release);
      x = p;
    }
  }
  void unite(int32_t a, int32_t b) {
    for (;;) {
      a = find(a);
      b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      int32_t expected = a;
      if (at(a).compare_exchange_strong(expected, b, std::memory_order_acq_rel)) return;
    }
  }
  // The table itself (once no thread unites any more): parents at most their children, roots
  // their own parents.
  std::vector<int32_t>& parents() { return parent_; }

 private:
  ::hbc::detail::atomic_ref<int32_t> at(int32_t x) { return ::hbc::detail::atomic_ref<int32_t>(parent_[static_cast<size_t>(x)]); }
  std::vector<int32_t> parent_;
};

// The classes of the elements 0..n-1 that `take` accepts, numbered by their lowest element (their
// root): label[x] = class (-1 when not taken), and one row of increasing members per class.
// The labels are written over the union-find's own table, which is handed over to `label` (the
// union-find is spent): at 10^7 elements a second table of n ids is 40-120 MB of fresh pages,
// which the kernel zeroes at under 1 GB/s here.
template <class Take>
void number_classes(ConcurrentUnionFind& uf, size_t n, const Threads& par, Take take,
                             std::vector<int32_t>& label, Csr<int32_t>& groups) {
  std::vector<int32_t>& p = uf.parents();
  const size_t nr = static_cast<size_t>(range_count(n, par));
  std::vector<int32_t> roots(nr + 1, 0);
  // Every member linked straight to its root (a root is an ancestor: other threads' finds stay
  // right), roots counted per range.
  parallel_ranges(n, par, [&](size_t b, size_t e, int r) {
    int32_t count = 0;
    for (size_t x = b; x < e; ++x) {
      if (!take(x)) continue;
      const int32_t root = uf.find(static_cast<int32_t>(x));
      if (root == static_cast<int32_t>(x)) ++count;
      else ::hbc::detail::atomic_ref<int32_t>(p[x]).store(root, std::memory_order_relaxed);
    }
    roots[static_cast<size_t>(r) + 1] = count;
  });
  for (size_t r = 0; r < nr; ++r) roots[r + 1] += roots[r];
  // Then, each pass reading only entries no thread writes in it: roots get their class as
  // -2 - class (elements not taken -1), members their root's class, roots theirs decoded.
  parallel_ranges(n, par, [&](size_t b, size_t e, int r) {
    int32_t next = roots[static_cast<size_t>(r)];
    for (size_t x = b; x < e; ++x)
      if (!take(x)) p[x] = -1;
      else if (p[x] == static_cast<int32_t>(x)) p[x] = -2 - next++;
  });
  parallel_ranges(n, par, [&](size_t b, size_t e, int) {
    for (size_t x = b; x < e; ++x)
      if (p[x] >= 0) p[x] = -2 - p[static_cast<size_t>(p[x])];
  });
  parallel_ranges(n, par, [&](size_t b, size_t e, int) {
    for (size_t x = b; x < e; ++x)
      if (p[x] < -1) p[x] = -2 - p[x];
  });
  label = std::move(p);
  const auto nclasses = static_cast<size_t>(roots[nr]);
  groups = group_by_key(n, nclasses + 1, par, [&](size_t x) { return label[x] < 0 ? nclasses : static_cast<size_t>(label[x]); });
  groups.offsets.pop_back();
  groups.items.resize(static_cast<size_t>(groups.offsets.back()));
}

}  // namespace hbc::detail
