#pragma once
// The hbc command's subcommands, one file each, on CLI11. Each add_<command> registers its
// subcommand on the top-level app: its options (typed, with ranges and choices, so CLI11 rejects
// bad values before any work) and a callback that runs the command once the line has parsed.
// Exit status (set in hbc_main.cpp; docs/development.md): 0 success; 1 a malformed command line (unknown
// option, missing argument); 2 bad input: a value an option cannot take (`--rho abc`, `--rho 7`),
// or a file that cannot be read (message on stderr naming file and line).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "hbc/exports.hpp"
#include "hbc/io.hpp"
#include "hbc/level.hpp"

namespace hbc::cli {

void add_info(CLI::App& app);
void add_generate(CLI::App& app);
void add_export_surface(CLI::App& app);
void add_export_html(CLI::App& app);
void add_analyze(CLI::App& app);
void add_wireframe(CLI::App& app);
void add_sheets(CLI::App& app);
void add_table(CLI::App& app);
void add_export_vtu(CLI::App& app);
void add_quality(CLI::App& app);
void add_check(CLI::App& app);
void add_metrics(CLI::App& app);
void add_compare(CLI::App& app);
// hbc gallery: runs `python -m hbc.gallery` (docs/gallery.md).
void add_gallery(CLI::App& app);

// The mesh file every reading command takes: FILE, --format NAME (default: by extension) and
// --threads N (default: HBC_THREADS, else every core; the results are the same for any number).
struct InputArgs {
  std::string file;
  std::string format;  // empty: by extension; else a name format_from_name accepts
  int threads = 0;     // 0: HBC_THREADS, else every core (Threads::count)
  bool skip_invalid = false;  // drop the cells build_mesh refuses (hbc/check.hpp) instead of failing
  Format parsed_format() const { return format.empty() ? Format::Auto : format_from_name(format); }
  Threads load_threads() const {
    Threads o;
    if (threads > 0) o.count = threads;
    return o;
  }
};
void add_input(CLI::App& cmd, InputArgs& in);
// --format, --threads and --skip-invalid alone, with the help every reading command gives them: for
// the commands that read many meshes, each in a child (table, compare), which passes them on.
void add_reading_options(CLI::App& cmd, InputArgs& in);
// Those options of `in` as a child's arguments (the ones given; none for the defaults).
std::vector<std::string> reading_args(const InputArgs& in);
// A subcommand that reads one mesh: FILE and --format into `input`, --json (help `json_help`) into
// `json`. Returns the subcommand for its own options.
CLI::App* add_mesh_command(CLI::App& app, const std::string& name, const std::string& help, InputArgs& input,
                           bool& json, const std::string& json_help = "print JSON");
// --format NAME alone (for writers).
void add_format(CLI::App& cmd, std::string& format);
// --level complex|mesh, parsed by level_from_name (the binding's parser too).
void add_level(CLI::App& cmd, std::string& level, const std::string& help);

// A subcommand that reads one mesh (FILE, --format) and writes -o OUT (required; help `out_help`).
CLI::App* add_export_command(CLI::App& app, const std::string& name, const std::string& help, InputArgs& input,
                             std::string& out, const std::string& out_help);
// --sheet N (N >= 0; absent: none), help `help`.
void add_sheet_option(CLI::App& cmd, std::optional<int32_t>& sheet, const std::string& help);
// Throws std::invalid_argument ("--sheet N: the mesh has K sheets") unless the analysis' sheet
// stage holds `sheet` (when one is given).
void check_sheet_option(const Analysis& analysis, const std::optional<int32_t>& sheet);

// An integer option's range [min, INT32_MAX] (CLI11's NonNegativeNumber prints DBL_MAX).
CLI::Range at_least(int min);

// The analysis options of a command: `settings` (analyze's options by name, hbc/exports.hpp, the
// reader Python's and JavaScript's analyze use) and --threads when given. CLI11 has checked every
// value the command line gave, so a throw here is a command's own mistake.
AnalysisOptions analysis_options(const InputArgs& in, std::vector<OptionSetting> settings);

// Loads a mesh and prints its warnings on stderr (with --skip-invalid, what was dropped, which
// `dropped` receives when given).
Mesh load_for_cli(const InputArgs& in, double* seconds = nullptr, std::vector<DroppedCell>* dropped = nullptr);
// Writes `text` to `path`, or to stdout when there is none.
void write_output(const std::string& text, const std::optional<std::string>& path);

}  // namespace hbc::cli
