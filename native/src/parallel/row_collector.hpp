#pragma once
// Distinct ids gathered row by row (the incidences of patches and components), each row then
// written sorted. Most rows hold a handful of ids, found by a scan of the row itself; only a row
// that grows long marks its ids in a table over all ids, so that the table's pages (tens of MB
// on 10^6 cells) are touched only where long rows need them: the table comes zeroed from calloc,
// which costs nothing until a page is written. One collector per thread.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "hbc/csr.hpp"

namespace hbc::detail {

class RowCollector {
 public:
  explicit RowCollector(size_t n) : stamp_(static_cast<int32_t*>(std::calloc(std::max<size_t>(n, 1), sizeof(int32_t)))) {
    if (!stamp_) throw std::bad_alloc();
  }
  void begin() {
    ++current_;
    row_.clear();
  }
  void add(int32_t id) {
    if (row_.size() < kScan) {
      for (int32_t x : row_)
        if (x == id) return;
      row_.push_back(id);
      if (row_.size() == kScan)  // from here on the table decides: mark what the row holds
        for (int32_t x : row_) stamp_.get()[x] = current_;
      return;
    }
    if (stamp_.get()[id] == current_) return;
    stamp_.get()[id] = current_;
    row_.push_back(id);
  }
  void end(Csr<int32_t>& out) {
    int32_t* r = row_.data();
    const size_t n = row_.size();
    if (n <= 32) {  // the usual case: a handful of ids; a shift, not a swap, per step
      for (size_t i = 1; i < n; ++i) {
        const int32_t x = r[i];
        size_t j = i;
        for (; j > 0 && r[j - 1] > x; --j) r[j] = r[j - 1];
        r[j] = x;
      }
    } else {
      std::sort(row_.begin(), row_.end());
    }
    out.items.insert(out.items.end(), row_.begin(), row_.end());
    out.offsets.push_back(static_cast<int32_t>(out.items.size()));
  }

 private:
  static constexpr size_t kScan = 24;  // the longest row found by scanning (a cube's curve ends)
  struct Free {
    void operator()(int32_t* p) const { std::free(p); }
  };
  std::unique_ptr<int32_t, Free> stamp_;
  std::vector<int32_t> row_;
  int32_t current_ = 0;  // 0 marks nothing: the table starts zeroed
};

// Appends the rows of `part` to `out`.
inline void append_rows(Csr<int32_t>& out, const Csr<int32_t>& part) {
  const int32_t base = static_cast<int32_t>(out.items.size());
  out.items.insert(out.items.end(), part.items.begin(), part.items.end());
  for (size_t r = 1; r < part.offsets.size(); ++r) out.offsets.push_back(base + part.offsets[r]);
}

}  // namespace hbc::detail
