#pragma once
// VSG wireframe simplification (paper §5.2): non-important vertices and edges, reactivation, and
// the kept chains re-chained: vsg_simplification.cpp.
#include <cstdint>
#include <vector>

#include "structure/vsg_chains.hpp"

namespace hbc::vsg {

// Per complete chain: redundant_vert (nv): a redundant singular vertex (non-important);
// non_important: 0 kept, 1 both ends redundant, 2 in a removable pair; reactivated; kept.
struct Cleaning {
  std::vector<uint8_t> redundant_vert, non_important, reactivated, kept;
};

// The non-important chains of the complete wireframe `ch` and the reactivated ones; `parallel`:
// complex edges whose all-parallel chains are removed last (a sheet's wireframe).
Cleaning clean_chains(const Region& r, const Chains& ch, const std::vector<uint8_t>& singular,
                      const std::vector<uint8_t>& parallel, const Threads& par);
// The kept chains re-chained through the vertices that stop being singular.
Chains final_chains(const Region& r, const Chains& ch, const std::vector<uint8_t>& kept, const Threads& par);

}  // namespace hbc::vsg
