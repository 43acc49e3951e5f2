// Structural complexity metrics in Python: Analysis.metrics() gives the `hbc metrics --json`
// object (without "file" and "timings") as a dict, hbc.METRIC_FIELDS describes every scalar
// (hbc/metrics.hpp; definitions in docs/metrics.md). Computed with the GIL released.
#include <cmath>

#include "bindings.hpp"
#include "hbc/metrics.hpp"

namespace hbc::python {
namespace {

// As the CLI writes them: NaN as None, counts and ids as int, ratios as float.
py::object scalar(const MetricField& f, double v) {
  if (!std::isfinite(v)) return py::none();
  if (f.unit != "ratio" && v == std::floor(v) && std::fabs(v) < 9e15) return py::int_(static_cast<int64_t>(v));
  return py::float_(v);
}

// A histogram indexed by value as {"value": count} without the empty bins (string keys, as in JSON).
py::dict by_value(const std::vector<int64_t>& hist) {
  py::dict d;
  for (size_t i = 0; i < hist.size(); ++i)
    if (hist[i] != 0) d[py::str(std::to_string(i))] = hist[i];
  return d;
}

py::dict metrics_dict(const Metrics& m) {
  py::dict d;
  const auto fields = metric_fields();
  for (size_t i = 0; i < fields.size(); ++i) {
    const py::str group(std::string(fields[i].group));
    if (!d.contains(group)) d[group] = py::dict();
    d[group][py::str(std::string(fields[i].key))] = scalar(fields[i], m.values[i]);
  }
  auto list = [](const std::vector<int32_t>& v) {
    py::list l;
    for (int32_t x : v) l.append(x);
    return l;
  };
  d["census"]["polyhedra_by_faces"] = by_value(m.polyhedra_by_faces);
  d["singular"]["valence_interior"] = by_value(m.singular_valence_interior);
  d["singular"]["valence_boundary"] = by_value(m.singular_valence_boundary);
  d["singular"]["singularity_edges"] = list(m.singularity_edges);
  d["complex"]["component_cells"] = list(m.component_cells);
  d["sheets"]["subsheets_per_sheet"] = list(m.subsheets_per_sheet);
  d["non_hex"]["region_cells"] = list(m.non_hex_region_cells);
  py::list vec, keys;
  for (double x : m.summary_vector) vec.append(std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none()));
  for (std::string_view k : summary_fields()) keys.append(std::string(k));
  d["summary"]["vector"] = vec;
  d["summary"]["vector_keys"] = keys;
  // The deprecated keys beside the new ones, as `hbc metrics --json` writes them.
  for (const MetricAlias& a : metric_aliases()) {
    py::dict g = d[py::str(std::string(a.group))];
    if (g.contains(std::string(a.key))) g[py::str(std::string(a.old_key))] = g[py::str(std::string(a.key))];
  }
  return d;
}

py::dict analysis_metrics(const PyAnalysisPtr& p, const py::object& threads, bool quality) {
  Threads t;
  if (!threads.is_none()) {
    t.count = threads.cast<int>();
    if (t.count <= 0) throw py::value_error("threads must be a positive number or None");
  }
  Metrics m;
  {
    py::gil_scoped_release unlocked;  // the metrics touch no Python object
    MetricsOptions o;
    o.quality = quality;
    m = compute_metrics(p->mesh->mesh, p->analysis, t, o);
  }
  return metrics_dict(m);
}

}  // namespace

void bind_metrics(py::module_& m) {
  // A Field with a group and a refinement rule (hbc/metrics.hpp): key, label, notation, meaning,
  // unit and kind come from Field's binding (bind_schema, registered before this).
  py::class_<MetricField, Field>(m, "MetricField",
                                 "One structural metric (docs/metrics.md): a Field with its group and how it "
                                 "changes when every cell is split into 8.")
      .def_property_readonly("group", [](const MetricField& f) { return std::string(f.group); },
                             "census, singular, complex, sheets, non_hex, quality or summary.")
      .def_property_readonly("refinement", [](const MetricField& f) { return refinement_name(f.refinement); },
                             "'invariant', 'x8', 'x2', 'x4' or 'none' under uniform refinement.")
      .def("__repr__", [](const MetricField& f) {
        return "<hbc.MetricField " + std::string(f.group) + "." + std::string(f.key) + ">";
      });
  const auto fields = metric_fields();
  py::tuple t(fields.size());
  for (size_t i = 0; i < fields.size(); ++i) t[i] = py::cast(&fields[i], py::return_value_policy::reference);
  m.attr("METRIC_FIELDS") = t;
  py::tuple s(summary_fields().size());
  for (size_t i = 0; i < s.size(); ++i) s[i] = std::string(summary_fields()[i]);
  m.attr("SUMMARY_FIELDS") = s;
  auto cls = py::reinterpret_borrow<py::class_<PyAnalysis, PyAnalysisPtr>>(m.attr("Analysis"));
  cls.def("metrics", &analysis_metrics, py::arg("threads") = py::none(), py::arg("quality") = true,
          "Structural complexity metrics (docs/metrics.md), computed with the GIL released: the "
          "`hbc metrics --json` object without 'file' and 'timings', a dict of groups. quality=False "
          "skips the scaled Jacobians (the quality group is then None), as --no-quality does.");
}

}  // namespace hbc::python
