#include "hbc/level.hpp"

#include <stdexcept>
#include <string>

namespace hbc {

const char* level_name(Level level) { return level == Level::Mesh ? "mesh" : "complex"; }

Level level_from_name(std::string_view name) {
  if (name == "mesh") return Level::Mesh;
  if (name == "complex") return Level::Complex;
  throw std::invalid_argument("level must be 'complex' or 'mesh', not '" + std::string(name) + "'");
}

}  // namespace hbc
