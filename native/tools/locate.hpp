#pragma once
// Where the hbc command looks for the pieces it runs or embeds, each in one order with at most one
// variable (docs/development.md, "Where hbc looks for its pieces"); the Python side looks in
// hbc/locate.py. Everything else of the command is self-contained.
#include <filesystem>
#include <string>

namespace hbc::cli {

// The Python that draws report.html (`PYTHON -m hbc.report`) and the folder to put first on its
// PYTHONPATH (empty: the package must be importable already).
struct ReportPython {
  std::string python;
  std::string package_dir;
};
// python: $HBC_PYTHON, else, when this executable is BUILD/bin/hbc of a build tree holding the
// package (BUILD/python/hbc), the Python that tree was configured for (its CMakeCache's
// Python_EXECUTABLE: the one interpreter its compiled module surely imports in), else python3 on
// PATH. package_dir: BUILD/python when there is that package.
ReportPython report_python();

// The web viewer page `hbc export-html` embeds a mesh into: `given` (--viewer), else $HBC_VIEWER,
// else BIN/../web/viewer.html (a build tree: scripts/build_web.sh), else
// BIN/../share/hbc/viewer.html (an install prefix). Throws std::runtime_error naming what it tried.
std::filesystem::path viewer_page(const std::string& given);

}  // namespace hbc::cli
