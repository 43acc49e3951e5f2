// hbc.compare's compiled half (hbc/comparison.py): one mesh measured as `hbc compare` measures it,
// and metrics.json, metrics.csv and metrics.tex written from the columns, by the library's writers
// (hbc/comparison.hpp), so that the Python and the CLI comparisons are the same text. Private
// (underscored): hbc.compare() is the interface.
#include "hbc/comparison.hpp"

#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"

namespace hbc::python {
namespace {

// The measurement's JSON text: text crosses process and machine boundaries (a process pool, a
// Dask worker) as it is, and the tables parse it as the CLI parses its children's output.
std::string measurement(const PyMeshPtr& p, const py::object& file, const py::object& threads) {
  const std::string name = py::module_::import("os").attr("fspath")(file).cast<std::string>();
  int count = 0;
  if (!threads.is_none()) {
    count = threads.cast<int>();
    if (count < 1) throw py::value_error("threads must be a positive number or None");
  }
  py::gil_scoped_release unlocked;  // the analysis and metrics touch no Python object
  return json_text(comparison_measurement(p->mesh, name, count, p->load_seconds, p->skip_invalid, p->dropped));
}

std::vector<std::string> names(const std::vector<std::string>& files, const std::vector<std::string>& given) {
  std::vector<std::string> out;
  for (const ComparisonColumn& c : comparison_columns(files, given)) out.push_back(c.name);
  return out;
}

// Column i holds measurements[i] when errors[i] is empty, else fails with errors[i].
py::tuple tables(const std::vector<std::string>& files, const std::vector<std::string>& given,
                 const std::vector<std::string>& measurements, const std::vector<std::string>& errors,
                 bool skip_invalid) {
  if (measurements.size() != files.size() || errors.size() != files.size())
    throw py::value_error("one measurement or error per file");
  std::string json, csv, tex;
  {
    py::gil_scoped_release unlocked;
    std::vector<ComparisonColumn> cols = comparison_columns(files, given);
    for (size_t i = 0; i < cols.size(); ++i) {
      if (errors[i].empty()) set_measurement(cols[i], measurements[i]);
      else cols[i].error = errors[i];
    }
    json = json_text(comparison_json(cols, skip_invalid));
    csv = comparison_csv(cols);
    tex = comparison_tex(cols);
  }
  // Bytes, written as they are: a file name that is not UTF-8 reaches the CSV and TeX as the CLI writes it.
  return py::make_tuple(py::bytes(json), py::bytes(csv), py::bytes(tex));
}

}  // namespace

void bind_comparison(py::module_& m) {
  m.def("_comparison_measurement", &measurement, py::arg("mesh"), py::arg("file"), py::arg("threads") = py::none(),
        "One mesh measured as `hbc compare-one` measures it (GIL released): its JSON text, with the mesh's "
        "load time and, for hbc.load(skip_invalid=True), what the load dropped.");
  m.def("_comparison_names", &names, py::arg("files"), py::arg("names"),
        "The column names of files (names: one per file, or empty for the file names); ValueError when the "
        "counts differ.");
  m.def("_comparison_tables", &tables, py::arg("files"), py::arg("names"), py::arg("measurements"),
        py::arg("errors"), py::arg("skip_invalid"),
        "(metrics.json, metrics.csv, metrics.tex) as bytes, as `hbc compare` writes them.");
}

}  // namespace hbc::python
