#pragma once
// A cursor over a file that mixes text lines and binary blocks (Gmsh .msh, legacy VTK): text
// tokens with line tracking, fixed-size binary numbers of either byte order, and messages that
// name the line while the file is read as text and the byte offset once it is read as binary.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "hbc/error.hpp"

namespace hbc::detail {

class ByteCursor {
 public:
  ByteCursor(std::string_view data, std::string source) : d_(data), source_(std::move(source)) {}

  // Switches messages to byte offsets (the file's body is binary).
  void set_binary(bool b) { binary_ = b; }
  bool binary() const { return binary_; }
  size_t pos() const { return pos_; }
  size_t remaining() const { return d_.size() - pos_; }
  int64_t line() const { return line_; }
  // Where the next item starts, as a line (text) or byte offset (binary).
  int64_t loc() { if (!binary_) skip_space(); return binary_ ? static_cast<int64_t>(pos_) : line_; }
  const std::string& source() const { return source_; }

  // Text: the next whitespace-separated token (false at the end).
  bool token(std::string_view& t);
  std::string_view word(const char* expected);
  int64_t integer(const char* expected);
  int64_t integer_in(int64_t lo, int64_t hi, const char* expected);
  double real(const char* expected);
  // The rest of the current line (without the newline), which is consumed.
  std::string_view line_text();
  // Consumes the end of the current line: binary data starts right after it.
  void end_line();
  // Moves just past the next occurrence of `s`; false (at the end) when there is none.
  bool skip_past(std::string_view s);

  // Binary: `n` bytes, failing when the file is shorter.
  const char* bytes(size_t n, const char* expected);
  template <class T>
  T bin(bool swap, const char* expected) {
    T v;
    std::memcpy(&v, bytes(sizeof(T), expected), sizeof(T));
    if (swap) v = byteswap_any(v);
    return v;
  }
  // A count of items of at least `item_bytes` each that the rest of the file can hold.
  int64_t checked_count(int64_t n, int64_t item_bytes, const char* expected);

  [[noreturn]] void fail(const std::string& expected);
  [[noreturn]] void fail_at(int64_t loc, const std::string& expected) const;

 private:
  template <class T>
  static T byteswap_any(T v) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    std::memcpy(&v, b, sizeof(T));
    return v;
  }
  void skip_space();
  std::string_view d_;
  std::string source_;
  size_t pos_ = 0;
  int64_t line_ = 1;
  bool binary_ = false;
};

// True on a little-endian machine (the byte order binary readers compare against).
constexpr bool kLittleEndian = std::endian::native == std::endian::little;

}  // namespace hbc::detail
