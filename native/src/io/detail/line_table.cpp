#include "io/detail/line_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "parallel/parallel.hpp"
#include "platform/charconv.hpp"

namespace hbc::detail {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The newlines in [p, e). std::count widens every byte's match to a 64-bit sum (several
// shuffles per 16 bytes); with SSE2 the matches add up in byte lanes, summed every 255 blocks.
int64_t count_newlines(const char* p, const char* e) {
  int64_t n = 0;
#ifdef __SSE2__
  const __m128i nl = _mm_set1_epi8('\n');
  while (e - p >= 16) {
    __m128i acc = _mm_setzero_si128();
    const int64_t blocks = std::min<int64_t>((e - p) / 16, 255);
    for (int64_t i = 0; i < blocks; ++i, p += 16)
      acc = _mm_sub_epi8(acc, _mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), nl));
    const __m128i sums = _mm_sad_epu8(acc, _mm_setzero_si128());
    n += _mm_cvtsi128_si64(sums) + _mm_cvtsi128_si64(_mm_unpackhi_epi64(sums, sums));
  }
#endif
  return n + std::count(p, e, '\n');
}

// Where the section's lines start: position `begin` (just after the newline ending the count's
// line) and every 1/nranges of the n lines; starts.back() is the end of the n-th line. False
// when the text has fewer than n complete lines. Threads count the newlines of equal slices of
// the text ahead (a vectorised count), then the slices holding the wanted lines are searched.
bool split_lines(std::string_view text, size_t begin, int64_t n, int nranges, const Threads& par,
                 std::vector<size_t>& starts) {
  // The section is at least n bytes long; look at no more than the text holds.
  const size_t rest = text.size() - begin;
  const size_t nslices = static_cast<size_t>(std::max(1, par.count)) * 8;
  std::vector<int64_t> count(nslices, 0);
  auto slice = [&](size_t i) { return begin + rest * i / nslices; };
  parallel_ranges(nslices, with_grain(par, 1), [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i) count[i] = count_newlines(text.data() + slice(i), text.data() + slice(i + 1));
  });
  // The position just after newline number `k` (1-based) counted from `begin`.
  auto after_newline = [&](int64_t k) -> size_t {
    int64_t seen = 0;
    size_t i = 0;
    while (i < nslices && seen + count[i] < k) seen += count[i++];
    if (i == nslices) return std::string_view::npos;
    const char* p = text.data() + slice(i);
    for (;;) {
      p = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(text.data() + slice(i + 1) - p)));
      if (++seen == k) return static_cast<size_t>(p - text.data()) + 1;
      ++p;
    }
  };
  starts.assign(1, begin);
  for (int r = 1; r < nranges; ++r) starts.push_back(after_newline(n * r / nranges));
  const size_t end = after_newline(n);
  if (end == std::string_view::npos) return false;
  starts.push_back(end);
  return true;
}

// Start of the line after the scanner's position when only blanks are left on the current one.
bool after_blank_rest(const TextScanner& s, size_t& begin) {
  std::string_view t = s.text();
  size_t p = s.pos();
  while (p < t.size() && is_blank(t[p])) ++p;
  if (p >= t.size() || t[p] != '\n') return false;
  begin = p + 1;
  return true;
}

// Parses one number at p (blanks before it skipped), which must end at a blank or the newline.
template <class T>
bool number(const char*& p, const char* end, T& v) {
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  if constexpr (std::is_integral_v<T>) {
    // Up to 9 digits cannot overflow: summed here, a third of from_chars' work; longer ones (and
    // anything else) take from_chars, which rejects what it rejects. Every range of lines ends
    // with a newline, which stops the digits without a bound check.
    const bool neg = *p == '-';
    const char* d = p + neg;
    const char* q = d;
    uint32_t x = 0;
    for (unsigned digit; (digit = static_cast<unsigned char>(*q) - unsigned{'0'}) < 10; ++q) x = 10 * x + digit;
    if (q > d && q - d < 10 && (is_blank(*q) || *q == '\n')) {
      const int64_t value = neg ? -static_cast<int64_t>(x) : static_cast<int64_t>(x);
      if (value < std::numeric_limits<T>::min() || value > std::numeric_limits<T>::max()) return false;
      v = static_cast<T>(value);
      p = q;
      return true;
    }
  }
  auto r = ::hbc::detail::from_chars(p, end, v);
  if (r.ec != std::errc() || r.ptr == p) return false;
  p = r.ptr;
  return p == end || is_blank(*p) || *p == '\n';
}

