#pragma once
// Errors raised for bad input. Every message names the file, the place in it and what was expected,
// so that a user can open the file at that spot; the CLI maps InputError to exit status 2.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace hbc {

// Where in a file something was found. For text files `line` is 1-based; for binary files
// `byte_offset` is set instead. Both unset (-1) means "the file as a whole".
struct SourceLoc {
  int64_t line = -1;
  int64_t byte_offset = -1;
  static SourceLoc at_line(int64_t l) { return {l, -1}; }
  static SourceLoc at_byte(int64_t b) { return {-1, b}; }
};

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, SourceLoc loc, const std::string& what);
  const std::string& file() const { return file_; }
  const SourceLoc& loc() const { return loc_; }
  // The message without the "file:line: " prefix.
  const std::string& detail() const { return detail_; }

 private:
  std::string file_;
  SourceLoc loc_;
  std::string detail_;
};

// Formats "file:line: " / "file: byte N: " / "file: ".
std::string format_location(const std::string& file, SourceLoc loc);

}  // namespace hbc
