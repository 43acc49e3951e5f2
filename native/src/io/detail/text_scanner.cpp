#include "io/detail/text_scanner.hpp"
#include "platform/charconv.hpp"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

namespace hbc::detail {

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

void TextScanner::skip_space() {
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (hash_comments_ && c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      break;
    }
  }
}

bool TextScanner::next(std::string_view& tok) {
  skip_space();
  if (pos_ >= text_.size()) {
    // "Found the end of the file" points at the last line, not the empty one after its newline.
    tok_line_ = (line_ > 1 && text_.back() == '\n') ? line_ - 1 : line_;
    return false;
  }
  size_t start = pos_;
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') break;
    if (hash_comments_ && c == '#') break;
    ++pos_;
  }
  tok_line_ = line_;
  tok = text_.substr(start, pos_ - start);
  last_ = tok;
  return true;
}

void TextScanner::skip_numbers() {
  // Digits, signs, points and whitespace are all below 0x40, where no letter (nor any byte that
  // could start one) is; '#' too, but comments may hold words. Eight bytes at a time pass while
  // none is 0x40 or above or a '#', their newlines counted at once: reading past armadillo's
  // 9,034 boundary quadrangles token by token took 0.4 ms of its 16 ms load.
  constexpr uint64_t kOnes = 0x0101010101010101u, kLow7 = 0x7f7f7f7f7f7f7f7fu;
  auto zero_bytes = [](uint64_t x) { return ~(((x & kLow7) + kLow7) | x | kLow7); };  // high bit of each zero byte
  const size_t start = pos_;
  size_t p = pos_;
  for (uint64_t w; p + 8 <= text_.size(); p += 8) {
    std::memcpy(&w, text_.data() + p, 8);
    if ((w & (0xc0 * kOnes)) != 0 || zero_bytes(w ^ ('#' * kOnes)) != 0) break;
    line_ += std::popcount(zero_bytes(w ^ ('\n' * kOnes)));
  }
  // Back to the start of the token p may have stopped in (no newline lies between), so that
  // next() does not take the end of 123Tetrahedra for a word.
  while (p > start && !std::isspace(static_cast<unsigned char>(text_[p - 1]))) --p;
  pos_ = p;
}

bool TextScanner::next_word(std::string_view& tok) {
  for (;;) {
    skip_numbers();
    if (!next(tok)) return false;
    if (std::isalpha(static_cast<unsigned char>(tok[0]))) return true;
  }
}

bool TextScanner::at_end() {
  skip_space();
  return pos_ >= text_.size();
}

int64_t TextScanner::next_line() {
  skip_space();
  return line_;
}

void TextScanner::fail(const std::string& expected) const { fail_at(tok_line_, expected); }

void TextScanner::fail_at(int64_t line, const std::string& expected) const {
  throw InputError(source_, SourceLoc::at_line(line), "expected " + expected);
}

std::string_view TextScanner::word(const char* expected) {
  std::string_view t;
  if (!next(t)) fail(std::string(expected) + ", found the end of the file");
  return t;
}

static std::string shown(std::string_view t) {
  std::string s(t.substr(0, 40));
  return "'" + s + (t.size() > 40 ? "...'" : "'");
}

int64_t TextScanner::integer(const char* expected) {
  // Fast path for the common plain decimal token; anything unusual takes the checked path below.
  skip_space();
  {
    size_t p = pos_;
    const bool neg = p < text_.size() && text_[p] == '-';
    if (neg || (p < text_.size() && text_[p] == '+')) ++p;
    const size_t digits_start = p;
    uint64_t v = 0;
    while (p < text_.size() && p - digits_start < 18 && text_[p] >= '0' && text_[p] <= '9')
      v = v * 10 + static_cast<uint64_t>(text_[p++] - '0');
    const bool ended = p == text_.size() || text_[p] == ' ' || text_[p] == '\n' || text_[p] == '\t' ||
                       text_[p] == '\r' || (hash_comments_ && text_[p] == '#');
    if (p > digits_start && ended) {
      tok_line_ = line_;
      last_ = text_.substr(pos_, p - pos_);
      pos_ = p;
      return neg ? -static_cast<int64_t>(v) : static_cast<int64_t>(v);
    }
  }
  std::string_view t = word(expected);
  int64_t v = 0;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (b != e && *b == '+') ++b;
  auto r = ::hbc::detail::from_chars(b, e, v);
  if (r.ec != std::errc() || r.ptr != e) fail(std::string(expected) + " (an integer), found " + shown(t));
  return v;
}

double TextScanner::real(const char* expected) {
  std::string_view t = word(expected);
  double v = 0;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (b != e && *b == '+') ++b;
  auto r = ::hbc::detail::from_chars(b, e, v);
  if (r.ec == std::errc::result_out_of_range) fail(std::string(expected) + " (a finite number), found " + shown(t));
  if (r.ec != std::errc() || r.ptr != e) fail(std::string(expected) + " (a number), found " + shown(t));
  if (!std::isfinite(v)) fail(std::string(expected) + " (a finite number), found " + shown(t));
  return v;
}

int64_t TextScanner::integer_in(int64_t lo, int64_t hi, const char* expected) {
  int64_t v = integer(expected);
  if (v < lo || v > hi)
    fail(std::string(expected) + " in [" + std::to_string(lo) + ", " + std::to_string(hi) +
         "], found " + std::to_string(v));
  return v;
}

int64_t TextScanner::count(int64_t min_bytes, const char* expected) {
  int64_t n = integer(expected);
  if (n < 0) fail(std::string(expected) + " (a count >= 0), found " + std::to_string(n));
  const int64_t room = static_cast<int64_t>(remaining_bytes()) / std::max<int64_t>(min_bytes, 1) + 1;
  if (n > room)
    fail(std::string(expected) + " that the rest of the file can hold (at most " +
         std::to_string(room) + "), found " + std::to_string(n));
  return n;
}

void read_points(TextScanner& s, int64_t nv, MeshInput& in) {
  in.points.reserve(static_cast<size_t>(3 * nv));
  in.vertex_loc.reserve(static_cast<size_t>(nv));
  for (int64_t i = 0; i < nv; ++i) {
    in.vertex_loc.push_back(s.next_line());
    for (int k = 0; k < 3; ++k) in.points.push_back(s.real("a vertex coordinate"));
  }
}

void read_face_loops(TextScanner& s, int64_t nf, int64_t nv, int base, MeshInput& in) {
  const char* what = base == 0 ? "a vertex index (0-based)" : "a vertex index (1-based)";
  for (int64_t f = 0; f < nf; ++f) {
    in.face_loc.push_back(s.next_line());
    // Fewer than 3 are read: build_mesh names the face, hbc check lists it, --skip-invalid drops its cells.
    const int64_t n = s.integer_in(1, 1 << 20, "the number of vertices of a face");
    for (int64_t k = 0; k < n; ++k)
      in.faces.items.push_back(static_cast<int32_t>(s.integer_in(base, nv - 1 + base, what) - base));
    in.faces.offsets.push_back(static_cast<int32_t>(in.faces.items.size()));
  }
}

}  // namespace hbc::detail
