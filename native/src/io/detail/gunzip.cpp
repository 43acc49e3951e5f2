#include "io/detail/gunzip.hpp"

#include "hbc/error.hpp"

#if HBC_GZIP
#include <zlib.h>

#include <algorithm>
#include <memory>
#endif

namespace hbc::detail {

#if HBC_GZIP
std::string gunzip(std::string_view bytes, const std::string& source) {
  z_stream z{};
  // 16 + MAX_WBITS: a gzip header and trailer around the deflate data.
  if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) throw InputError(source, {}, "expected gzip data (zlib could not start)");
  const std::unique_ptr<z_stream, int (*)(z_stream*)> end(&z, inflateEnd);
  std::string out;
  // The trailer's size (mod 2^32) of the last member, as a first guess; the loop grows past it.
  if (bytes.size() >= 18) {
    uint32_t isize = 0;
    for (int k = 3; k >= 0; --k) isize = (isize << 8) | static_cast<unsigned char>(bytes[bytes.size() - 4 + static_cast<size_t>(k)]);
    out.reserve(std::min<size_t>(isize, 1032 * bytes.size()));
  }
  size_t in_pos = 0;
  while (in_pos < bytes.size()) {
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + in_pos));
    z.avail_in = static_cast<uInt>(std::min<size_t>(bytes.size() - in_pos, 1u << 30));
    int rc = Z_OK;
    while (rc == Z_OK) {
      const size_t have = out.size();
      out.resize(have + std::max<size_t>(1 << 16, have / 2));
      z.next_out = reinterpret_cast<Bytef*>(out.data() + have);
      z.avail_out = static_cast<uInt>(out.size() - have);
      rc = inflate(&z, Z_NO_FLUSH);
      out.resize(out.size() - z.avail_out);
    }
    const size_t used = static_cast<size_t>(reinterpret_cast<const char*>(z.next_in) - bytes.data());
    if (rc != Z_STREAM_END)
      throw InputError(source, SourceLoc::at_byte(static_cast<int64_t>(used)),
                       std::string("expected gzip data (zlib: ") + (z.msg ? z.msg : rc == Z_BUF_ERROR ? "cut short" : zError(rc)) + ")");
    in_pos = used;
    // Another member may follow (concatenated .gz files); padding zeros end the data.
    while (in_pos < bytes.size() && bytes[in_pos] == '\0') ++in_pos;
    if (in_pos < bytes.size()) inflateReset(&z);
  }
  return out;
}
#else
std::string gunzip(std::string_view, const std::string& source) {
  throw InputError(source, {}, "expected an uncompressed file (this hbc was built without zlib, HBC_GZIP=OFF: gunzip the file first)");
}
#endif

}  // namespace hbc::detail
