#pragma once
// The two levels every structure stage can work at (docs/concepts.md, "Level"): the fine mesh as it
// is, or the hybrid base complex seen as a coarse mesh (the paper's, §4 and its T_VSGW). Sheets, the cell complex and the
// VSG wireframe all take this one enum; the CLI and the binding parse its name with level_from_name.
#include <cstdint>
#include <string_view>

namespace hbc {

enum class Level : uint8_t { Mesh = 0, Complex = 1 };

const char* level_name(Level level);  // "mesh" or "complex"
// "mesh" or "complex" (exactly); anything else throws std::invalid_argument naming the value.
Level level_from_name(std::string_view name);

}  // namespace hbc
