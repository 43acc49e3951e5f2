#pragma once
// Shared pieces of the hbc._core binding. Each concept is bound in its own file by a
// bind_<concept>(module) function called from module.cpp; later stages add theirs the same way.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "hbc/mesh.hpp"

namespace hbc::python {

namespace py = pybind11;

// What a Python hbc.Mesh holds. Shared ownership lets results of later stages keep the mesh they
// refer to alive. `points32` is the float32 copy of mesh.points, made on first request.
struct PyMesh {
  Mesh mesh;
  std::vector<float> points32;
};
using PyMeshPtr = std::shared_ptr<PyMesh>;

// A read-only numpy array over `data` (no copy) with the given shape (C order). `owner` is the
// Python object whose lifetime covers `data`; numpy keeps a reference to it as the array's base.
// `dtype` may differ from T when the bytes are compatible (uint8 0/1 viewed as bool).
template <class T>
py::array view(const T* data, std::vector<py::ssize_t> shape, py::handle owner,
               py::dtype dtype = py::dtype::of<T>()) {
  py::array a(std::move(dtype), std::move(shape), std::vector<py::ssize_t>{}, data, owner);
  a.attr("flags").attr("writeable") = false;
  return a;
}

// A new (owning, writable) 1-D numpy array holding a copy of `v`.
template <class T>
py::array_t<T> copy_1d(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

void bind_errors(py::module_& m);  // errors.cpp: MeshFormatError and its translation
void bind_mesh(py::module_& m);    // mesh.cpp: the Mesh class and its arrays
void bind_from_arrays(py::class_<PyMesh, PyMeshPtr>& cls);  // from_arrays.cpp, called by bind_mesh
void bind_io(py::module_& m);      // io.cpp: load()

}  // namespace hbc::python
