// hbc export-html: the page is the viewer template with its one placeholder element replaced by the
// mesh, base64 of its bytes under its file name; the rest of the template is kept byte for byte.
// A tiny template stands in for the built viewer, so these tests need no browser and no web build
// (tests/web/ opens real exported pages in chromium).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "hbc/generate.hpp"
#include "io/detail/base64.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::slurp;

constexpr const char* kPlaceholder =
    R"(<script type="application/octet-stream" id="hbc-embedded-mesh" data-name=""></script>)";
const std::string kHead = "<!doctype html>\n<html><body>\n";
const std::string kTail = "\n<script>/* viewer */</script>\n</body></html>\n";

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

class CliExportHtml : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_);
    write_file(tpl_, kHead + kPlaceholder + kTail);
    mesh_text_ = medit_text(build_mesh(generate_sector(5, 1, 1)));
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string q(const fs::path& p) const { return "'" + p.string() + "'"; }

  // The page's embedded element: its data-name and the decoded bytes; fails the test when the
  // page is not the template with the placeholder replaced, or the text is not pure base64.
  struct Embedded {
    std::string name, bytes;
  };
  Embedded embedded(const fs::path& page_path) {
    const std::string page = slurp(page_path);
    EXPECT_EQ(page.substr(0, kHead.size()), kHead);
    EXPECT_EQ(page.substr(page.size() - kTail.size()), kTail);
    const std::string open = R"(<script type="application/octet-stream" id="hbc-embedded-mesh" data-name=")";
    EXPECT_EQ(page.compare(kHead.size(), open.size(), open), 0) << page.substr(0, 300);
    const size_t name_at = kHead.size() + open.size();
    const size_t name_end = page.find("\">", name_at);
    const size_t text_end = page.find("</script>", name_end);
    EXPECT_EQ(text_end + 9, page.size() - kTail.size());
    Embedded e{page.substr(name_at, name_end - name_at), {}};
    const std::string text = page.substr(name_end + 2, text_end - name_end - 2);
    // HTML-safe: only the base64 alphabet, so no '<' can end the element early.
    EXPECT_EQ(text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/="),
              std::string::npos);
    size_t bad_at = 0;
    std::string why;
    EXPECT_TRUE(detail::base64_decode(text, e.bytes, bad_at, why)) << why << " at " << bad_at;
    return e;
  }

  const fs::path dir_ = fs::temp_directory_path() / ("hbc_cli_html_" + std::to_string(::getpid()));
  const fs::path tpl_ = dir_ / "tpl.html";
  std::string mesh_text_;
};

// Round trip: the decoded bytes are the file's. Files of three successive lengths cover the three
// base64 endings (no padding, "=", "=="), since one of any three lengths is 0, 1, 2 mod 3.
TEST_F(CliExportHtml, EmbedsTheFilesBytesUnderItsName) {
  for (int extra = 0; extra < 3; ++extra) {
    const std::string bytes = mesh_text_ + std::string(extra, '\n');
    write_file(dir_ / "s.mesh", bytes);
    const test::CliRun r = run_cli("export-html " + q(dir_ / "s.mesh") + " -o " + q(dir_ / "s.html") + " --viewer " + q(tpl_));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("wrote"), std::string::npos) << r.out;
    const Embedded e = embedded(dir_ / "s.html");
    EXPECT_EQ(e.name, "s.mesh");
    EXPECT_EQ(e.bytes, bytes) << "extra newlines " << extra;
  }
}

// The name is an attribute value: & " < > are escaped (a"b&<c>.mesh -> a&quot;b&amp;&lt;c&gt;.mesh).
TEST_F(CliExportHtml, EscapesTheNameAndTakesHbcViewer) {
  const fs::path odd = dir_ / "a\"b&<c>.mesh";
  write_file(odd, mesh_text_);
  const std::string cmd = "HBC_VIEWER=" + q(tpl_) + " '" + std::string(HBC_CLI) + "' export-html " + q(odd) + " -o " +
                          q(dir_ / "odd.html") + " >/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const Embedded e = embedded(dir_ / "odd.html");
  EXPECT_EQ(e.name, "a&quot;b&amp;&lt;c&gt;.mesh");
  EXPECT_EQ(e.bytes, mesh_text_);
}

