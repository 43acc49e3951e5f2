// hbc.load(): reads a mesh file into an hbc.Mesh.
#include "hbc/io.hpp"

#include <chrono>
#include <string>

#include "bindings.hpp"

namespace hbc::python {

namespace {

PyMeshPtr load(const py::object& path, const py::object& format, const py::object& threads) {
  // os.fspath accepts str, bytes and path-likes (pathlib.Path) and raises TypeError for the rest.
  const std::string file = py::module_::import("os").attr("fspath")(path).cast<std::string>();
  const Format fmt = format.is_none() ? Format::Auto : format_from_name(format.cast<std::string>());
  Threads split;
  if (!threads.is_none()) {
    split.count = threads.cast<int>();
    if (split.count < 1) throw py::value_error("threads must be a positive number or None");
  }
  auto out = std::make_shared<PyMesh>();
  {
    py::gil_scoped_release unlocked;  // reading and building touch no Python objects
    const auto t0 = std::chrono::steady_clock::now();
    out->mesh = load_mesh(file, fmt, split);
    out->load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return out;
}

}  // namespace

void bind_io(py::module_& m) {
  m.def("load", &load, py::arg("path"), py::arg("format") = py::none(), py::kw_only(),
        py::arg("threads") = py::none(),
        "Reads a volume mesh. format: 'ovm', 'ovmb', 'mesh', 'hybrid', 'hedra' or None to choose by "
        "the file extension. threads: how many threads read and build it (results are the same for "
        "any number); None: HBC_THREADS, else every core. Raises MeshFormatError (a ValueError) naming file and line on bad "
        "input, ValueError for an unknown format name.");
}

}  // namespace hbc::python
