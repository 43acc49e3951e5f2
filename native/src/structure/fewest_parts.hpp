#pragma once
// The fewest subsheets of one sheet as an abstract problem (docs/validation.md): split the curves
// 0..n-1 into parts, each connected over `parallels` and holding no pair listed in `conflicts`,
// with as few parts as possible. Internal to the subsheet stage; the tests call it on small
// graphs whose minimum they derive by hand.
#include <cstdint>
#include <vector>

#include "hbc/csr.hpp"

namespace hbc::detail {

struct FewestParts {
  std::vector<int32_t> part;  // per curve, its part (parts numbered by their lowest curve)
  int32_t count = 0;          // parts
  int32_t lower_bound = 0;    // no split has fewer parts (the largest set of pairwise conflicting curves)
  bool proven = false;        // count is the minimum: it meets the bound, or the search was exhaustive
  int64_t nodes = 0;          // search nodes spent
};

// `parallels` and `conflicts`: n rows each, symmetric, sorted. `node_budget` caps the exact search
// (a count of steps, not seconds, so the answer does not depend on the machine or its load).
// `hint` (n entries, or empty): a grouping of the curves to start from (the authors' layers), each
// group split into conflict-free connected pieces before the merges.
FewestParts fewest_parts(const Csr<int32_t>& parallels, const Csr<int32_t>& conflicts, int64_t node_budget,
                         const std::vector<int32_t>& hint = {});

}  // namespace hbc::detail
