#include "hbc/io.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/detail/text_scanner.hpp"
#include "platform/file_map.hpp"
#include "platform/worker_pool.hpp"

namespace hbc {

namespace {

constexpr FormatInfo kFormats[] = {
    {Format::Ovm, "ovm", "", ".ovm", "OpenVolumeMesh ASCII", true},
    {Format::Ovmb, "ovmb", "", ".ovmb", "OpenVolumeMesh binary", false},
    {Format::Medit, "mesh", "medit", ".mesh", "MEDIT (At-Most-Hexa, HexaLab, Gmsh)", true},
    {Format::Hybrid, "hybrid", "", ".HYBRID", "Robust Hex-Dominant Meshing", false},
    {Format::Hedra, "hedra", "", ".hedra", "LoopyCuts / cinolib", false},
    {Format::Msh, "msh", "", ".msh", "Gmsh 2.2 and 4.1, ASCII or binary", false},
    {Format::Vtk, "vtk", "", ".vtk", "legacy VTK unstructured grid", false},
    {Format::Vtu, "vtu", "", ".vtu", "VTK XML unstructured grid", false},
    {Format::Foam, "foam", "openfoam", ".foam", "OpenFOAM polyMesh (case folder, .foam file or polyMesh/owner)", false},
    {Format::Su2, "su2", "", ".su2", "SU2 native mesh (zones joined)", false},
    {Format::Ugrid, "ugrid", "", ".ugrid", "AFLR3 UGRID: ASCII, .b8/.lb8 binary, .r8/.lr8 Fortran records", false},
    {Format::Fluent, "fluent", "", ".msh", "Fluent mesh, ASCII or binary (.msh told from Gmsh's by content)", false},
    // Exodus II has three extensions: one row each, so that every list (--format, file filters) has them.
    {Format::Exodus, "exo", "exodus", ".exo", "Exodus II (Cubit, MOOSE; netCDF classic or HDF5)", false},
    {Format::Exodus, "e", "", ".e", "Exodus II", false},
    {Format::Exodus, "g", "", ".g", "Exodus II (Genesis)", false},
    {Format::Cgns, "cgns", "", ".cgns", "CGNS (ADF or HDF5; unstructured and structured zones)", false},
    {Format::Abaqus, "inp", "abaqus", ".inp", "Abaqus input deck", false},
    {Format::Nastran, "bdf", "nas", ".bdf", "Nastran bulk data", false, ".nas"},
    {Format::LsDyna, "k", "key", ".k", "LS-DYNA keyword file", false, ".key"},
    {Format::Med, "med", "", ".med", "Salome MED (MED-fichier 3/4, HDF5)", false},
    {Format::Xdmf, "xdmf", "xmf", ".xdmf", "XDMF3 (FEniCS/dolfinx, meshio; data inline or in HDF5)", false, ".xmf"},
};

// "a, b, c or d" of each format's `part`, each once (Gmsh and Fluent share .msh).
template <class Part>
std::string listed(Part part) {
  std::vector<std::string> parts;
  for (const FormatInfo& f : kFormats)
    if (std::find(parts.begin(), parts.end(), part(f)) == parts.end()) parts.push_back(part(f));
  std::string out;
  for (size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? "" : i + 1 == parts.size() ? " or " : ", ") + parts[i];
  return out;
}

}  // namespace

std::span<const FormatInfo> formats() { return kFormats; }

std::vector<std::string_view> extensions_of(const FormatInfo& f) {
  std::vector<std::string_view> out{f.extension};
  for (std::string_view m = f.more_extensions; !m.empty();) {
    const size_t sp = m.find(' ');
    if (sp != 0) out.push_back(m.substr(0, sp));
    m = sp == std::string_view::npos ? std::string_view() : m.substr(sp + 1);
  }
  return out;
}

Format format_from_name(std::string_view name) {
  const std::string n = detail::lower(name);
  for (const FormatInfo& f : kFormats)
    if (n == f.name || (!f.alias.empty() && n == f.alias)) return f.format;
  throw std::invalid_argument("unknown format '" + std::string(name) + "' (expected " +
                              listed([](const FormatInfo& f) { return std::string(f.name); }) + ")");
}

Format format_from_path(const std::string& path) {
  static const std::string kExtensions =
      "a file name ending in " + listed([](const FormatInfo& f) { return std::string(f.extension); }) +
      " (or --format)";
  // OpenFOAM keeps a mesh in a folder of files without extensions: the folder, or its owner file;
  // `case/processor*` names a decomposed case's processors.
  std::error_code ec;
  const std::string base = std::filesystem::path(path).filename().string();
  if (std::filesystem::is_directory(path, ec) || base == "owner" || base == "owner.gz" || base == "processor*")
    return Format::Foam;
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    throw InputError(path, {}, kExtensions);
  try {
    return format_from_name(std::string_view(path).substr(dot + 1));
  } catch (const std::invalid_argument&) {
    throw InputError(path, {}, kExtensions);
  }
}

const char* format_name(Format f) {
  for (const FormatInfo& i : kFormats)
    if (i.format == f) return i.name.data();
  return f == Format::Auto ? "auto" : "?";
}

std::string read_file_bytes(const std::string& path) {
  // A folder opens as a stream on Linux, and its "size" would be allocated.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, {}, "expected a file, found a folder");
  // One read into a buffer of the file's size: no stream buffering, no copy of the text.
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) throw InputError(path, {}, "a readable file (cannot open it)");
  const std::streamoff size = f.tellg();
  std::string bytes;
  if (size > 0) {
    bytes.resize(static_cast<size_t>(size));
    f.seekg(0);
    f.read(bytes.data(), size);
    if (f.gcount() != size) throw InputError(path, {}, "a readable file (read failed)");
  } else {
    // Sizes unknown up front (pipes, /proc): read what there is.
    f.clear();
    f.seekg(0);
    bytes.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  }
  if (f.bad()) throw InputError(path, {}, "a readable file (read failed)");
  return bytes;
}