// An OpenFOAM case is several files: the page gets the loaded mesh as one OpenVolumeMesh file,
// named after the case, whose counts are the case's.
TEST_F(CliExportHtml, EmbedsAFoamCaseAsOvm) {
  const std::string foam = std::string(HBC_FORMATS_DIR) + "/foam/hex2_ascii";
  const test::CliRun r = run_cli("export-html " + q(foam) + " -o " + q(dir_ / "f.html") + " --viewer " + q(tpl_));
  ASSERT_EQ(r.status, 0) << r.err;
  const Embedded e = embedded(dir_ / "f.html");
  EXPECT_EQ(e.name, "hex2_ascii.ovm");
  write_file(dir_ / e.name, e.bytes);
  nlohmann::json from_page = run_cli("info --json " + q(dir_ / e.name)).json();
  nlohmann::json from_case = run_cli("info --json " + q(foam)).json();
  from_page.erase("file");
  from_case.erase("file");
  EXPECT_EQ(from_page, from_case);
}

// A file whose name does not tell its format (read with --format) is embedded as .ovm too: the page
// picks the reader by the name's extension.
TEST_F(CliExportHtml, EmbedsAFileReadByFormatAsOvm) {
  write_file(dir_ / "s.txt", mesh_text_);
  const test::CliRun r =
      run_cli("export-html " + q(dir_ / "s.txt") + " --format mesh -o " + q(dir_ / "t.html") + " --viewer " + q(tpl_));
  ASSERT_EQ(r.status, 0) << r.err;
  const Embedded e = embedded(dir_ / "t.html");
  EXPECT_EQ(e.name, "s.ovm");
  write_file(dir_ / e.name, e.bytes);
  nlohmann::json from_page = run_cli("info --json " + q(dir_ / e.name)).json();
  nlohmann::json from_file = run_cli("info --json --format mesh " + q(dir_ / "s.txt")).json();
  from_page.erase("file");
  from_file.erase("file");
  EXPECT_EQ(from_page, from_file);
}

#if (HBC_TEST_EXODUS && HBC_TEST_CGNS) || HBC_TEST_MED
// The page's WebAssembly core reads neither Exodus II, CGNS, MED nor XDMF's HDF5 data: their meshes
// go in as .ovm, with the counts of the file itself.
TEST_F(CliExportHtml, EmbedsExodusCgnsMedAndXdmfAsOvm) {
  std::vector<std::string> names;
#if HBC_TEST_EXODUS && HBC_TEST_CGNS
  names = {"slab_hdf5.exo", "mixed4.cgns"};
#endif
#if HBC_TEST_MED
  names.insert(names.end(), {"mixed4_med_order.med", "mixed4_meshio.xdmf"});
#endif
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const std::string file = std::string(HBC_FORMATS_DIR) + "/real/" + name;
    const test::CliRun r = run_cli("export-html " + q(file) + " -o " + q(dir_ / "x.html") + " --viewer " + q(tpl_));
    ASSERT_EQ(r.status, 0) << r.err;
    const Embedded e = embedded(dir_ / "x.html");
    EXPECT_EQ(e.name, fs::path(name).stem().string() + ".ovm");
    write_file(dir_ / e.name, e.bytes);
    nlohmann::json from_page = run_cli("info --json " + q(dir_ / e.name)).json();
    nlohmann::json from_file = run_cli("info --json " + q(file)).json();
    from_page.erase("file");
    from_file.erase("file");
    EXPECT_EQ(from_page, from_file);
  }
}
#endif

// A finite-element deck is embedded as it is, unless it includes other files, which the page
// could not fetch: then as .ovm, with the deck's counts, and its warnings (a skipped shell).
TEST_F(CliExportHtml, EmbedsADeckAsItIsOrWithItsIncludesAsOvm) {
  const std::string nodes = "1, 0,0,0\n2, 1,0,0\n3, 0,1,0\n4, 0,0,1\n";
  const std::string elements = "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n*ELEMENT, TYPE=S3\n2, 1, 2, 3\n";
  write_file(dir_ / "whole.inp", "*NODE\n" + nodes + elements);
  ASSERT_EQ(run_cli("export-html " + q(dir_ / "whole.inp") + " -o " + q(dir_ / "w.html") + " --viewer " + q(tpl_)).status, 0);
  EXPECT_EQ(embedded(dir_ / "w.html").name, "whole.inp");
  write_file(dir_ / "nodes.inp", nodes);
  write_file(dir_ / "top.inp", "*NODE\n*INCLUDE, INPUT=nodes.inp\n" + elements);
  const test::CliRun r = run_cli("export-html " + q(dir_ / "top.inp") + " -o " + q(dir_ / "i.html") + " --viewer " + q(tpl_));
  ASSERT_EQ(r.status, 0) << r.err;
  const Embedded e = embedded(dir_ / "i.html");  // its name runs on into the data-warnings attribute
  const std::string name = e.name.substr(0, e.name.find('"'));
  EXPECT_EQ(name, "top.ovm");
  EXPECT_NE(e.name.find("data-warnings=\"" + (dir_ / "top.inp").string() + ": read past 0 point, 0 line and 1 surface"),
            std::string::npos) << e.name;
  write_file(dir_ / name, e.bytes);
  nlohmann::json from_page = run_cli("info --json " + q(dir_ / name)).json();
  nlohmann::json from_deck = run_cli("info --json " + q(dir_ / "top.inp")).json();
  from_page.erase("file");
  from_deck.erase("file");
  EXPECT_EQ(from_page, from_deck);
}

