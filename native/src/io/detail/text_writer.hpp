#pragma once
// Number formatting shared by the text writers: the shortest decimal text that reads back to the
// same value (std::to_chars round trip), appended without temporaries.
#include <charconv>
#include <cstdint>
#include <string>

#include "platform/charconv.hpp"

namespace hbc::detail {

inline void append_real(std::string& out, double x) {
  char buf[32];
  out.append(buf, to_chars_shortest(buf, buf + sizeof buf, x));
}

inline void append_int(std::string& out, int64_t x) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

}  // namespace hbc::detail
