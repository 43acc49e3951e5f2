#include "hbc/error.hpp"

namespace hbc {

std::string format_location(const std::string& file, SourceLoc loc) {
  if (loc.line >= 0) return file + ":" + std::to_string(loc.line) + ": ";
  if (loc.byte_offset >= 0) return file + ": byte " + std::to_string(loc.byte_offset) + ": ";
  return file + ": ";
}

InputError::InputError(std::string file, SourceLoc loc, const std::string& what)
    : std::runtime_error(format_location(file, loc) + what),
      file_(std::move(file)),
      loc_(loc),
      detail_(what) {}

}  // namespace hbc
