// TEMPORARY: replaced by the OpenMesh export in this session.
#include <stdexcept>
#include "commands.hpp"
namespace hbc::cli {
int cmd_export_surface(const Args&) { throw std::invalid_argument("export-surface: not built yet"); }
}
