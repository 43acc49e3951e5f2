#pragma once
// Fast path of the text readers for a section of n lines holding the same number of plain
// numbers each (MEDIT's Vertices and element sections, as every mesher writes them): the
// section's line starts are found with memchr, then threads parse ranges of lines straight into
// the output arrays with std::from_chars, without tokens or allocations. Anything else (comments,
// blank lines, entries spread over lines, '+' signs, values out of range) makes it return false
// and leave the scanner untouched, so the token-by-token path reads the section and words the
// message exactly as before.
#include <cstdint>
#include <vector>

#include "io/detail/text_scanner.hpp"

namespace hbc::detail {

// n lines of "x y z ref" after the scanner's position (the rest of the current line blank):
// appends 3 coordinates per line to points and the line number to lines.
bool fast_vertex_lines(TextScanner& s, int64_t n, std::vector<double>& points, std::vector<int64_t>& lines,
                       const Threads& par);

// n lines of `k` vertex ids in [1, 2^31) then a reference number: appends the ids to ids and
// the line number to lines.
bool fast_element_lines(TextScanner& s, int64_t n, int k, std::vector<int32_t>& ids, std::vector<int64_t>& lines,
                        const Threads& par);

}  // namespace hbc::detail
