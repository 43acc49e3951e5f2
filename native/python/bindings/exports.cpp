// The binding surface's one description (hbc/exports.hpp), for Python: the lookup every array
// property is registered through, and the tables as hbc._core.EXPORTED_ARRAYS, DIMENSIONS and
// ANALYZE_OPTIONS, which tests/python/test_exports.py checks the objects and _core.pyi against.
#include <stdexcept>
#include <string>

#include "bindings.hpp"

namespace hbc::python {

const ExportedArray& exported(std::string_view holder, std::string_view name) {
  const ExportedArray* e = find_exported_array(holder, name);
  if (!e || !(e->surfaces & kPython))
    throw std::logic_error("hbc._core: " + std::string(holder) + "." + std::string(name) +
                           " is not an exported Python array of hbc/exports.hpp");
  return *e;
}

const ExportedArray& exported(py::handle cls, std::string_view name) {
  return exported(cls.attr("__name__").cast<std::string>(), name);
}

std::string array_doc(const ExportedArray& a) { return numpy_shape_text(a) + ": " + std::string(a.meaning) + "."; }

namespace {

py::dict array_dict(const ExportedArray& a) {
  py::dict d;
  d["holder"] = std::string(a.holder);
  d["name"] = std::string(a.name);
  d["dtype"] = dtype_name(a.dtype);
  d["csr"] = a.csr;
  d["rows"] = std::string(a.rows);
  d["width"] = a.width;
  d["python"] = (a.surfaces & kPython) != 0;
  d["js"] = (a.surfaces & kJs) != 0;
  d["deprecated"] = std::string(a.deprecated);
  d["meaning"] = std::string(a.meaning);
  return d;
}

py::dict option_dict(const AnalyzeOption& o) {
  py::dict d;
  d["key"] = std::string(o.key);
  d["type"] = option_type_name(o.type);
  d["default"] = std::string(o.default_text);
  py::list choices;
  for (size_t b = 0; !o.choices.empty() && b <= o.choices.size();) {
    const size_t e = std::min(o.choices.find('|', b), o.choices.size());
    choices.append(std::string(o.choices.substr(b, e - b)));
    b = e + 1;
  }
  d["choices"] = py::tuple(choices);
  d["min"] = o.min;
  d["max"] = o.max;
  d["meaning"] = std::string(o.meaning);
  return d;
}

}  // namespace

void bind_exports(py::module_& m) {
  py::list arrays, options;
  for (const ExportedArray& a : exported_arrays()) arrays.append(array_dict(a));
  for (const AnalyzeOption& o : analyze_options()) options.append(option_dict(o));
  py::dict dims;
  for (const Dimension& d : dimensions()) dims[py::str(std::string(d.symbol))] = std::string(d.meaning);
  m.attr("EXPORTED_ARRAYS") = py::tuple(arrays);
  m.attr("ANALYZE_OPTIONS") = py::tuple(options);
  m.attr("DIMENSIONS") = dims;
}

}  // namespace hbc::python