IncludeReader include_from_disk() {
  return [](const std::string& from, const std::string& path, std::string& name) {
    const std::filesystem::path p(path);
    name = p.is_absolute() ? path : (std::filesystem::path(from).parent_path() / p).string();
    return read_file_bytes(name);
  };
}

namespace {

// A file's bytes for parsing: a regular file mapped where the platform maps files, anything else
// (a pipe) read.
class FileBytes {
 public:
  explicit FileBytes(const std::string& path) : map_(path) {
    if (map_.mapped()) {
      view_ = map_.view();
    } else {
      copy_ = read_file_bytes(path);
      view_ = copy_;
    }
  }
  std::string_view view() const { return view_; }

 private:
  detail::FileMap map_;
  std::string copy_;
  std::string_view view_;
};

// Gmsh's .msh starts with $MeshFormat (or $NOD), Fluent's with a section "(".
bool starts_like_fluent(std::string_view bytes) {
  const size_t at = bytes.find_first_not_of(" \t\r\n");
  return at != std::string_view::npos && bytes[at] == '(';
}

}  // namespace

MeshInput read_input(const std::string& path, Format format, const Threads& threads) {
  if (format == Format::Auto) format = format_from_path(path);
  if (format == Format::Foam) return read_foam_case(path, threads);  // four files (or a folder of processors), not one
  if (format == Format::Cgns) return read_cgns(path);        // the CGNS library opens the file itself
  const FileBytes file(path);
  const std::string_view bytes = file.view();
  switch (format) {
    case Format::Ovm: return read_ovm(bytes, path);
    case Format::Ovmb: return read_ovmb(bytes, path);
    case Format::Medit: return read_medit(bytes, path, threads);
    case Format::Hybrid: return read_hybrid(bytes, path);
    case Format::Hedra: return read_hedra(bytes, path);
    case Format::Msh: return starts_like_fluent(bytes) ? read_fluent(bytes, path) : read_msh(bytes, path);
    case Format::Vtk: return read_vtk(bytes, path);
    case Format::Vtu: return read_vtu(bytes, path);
    case Format::Su2: return read_su2(bytes, path);
    case Format::Ugrid: return read_ugrid(bytes, path, ugrid_encoding_of(path));
    case Format::Fluent: return read_fluent(bytes, path);
    case Format::Exodus: return read_exodus(bytes, path);
    case Format::Abaqus: return read_abaqus(bytes, path, include_from_disk());
    case Format::Nastran: return read_nastran(bytes, path, include_from_disk());
    case Format::LsDyna: return read_lsdyna(bytes, path, include_from_disk());
    case Format::Med: return read_med(bytes, path);
    case Format::Xdmf: return read_xdmf(bytes, path);
    case Format::Foam:
    case Format::Cgns:
    case Format::Auto: break;
  }
  throw InputError(path, {}, "a known format");
}

Mesh load_mesh(const std::string& path, Format format, const Threads& threads) {
  const detail::RunOptions run(threads);  // one pool for the reading and the building
  const Threads& par = run.get();
  return build_mesh(read_input(path, format, par), par);
}

Mesh load_mesh_skipping_invalid(const std::string& path, std::vector<DroppedCell>& dropped, Format format,
                                const Threads& threads) {
  const detail::RunOptions run(threads);
  const Threads& par = run.get();
  return build_mesh_skipping_invalid(read_input(path, format, par), dropped, par);
}

CheckReport check_file(const std::string& path, Format format, size_t listed, const Threads& threads) {
  const detail::RunOptions run(threads);
  const Threads& par = run.get();
  return check_input(read_input(path, format, par), listed, par);
}

void write_mesh(const Mesh& mesh, const std::string& path, Format format) {
  if (format == Format::Auto) format = format_from_path(path);
  std::string text;
  if (format == Format::Ovm) text = ovm_text(mesh);
  else if (format == Format::Medit) text = medit_text(mesh);
  else throw std::invalid_argument(std::string("writing ") + format_name(format) + " is not supported (use .ovm or .mesh)");
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << text;
  if (!f) throw std::runtime_error("write failed: " + path);
}

}  // namespace hbc
