#include "locate.hpp"

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace hbc::cli {
namespace {

namespace fs = std::filesystem;

// This executable's folder (BIN); empty where the system cannot say.
fs::path bin_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// The Python a build tree was configured for (BUILD/CMakeCache.txt's Python_EXECUTABLE).
std::string configured_python(const fs::path& build) {
  std::ifstream cache(build / "CMakeCache.txt");
  for (std::string line; std::getline(cache, line);)
    if (line.rfind("Python_EXECUTABLE:", 0) == 0) return line.substr(line.find('=') + 1);
  return "";
}

}  // namespace

ReportPython report_python() {
  ReportPython r;
  const fs::path bin = bin_dir();
  if (!bin.empty() && fs::exists(bin.parent_path() / "python" / "hbc" / "report.py"))
    r.package_dir = (bin.parent_path() / "python").string();
  if (const char* env = std::getenv("HBC_PYTHON"); env && *env)
    r.python = env;
  else if (!r.package_dir.empty())
    r.python = configured_python(bin.parent_path());
  if (r.python.empty()) r.python = "python3";
  return r;
}

fs::path viewer_page(const std::string& given) {
  if (!given.empty()) {
    if (!fs::is_regular_file(given)) throw std::runtime_error("--viewer " + given + ": no such file");
    return given;
  }
  if (const char* env = std::getenv("HBC_VIEWER"); env && *env) {
    if (!fs::is_regular_file(env)) throw std::runtime_error(std::string("HBC_VIEWER=") + env + ": no such file");
    return env;
  }
  const fs::path bin = bin_dir();
  // Appended, not `" " + text`: g++ 12 warns wrongly there (-Wrestrict).
  std::string tried;
  if (!bin.empty()) {
    for (const fs::path& p : {bin / ".." / "web" / "viewer.html", bin / ".." / "share" / "hbc" / "viewer.html"}) {
      if (fs::is_regular_file(p)) return p.lexically_normal();
      tried.append(" ").append(p.lexically_normal().string());
    }
  }
  throw std::runtime_error(std::string("no viewer page (tried")
                               .append(tried)
                               .append("); build it with `bash scripts/build_web.sh`, or give --viewer PATH or HBC_VIEWER"));
}

}  // namespace hbc::cli
