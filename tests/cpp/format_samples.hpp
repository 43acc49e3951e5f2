#pragma once
// Binary files encoded field by field, for the format tests and the malformed-file corpus.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

namespace hbc::test {

// Appends numbers in native order, or byte-swapped (the other endianness).
struct Bytes {
  std::string s;
  bool swap = false;
  template <class T>
  Bytes& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (swap) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& t) {
    s += t;
    return *this;
  }
};

// prism_gmsh.msh as binary 4.1 (size_t of 8 bytes) in the chosen byte order. Byte offsets:
// check value 20, $Nodes header 47 (node count at 55), node block 79, tags 99, coordinates 147,
// $Elements header 312, element block 344 (type at 352), element 364, its node tags 372-419.
inline std::string prism_msh41_binary(bool swap) {
  const double pts[6][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  Bytes b{"", swap};
  b.text("$MeshFormat\n4.1 1 8\n").put<int32_t>(1).text("\n$EndMeshFormat\n$Nodes\n");
  b.put<uint64_t>(1).put<uint64_t>(6).put<uint64_t>(1).put<uint64_t>(6);
  b.put<int32_t>(3).put<int32_t>(1).put<int32_t>(0).put<uint64_t>(6);
  for (uint64_t t = 1; t <= 6; ++t) b.put<uint64_t>(t);
  for (auto& p : pts)
    for (double x : p) b.put<double>(x);
  b.text("\n$EndNodes\n$Elements\n");
  b.put<uint64_t>(1).put<uint64_t>(1).put<uint64_t>(1).put<uint64_t>(1);
  b.put<int32_t>(3).put<int32_t>(1).put<int32_t>(6).put<uint64_t>(1);
  b.put<uint64_t>(1);
  for (uint64_t t = 1; t <= 6; ++t) b.put<uint64_t>(t);
  b.text("\n$EndElements\n");
  return b.s;
}

}  // namespace hbc::test
