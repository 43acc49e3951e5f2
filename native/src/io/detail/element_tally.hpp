#pragma once
// Element-list formats (Gmsh, VTK, VTU, the FE decks) mix points, lines and surface elements with the volume
// cells; the readers skip those and report how many in one warning.
#include <array>
#include <cstdint>
#include <string>

#include "hbc/mesh.hpp"

namespace hbc::detail {

class ElementTally {
 public:
  void skip(int dim) { ++n_[static_cast<size_t>(dim < 0 ? 0 : dim > 2 ? 2 : dim)]; }
  void add(const ElementTally& o) {
    for (size_t d = 0; d < 3; ++d) n_[d] += o.n_[d];
  }
  int64_t skipped() const { return n_[0] + n_[1] + n_[2]; }
  // Adds "read past N point, line and surface element(s)" to the input's warnings when any.
  void report(MeshInput& in) const {
    if (skipped() == 0) return;
    in.warnings.push_back("read past " + std::to_string(n_[0]) + " point, " + std::to_string(n_[1]) + " line and " +
                          std::to_string(n_[2]) + " surface element(s); only volume elements are cells");
  }

 private:
  std::array<int64_t, 3> n_{};
};

}  // namespace hbc::detail
