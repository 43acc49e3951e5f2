#pragma once
// Shared pieces of the hbc._core binding. Each concept is bound in its own file by a
// bind_<concept>(module) function called from module.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "hbc/exports.hpp"
#include "hbc/mesh.hpp"
#include "hbc/region.hpp"
#include "hbc/render_geometry.hpp"
#include "hbc/wireframe_style.hpp"

namespace hbc::python {

namespace py = pybind11;

// What a Python hbc.Mesh holds. Shared ownership lets every result computed from the mesh keep
// it alive. `points32` is the float32 copy of mesh.points, made on first request.
struct PyMesh {
  Mesh mesh;
  std::vector<float> points32;
  double load_seconds = 0;  // set by hbc.load(); reported as the analysis' "load" timing
  bool skip_invalid = false;           // hbc.load(skip_invalid=True)
  std::vector<DroppedCell> dropped;    // the cells that load dropped (hbc/check.hpp)
};
using PyMeshPtr = std::shared_ptr<PyMesh>;
// Mesh.dropped (io.cpp).
py::object dropped_dict(const PyMesh& p);

inline py::ssize_t ssize(size_t n) { return static_cast<py::ssize_t>(n); }

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

// A numpy array that takes over `v` without copying: the vector moves to the heap and a capsule,
// the array's base, deletes it with the array. Writable, since nothing else refers to it.
template <class T>
py::array adopt(std::vector<T>&& v, std::vector<py::ssize_t> shape, py::dtype dtype = py::dtype::of<T>()) {
  auto* heap = new std::vector<T>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array(std::move(dtype), std::move(shape), std::vector<py::ssize_t>{}, heap->data(), owner);
}

// The entry of the exported-array table (hbc/exports.hpp) that class `cls` (its Python name is the
// holder) binds as `name`: every array property is registered through it, so a name the table
// does not list for Python stops the module at import (std::logic_error), and its docstring is
// the table's ("int32 (ne,): meaning.").
const ExportedArray& exported(py::handle cls, std::string_view name);
const ExportedArray& exported(std::string_view holder, std::string_view name);
std::string array_doc(const ExportedArray& a);

// Every CSR is exposed the same way: `<name>_offsets`, int32 (rows + 1,), and `<name>_items`,
// int32 (<name>_offsets[-1],), read-only views of the Csr get(holder) returns, whose numpy base is
// the Python object (which keeps the data alive); rows and meaning are the table's.
template <class H, class... Opts, class Get>
void def_csr(py::class_<H, Opts...>& cls, const std::string& name, Get get) {
  const ExportedArray& e = exported(cls, name);
  // pybind11 copies names and docstrings, so temporaries are fine.
  cls.def_property_readonly(
      (name + "_offsets").c_str(),
      [get](py::object self) -> py::array {
        const auto& v = get(self.cast<const H&>()).offsets;
        return view(v.data(), {ssize(v.size())}, self);
      },
      ("int32 (" + std::string(e.rows) + " + 1,): row r's items are " + name + "_items[" + name + "_offsets[r]:" +
       name + "_offsets[r + 1]].")
          .c_str());
  cls.def_property_readonly(
      (name + "_items").c_str(),
      [get](py::object self) -> py::array {
        const auto& v = get(self.cast<const H&>()).items;
        return view(v.data(), {ssize(v.size())}, self);
      },
      array_doc(e).c_str());
}

// What a Python hbc.Analysis holds: the mesh it was computed on (kept alive), the options (for
// the region wireframes computed on demand), the analysis, and the per-sheet arrays flattened once.
// Without a sheet stage the per-sheet arrays are empty (Analysis.has_sheets tells the two apart).
struct PyAnalysis {
  PyMeshPtr mesh;
  AnalysisOptions options;
  Analysis analysis;
  // Mesh.analyze(rho=...): the ρ of wireframe() without one. Presentation only, outside the
  // analysis: the style is the render layer's (wireframe_style.hpp), computed per wireframe.
  double rho = WireframeStyleOptions{}.rho;
  // The whole-mesh wireframe's style at whole_style_rho, made on the first wireframe() asking for it.
  std::shared_ptr<const WireframeStyle> whole_style;
  double whole_style_rho = -1;
  ClassArrays sheet_classes;               // per sheet
  Csr<int32_t> sheet_components;           // per sheet: base-complex components
  std::vector<int32_t> self_intersecting;  // sheet ids with a decomposition, increasing
  struct Sub {
    ClassArrays classes;
    Csr<int32_t> components;
  };
  std::vector<Sub> subsheets;              // aligned with the sheet stage's subsheets
  Sheets no_sheets;                        // what sheets() returns without a sheet stage

  const Sheets& sheets() const { return analysis.sheet_stage ? analysis.sheet_stage->sheets : no_sheets; }
  // The decompositions; the subsheet stage must have run (subsheets() checks it).
  const std::vector<Subsheets>& decompositions() const { return *analysis.sheet_stage->subsheets; }
};
using PyAnalysisPtr = std::shared_ptr<PyAnalysis>;

// What a Python hbc.Wireframe holds: the whole-mesh wireframe of an analysis and its view (aliasing
// pointers that keep the analysis alive) or one computed on demand for a region (owned alone), and
// its style at `rho` (Wireframe.restyled(rho) shares the wireframe and view, with a new style).
struct PyWireframe {
  std::shared_ptr<const VsgWireframe> w;
  std::shared_ptr<const CellComplex> view;  // the view w was computed on, which the style reads
  std::shared_ptr<const WireframeStyle> style;
  double rho = WireframeStyleOptions{}.rho;
};

// The style of wireframe `w` on `view` at rho (the GIL released while it is computed); ValueError
// for rho outside [0, 1].
std::shared_ptr<const WireframeStyle> style_of(const CellComplex& view, const VsgWireframe& w, double rho);
// rho checked to be in [0, 1] (std::invalid_argument otherwise).
double checked_rho(double rho);

// An optional id argument: None is none; anything else must be an int in [0, INT32_MAX]
// (std::invalid_argument naming `what` otherwise).
std::optional<int32_t> optional_id(const py::object& v, const char* what);

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
void bind_analysis(py::module_& m);  // analysis.cpp: Mesh.analyze and the Analysis classes
void bind_geometry(py::module_& m);  // geometry.cpp: block_soup(), polylines()
void bind_quality(py::module_& m);   // quality.cpp: cell_quality(), cell_depth()
void bind_schema(py::module_& m);    // schema.cpp: the fields and name tables of what hbc reports
void bind_metrics(py::module_& m);   // metrics.cpp: Analysis.metrics(), METRIC_FIELDS (after bind_analysis)
void bind_comparison(py::module_& m);  // comparison.cpp: hbc.compare's measurement and tables
void bind_exports(py::module_& m);   // exports.cpp: EXPORTED_ARRAYS, DIMENSIONS, ANALYZE_OPTIONS
// schema.cpp: a statistics dict / wireframe counts dict keyed by the schema's fields.
py::dict stats_dict(const Stats& s);
py::dict wireframe_counts(const VsgWireframe& w);

}  // namespace hbc::python
