#pragma once
// hbc::detail::atomic_ref<T>: std::atomic_ref where the standard library has it, else the same
// operations (load, store, fetch_add, compare_exchange_strong/weak) through the compiler's __atomic
// builtins, which GCC and Clang provide on every target (emscripten's libc++ 14 lacks
// std::atomic_ref). Both are the same lock-free instructions for the 1- and 4-byte types used here.
#include <atomic>
#include <version>

namespace hbc::detail {

#if defined(__cpp_lib_atomic_ref)
template <class T>
using atomic_ref = std::atomic_ref<T>;
#else
template <class T>
class atomic_ref {
 public:
  explicit atomic_ref(T& ref) noexcept : p_(&ref) {}
  T load(std::memory_order o = std::memory_order_seq_cst) const noexcept { return __atomic_load_n(p_, order(o)); }
  void store(T v, std::memory_order o = std::memory_order_seq_cst) const noexcept { __atomic_store_n(p_, v, order(o)); }
  T fetch_add(T v, std::memory_order o = std::memory_order_seq_cst) const noexcept {
    return __atomic_fetch_add(p_, v, order(o));
  }
  bool compare_exchange_strong(T& expected, T desired, std::memory_order o = std::memory_order_seq_cst) const noexcept {
    return __atomic_compare_exchange_n(p_, &expected, desired, false, order(o), failure_order(o));
  }
  bool compare_exchange_weak(T& expected, T desired, std::memory_order o = std::memory_order_seq_cst) const noexcept {
    return __atomic_compare_exchange_n(p_, &expected, desired, true, order(o), failure_order(o));
  }

 private:
  static constexpr int order(std::memory_order o) noexcept {
    switch (o) {
      case std::memory_order_relaxed: return __ATOMIC_RELAXED;
      case std::memory_order_consume: return __ATOMIC_CONSUME;
      case std::memory_order_acquire: return __ATOMIC_ACQUIRE;
      case std::memory_order_release: return __ATOMIC_RELEASE;
      case std::memory_order_acq_rel: return __ATOMIC_ACQ_REL;
      default: return __ATOMIC_SEQ_CST;
    }
  }
  // The failure order may not release: acq_rel fails as acquire and release as relaxed (as std does).
  static constexpr int failure_order(std::memory_order o) noexcept {
    if (o == std::memory_order_acq_rel) return __ATOMIC_ACQUIRE;
    if (o == std::memory_order_release) return __ATOMIC_RELAXED;
    return order(o);
  }
  T* p_;
};
#endif

}  // namespace hbc::detail
