#pragma once
// Compressed sparse rows: the one container for every variable-length incidence in the library.
#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace hbc {

template <class T = int32_t>
struct Csr {
  std::vector<int32_t> offsets{0};  // size rows()+1, offsets[0] == 0
  std::vector<T> items;             // size offsets.back()

  size_t rows() const { return offsets.size() - 1; }
  size_t size() const { return rows(); }
  int32_t count(size_t r) const { return offsets[r + 1] - offsets[r]; }
  std::span<const T> operator[](size_t r) const {
    return {items.data() + offsets[r], static_cast<size_t>(offsets[r + 1] - offsets[r])};
  }
  std::span<T> row(size_t r) {
    return {items.data() + offsets[r], static_cast<size_t>(offsets[r + 1] - offsets[r])};
  }
  void clear() {
    offsets.assign(1, 0);
    items.clear();
  }
  template <class It>
  void push_row(It first, It last) {
    // Element by element: rows are short, and with reserved room this beats a generic insert.
    for (; first != last; ++first) items.push_back(*first);
    offsets.push_back(static_cast<int32_t>(items.size()));
  }
  void reserve(size_t rows_, size_t items_) {
    offsets.reserve(rows_ + 1);
    items.reserve(items_);
  }
  void push_row(std::span<const T> r) { push_row(r.begin(), r.end()); }

  // The same rows.
  bool operator==(const Csr&) const = default;
};

// Transposes an incidence: rows of `a` hold column ids in [0, ncols); the result has ncols rows,
// each listing the rows of `a` that name it, in increasing order (stable, hence deterministic).
Csr<int32_t> transpose(const Csr<int32_t>& a, size_t ncols);

// Counting sort of the positions of `keys` by key: row k lists every i with keys[i] == k, in
// increasing i. keys[i] in [0, nkeys). Linear in keys.size() + nkeys.
Csr<int32_t> group_by(std::span<const int32_t> keys, size_t nkeys);

// The rows of `parts` one after the other (parts are consumed).
template <class T>
Csr<T> concat(std::vector<Csr<T>>&& parts) {
  if (parts.size() == 1) return std::move(parts[0]);
  Csr<T> all;
  size_t rows = 0, items = 0;
  for (const auto& p : parts) rows += p.rows(), items += p.items.size();
  all.reserve(rows, items);
  for (auto& p : parts) {
    const int32_t base = static_cast<int32_t>(all.items.size());
    for (size_t r = 1; r < p.offsets.size(); ++r) all.offsets.push_back(base + p.offsets[r]);
    all.items.insert(all.items.end(), p.items.begin(), p.items.end());
    p = Csr<T>{};
  }
  return all;
}

// Sorts v and removes repeated values.
template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace hbc
