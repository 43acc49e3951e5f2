#pragma once
// A tiny open-addressing table from int32 keys to a count and a first position, for per-cell
// work (a hex has 12 edges and 8 vertices): cleared in O(1) by a generation stamp, so one table
// serves every cell of a range without sorting or allocating.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace hbc::detail {

// Sorts the handful of values of one face, cell or vertex bucket by insertion (faster than
// std::sort there), and falls back to std::sort for the rare large range (a vertex in thousands
// of faces), where insertion would be quadratic.
template <class It>
void sort_small(It first, It last) {
  if (last - first > 32) return std::sort(first, last);
  for (It i = first; i != last; ++i)
    for (It j = i; j != first && *j < *(j - 1); --j) std::iter_swap(j - 1, j);
}

class SmallTable {
 public:
  struct Entry {
    int32_t key, count, first;
  };
  // Starts over for at most n distinct keys.
  void reset(size_t n) {
    size_t cap = 32;
    while (cap < 2 * n) cap <<= 1;
    if (cap != entries_.size() || ++generation_ == 0) {
      entries_.assign(cap, {});
      stamp_.assign(cap, 0);
      generation_ = 1;
    }
    mask_ = cap - 1;
    used_.clear();
  }
  // The entry of `key`, added with count 0 and first -1 when new.
  Entry& operator[](int32_t key) {
    size_t h = (static_cast<uint32_t>(key) * 2654435761u) & mask_;
    while (stamp_[h] == generation_ && entries_[h].key != key) h = (h + 1) & mask_;
    if (stamp_[h] != generation_) {
      stamp_[h] = generation_;
      entries_[h] = {key, 0, -1};
      used_.push_back(static_cast<int32_t>(h));
    }
    return entries_[h];
  }
  // Keys in the order they were first added.
  size_t size() const { return used_.size(); }
  const Entry& at(size_t i) const { return entries_[static_cast<size_t>(used_[i])]; }

 private:
  std::vector<Entry> entries_;
  std::vector<uint32_t> stamp_;
  std::vector<int32_t> used_;
  uint32_t generation_ = 0;
  size_t mask_ = 0;
};

}  // namespace hbc::detail
