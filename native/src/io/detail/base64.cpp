#include "io/detail/base64.hpp"

#include <cstdint>

namespace hbc::detail {

static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64_encode(std::string_view in) {
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (size_t i = 0; i < in.size(); i += 3) {
    const size_t n = in.size() - i;
    uint32_t w = static_cast<uint32_t>(static_cast<unsigned char>(in[i])) << 16;
    if (n > 1) w |= static_cast<uint32_t>(static_cast<unsigned char>(in[i + 1])) << 8;
    if (n > 2) w |= static_cast<unsigned char>(in[i + 2]);
    out += kAlphabet[w >> 18];
    out += kAlphabet[(w >> 12) & 63];
    out += n > 1 ? kAlphabet[(w >> 6) & 63] : '=';
    out += n > 2 ? kAlphabet[w & 63] : '=';
  }
  return out;
}

static int value(char ch) {
  if (ch >= 'A' && ch <= 'Z') return ch - 'A';
  if (ch >= 'a' && ch <= 'z') return ch - 'a' + 26;
  if (ch >= '0' && ch <= '9') return ch - '0' + 52;
  if (ch == '+') return 62;
  if (ch == '/') return 63;
  if (ch == '=') return 64;
  return -1;
}

bool base64_decode(std::string_view s, std::string& out, size_t& bad_at, std::string& why) {
  out.clear();
  out.reserve(s.size() / 4 * 3);
  int q[4];
  int nq = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const char ch = s[i];
    if (ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t') continue;
    const int v = value(ch);
    if (v < 0) {
      bad_at = i;
      why = "base64 data, found the character code " + std::to_string(static_cast<unsigned char>(ch));
      return false;
    }
    q[nq++] = v;
    if (nq < 4) continue;
    nq = 0;
    if (q[0] == 64 || q[1] == 64 || (q[2] == 64 && q[3] != 64)) {
      bad_at = i;
      why = "base64 padding only at the end of a group of 4 characters";
      return false;
    }
    const uint32_t w = (static_cast<uint32_t>(q[0]) << 18) | (static_cast<uint32_t>(q[1]) << 12) |
                       (static_cast<uint32_t>(q[2] & 63) << 6) | static_cast<uint32_t>(q[3] & 63);
    out.push_back(static_cast<char>(w >> 16));
    if (q[2] != 64) out.push_back(static_cast<char>((w >> 8) & 255));
    if (q[3] != 64) out.push_back(static_cast<char>(w & 255));
  }
  if (nq != 0) {
    bad_at = s.size();
    why = "base64 data in groups of 4 characters, found " + std::to_string(nq) + " left over";
    return false;
  }
  return true;
}

}  // namespace hbc::detail
