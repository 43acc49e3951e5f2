#pragma once
// Floating-point <charconv> where the standard library lacks it.
// hbc::detail::from_chars: std::from_chars for integers, and for float and double where the
// standard library implements it (__cpp_lib_to_chars: libstdc++ 11+); elsewhere (libc++ before
// 17, emscripten's among them) fast_float, which rounds every decimal string correctly as the
// standard requires, so both give the same bits. The result keeps std::from_chars' contract:
// ptr past the number, errc::invalid_argument for no number, errc::result_out_of_range when the
// magnitude overflows or a nonzero number underflows to zero.
#include <charconv>
#include <limits>
#include <system_error>
#include <type_traits>
#include <version>

#if !defined(__cpp_lib_to_chars)
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fast_float/fast_float.h>
#endif

namespace hbc::detail {

template <class T>
std::from_chars_result from_chars(const char* first, const char* last, T& value) {
#if !defined(__cpp_lib_to_chars)
  if constexpr (std::is_floating_point_v<T>) {
    T v{};
    const auto r = fast_float::from_chars(first, last, v);
    if (r.ec != std::errc()) return {r.ptr, r.ec};
    bool range = v == std::numeric_limits<T>::infinity() || v == -std::numeric_limits<T>::infinity();
    if (v == 0) {
      // Zero from a nonzero mantissa (1e-400) is an underflow, as libstdc++ reports it.
      for (const char* p = first; p < r.ptr && *p != 'e' && *p != 'E'; ++p) range = range || (*p >= '1' && *p <= '9');
    }
    // "inf" spelled out is a value, not an overflow.
    if (range && (v != v || (*first == 'i' || *first == 'I' || ((*first == '-') && r.ptr - first > 1 && (first[1] == 'i' || first[1] == 'I')))))
      range = false;
    if (range) return {r.ptr, std::errc::result_out_of_range};
    value = v;
    return {r.ptr, std::errc()};
  } else
#endif
  {
    return std::from_chars(first, last, value);
  }
}

// to_chars_shortest: std::to_chars(first, last, x) for a finite double, the shortest text that
// reads back to x, in fixed or scientific notation, whichever is shorter (fixed on a tie). The
// fallback finds the fewest significant digits that round-trip through printf's correctly rounded
// %.*e and strtod, then lays them out as std::to_chars does. last - first must be at least 32.
inline char* to_chars_shortest(char* first, char* last, double x) {
#if defined(__cpp_lib_to_chars)
  return std::to_chars(first, last, x).ptr;
#else
  (void)last;
  char sci[40];
  int prec = 0;
  for (; prec < 17; ++prec) {
    std::snprintf(sci, sizeof sci, "%.*e", prec, x);
    if (std::strtod(sci, nullptr) == x) break;
  }
  if (prec == 17) std::snprintf(sci, sizeof sci, "%.*e", prec, x);
  // sci is [-]d[.ddd]e(+|-)XX: its digits and decimal exponent.
  const char* p = sci;
  char* out = first;
  if (*p == '-') *out++ = *p++;
  char digits[24];
  int n = 0;
  for (; *p != 'e'; ++p)
    if (*p != '.') digits[n++] = *p;
  const int exp10 = std::atoi(p + 1);
  while (n > 1 && digits[n - 1] == '0') --n;
  if (n == 1 && digits[0] == '0') {
    *out++ = '0';
    return out;
  }
  // Scientific: d[.ddd]e(+|-)XX, at least two exponent digits.
  char s_buf[40];
  int sl = 0;
  s_buf[sl++] = digits[0];
  if (n > 1) {
    s_buf[sl++] = '.';
    for (int i = 1; i < n; ++i) s_buf[sl++] = digits[i];
  }
  sl += std::snprintf(s_buf + sl, sizeof s_buf - static_cast<size_t>(sl), "e%c%02d", exp10 < 0 ? '-' : '+', exp10 < 0 ? -exp10 : exp10);
  // Fixed.
  char f_buf[400];
  int fl = 0;
  if (exp10 >= n - 1) {
    // An integer: std::to_chars prints its exact digits (as %.0f), not the shortest then zeros.
    fl = std::snprintf(f_buf, sizeof f_buf, "%.0f", x < 0 ? -x : x);
  } else if (exp10 >= 0) {
    for (int i = 0; i < n || i <= exp10; ++i) {
      if (i == exp10 + 1) f_buf[fl++] = '.';
      f_buf[fl++] = i < n ? digits[i] : '0';
    }
  } else {
    f_buf[fl++] = '0';
    f_buf[fl++] = '.';
    for (int i = 0; i < -exp10 - 1; ++i) f_buf[fl++] = '0';
    for (int i = 0; i < n; ++i) f_buf[fl++] = digits[i];
  }
  const char* best = fl <= sl ? f_buf : s_buf;
  const int len = fl <= sl ? fl : sl;
  std::memcpy(out, best, static_cast<size_t>(len));
  return out + len;
#endif
}

}  // namespace hbc::detail
