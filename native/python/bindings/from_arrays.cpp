// Mesh.from_arrays(): builds a mesh from numpy arrays in the same CSR layout the Mesh exposes.
// Shapes and dtypes are checked here (TypeError / ValueError); the content (index ranges, closed
// cells, conformity) is checked by build_mesh, whose InputError becomes MeshFormatError.
#include <limits>
#include <optional>
#include <string>

#include "bindings.hpp"

namespace hbc::python {

namespace {

constexpr int64_t kMaxIndex = std::numeric_limits<int32_t>::max();

py::array as_array(const py::object& obj, const char* name) {
  py::array a = py::array::ensure(obj);
  if (!a) throw py::type_error(std::string(name) + ": expected an array-like");
  return a;
}

// A 1-D integer array as int64 values; floats and bools are refused rather than cast silently.
std::vector<int64_t> int_values(const py::object& obj, const char* name) {
  py::array a = as_array(obj, name);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + ": expected an integer array, got dtype " +
                         py::str(a.dtype()).cast<std::string>());
  if (a.ndim() != 1)
    throw py::value_error(std::string(name) + ": expected a 1-D array, got " +
                          std::to_string(a.ndim()) + " dimensions");
  auto c = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!c) throw py::error_already_set();
  return std::vector<int64_t>(c.data(), c.data() + c.size());
}

// The arguments <name>_offsets and <name>_items as one CSR table; items are range-checked against
// [0, limit).
Csr<int32_t> csr(const py::object& offsets_obj, const py::object& items_obj, const std::string& name, int64_t limit,
                 const std::string& source) {
  const std::string offsets_name = name + "_offsets", items_name = name + "_items";
  const std::vector<int64_t> off = int_values(offsets_obj, offsets_name.c_str());
  const std::vector<int64_t> items = int_values(items_obj, items_name.c_str());
  if (off.empty() || off.front() != 0)
    throw InputError(source, {}, offsets_name + " starting with 0");
  if (off.back() != static_cast<int64_t>(items.size()) || items.size() > static_cast<size_t>(kMaxIndex))
    throw InputError(source, {},
                     offsets_name + "[-1] == len(" + items_name + ") = " +
                         std::to_string(items.size()) + " (below 2^31), found " +
                         std::to_string(off.back()));
  Csr<int32_t> out;
  out.offsets.resize(off.size());
  for (size_t i = 0; i < off.size(); ++i) {
    if (i > 0 && off[i] < off[i - 1])
      throw InputError(source, {},
                       offsets_name + " non-decreasing, found " +
                           std::to_string(off[i]) + " after " + std::to_string(off[i - 1]) +
                           " at index " + std::to_string(i));
    out.offsets[i] = static_cast<int32_t>(off[i]);
  }
  out.items.resize(items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i] < 0 || items[i] >= limit)
      throw InputError(source, {},
                       std::string(items_name) + " values in [0, " + std::to_string(limit) +
                           "), found " + std::to_string(items[i]) + " at index " + std::to_string(i));
    out.items[i] = static_cast<int32_t>(items[i]);
  }
  return out;
}

std::vector<double> point_values(const py::object& obj) {
  py::array a = as_array(obj, "points");
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error("points: expected a float array, got dtype " +
                         py::str(a.dtype()).cast<std::string>());
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error("points: expected shape (n, 3), got " +
                          py::str(py::tuple(a.attr("shape"))).cast<std::string>());
  auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!c) throw py::error_already_set();
  return std::vector<double>(c.data(), c.data() + c.size());
}

PyMeshPtr from_arrays(const py::object& points, const py::object& face_vertices_offsets,
                      const py::object& face_vertices_items, const py::object& cell_faces_offsets,
                      const py::object& cell_faces_items, const py::object& cell_face_flip,
                      const std::string& source) {
  MeshInput in;
  in.source = source;
  in.points = point_values(points);
  // Vertex ids are range-checked by build_mesh with a better message; here only int32 fit.
  in.faces = csr(face_vertices_offsets, face_vertices_items, "face_vertices", kMaxIndex, source);
  // Cells store 2*face+flip, so face ids must stay below 2^30.
  const int64_t nf = static_cast<int64_t>(in.faces.rows());
  if (nf > kMaxIndex / 2) throw InputError(source, {}, "fewer than 2^30 faces");
  in.cells = csr(cell_faces_offsets, cell_faces_items, "cell_faces", nf, source);
  if (!cell_face_flip.is_none()) {
    py::array a = as_array(cell_face_flip, "cell_face_flip");
    const std::vector<int64_t> flip =
        a.dtype().kind() == 'b' ? int_values(a.attr("astype")("uint8"), "cell_face_flip")
                                : int_values(a, "cell_face_flip");
    if (flip.size() != in.cells.items.size())
      throw py::value_error("cell_face_flip: expected len(cell_faces_items) = " +
                            std::to_string(in.cells.items.size()) + " entries, got " +
                            std::to_string(flip.size()));
    for (size_t i = 0; i < flip.size(); ++i) {
      if (flip[i] != 0 && flip[i] != 1)
        throw py::value_error("cell_face_flip: expected 0 or 1, found " + std::to_string(flip[i]) +
                              " at index " + std::to_string(i));
      in.cells.items[i] = 2 * in.cells.items[i] + static_cast<int32_t>(flip[i]);
    }
  } else {
    for (int32_t& f : in.cells.items) f *= 2;
  }
  auto out = std::make_shared<PyMesh>();
  {
    py::gil_scoped_release unlocked;
    out->mesh = build_mesh(std::move(in));
  }
  return out;
}

}  // namespace

void bind_from_arrays(py::class_<PyMesh, PyMeshPtr>& cls) {
  cls.def_static("from_arrays", &from_arrays, py::arg("points"), py::arg("face_vertices_offsets"),
                 py::arg("face_vertices_items"), py::arg("cell_faces_offsets"), py::arg("cell_faces_items"),
                 py::arg("cell_face_flip") = py::none(), py::arg("source") = "<arrays>",
                 "Builds a mesh from arrays in the layout the Mesh properties use: points (nv, 3) "
                 "float; face_vertices_offsets (nf + 1,) and face_vertices_items, the CSR of vertex "
                 "loops; cell_faces_offsets (nc + 1,) and cell_faces_items, the CSR of face ids; "
                 "optional cell_face_flip (len(cell_faces_items),) "
                 "0/1, 1 when the cell sees the loop reversed (orientation only; topology does not "
                 "depend on it). Copies the data. Raises MeshFormatError (a ValueError) for a "
                 "mesh that is not valid, TypeError/ValueError for wrong dtypes or shapes.");
}

}  // namespace hbc::python
