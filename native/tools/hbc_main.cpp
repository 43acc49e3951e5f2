// hbc: the structure analyser for hex-dominant meshes, command-line front end (CLI11).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "hbc/error.hpp"
#include "hbc/io.hpp"
#include "hbc/version.hpp"

namespace {

// A value an option cannot take is bad input (2), like a bad file; any other mistake
// in the command line is a usage error (1); --help and --version succeed (0).
int exit_status(const CLI::ParseError& e, int cli11_status) {
  if (cli11_status == 0) return 0;
  const bool bad_value = dynamic_cast<const CLI::ConversionError*>(&e) || dynamic_cast<const CLI::ValidationError*>(&e);
  return bad_value ? 2 : 1;
}

// "ovm, ovmb, ...": the names of the one format table.
std::string format_names() {
  std::string s;
  for (const hbc::FormatInfo& f : hbc::formats()) s += (s.empty() ? "" : ", ") + std::string(f.name);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hbc: structure of hex-dominant meshes (hybrid singularity graph, base complex, sheets, VSG wireframe)."
               "\nformats: " + format_names() + " (chosen by extension unless --format is given)",
               "hbc"};
  app.set_version_flag("--version", std::string("hbc ") + hbc::version());
  app.require_subcommand(1);
  hbc::cli::add_info(app);
  hbc::cli::add_analyze(app);
  hbc::cli::add_sheets(app);
  hbc::cli::add_table(app);
  hbc::cli::add_export_vtu(app);
  hbc::cli::add_quality(app);
  hbc::cli::add_metrics(app);
  hbc::cli::add_compare(app);
  hbc::cli::add_gallery(app);
  hbc::cli::add_check(app);
  hbc::cli::add_generate(app);
  hbc::cli::add_export_surface(app);
  hbc::cli::add_export_html(app);
  hbc::cli::add_wireframe(app);
  try {
    app.parse(argc, argv);  // runs the chosen command's callback
    return 0;
  } catch (const CLI::ParseError& e) {
    return exit_status(e, app.exit(e));
  } catch (const hbc::InputError& e) {
    std::fprintf(stderr, "hbc: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "hbc: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "hbc: error: out of memory\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hbc: error: %s\n", e.what());
    return 2;
  }
}
