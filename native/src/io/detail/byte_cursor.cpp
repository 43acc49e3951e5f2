#include "io/detail/byte_cursor.hpp"
#include "platform/charconv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace hbc::detail {

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

static std::string shown(std::string_view t) {
  std::string s(t.substr(0, 40));
  return "'" + s + (t.size() > 40 ? "...'" : "'");
}

// The whole token as a number (a leading '+' allowed, which from_chars refuses).
template <class T>
static bool parse_whole(std::string_view t, T& v) {
  const char* b = t.data() + (t.front() == '+' ? 1 : 0);
  const auto r = ::hbc::detail::from_chars(b, t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

void ByteCursor::skip_space() {
  while (pos_ < d_.size() && is_space(d_[pos_])) {
    if (d_[pos_] == '\n') ++line_;
    ++pos_;
  }
}

bool ByteCursor::token(std::string_view& t) {
  skip_space();
  if (pos_ >= d_.size()) return false;
  const size_t start = pos_;
  while (pos_ < d_.size() && !is_space(d_[pos_])) ++pos_;
  t = d_.substr(start, pos_ - start);
  return true;
}

std::string_view ByteCursor::word(const char* expected) {
  std::string_view t;
  if (!token(t)) fail(std::string(expected) + ", found the end of the file");
  return t;
}

int64_t ByteCursor::integer(const char* expected) {
  const std::string_view t = word(expected);
  int64_t v = 0;
  if (!parse_whole(t, v)) fail(std::string(expected) + " (an integer), found " + shown(t));
  return v;
}

int64_t ByteCursor::integer_in(int64_t lo, int64_t hi, const char* expected) {
  const int64_t v = integer(expected);
  if (v < lo || v > hi)
    fail(std::string(expected) + " in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " + std::to_string(v));
  return v;
}

double ByteCursor::real(const char* expected) {
  const std::string_view t = word(expected);
  double v = 0;
  if (!parse_whole(t, v) || !std::isfinite(v))
    fail(std::string(expected) + " (a finite number), found " + shown(t));
  return v;
}

std::string_view ByteCursor::line_text() {
  const size_t start = pos_;
  while (pos_ < d_.size() && d_[pos_] != '\n') ++pos_;
  std::string_view t = d_.substr(start, pos_ - start);
  if (!t.empty() && t.back() == '\r') t.remove_suffix(1);
  if (pos_ < d_.size()) {
    ++pos_;
    ++line_;
  }
  return t;
}

void ByteCursor::end_line() {
  while (pos_ < d_.size() && d_[pos_] != '\n') {
    if (!is_space(d_[pos_])) fail("the end of the line before binary data, found " + shown(d_.substr(pos_, 10)));
    ++pos_;
  }
  if (pos_ < d_.size()) {
    ++pos_;
    ++line_;
  }
}

bool ByteCursor::skip_past(std::string_view s) {
  const size_t at = d_.find(s, pos_);
  const size_t end = at == std::string_view::npos ? d_.size() : at + s.size();
  line_ += std::count(d_.begin() + static_cast<std::ptrdiff_t>(pos_), d_.begin() + static_cast<std::ptrdiff_t>(end), '\n');
  pos_ = end;
  return at != std::string_view::npos;
}

const char* ByteCursor::bytes(size_t n, const char* expected) {
  if (n > remaining())
    fail(std::string(expected) + " (" + std::to_string(n) + " bytes), found the end of the file after " +
         std::to_string(remaining()));
  const char* p = d_.data() + pos_;
  pos_ += n;
  return p;
}

int64_t ByteCursor::checked_count(int64_t n, int64_t item_bytes, const char* expected) {
  const int64_t room = static_cast<int64_t>(remaining()) / std::max<int64_t>(item_bytes, 1) + 1;
  if (n < 0 || n > room)
    fail(std::string(expected) + " that the rest of the file can hold (0 to " + std::to_string(room) + "), found " +
         std::to_string(n));
  return n;
}

void ByteCursor::fail(const std::string& expected) {
  // "Found the end of the file" points at the last line, not the empty one after its newline.
  const bool past_last = pos_ == d_.size() && line_ > 1 && !d_.empty() && d_.back() == '\n';
  fail_at(binary_ ? static_cast<int64_t>(pos_) : line_ - (past_last ? 1 : 0), expected);
}

void ByteCursor::fail_at(int64_t loc, const std::string& expected) const {
  throw InputError(source_, binary_ ? SourceLoc::at_byte(loc) : SourceLoc::at_line(loc), "expected " + expected);
}

}  // namespace hbc::detail
