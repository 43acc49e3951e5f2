// hbc export-html FILE -o VIEW.html [--viewer PATH]: one self-contained page showing FILE in the
// browser: the viewer page built by scripts/build_web.sh with the mesh's bytes embedded in its
// placeholder element (base64), so the page needs neither a server nor the file beside it.
#include <algorithm>
#include <cctype>
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "locate.hpp"
#include "hbc/error.hpp"

namespace hbc::cli {
namespace {

namespace fs = std::filesystem;

// The viewer's one empty placeholder; the page decodes the element's text and reads it with the
// reader its data-name's extension picks, as the CLI would.
constexpr std::string_view kPlaceholder =
    R"(<script type="application/octet-stream" id="hbc-embedded-mesh" data-name=""></script>)";

struct ExportHtmlArgs {
  InputArgs input;
  std::string out;
  std::string viewer;  // empty: $HBC_VIEWER, then beside the executable
};

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int shift : {18, 12, 6, 0}) out += kAlphabet[(v >> shift) & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += two ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// The name goes into an attribute value in double quotes.
std::string html_attribute(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + p.string());
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// What the page reads: the file's own bytes under its own name when it is one file whose extension
// names its format and the page's core reads it; else (an OpenFOAM case, Exodus II, CGNS, MED or XDMF, a
// format given by --format, cells dropped by --skip-invalid) the loaded mesh written as
// OpenVolumeMesh ASCII, which keeps every cell as read.
// Then the page cannot tell what reading the source said (how many cells --skip-invalid dropped,
// ...): `warnings` carries the CLI's warning lines ("FILE: TEXT"), which the page shows.
struct Embedded {
  std::string name, bytes, warnings;
};
Embedded embedded_mesh(const InputArgs& in, const Mesh& mesh) {
  const fs::path path(in.file);
  Format by_name = Format::Foam;  // a folder is a case
  if (fs::is_regular_file(path)) {
    try {
      by_name = format_from_path(in.file);
    } catch (const InputError&) {
      by_name = Format::Auto;  // read by --format; its name would not tell the page the format
    }
  }
  // The page's WebAssembly core has neither netCDF-C, the CGNS library nor HDF5: those go in as .ovm.
  const bool page_reads = by_name != Format::Exodus && by_name != Format::Cgns && by_name != Format::Med &&
                          by_name != Format::Xdmf;  // its data lies in another file
  const bool as_read = by_name != Format::Foam && by_name != Format::Auto && page_reads && !in.skip_invalid &&
                       (in.format.empty() || in.parsed_format() == by_name);
  if (as_read) {
    std::string bytes = read_file_bytes(in.file);
    // A deck that includes other files cannot be read from its own bytes in the page (any
    // "include" in it counts: the mesh as OVM is right either way).
    const bool deck = by_name == Format::Abaqus || by_name == Format::Nastran || by_name == Format::LsDyna;
    const auto ci = [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; };
    const std::string_view word = "include";
    if (!deck || std::search(bytes.begin(), bytes.end(), word.begin(), word.end(), ci) == bytes.end())
      return {path.filename().string(), std::move(bytes), {}};
  }
  std::string stem = fs::is_directory(path) ? fs::absolute(path).lexically_normal().filename().string() : path.stem().string();
  if (stem.empty()) stem = "mesh";
  std::string warnings;
  for (const std::string& w : mesh.warnings) warnings += (warnings.empty() ? "" : "\n") + in.file + ": " + w;
  return {stem + ".ovm", ovm_text(mesh), warnings};
}

void run_export_html(const ExportHtmlArgs& args) {
  // The mesh first: a bad file fails as in every other command, before the page is looked for.
  const Mesh mesh = load_for_cli(args.input);
  const fs::path viewer = viewer_page(args.viewer);
  std::string page = read_text(viewer);
  const size_t at = page.find(kPlaceholder);
  if (at == std::string::npos || page.find(kPlaceholder, at + 1) != std::string::npos)
    throw std::runtime_error(viewer.string() + ": not a viewer page (expected one empty " + std::string(kPlaceholder) +
                             "; rebuild it with `bash scripts/build_web.sh`)");
  const Embedded e = embedded_mesh(args.input, mesh);
  const std::string warnings = e.warnings.empty() ? "" : " data-warnings=\"" + html_attribute(e.warnings) + "\"";
  const std::string element = R"(<script type="application/octet-stream" id="hbc-embedded-mesh" data-name=")" +
                              html_attribute(e.name) + "\"" + warnings + ">" + base64(e.bytes) + "</script>";
  page.replace(at, kPlaceholder.size(), element);
  write_output(page, args.out);
  std::printf("wrote %s: %s embedded (%zu bytes), %zu cells\n", args.out.c_str(), e.name.c_str(), e.bytes.size(),
              mesh.num_cells());
}

}  // namespace

void add_export_html(CLI::App& app) {
  auto args = std::make_shared<ExportHtmlArgs>();
  CLI::App* cmd = add_export_command(app, "export-html", "a self-contained web page showing the mesh (the browser viewer)",
                                     args->input, args->out, "output page, .html");
  cmd->add_option("--viewer", args->viewer,
                  "viewer page to embed into (default: $HBC_VIEWER, else build/web/viewer.html beside the executable)");
  cmd->callback([args] { run_export_html(*args); });
}

}  // namespace hbc::cli
