// export-surface in the WebAssembly build: OpenMesh is not built for it, so the subcommand is
// listed (the command line stays the same) and says so when run (exit status 2).
#include <stdexcept>

#include "../tools/commands.hpp"

namespace hbc::cli {

void add_export_surface(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("export-surface", "surfaces through OpenMesh (not in this WebAssembly build)");
  cmd->allow_extras();
  cmd->callback([] { throw std::runtime_error("export-surface needs OpenMesh, which the WebAssembly build leaves out"); });
}

}  // namespace hbc::cli
