// Entry point of hbc._core, the compiled half of the `hbc` Python package (see hbc/__init__.py).
#include "bindings.hpp"
#include "numpy_abi.hpp"
#include "hbc/version.hpp"

namespace hbc::python {
void bind_layer_plan(py::module_& m);  // layer_plan.cpp: layers, colours by role, legends
}

PYBIND11_MODULE(_core, m) {
  namespace hp = hbc::python;
  hp::require_numpy_abi();  // before anything: never a module whose arrays are wrong
  m.doc() = "Compiled core of hbc; import the `hbc` package instead of this module.";
  m.attr("__version__") = hbc::version();
  // Errors first: the other bindings may raise them at import time.
  hp::bind_errors(m);
  hp::bind_mesh(m);
  hp::bind_io(m);
  hp::bind_analysis(m);  // adds Mesh.analyze, so after bind_mesh
  hp::bind_geometry(m);
  hp::bind_quality(m);
  hp::bind_schema(m);
  hp::bind_layer_plan(m);
  hp::bind_metrics(m);  // adds Analysis.metrics, so after bind_analysis; MetricField is a Field, so after bind_schema
  hp::bind_comparison(m);
  hp::bind_exports(m);
}
