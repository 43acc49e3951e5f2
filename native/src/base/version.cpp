#include "hbc/version.hpp"

namespace hbc {

const char* version() { return HBC_VERSION; }

}  // namespace hbc
