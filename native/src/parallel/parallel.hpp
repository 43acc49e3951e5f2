#pragma once
// Splitting a loop over [0, n) into one contiguous range per thread. Every range writes only its
// own outputs, so results do not depend on the number of threads; the caller combines per-range
// results in range order.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <span>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "hbc/csr.hpp"
#include "hbc/threads.hpp"
#include "platform/huge_pages.hpp"
#include "platform/worker_pool.hpp"
#include "platform/atomic_ref.hpp"

namespace hbc::detail {

// Sets flag i of v from any thread: threads only ever store the same value into a shared flag,
// through relaxed atomic stores, so the result does not depend on which thread wrote it.
template <class Index>
void set_flag(std::vector<uint8_t>& v, Index i, uint8_t value = 1) {
  ::hbc::detail::atomic_ref<uint8_t>(v[static_cast<size_t>(i)]).store(value, std::memory_order_relaxed);
}

// Number of ranges parallel_ranges will use for n items: one per thread, each of at least
// par.grain items.
inline int range_count(size_t n, const Threads& par) {
  const size_t by_size = n / static_cast<size_t>(std::max(1, par.grain));
  const size_t t = par.count < 1 ? 1 : static_cast<size_t>(par.count);
  return static_cast<int>(std::max<size_t>(1, std::min(t, by_size)));
}

// Calls f(begin, end, r) for ranges r = 0 .. range_count(n, par)-1 covering [0, n) in order,
// range 0 on the calling thread, the others on par.pool's workers when it has them free, else on
// threads of their own. An exception thrown in a range is rethrown after all ranges end;
// when several throw, the one of the lowest range wins (the first bad element in order, when each
// range stops at its first).
template <class F>
void parallel_ranges(size_t n, const Threads& par, F&& f) {
  const int nr = range_count(n, par);
  std::vector<std::exception_ptr> errors(static_cast<size_t>(nr));
  auto run = [&](int r) {
    const size_t b = n * static_cast<size_t>(r) / static_cast<size_t>(nr);
    const size_t e = n * static_cast<size_t>(r + 1) / static_cast<size_t>(nr);
    try {
      f(b, e, r);
    } catch (...) {
      errors[static_cast<size_t>(r)] = std::current_exception();
    }
  };
  if (nr == 1 || !kThreadsAvailable) {
    // Without threads (HBC_SINGLE_THREADED) the same ranges run in order: same results.
    for (int r = 0; r < nr; ++r) run(r);
  } else if (!par.pool || !par.pool->run(nr, run)) {
    std::vector<std::thread> pool;
    pool.reserve(static_cast<size_t>(nr - 1));
    for (int r = 1; r < nr; ++r) pool.emplace_back(run, r);
    run(0);
    for (auto& t : pool) t.join();
  }
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

// Where each of parallel_ranges' ranges of [0, n) starts writing when the ranges write their
// outputs one after another: count(b, e) returns a range's totals, and entry r of the result sums
// those of the ranges before r (range_count(n, par) + 1 entries, the last being the total). The
// caller sizes its outputs from the total, then fills them by parallel_ranges over the same n
// and par, range r from entry r. T is a number or a struct of them with +=.
template <class T, class Count>
std::vector<T> range_starts(size_t n, const Threads& par, Count&& count) {
  const auto nr = static_cast<size_t>(range_count(n, par));
  std::vector<T> at(nr + 1, T{});
  parallel_ranges(n, par, [&](size_t b, size_t e, int r) {
    at[static_cast<size_t>(r) + 1] = count(b, e);  // counted locally by count: the entries share cache lines
  });
  for (size_t r = 0; r < nr; ++r) at[r + 1] += at[r];
  return at;
}

// How many i in [b, e) satisfy take(i).
template <class Take>
size_t count_in(size_t b, size_t e, Take& take) {
  size_t k = 0;
  for (size_t i = b; i < e; ++i) k += take(i) ? 1 : 0;
  return k;
}

// How many i < n satisfy take(i), counted by ranges.
template <class Take>
size_t count_where(size_t n, const Threads& par, Take&& take) {
  return range_starts<size_t>(n, par, [&](size_t b, size_t e) { return count_in(b, e, take); }).back();
}

// The ids i < n for which take(i) holds, in increasing order: ranges count theirs, then write them
// from where range_starts puts them (a serial scan over the tens of MB of a 10^7-cell mesh's
// edge flags took longer than the pass that set them).
template <class Take>
std::vector<int32_t> ids_where(size_t n, const Threads& par, Take&& take) {
  const std::vector<size_t> at = range_starts<size_t>(n, par, [&](size_t b, size_t e) { return count_in(b, e, take); });
  std::vector<int32_t> out(at.back());
  parallel_ranges(n, par, [&](size_t b, size_t e, int r) {
    size_t k = at[static_cast<size_t>(r)];
    for (size_t i = b; i < e; ++i)
      if (take(i)) out[k++] = static_cast<int32_t>(i);
  });
  return out;
}

// par with another grain (and the same threads and pool).
inline Threads with_grain(const Threads& par, int grain) {
  Threads p = par;
  p.grain = grain;
  return p;
}

// Runs independent jobs, one per thread when threads > 1.
template <class... F>
void parallel_invoke(const Threads& par, F&&... jobs) {
  if (par.count <= 1 || !kThreadsAvailable) {
    (jobs(), ...);
    return;
  }
  std::vector<std::exception_ptr> errors(sizeof...(F));
  std::vector<std::thread> pool;
  size_t i = 0;
  auto start = [&](auto& job) {
    const size_t k = i++;
    pool.emplace_back([&job, &errors, k] {
      try {
        job();
      } catch (...) {
        errors[k] = std::current_exception();
      }
    });
  };
  (start(jobs), ...);
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}


// Faults in the fresh pages of [p, p + bytes) from every thread at once. A first touch costs
// more than the write itself (the kernel zeroes the page, 0.6-0.8 s per GB here), and
// vector::resize would have it all happen on the calling thread.
inline void touch_pages(void* p, size_t bytes, const Threads& par) {
  constexpr size_t kPage = 4096;
  const size_t npages = bytes / kPage;
  if (par.count <= 1 || !kThreadsAvailable || npages < 1024) return;  // under 4 MB: not worth a thread
  auto* b = static_cast<volatile char*>(p);
  parallel_ranges(npages, with_grain(par, 256), [&](size_t pb, size_t pe, int) {
    for (size_t i = pb; i < pe; ++i) b[i * kPage] = 0;
  });
}

// resize_huge / assign_huge with the pages faulted in by every thread (see touch_pages).
template <class T>
void resize_touched(std::vector<T>& v, size_t n, const Threads& par, const T& value = T()) {
  reserve_huge(v, n);
  if (n > v.size()) touch_pages(v.data() + v.size(), (n - v.size()) * sizeof(T), par);
  resize_with(v, n, value);
}
template <class T>
void assign_touched(std::vector<T>& v, size_t n, const T& value, const Threads& par) {
  if (n > v.capacity()) std::vector<T>().swap(v);
  reserve_huge(v, n);
  touch_pages(v.data(), n * sizeof(T), par);
  v.assign(n, value);
}

// A scratch array of n trivially copyable T that the caller fills entirely: not value-initialised,
// unlike a std::vector, whose resize zeroes every byte on the calling thread alone (a sequential
// pass over tens of MB, as long as the parallel fill that follows); on advised huge pages whose
// first touch every thread shares.
template <class T>
class RawArray {
  static_assert(std::is_trivially_default_constructible_v<T>);

 public:
  RawArray() = default;
  RawArray(size_t n, const Threads& par) : data_(n ? new T[n] : nullptr), size_(n) {
    advise_huge_pages(data_.get(), n * sizeof(T));
    touch_pages(data_.get(), n * sizeof(T), par);
  }
  size_t size() const { return size_; }
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }

 private:
  std::unique_ptr<T[]> data_;
  size_t size_ = 0;
};

// Rows of item ids as group_units_by_key makes them, over a RawArray: for the load's scratch
// groupings, which are read and dropped within their step.
struct RawRows {
  std::vector<int32_t> offsets{0};
  RawArray<int32_t> items;
  size_t rows() const { return offsets.size() - 1; }
  std::span<const int32_t> operator[](size_t r) const {
    return {items.data() + offsets[r], static_cast<size_t>(offsets[r + 1] - offsets[r])};
  }
};

// Turns the counts of each range of units per key (next[r][k]) into where range r writes its
// first value of key k, keys in order and ranges in order within a key, and sets offsets[k] to
// the first position of key k (offsets has nkeys + 1 entries). Blocks of keys in parallel: their
// totals first, then each block's positions from its start. Returns the total.
inline int32_t count_positions(std::vector<std::vector<int32_t>>& next, std::vector<int32_t>& offsets, const Threads& par) {
  const size_t nkeys = offsets.size() - 1;
  std::vector<int64_t> start(static_cast<size_t>(range_count(nkeys, par)) + 1, 0);
  parallel_ranges(nkeys, par, [&](size_t b, size_t e, int q) {
    int64_t total = 0;
    for (size_t k = b; k < e; ++k)
      for (const auto& count : next) total += count[k];
    start[static_cast<size_t>(q) + 1] = total;
  });
  for (size_t q = 1; q < start.size(); ++q) start[q] += start[q - 1];
  parallel_ranges(nkeys, par, [&](size_t b, size_t e, int q) {
    auto pos = static_cast<int32_t>(start[static_cast<size_t>(q)]);
    for (size_t k = b; k < e; ++k) {
      offsets[k] = pos;
      for (auto& count : next) {
        const int32_t c = count[k];
        count[k] = pos;
        pos += c;
      }
    }
  });
  offsets[nkeys] = static_cast<int32_t>(start.back());
  return offsets[nkeys];
}

// Counting sort of values by key: row k lists the values emitted with key k, in the order they
// were emitted. each(u, emit) calls emit(key, value) for the entries of unit u, key in
// [0, nkeys); units are visited in order. Each range of units counts into its own table
// (ranges x nkeys ints) and fills its own share of every row, so the result does not depend on
// the number of threads. The entries are found twice instead of being kept in an array.
// Rows is Csr<int32_t>, or RawRows for scratch rows.
template <class Rows = Csr<int32_t>, class Each>
Rows group_values_by_key(size_t nunits, size_t nkeys, const Threads& par, Each&& each) {
  const int nr = range_count(nunits, par);
  std::vector<std::vector<int32_t>> next(static_cast<size_t>(nr));
  parallel_ranges(nunits, par, [&](size_t b, size_t e, int r) {
    std::vector<int32_t>& count = next[static_cast<size_t>(r)];
    count.assign(nkeys, 0);
    for (size_t u = b; u < e; ++u) each(u, [&](int32_t key, int32_t) { ++count[static_cast<size_t>(key)]; });
  });
  Rows g;
  resize_touched(g.offsets, nkeys + 1, par);
  const int32_t pos = count_positions(next, g.offsets, par);
  if constexpr (std::is_same_v<Rows, RawRows>) g.items = RawArray<int32_t>(static_cast<size_t>(pos), par);
  else resize_touched(g.items, static_cast<size_t>(pos), par);
  parallel_ranges(nunits, par, [&](size_t b, size_t e, int r) {
    std::vector<int32_t>& at = next[static_cast<size_t>(r)];
    for (size_t u = b; u < e; ++u)
      each(u, [&](int32_t key, int32_t value) { g.items[static_cast<size_t>(at[static_cast<size_t>(key)]++)] = value; });
  });
  return g;
}

// The transpose of `a` through maps: row j lists row_of(r) for every row r of `a` that names a
// column c with col_of(c) == j, rows r in increasing order; rows and columns mapped to -1 are
// left out. With increasing maps and rows of `a` sorted and distinct, the rows come out sorted and
// distinct.
template <class RowOf, class ColOf>
Csr<int32_t> transpose_mapped(const Csr<int32_t>& a, size_t ncols, const Threads& par, RowOf&& row_of, ColOf&& col_of) {
  return group_values_by_key(a.rows(), ncols, par, [&](size_t r, auto&& emit) {
    const int32_t to = row_of(r);
    if (to < 0) return;
    for (int32_t c : a[r]) {
      const int32_t j = col_of(c);
      if (j >= 0) emit(j, to);
    }
  });
}

// transpose (csr.hpp) by ranges of rows in parallel.
inline Csr<int32_t> transpose(const Csr<int32_t>& a, size_t ncols, const Threads& par) {
  return transpose_mapped(a, ncols, par, [](size_t r) { return static_cast<int32_t>(r); }, [](int32_t c) { return c; });
}

// Counting sort of items that come in units (a cell's slots) by key: row k lists the items with
// key k in increasing order. Unit u holds the items first(u) .. first(u+1)-1, and each_key(u,
// emit) calls emit(key) for each of them in order, key in [0, nkeys). emit(key, tag) with a tag
// (a bit above 31-bit item ids, say) stores item | tag instead.
template <class Rows = Csr<int32_t>, class First, class EachKey>
Rows group_units_by_key(size_t nunits, size_t nkeys, const Threads& par, First&& first, EachKey&& each_key) {
  return group_values_by_key<Rows>(nunits, nkeys, par, [&](size_t u, auto&& emit) {
    auto item = static_cast<uint32_t>(first(u));
    each_key(u, [&](int32_t key, uint32_t tag = 0) { emit(key, static_cast<int32_t>(item++ | tag)); });
  });
}

// Counting sort of the items 0..n-1 by key_of(i) in [0, nkeys): row k lists the items with key k
// in increasing order: group_units_by_key with one item a unit.
template <class KeyOf>
Csr<int32_t> group_by_key(size_t n, size_t nkeys, const Threads& par, KeyOf&& key_of) {
  return group_units_by_key(
      n, nkeys, par, [](size_t u) { return u; },
      [&](size_t u, auto&& emit) { emit(static_cast<int32_t>(key_of(u))); });
}

// Number of ranges weighted_ranges will use for the n = prefix.size() - 1 units of `prefix`.
template <class Prefix>
int weighted_range_count(const Prefix& prefix, const Threads& par) {
  return range_count(std::max(prefix.size() - 1, static_cast<size_t>(prefix.back())), par);
}

// Calls f(begin, end, r) over ranges r of the units 0 .. n-1 holding about equal weight, where
// prefix[i] (n + 1 increasing entries) is the weight of the units before i: rows of very
// different lengths (vertex buckets are longest at low ids when the lowest vertex of random ids
// is taken; a sheet's class of wires holds thousands) still split evenly. Ranges may be empty.
// Results must not depend on the split.
template <class Prefix, class F>
void weighted_ranges(const Prefix& prefix, const Threads& par, F&& f) {
  const size_t n = prefix.size() - 1;
  const auto total = static_cast<uint64_t>(prefix.back());
  const auto nr = static_cast<size_t>(weighted_range_count(prefix, par));
  std::vector<size_t> start(nr + 1, n);
  start[0] = 0;
  for (size_t r = 1; r < nr; ++r) {
    const uint64_t target = total * r / nr;
    start[r] = static_cast<size_t>(std::lower_bound(prefix.begin(), prefix.end() - 1, target, [](auto w, uint64_t t) {
                                     return static_cast<uint64_t>(w) < t;
                                   }) - prefix.begin());
  }
  parallel_ranges(nr, with_grain(par, 1), [&](size_t b, size_t e, int) {
    for (size_t r = b; r < e; ++r) f(start[r], start[r + 1], static_cast<int>(r));
  });
}

// weighted_ranges over the rows of `rows`, each weighing its items.
template <class Rows, class F>
void parallel_rows(const Rows& rows, const Threads& par, F&& f) {
  weighted_ranges(rows.offsets, par, std::forward<F>(f));
}

// Rows [0, n) built by row(i, out, scratch) (appending row i's items to out.items), ranges of rows
// in parallel, each into rows of its own with scratch room of its own, kept as the ranges made
// them: the same rows for any thread count. Joining the parts into one Csr (parallel_rows_of)
// holds them twice at its end; a table read row by row is kept parted instead.
template <class T>
struct PartedRows {
  std::vector<size_t> first;  // per part: its first row
  std::vector<Csr<T>> parts;
  std::span<const T> operator[](size_t r) const {
    const size_t k = static_cast<size_t>(std::upper_bound(first.begin(), first.end(), r) - first.begin()) - 1;
    return parts[k][r - first[k]];
  }
};

// No bound on a range's items: its table grows as it is filled.
struct NoBound {
  size_t operator()(size_t, size_t) const { return 0; }
};

// `bound(b, e)`: as many items as rows b..e-1 may hold, reserved up front (more only lets the
// table grow as without a bound, never changes what it holds). A table that
// grows by doubling copies itself at each step into fresh memory the kernel must zero first (on
// the split grid's counts, some 100 MB, a quarter of their time); an over-estimate costs nothing,
// as pages of the reservation that are never written are never touched.
//
// `ranges(run)` calls run(b, e, k) for each of its nr ranges k.
template <class T, class Scratch, class Ranges, class Row, class Bound>
PartedRows<T> parted_rows_over(size_t nr, Ranges&& ranges, Row&& row, Bound bound) {
  PartedRows<T> rows{std::vector<size_t>(nr, 0), std::vector<Csr<T>>(nr)};
  ranges([&](size_t b, size_t e, int k) {
    rows.first[static_cast<size_t>(k)] = b;
    // Filled on this thread's stack, then moved in: the parts' headers share cache lines, and a
    // push per row there would bounce them between the cores.
    Csr<T> out;
    out.offsets.reserve(e - b + 1);
    out.items.reserve(bound(b, e));
    Scratch scratch{};
    for (size_t i = b; i < e; ++i) {
      row(i, out, scratch);
      out.offsets.push_back(static_cast<int32_t>(out.items.size()));
    }
    rows.parts[static_cast<size_t>(k)] = std::move(out);
  });
  return rows;
}

// Ranges of as many rows each.
template <class T, class Scratch, class Row, class Bound = NoBound>
PartedRows<T> parallel_parted_rows(size_t n, const Threads& par, Row&& row, Bound bound = {}) {
  return parted_rows_over<T, Scratch>(
      static_cast<size_t>(range_count(n, par)), [&](auto&& run) { parallel_ranges(n, par, run); }, row, bound);
}

// Ranges of about equal weight (weighted_ranges): for rows whose cost is far from even.
template <class T, class Scratch, class Prefix, class Row, class Bound = NoBound>
PartedRows<T> weighted_parted_rows(const Prefix& prefix, const Threads& par, Row&& row, Bound bound = {}) {
  return parted_rows_over<T, Scratch>(
      static_cast<size_t>(weighted_range_count(prefix, par)), [&](auto&& run) { weighted_ranges(prefix, par, run); }, row, bound);
}

template <class T, class Scratch, class Row, class Bound = NoBound>
Csr<T> parallel_rows_of(size_t n, const Threads& par, Row&& row, Bound bound = {}) {
  return concat(parallel_parted_rows<T, Scratch>(n, par, std::forward<Row>(row), bound).parts);
}

}  // namespace hbc::detail
