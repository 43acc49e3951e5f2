#pragma once
// Refuses to import, with the reason and the remedy, where the module's arrays would be wrong.
// pybind11 before 2.12 reads numpy's array descriptors with NumPy 1's layout: under NumPy 2 every
// itemsize comes out 0, so each array the module returns has stride 0 (every element equal to the
// first) and nothing raises. The build asks for pybind11 >= 2.12 (native/python/CMakeLists.txt);
// a module built with an older one anyway (HBC_ALLOW_OLD_PYBIND11) works under NumPy 1 only.
// Header-only so that tests/numpy_abi/ compiles the same check against Debian's pybind11 2.10.
#include <pybind11/pybind11.h>

#include <string>

namespace hbc::python {

// Called first in the module's init: with a pybind11 older than 2.12, throws ImportError under
// NumPy >= 2; otherwise does nothing (and imports nothing).
inline void require_numpy_abi() {
#if PYBIND11_VERSION_MAJOR < 2 || (PYBIND11_VERSION_MAJOR == 2 && PYBIND11_VERSION_MINOR < 12)
  namespace py = pybind11;
  const std::string numpy = py::module_::import("numpy").attr("__version__").cast<std::string>();
  if (std::stoi(numpy) < 2) return;  // "1.24.2" -> 1
  throw py::import_error(
      "hbc._core was built with pybind11 " PYBIND11_TOSTRING(PYBIND11_VERSION_MAJOR) "." PYBIND11_TOSTRING(
          PYBIND11_VERSION_MINOR) "." PYBIND11_TOSTRING(PYBIND11_VERSION_PATCH) ", which predates NumPy 2, and "
      "this Python has NumPy " + numpy + ": every array would come out wrong (stride 0), so it refuses to "
      "load. Rebuild it with pybind11 2.12 or newer: `bash scripts/build.sh` (PyPI's pinned pybind11, "
      "scripts/env/pybind11.sh), `python -m pip install .`, or CMake with "
      "-Dpybind11_DIR=\"$(python -m pybind11 --cmakedir)\" after `python -m pip install 'pybind11>=2.12,<3'`; "
      "or use NumPy < 2 with this build.");
#endif
}

}  // namespace hbc::python
