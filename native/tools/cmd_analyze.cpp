// TEMPORARY: replaced by the analysis in this session.
#include <stdexcept>
#include "commands.hpp"
namespace hbc::cli {
int cmd_analyze(const Args&) { throw std::invalid_argument("analyze: not built yet"); }
}
