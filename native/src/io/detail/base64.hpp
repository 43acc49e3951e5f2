#pragma once
// Base64 as VTK's XML files use it (RFC 4648 alphabet, '=' padding).
#include <cstddef>
#include <string>
#include <string_view>

namespace hbc::detail {

std::string base64_encode(std::string_view bytes);

// Decodes group by group of 4 characters, so that separately encoded pieces written one after the
// other (VTK encodes a header and its data apart, leaving padding mid-stream) decode as one stream.
// Whitespace is skipped. On bad input returns false with `bad_at` the offset of the offending
// character and `why` what was expected there.
bool base64_decode(std::string_view text, std::string& out, size_t& bad_at, std::string& why);

}  // namespace hbc::detail
