// The library's one description of what it reports, for Python: the statistics fields
// (hbc.STAT_FIELDS, TIMING_FIELDS, WIREFRAME_COUNT_FIELDS, TABLE1_COLUMNS) and the name tables
// (SHEET_TYPES, CELL_TYPES, COMPONENT_KINDS, FORMATS). The add-on and the figures read these
// instead of restating them; the .pyi stub is checked against them.
#include "bindings.hpp"
#include "hbc/base_complex.hpp"
#include "hbc/io.hpp"
#include "hbc/schema.hpp"
#include "hbc/sheets.hpp"

namespace hbc::python {
namespace {

py::tuple field_tuple(std::span<const Field> fields) {
  py::tuple t(fields.size());
  for (size_t i = 0; i < fields.size(); ++i) t[i] = py::cast(&fields[i], py::return_value_policy::reference);
  return t;
}

// f(value) per enum value 0 .. n-1: index i of the tuple describes the enum's value i.
template <class Enum, class F>
py::tuple per_value(int n, F f) {
  py::tuple t(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) t[static_cast<size_t>(i)] = f(static_cast<Enum>(i));
  return t;
}

}  // namespace

py::dict stats_dict(const Stats& s) {
  py::dict d;
  const auto fields = stat_fields();
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::optional<double> v = stat_value(s, i);
    if (!v) continue;  // a stage that did not run leaves its keys out, as `hbc analyze --json` does
    const py::str key(std::string(fields[i].key));
    if (fields[i].kind == FieldKind::Count) d[key] = static_cast<int64_t>(*v);
    else d[key] = *v;
  }
  py::dict t;
  const auto timings = timing_fields();
  for (size_t i = 0; i < timings.size(); ++i) t[py::str(std::string(timings[i].key))] = timing_value(s.timings, i);
  d["timings"] = t;
  return d;
}

py::dict wireframe_counts(const VsgWireframe& w) {
  py::dict d;
  const auto fields = wireframe_count_fields();
  for (size_t i = 0; i < fields.size(); ++i) d[py::str(std::string(fields[i].key))] = wireframe_count(w, i);
  // The deprecated keys beside the new ones, as `hbc wireframe --json` writes them.
  for (const FieldAlias& a : wireframe_count_aliases())
    d[py::str(std::string(a.old_key))] = d[py::str(std::string(a.key))];
  return d;
}

void bind_schema(py::module_& m) {
  py::class_<Field>(m, "Field", "One reported number: its key (JSON/CSV), label, notation, meaning and unit.")
      .def_property_readonly("key", [](const Field& f) { return std::string(f.key); }, "JSON key and CSV column.")
      .def_property_readonly("label", [](const Field& f) { return std::string(f.label); }, "In words, for panels.")
      .def_property_readonly("notation", [](const Field& f) { return std::string(f.notation); },
                             "The paper's Table 1 symbol, or ''.")
      .def_property_readonly("latex", [](const Field& f) { return std::string(f.latex); }, "The same in LaTeX, or ''.")
      .def_property_readonly("meaning", [](const Field& f) { return std::string(f.meaning); }, "One line.")
      .def_property_readonly("unit", [](const Field& f) { return std::string(f.unit); },
                             "What is counted, 'ratio' or 's'.")
      .def_property_readonly("kind", [](const Field& f) { return field_kind_name(f.kind); },
                             "'count', 'ratio' or 'seconds'.")
      .def("__repr__", [](const Field& f) { return "<hbc.Field " + std::string(f.key) + ">"; });
  m.attr("STAT_FIELDS") = field_tuple(stat_fields());
  m.attr("TIMING_FIELDS") = field_tuple(timing_fields());
  m.attr("WIREFRAME_COUNT_FIELDS") = field_tuple(wireframe_count_fields());
  py::tuple columns(table1_columns().size());
  for (size_t i = 0; i < table1_columns().size(); ++i) {
    const Table1Column& c = table1_columns()[i];
    columns[i] = py::make_tuple(py::cast(c.field, py::return_value_policy::reference), c.timing);
  }
  m.attr("TABLE1_COLUMNS") = columns;
  m.attr("SHEET_TYPES") =
      per_value<SheetType>(4, [](SheetType t) { return py::make_tuple(sheet_type_name(t), sheet_type_label(t)); });
  m.attr("CELL_TYPES") = per_value<CellType>(5, [](CellType t) { return py::str(cell_type_name(t)); });
  m.attr("COMPONENT_KINDS") =
      per_value<ComponentKind>(4, [](ComponentKind k) { return py::str(component_kind_name(k)); });
  py::tuple fmts(formats().size());
  for (size_t i = 0; i < formats().size(); ++i) {
    const FormatInfo& f = formats()[i];
    py::dict d;
    d["name"] = std::string(f.name);
    d["alias"] = std::string(f.alias);
    d["extension"] = std::string(f.extension);
    py::list all;
    for (std::string_view e : extensions_of(f)) all.append(std::string(e));
    d["extensions"] = all;
    d["title"] = std::string(f.title);
    d["writable"] = f.writable;
    fmts[i] = d;
  }
  m.attr("FORMATS") = fmts;
}

}  // namespace hbc::python