// With --skip-invalid the page reads the kept cells (as .ovm) and cannot count the dropped ones:
// the element carries the CLI's warnings about the source in data-warnings, one line each as the
// CLI prints them on stderr without "hbc: warning: ", for the page to show.
TEST_F(CliExportHtml, SkipInvalidPageCarriesTheCliWarnings) {
  const std::string defects = std::string(HBC_FORMATS_DIR) + "/../check/defects.HYBRID";
  const test::CliRun r =
      run_cli("export-html " + q(defects) + " --skip-invalid -o " + q(dir_ / "d.html") + " --viewer " + q(tpl_));
  ASSERT_EQ(r.status, 0) << r.err;
  std::string lines;
  for (size_t at = 0, end; (end = r.err.find('\n', at)) != std::string::npos; at = end + 1) {
    const std::string line = r.err.substr(at, end - at);
    const std::string prefix = "hbc: warning: ";
    ASSERT_EQ(line.rfind(prefix, 0), 0u) << line;
    lines += (lines.empty() ? "" : "\n") + line.substr(prefix.size());
  }
  EXPECT_NE(lines.find(defects + ": 5 cell(s) dropped ("), std::string::npos) << r.err;
  const std::string page = slurp(dir_ / "d.html");
  const std::string open = R"(id="hbc-embedded-mesh" data-name="defects.ovm" data-warnings=")";
  const size_t at = page.find(open);
  ASSERT_NE(at, std::string::npos) << page.substr(0, 300);
  EXPECT_EQ(page.substr(at + open.size(), lines.size() + 2), lines + "\">");
}

// A bad mesh fails as in every other command (exit 2, file and line), before any page is written.
TEST_F(CliExportHtml, BadMeshExits2WithItsLine) {
  write_file(dir_ / "bad.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\nx\n");
  const test::CliRun r = run_cli("export-html " + q(dir_ / "bad.mesh") + " -o " + q(dir_ / "bad.html") + " --viewer " + q(tpl_));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.mesh:4"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.html"));
}

// Without --viewer and HBC_VIEWER the page is looked for beside the executable (<bin>/../web/);
// when it is not there, exit 2 saying how to build it. A copy of hbc in a folder of its own makes
// both cases independent of whether this build has made the page.
TEST_F(CliExportHtml, FindsThePageBesideTheExecutableOrSaysHowToBuildIt) {
  write_file(dir_ / "s.mesh", mesh_text_);
  fs::create_directories(dir_ / "prefix" / "bin");
  fs::copy_file(HBC_CLI, dir_ / "prefix" / "bin" / "hbc");
  const std::string run = "env -u HBC_VIEWER " + q(dir_ / "prefix" / "bin" / "hbc") + " export-html " + q(dir_ / "s.mesh") +
                          " -o " + q(dir_ / "p.html") + " 2>" + q(dir_ / "err.txt") + " >/dev/null";
  const int missing = std::system(run.c_str());
  EXPECT_TRUE(WIFEXITED(missing) && WEXITSTATUS(missing) == 2);
  EXPECT_NE(slurp(dir_ / "err.txt").find("bash scripts/build_web.sh"), std::string::npos) << slurp(dir_ / "err.txt");
  EXPECT_FALSE(fs::exists(dir_ / "p.html"));

  fs::create_directories(dir_ / "prefix" / "web");
  fs::copy_file(tpl_, dir_ / "prefix" / "web" / "viewer.html");
  ASSERT_EQ(std::system(run.c_str()), 0) << slurp(dir_ / "err.txt");
  EXPECT_EQ(embedded(dir_ / "p.html").bytes, mesh_text_);
}

// A template without the placeholder (not the viewer, or one already filled) is refused.
TEST_F(CliExportHtml, RefusesATemplateWithoutThePlaceholder) {
  write_file(dir_ / "s.mesh", mesh_text_);
  write_file(dir_ / "other.html", "<html></html>\n");
  const test::CliRun r =
      run_cli("export-html " + q(dir_ / "s.mesh") + " -o " + q(dir_ / "o.html") + " --viewer " + q(dir_ / "other.html"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not a viewer page"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hbc
