// The test module of test_old_pybind11.py: hbc._core's first step, then an array built as the
// binding builds its views (a dtype, a shape, no strides: pybind11 computes them from the dtype's
// itemsize, which a pybind11 older than 2.12 reads as 0 under NumPy 2).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

#include "numpy_abi.hpp"

namespace py = pybind11;

PYBIND11_MODULE(numpy_abi_probe, m) {
  hbc::python::require_numpy_abi();
  m.attr("pybind11_version") = py::make_tuple(PYBIND11_VERSION_MAJOR, PYBIND11_VERSION_MINOR);
  m.def("iota", [](int n) {
    std::vector<int32_t> v(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) v[static_cast<size_t>(i)] = i;
    return py::array(py::dtype::of<int32_t>(), {static_cast<py::ssize_t>(n)}, {}, v.data());  // copies
  });
}
