#pragma once
// Included before every C++ file of the WebAssembly build (wasm.cmake): the two C++20 library
// functions the sources use that emscripten 3.1.6's libc++ lacks, each defined only where the
// library's feature-test macro says it is missing, so a newer emscripten uses its own.
#include <bit>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <version>

namespace std {
#if !defined(__cpp_lib_bit_cast)
template <class To, class From>
constexpr To bit_cast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From));
  return __builtin_bit_cast(To, from);
}
#endif
#if !defined(__cpp_lib_smart_ptr_for_overwrite)
template <class T>
  requires is_unbounded_array_v<T>
unique_ptr<T> make_unique_for_overwrite(size_t n) {
  return unique_ptr<T>(new remove_extent_t<T>[n]);
}
#endif
}  // namespace std
