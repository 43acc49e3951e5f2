// Per-cell quality and depth as numpy arrays: hbc.cell_quality() and hbc.cell_depth(). Computed
// in C++ (cell_quality.hpp, cell_depth.hpp) with the GIL released; the vectors move into numpy.
#include "bindings.hpp"
#include "hbc/cell_depth.hpp"
#include "hbc/cell_quality.hpp"

namespace hbc::python {

namespace {

py::dict cell_quality_arrays(const PyMeshPtr& mesh) {
  CellQuality q;
  {
    py::gil_scoped_release unlocked;
    q = cell_quality(mesh->mesh);
  }
  const auto nc = static_cast<py::ssize_t>(q.scaled_jacobian.size());
  py::dict d;
  d["scaled_jacobian"] = adopt(std::move(q.scaled_jacobian), {nc});
  d["edge_ratio"] = adopt(std::move(q.edge_ratio), {nc});
  return d;
}

py::array cell_depth_array(const PyMeshPtr& mesh) {
  std::vector<int32_t> depth;
  {
    py::gil_scoped_release unlocked;
    depth = cell_depth(mesh->mesh);
  }
  const auto nc = static_cast<py::ssize_t>(depth.size());
  return adopt(std::move(depth), {nc});
}

}  // namespace

void bind_quality(py::module_& m) {
  m.def("cell_quality", &cell_quality_arrays, py::arg("mesh"),
        "Verdict's per-cell quality (definitions in hbc/cell_quality.hpp): a dict with "
        "'scaled_jacobian' float64 (num_cells,), in [-1, 1] for hexes, < 0 for inverted cells, 1 for "
        "ideal hex/tet/prism/pyramid shapes, and 'edge_ratio' float64 (num_cells,), longest / shortest "
        "edge (inf with a zero-length edge).");
  m.def("cell_depth", &cell_depth_array, py::arg("mesh"),
        "int32 (num_cells,): cell layers from the boundary, 0 for cells with a boundary vertex, else "
        "the breadth-first distance over face neighbours from those cells.");
}

}  // namespace hbc::python
