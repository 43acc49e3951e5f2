#pragma once
// Token scanner shared by the text readers: whitespace-separated tokens, optional '#' comments,
// line tracking for messages, and checks that a declared count fits in what is left of the file.
#include <cstdint>
#include <string>
#include <string_view>

#include "hbc/error.hpp"
#include "hbc/mesh.hpp"

namespace hbc::detail {

class TextScanner {
 public:
  TextScanner(std::string_view text, std::string source, bool hash_comments)
      : text_(text), source_(std::move(source)), hash_comments_(hash_comments) {}

  // Next token, or false at the end of the text.
  bool next(std::string_view& tok);
  bool at_end();
  // The next token that starts with a letter (a section keyword), past all others; false at the
  // end of the text. What next() would find token by token, faster over runs of numbers.
  bool next_word(std::string_view& tok);
  // Line of the last token returned (1-based), or of the end of the text.
  int64_t line() const { return tok_line_; }
  // The line the next token starts on (skips whitespace and comments).
  int64_t next_line();

  std::string_view word(const char* expected);
  int64_t integer(const char* expected);
  double real(const char* expected);
  // An integer in [lo, hi].
  int64_t integer_in(int64_t lo, int64_t hi, const char* expected);
  // A count of elements each needing at least `min_bytes` of text: rejects counts the rest of the
  // file cannot hold, so that a tiny file cannot make us allocate gigabytes.
  int64_t count(int64_t min_bytes, const char* expected);
  size_t remaining_bytes() const { return text_.size() - pos_; }
  const std::string& source() const { return source_; }
  std::string_view text() const { return text_; }
  size_t pos() const { return pos_; }
  // Moves to `pos`, `lines` lines further down (for a fast path that has read the text between).
  void skip_to(size_t pos, int64_t lines) {
    pos_ = pos;
    line_ += lines;
    tok_line_ = line_ - 1;
  }

  [[noreturn]] void fail(const std::string& expected) const;
  [[noreturn]] void fail_at(int64_t line, const std::string& expected) const;

 private:
  void skip_space();
  // Moves past the whole words that can hold no letter and no comment (see next_word).
  void skip_numbers();
  std::string_view text_;
  std::string source_;
  bool hash_comments_;
  size_t pos_ = 0;
  int64_t line_ = 1;      // line at pos_
  int64_t tok_line_ = 1;  // line of the last token
  std::string_view last_;
};

// Sections shared by the counted text formats (.hedra, .HYBRID): `nv` lines of "x y z", and
// `nf` lines "n v1 .. vn" with vertex ids counted from `base` (0 or 1). Filled into `in` with the
// line of each element.
void read_points(TextScanner& s, int64_t nv, MeshInput& in);
void read_face_loops(TextScanner& s, int64_t nf, int64_t nv, int base, MeshInput& in);

// Lower-case copy for case-insensitive keywords.
std::string lower(std::string_view s);

}  // namespace hbc::detail
