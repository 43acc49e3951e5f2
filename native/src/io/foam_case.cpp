// Where an OpenFOAM case keeps its mesh, and reading its four files (plain or .gz); a decomposed
// case goes to read_foam_decomposed.cpp.
#include <algorithm>
#include <charconv>
#include <filesystem>
#include <memory>
#include <system_error>

#include "hbc/io.hpp"
#include "io/detail/foam_files.hpp"
#include "io/detail/gunzip.hpp"
#include "platform/charconv.hpp"

namespace hbc {
namespace {

namespace fs = std::filesystem;

bool has_file(const fs::path& dir, const char* name) {
  std::error_code ec;
  return fs::is_regular_file(dir / name, ec) || fs::is_regular_file(dir / (std::string(name) + ".gz"), ec);
}

bool is_mesh_dir(const fs::path& dir) { return has_file(dir, "owner"); }

// A time folder's value ("0.5", "100"), or false for any other name.
bool time_value(const std::string& name, double& t) {
  const char* e = name.data() + name.size();
  auto r = ::hbc::detail::from_chars(name.data(), e, t);
  return r.ec == std::errc() && r.ptr == e;
}

}  // namespace

namespace detail {

// The case's mesh: the polyMesh of the newest time folder that holds one (snappyHexMesh without
// -overwrite writes there), else constant/polyMesh; empty when there is neither.
fs::path case_mesh(const fs::path& c) {
  std::error_code ec;
  fs::path best;
  double best_t = 0;
  for (fs::directory_iterator it(c, ec), end; !ec && it != end; it.increment(ec)) {
    double t = 0;
    if (it->is_directory(ec) && time_value(it->path().filename().string(), t) && (best.empty() || t > best_t) &&
        is_mesh_dir(it->path() / "polyMesh")) {
      best = it->path() / "polyMesh";
      best_t = t;
    }
  }
  if (!best.empty()) return best;
  return is_mesh_dir(c / "constant" / "polyMesh") ? c / "constant" / "polyMesh" : fs::path();
}

FileText mesh_file(const fs::path& dir, const char* name, const char* what) {
  std::error_code ec;
  FileText out;
  const fs::path plain = dir / name;
  if (fs::is_regular_file(plain, ec)) {
    out.name = plain.string();
    out.map = std::make_unique<FileMap>(out.name);
    if (!out.map->mapped()) out.bytes = read_file_bytes(out.name);
    return out;
  }
  const fs::path gz = dir / (std::string(name) + ".gz");
  if (!fs::is_regular_file(gz, ec))
    throw InputError(plain.string(), {}, std::string("expected the ") + what + " " + name + " (or " + name + ".gz), found neither");
  out.name = gz.string();
  out.bytes = gunzip(read_file_bytes(out.name), out.name);
  return out;
}

}  // namespace detail

std::string foam_mesh_dir(const std::string& path) {
  std::error_code ec;
  const fs::path p(path);
  const std::string file = p.filename().string();
  fs::path dir;
  if (fs::is_directory(p, ec)) {
    if (is_mesh_dir(p)) dir = p;                                  // constant/polyMesh itself
    else if (is_mesh_dir(p / "polyMesh")) dir = p / "polyMesh";   // constant/
    else dir = detail::case_mesh(p);                                      // the case folder
    if (dir.empty())
      throw InputError(path, {}, "expected a mesh file or an OpenFOAM case (a folder with constant/polyMesh/owner, or polyMesh "
                                 "itself), found a folder that is neither");
  } else if (file == "owner" || file == "owner.gz") {
    if (!fs::exists(p, ec)) throw InputError(path, {}, "expected a readable file (cannot open it)");
    dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  } else {
    // A .foam marker: the case is the folder it stands in (its content, often empty, is not read).
    if (!fs::exists(p, ec)) throw InputError(path, {}, "expected a readable file (cannot open it)");
    const fs::path c = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    dir = detail::case_mesh(c);
    if (dir.empty())
      throw InputError(path, {}, "expected an OpenFOAM case beside the .foam file, found no " + c.string() + "/constant/polyMesh/owner");
  }
  return dir.string();
}

MeshInput read_foam_case(const std::string& path, const Threads& threads) {
  if (const std::string c = foam_decomposed_case(path); !c.empty()) return read_foam_decomposed(c, threads);
  const fs::path dir = foam_mesh_dir(path);
  using detail::mesh_file;
  const detail::FileText points = mesh_file(dir, "points"), faces = mesh_file(dir, "faces"), owner = mesh_file(dir, "owner"),
                 neighbour = mesh_file(dir, "neighbour");
  return read_foam({points.view(), faces.view(), owner.view(), neighbour.view(), points.name, faces.name, owner.name,
                    neighbour.name});
}

}  // namespace hbc
