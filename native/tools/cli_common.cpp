#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "commands.hpp"

namespace hbc::cli {
namespace {

// A CLI11 check from one of the library's parsers: the value is valid when `parse` accepts it,
// and the parser's own message says why not, so the CLI and the binding cannot disagree.
template <class Parse>
CLI::Validator parsed_by(Parse parse, const std::string& description) {
  return CLI::Validator(
      [parse](std::string& value) -> std::string {
        try {
          parse(value);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      description);
}

}  // namespace

namespace {

// "a|b|c" of the format names, or ".a, .b, .c" of their extensions (formats(), the one list).
std::string format_list(bool extensions) {
  std::string out;
  for (const FormatInfo& f : formats()) {
    if (!out.empty()) out += extensions ? ", " : "|";
    out += extensions ? f.extension : f.name;
  }
  return out;
}

}  // namespace

void add_format(CLI::App& cmd, std::string& format) {
  cmd.add_option("--format", format, "file format (default: by the file's extension)")
      ->check(parsed_by([](const std::string& s) { format_from_name(s); }, format_list(false)));
}

void add_input(CLI::App& cmd, InputArgs& in) {
  cmd.add_option("FILE", in.file, "mesh file (" + format_list(true) + ") or OpenFOAM case folder ('CASE/processor*': its processors joined)")->required();
  add_reading_options(cmd, in);
}

void add_reading_options(CLI::App& cmd, InputArgs& in) {
  add_format(cmd, in.format);
  cmd.add_option("--threads", in.threads, "threads for reading and analysing the mesh (default: HBC_THREADS, else every core)")
      ->check(CLI::Range(1, 1024));
  cmd.add_flag("--skip-invalid", in.skip_invalid,
               "drop the cells that cannot be volumes (docs/check.md) instead of refusing the file; stderr says which");
}

std::vector<std::string> reading_args(const InputArgs& in) {
  std::vector<std::string> out;
  if (!in.format.empty()) out.insert(out.end(), {"--format", in.format});
  if (in.threads > 0) out.insert(out.end(), {"--threads", std::to_string(in.threads)});
  if (in.skip_invalid) out.push_back("--skip-invalid");
  return out;
}

CLI::App* add_mesh_command(CLI::App& app, const std::string& name, const std::string& help, InputArgs& input,
                           bool& json, const std::string& json_help) {
  CLI::App* cmd = app.add_subcommand(name, help);
  add_input(*cmd, input);
  cmd->add_flag("--json", json, json_help);
  return cmd;
}

CLI::App* add_export_command(CLI::App& app, const std::string& name, const std::string& help, InputArgs& input,
                             std::string& out, const std::string& out_help) {
  CLI::App* cmd = app.add_subcommand(name, help);
  add_input(*cmd, input);
  cmd->add_option("-o", out, out_help)->required();
  return cmd;
}

void add_sheet_option(CLI::App& cmd, std::optional<int32_t>& sheet, const std::string& help) {
  cmd.add_option("--sheet", sheet, help)->check(at_least(0));
}

void check_sheet_option(const Analysis& a, const std::optional<int32_t>& sheet) {
  const size_t n = a.sheet_stage ? a.sheet_stage->sheets.size() : 0;
  if (sheet && static_cast<size_t>(*sheet) >= n)
    throw std::invalid_argument("--sheet " + std::to_string(*sheet) + ": the mesh has " + std::to_string(n) + " sheets");
}

void add_level(CLI::App& cmd, std::string& level, const std::string& help) {
  cmd.add_option("--level", level, help)
      ->check(parsed_by([](const std::string& s) { level_from_name(s); }, "complex|mesh"))
      ->capture_default_str();
}

CLI::Range at_least(int min) { return CLI::Range(min, std::numeric_limits<int32_t>::max()); }

AnalysisOptions analysis_options(const InputArgs& in, std::vector<OptionSetting> settings) {
  if (in.threads > 0) settings.push_back({"threads", int64_t{in.threads}});
  return analyze_settings(settings).options;
}

Mesh load_for_cli(const InputArgs& in, double* seconds, std::vector<DroppedCell>* dropped) {
  auto t0 = std::chrono::steady_clock::now();
  std::vector<DroppedCell> skipped;
  Mesh m = in.skip_invalid ? load_mesh_skipping_invalid(in.file, skipped, in.parsed_format(), in.load_threads())
                           : load_mesh(in.file, in.parsed_format(), in.load_threads());
  if (dropped) *dropped = std::move(skipped);
  auto t1 = std::chrono::steady_clock::now();
  if (seconds) *seconds = std::chrono::duration<double>(t1 - t0).count();
  for (const auto& w : m.warnings) std::fprintf(stderr, "hbc: warning: %s: %s\n", in.file.c_str(), w.c_str());
  return m;
}

void write_output(const std::string& text, const std::optional<std::string>& path) {
  if (path) {
    std::ofstream f(*path, std::ios::binary);
    if (!f || !(f << text)) throw std::runtime_error("cannot write " + *path);
  } else {
    std::fwrite(text.data(), 1, text.size(), stdout);
  }
}

}  // namespace hbc::cli
