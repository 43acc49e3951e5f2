// hbc::InputError becomes hbc.MeshFormatError, a ValueError carrying where the problem is.
// Other C++ exceptions keep pybind11's default translation (std::invalid_argument -> ValueError,
// std::bad_alloc -> MemoryError, any other std::exception -> RuntimeError).
#include "hbc/error.hpp"

#include "bindings.hpp"

namespace hbc::python {

namespace {

py::object optional_int(int64_t v) { return v >= 0 ? py::object(py::int_(v)) : py::object(py::none()); }

// A reader quotes the token it rejects as the file has it, which need not be UTF-8: undecodable
// bytes become U+FFFD so the message (file, line, what was expected) still reaches Python.
py::str utf8_replace(const std::string& s) {
  PyObject* u = PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace");
  if (u == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(u);
}

// hbc.MeshFormatError's type object. A translator is a plain function, so it cannot capture it,
// and looking it up by the name "hbc._core" fails where the package lives under another name (the
// Blender add-on bundles it as hybrid_base_complex.hbc): the one piece of binding state, set once
// when the module initialises and kept alive by the module's attribute (plus the reference held).
py::handle& mesh_format_error_type() {
  static py::handle type;
  return type;
}

void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const InputError& e) {
    py::handle type = mesh_format_error_type();
    py::object err = type(utf8_replace(e.what()));
    err.attr("file") = utf8_replace(e.file());
    err.attr("line") = optional_int(e.loc().line);
    err.attr("byte_offset") = optional_int(e.loc().byte_offset);
    err.attr("detail") = utf8_replace(e.detail());
    PyErr_SetObject(type.ptr(), err.ptr());
  }
}

}  // namespace

void bind_errors(py::module_& m) {
  py::object type = py::exception<InputError>(m, "MeshFormatError", PyExc_ValueError);
  mesh_format_error_type() = type.inc_ref();
  type.attr("__doc__") =
      "A mesh file (or arrays) that is not a valid mesh. str(err) is 'file:line: expected ...'; "
      "the attributes file, line (None for binary files), byte_offset (None for text files) and "
      "detail (the message without the location) give the parts.";
  py::register_local_exception_translator(translate);
}

}  // namespace hbc::python
