// TEMPORARY: replaced by the real subcommands in this session.
#include <stdexcept>
#include "commands.hpp"
namespace hbc::cli {
int cmd_generate(const Args&) { throw std::invalid_argument("generate: not built yet"); }
int cmd_export_surface(const Args&) { throw std::invalid_argument("export-surface: not built yet"); }
int cmd_analyze(const Args&) { throw std::invalid_argument("analyze: not built yet"); }
}
