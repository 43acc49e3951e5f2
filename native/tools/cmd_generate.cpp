// TEMPORARY: replaced by the generators in this session.
#include <stdexcept>
#include "commands.hpp"
namespace hbc::cli {
int cmd_generate(const Args&) { throw std::invalid_argument("generate: not built yet"); }
}
