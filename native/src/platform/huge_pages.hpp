#pragma once
// The loader's large arrays (tens of MB for 10^6 cells) are allocated and then filled once, often
// by several threads. Most of the time of that first touch goes to page faults, one per 4 KiB
// page; asking the kernel for 2 MiB pages where it grants them (transparent huge pages in
// "madvise" mode, Linux's usual setting) takes 512 times fewer. The advice is asked for only with
// HBC_HUGE_PAGES=1 (huge_pages.cpp says why it is not the default). It changes nothing else:
// contents, sizes and results are the same with or without it, and it is ignored elsewhere.
#include <cstddef>
#include <vector>

namespace hbc::detail {

// Advises the whole 2 MiB pages inside [p, p + bytes); nothing for small ranges.
void advise_huge_pages(const void* p, size_t bytes);

// v.reserve(n) with the advice, before anything is written there.
template <class T>
void reserve_huge(std::vector<T>& v, size_t n) {
  if (n <= v.capacity()) return;
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
}

// v.resize(n, value), by the plain resize when value is T(). GCC compiles vector::resize(n, T())
// of a small aggregate (std::array<int32_t, 2>) into a loop that rebuilds the value on the stack
// with two narrow stores and reads it back as one wide load, a failed store forwarding per
// element: the 100k edges of armadillo's edge_verts took 0.55 ms that way and 0.03 ms by plain
// resize.
template <class T>
void resize_with(std::vector<T>& v, size_t n, const T& value) {
  if (value == T()) v.resize(n);
  else v.resize(n, value);
}

// v.resize(n, value) into advised room.
template <class T>
void resize_huge(std::vector<T>& v, size_t n, const T& value = T()) {
  reserve_huge(v, n);
  resize_with(v, n, value);
}

// v.assign(n, value) into advised room.
template <class T>
void assign_huge(std::vector<T>& v, size_t n, const T& value) {
  if (n > v.capacity()) std::vector<T>().swap(v);
  reserve_huge(v, n);
  v.assign(n, value);
}

}  // namespace hbc::detail