bool line_end(const char*& p, const char* end) {
  while (p < end && is_blank(*p)) ++p;
  if (p == end || *p != '\n') return false;
  ++p;
  return true;
}

// Runs parse_line(i, p, end) for each of the n lines, split over threads; on success moves the
// scanner past the section.
template <class ParseLine>
bool parse_lines(TextScanner& s, int64_t n, const Threads& par, ParseLine&& parse_line) {
  size_t begin = 0;
  if (n <= 0 || !after_blank_rest(s, begin)) return false;
  const int nr = range_count(static_cast<size_t>(n), par);
  std::vector<size_t> starts;
  if (!split_lines(s.text(), begin, n, nr, par, starts)) return false;
  std::vector<uint8_t> ok(static_cast<size_t>(nr), 1);
  parallel_ranges(static_cast<size_t>(n), par, [&](size_t b, size_t e, int r) {
    const char* p = s.text().data() + starts[static_cast<size_t>(r)];
    const char* end = s.text().data() + starts[static_cast<size_t>(r) + 1];
    for (size_t i = b; i < e; ++i)
      if (!parse_line(i, p, end) || !line_end(p, end)) {
        ok[static_cast<size_t>(r)] = 0;
        return;
      }
  });
  for (uint8_t k : ok)
    if (!k) return false;
  s.skip_to(starts.back(), n + 1);
  return true;
}

}  // namespace

bool fast_vertex_lines(TextScanner& s, int64_t n, std::vector<double>& points, std::vector<int64_t>& lines,
                       const Threads& par) {
  const size_t p0 = points.size(), l0 = lines.size();
  resize_touched(points, p0 + 3 * static_cast<size_t>(n), par);
  resize_touched(lines, l0 + static_cast<size_t>(n), par);
  const int64_t first_line = s.line() + 1;
  const bool ok = parse_lines(s, n, par, [&](size_t i, const char*& p, const char* end) {
    double* x = &points[p0 + 3 * i];
    int64_t ref = 0;
    for (int k = 0; k < 3; ++k)
      if (!number(p, end, x[k]) || !std::isfinite(x[k])) return false;
    lines[l0 + i] = first_line + static_cast<int64_t>(i);
    return number(p, end, ref);
  });
  if (!ok) points.resize(p0), lines.resize(l0);
  return ok;
}

bool fast_element_lines(TextScanner& s, int64_t n, int k, std::vector<int32_t>& ids, std::vector<int64_t>& lines,
                        const Threads& par) {
  const size_t i0 = ids.size(), l0 = lines.size();
  resize_touched(ids, i0 + static_cast<size_t>(k) * static_cast<size_t>(n), par);
  resize_touched(lines, l0 + static_cast<size_t>(n), par);
  const int64_t first_line = s.line() + 1;
  const bool ok = parse_lines(s, n, par, [&](size_t i, const char*& p, const char* end) {
    int32_t* out = &ids[i0 + static_cast<size_t>(k) * i];
    int64_t ref = 0;
    for (int j = 0; j < k; ++j)
      if (!number(p, end, out[j]) || out[j] < 1) return false;
    lines[l0 + i] = first_line + static_cast<int64_t>(i);
    return number(p, end, ref);
  });
  if (!ok) ids.resize(i0), lines.resize(l0);
  return ok;
}

}  // namespace hbc::detail
