#pragma once
// The hbc command's subcommands, one file each. Each returns the process exit status:
// 0 success, 1 usage error, 2 bad input (message on stderr naming file and line).
#include <optional>
#include <string>
#include <vector>

#include "hbc/io.hpp"

namespace hbc::cli {

using Args = std::vector<std::string>;

int cmd_info(const Args& args);
int cmd_generate(const Args& args);
int cmd_export_surface(const Args& args);
int cmd_export_vtu(const Args& args);
int cmd_analyze(const Args& args);
int cmd_wireframe(const Args& args);
int cmd_sheets(const Args& args);
int cmd_table(const Args& args);
int cmd_quality(const Args& args);

// Small shared helpers for argument handling.
bool take_flag(Args& args, const std::string& flag);                       // removes it if present
std::optional<std::string> take_option(Args& args, const std::string& opt);  // "--opt value"
// How to read the input: --format NAME (or Auto) and --threads N (default: HBC_THREADS, else
// every core).
struct InputFormat {
  Format format = Format::Auto;
  LoadOptions load;
  operator Format() const { return format; }
};
InputFormat take_format(Args& args);
// Loads a mesh and prints its warnings on stderr.
Mesh load_for_cli(const std::string& path, const InputFormat& format, double* seconds = nullptr);

}  // namespace hbc::cli
