#pragma once
// gzip-compressed files (OpenFOAM writes `points.gz` etc. with writeCompression on). The one place
// the readers call zlib for whole files; built without zlib (CMake option HBC_GZIP=OFF, e.g. for
// WebAssembly), gunzip refuses with a message that says so.
#include <string>
#include <string_view>

namespace hbc::detail {

// True when the bytes start with gzip's magic number.
inline bool is_gzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f && static_cast<unsigned char>(bytes[1]) == 0x8b;
}

// The inflated bytes of every gzip member in `bytes`; InputError naming `source` (and the byte
// offset of the compressed data where it went wrong) for data that is not gzip.
std::string gunzip(std::string_view bytes, const std::string& source);

}  // namespace hbc::detail
