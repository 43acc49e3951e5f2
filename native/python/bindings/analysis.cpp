// Mesh.analyze() and what it returns: hbc.Analysis (stats, per-sheet arrays, subsheets(),
// wireframe()), with its singularity graph (hbc.SingularityGraph) and base complex
// (hbc.BaseComplex) as views. Every array is a read-only numpy view into the C++ analysis (no
// copy) whose numpy base is the Python object that returned it; that object keeps the analysis,
// and the analysis its mesh, alive.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include <pybind11/stl.h>  // std::optional results as None

#include "bindings.hpp"
#include "hbc/vtu_export.hpp"
#include <vector>

namespace hbc::python {

std::optional<int32_t> optional_id(const py::object& v, const char* what) {
  if (v.is_none()) return std::nullopt;
  const int64_t i = v.cast<int64_t>();
  if (i < 0 || i > INT32_MAX) throw std::invalid_argument(std::string(what) + " must be a non-negative id");
  return static_cast<int32_t>(i);
}

namespace {

static_assert(sizeof(EdgeClass) == 1 && sizeof(ComponentKind) == 1, "enums are exposed as uint8");

// Views of the analysis' parts; each keeps the whole analysis alive.
struct GraphView {
  PyAnalysisPtr a;
};
struct ComplexView {
  PyAnalysisPtr a;
};
struct SubsheetsView {
  PyAnalysisPtr a;
  size_t index;  // into the sheet stage's subsheets
};

const PyAnalysis& analysis_of(const PyAnalysis& p) { return p; }
const PyAnalysis& analysis_of(const GraphView& v) { return *v.a; }
const PyAnalysis& analysis_of(const ComplexView& v) { return *v.a; }

template <class T>
py::array vec(const std::vector<T>& v, py::handle owner) {
  return view(v.data(), {ssize(v.size())}, owner);
}
// 0/1 bytes as numpy bool.
py::array flags(const std::vector<uint8_t>& v, py::handle owner) {
  return view(v.data(), {ssize(v.size())}, owner, py::dtype::of<bool>());
}
// One-byte enums as uint8.
template <class E>
py::array enums(const std::vector<E>& v, py::handle owner) {
  return view(reinterpret_cast<const uint8_t*>(v.data()), {ssize(v.size())}, owner);
}

// A read-only array property of class H computed by f(analysis, self), described by the table.
template <class H, class... Opts, class F>
void prop(py::class_<H, Opts...>& cls, const char* name, F f) {
  cls.def_property_readonly(
      name, [f](py::object self) -> py::array { return f(analysis_of(self.cast<const H&>()), self); },
      array_doc(exported(cls, name)).c_str());
}

// The CSR get(analysis) returns as `<name>_offsets` / `<name>_items` (def_csr) of class H.
template <class H, class... Opts, class Get>
void csr(py::class_<H, Opts...>& cls, const std::string& name, Get get) {
  def_csr(cls, name, [get](const H& h) -> const Csr<int32_t>& { return get(analysis_of(h)); });
}

// The per-row classification arrays shared by Analysis (row "sheet") and Subsheets (row
// "subsheet"): `<row>_type`, `<row>_flags` and four CSRs.
template <class H, class... Opts, class Get>
void class_arrays(py::class_<H, Opts...>& cls, const std::string& row, Get get) {
  cls.def_property_readonly((row + "_type").c_str(), [get](py::object self) -> py::array {
    return vec(get(self.cast<const H&>()).type, self);
  }, array_doc(exported(cls, row + "_type")).c_str());
  cls.def_property_readonly((row + "_flags").c_str(), [get](py::object self) -> py::array {
    const auto& f = get(self.cast<const H&>()).flags;
    return view(f.data(), {ssize(f.size() / 3), 3}, self, py::dtype::of<bool>());
  }, array_doc(exported(cls, row + "_flags")).c_str());
  const std::pair<const char*, Csr<int32_t> ClassArrays::*> csrs[] = {
      {"unmatched_vertices", &ClassArrays::unmatched_vertices},
      {"shared_vertices", &ClassArrays::shared_vertices},
      {"self_parallel_curves", &ClassArrays::self_parallel_curves},
      {"self_intersecting_components", &ClassArrays::self_intersecting_components}};
  for (const auto& [name, member] : csrs)
    def_csr(cls, row + "_" + name, [get, member = member](const H& h) -> const Csr<int32_t>& { return get(h).*member; });
}

// A keyword argument as the library's option value: bool before int (a Python bool is an int),
// anything with __index__ (numpy's integers) as an int, anything with __float__ as a float.
OptionValue option_value(const std::string& key, const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (PyIndex_Check(v.ptr())) return v.cast<int64_t>();
  if (py::hasattr(v, "__float__")) return v.cast<double>();
  throw py::type_error("analyze(" + key + "=...): a bool, int, float or str, not " +
                       py::str(py::type::of(v).attr("__name__")).cast<std::string>());
}

// Mesh.analyze(**options): the keyword arguments read by the library's one reader of analyze's
// options (hbc/exports.hpp), as the CLI's and JavaScript's are. None leaves an option whose
// default is none (threads) at that default; an unknown keyword is a TypeError, as Python's own.
PyAnalysisPtr analyze(PyMeshPtr mesh, const py::kwargs& kwargs) {
  std::vector<OptionSetting> settings;
  for (const auto& [k, v] : kwargs) {
    const std::string key = py::str(k);
    const AnalyzeOption* o = find_analyze_option(key);
    if (o && v.is_none() && o->default_text == "none") continue;
    settings.push_back({key, v.is_none() ? OptionValue(std::string("None")) : option_value(key, v)});
  }
  AnalyzeSettings set;
  try {
    set = analyze_settings(settings);
  } catch (const UnknownOptionError& e) {
    throw py::type_error(e.what());
  }
  auto out = std::make_shared<PyAnalysis>();
  out->mesh = std::move(mesh);
  out->options = set.options;
  out->rho = set.rho;
  const AnalysisOptions& o = out->options;
  {
    py::gil_scoped_release unlocked;  // the analysis touches no Python object
    PyAnalysis& p = *out;
    p.analysis = hbc::analyze(p.mesh->mesh, o);
    p.analysis.timings.load = p.mesh->load_seconds;
    if (const auto& st = p.analysis.sheet_stage) {
      p.sheet_classes = flatten_classes(st->domain, st->sheets.classes);
      p.sheet_components = blocks_as_components(st->domain, st->sheets.sheet_blocks);
      if (st->subsheets)
        for (const Subsheets& s : *st->subsheets) {
          p.self_intersecting.push_back(s.sheet);
          p.subsheets.push_back({flatten_classes(st->domain, s.classes), blocks_as_components(st->domain, s.blocks)});
        }
    }
  }
  return out;
}

// The CLI's `hbc analyze --json` object without "file" (schema.cpp's stats_dict).
py::dict analysis_stats(const PyAnalysis& p) { return stats_dict(compute_stats(p.mesh->mesh, p.analysis)); }

}  // namespace

double checked_rho(double rho) {
  if (!(rho >= 0.0 && rho <= 1.0)) throw std::invalid_argument("rho must be in [0, 1], not " + std::to_string(rho));
  return rho;
}

std::shared_ptr<const WireframeStyle> style_of(const CellComplex& view, const VsgWireframe& w, double rho) {
  WireframeStyleOptions o;
  o.rho = checked_rho(rho);
  auto st = std::make_shared<WireframeStyle>();
  py::gil_scoped_release unlocked;  // the style touches no Python object
  *st = wireframe_style(view, w, o);
  return st;
}

namespace {

// The whole-mesh wireframe (kept by the analysis) or a region's (computed now), styled at rho
// (the analysis' rho when None): a new rho restyles, it never analyses again.
PyWireframe wireframe(const PyAnalysisPtr& p, const py::object& sheet_arg, const py::object& subsheet_arg,
                      const py::object& rho_arg) {
  const auto sheet = optional_id(sheet_arg, "sheet"), subsheet = optional_id(subsheet_arg, "subsheet");
  if (!sheet && subsheet) throw std::invalid_argument("a subsheet needs its sheet");
  const double rho = checked_rho(rho_arg.is_none() ? p->rho : rho_arg.cast<double>());
  PyWireframe out;
  out.rho = rho;
  if (!sheet && p->analysis.wireframe_stage) {
    const WireframeStage& st = *p->analysis.wireframe_stage;
    out.w = std::shared_ptr<const VsgWireframe>(p, &st.wireframe);
    out.view = std::shared_ptr<const CellComplex>(p, &st.view);
    if (!p->whole_style || p->whole_style_rho != rho) {
      p->whole_style = style_of(st.view, st.wireframe, rho);
      p->whole_style_rho = rho;
    }
    out.style = p->whole_style;
    return out;
  }
  auto st = std::make_shared<WireframeStage>();
  {
    py::gil_scoped_release unlocked;
    *st = region_wireframe_stage(p->mesh->mesh, p->analysis, p->options.wireframe_level, {}, sheet, subsheet);
  }
  out.w = std::shared_ptr<const VsgWireframe>(st, &st->wireframe);
  out.view = std::shared_ptr<const CellComplex>(st, &st->view);
  out.style = style_of(st->view, st->wireframe, rho);
  return out;
}

SubsheetsView subsheets(const PyAnalysisPtr& p, int64_t sheet) {
  if (sheet < 0 || sheet > INT32_MAX) throw std::invalid_argument("sheet must be a non-negative id");
  const Subsheets& sub = require_subsheets(p->analysis, static_cast<int32_t>(sheet));
  return {p, static_cast<size_t>(&sub - p->decompositions().data())};
}

void bind_graph(py::module_& m) {
  py::class_<GraphView> g(m, "SingularityGraph",
                          "The hybrid singularity graph of an Analysis (paper §3.2); arrays are views.");
  prop(g, "edge_class", [](const PyAnalysis& p, py::handle s) { return enums(p.analysis.graph.edge_class, s); });
  prop(g, "edge_irregular", [](const PyAnalysis& p, py::handle s) { return flags(p.analysis.graph.edge_irregular, s); });
  prop(g, "edge_chain", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.graph.edge_chain, s); });
  csr(g, "chain_vertices", [](const PyAnalysis& p) -> auto& { return p.analysis.graph.chain_verts; });
  csr(g, "chain_edges", [](const PyAnalysis& p) -> auto& { return p.analysis.graph.chain_edges; });
  prop(g, "chain_valence", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.graph.chain_valence, s); });
  prop(g, "chain_boundary", [](const PyAnalysis& p, py::handle s) { return flags(p.analysis.graph.chain_boundary, s); });
  prop(g, "chain_closed", [](const PyAnalysis& p, py::handle s) { return flags(p.analysis.graph.chain_closed, s); });
  prop(g, "singular_vertices", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.graph.singular_vertices, s); });
  prop(g, "pseudo_singular_vertices",
       [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.graph.pseudo_singular_vertices, s); });
  prop(g, "pseudo_singular_edges", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.graph.pseudo_singular_edges, s); });
  prop(g, "non_manifold_edges", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.graph.non_manifold_edges, s); });
  g.def_property_readonly("num_singularities", [](const GraphView& v) { return v.a->analysis.graph.num_singularities(); });
}

void bind_complex(py::module_& m) {
  py::class_<ComplexView> c(m, "BaseComplex", "The hybrid base complex of an Analysis (paper §3.3); arrays are views.");
  prop(c, "cell_component", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.complex.cell_component, s); });
  prop(c, "component_kind", [](const PyAnalysis& p, py::handle s) { return enums(p.analysis.complex.component_kind, s); });
  csr(c, "component_cells", [](const PyAnalysis& p) -> auto& { return p.analysis.complex.component_cells; });
  csr(c, "component_adjacency", [](const PyAnalysis& p) -> auto& { return p.analysis.complex.component_adjacency; });
  prop(c, "face_separation", [](const PyAnalysis& p, py::handle s) { return flags(p.analysis.complex.face_separation, s); });
  prop(c, "face_patch", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.complex.face_patch, s); });
  csr(c, "patch_faces", [](const PyAnalysis& p) -> auto& { return p.analysis.complex.patch_faces; });
  csr(c, "curve_vertices", [](const PyAnalysis& p) -> auto& { return p.analysis.complex.curve_verts; });
  csr(c, "curve_edges", [](const PyAnalysis& p) -> auto& { return p.analysis.complex.curve_edges; });
  prop(c, "curve_closed", [](const PyAnalysis& p, py::handle s) { return flags(p.analysis.complex.curve_closed, s); });
  prop(c, "edge_curve", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.complex.edge_curve, s); });
  prop(c, "corners", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.complex.corners, s); });
  prop(c, "self_adjacent_faces", [](const PyAnalysis& p, py::handle s) { return vec(p.analysis.complex.self_adjacent_faces, s); });
  c.def_property_readonly("num_components", [](const ComplexView& v) { return v.a->analysis.complex.num_components(); });
  c.def_property_readonly("num_patches", [](const ComplexView& v) { return v.a->analysis.complex.num_patches(); });
  c.def_property_readonly("num_curves", [](const ComplexView& v) { return v.a->analysis.complex.num_curves(); });
}

void bind_subsheets(py::module_& m) {
  py::class_<SubsheetsView> c(m, "Subsheets",
                              "The subsheets of one self-intersecting sheet (paper §4.3); arrays are views.");
  const auto sub = [](const SubsheetsView& v) -> const Subsheets& { return v.a->decompositions()[v.index]; };
  c.def_property_readonly("sheet", [sub](const SubsheetsView& v) { return sub(v).sheet; });
  c.def_property_readonly("count", [sub](const SubsheetsView& v) { return sub(v).size(); });
  c.def_property_readonly("rule", [sub](const SubsheetsView& v) { return subsheet_rule_name(sub(v).rule); },
                          "'layers' or 'fewest': how the sheet was split.");
  c.def_property_readonly("lower_bound", [sub](const SubsheetsView& v) { return sub(v).lower_bound; },
                          "'fewest': no split has fewer subsheets; 0 for 'layers'.");
  c.def_property_readonly("proven", [sub](const SubsheetsView& v) { return sub(v).proven; },
                          "'fewest': count equals lower_bound (the count is the minimum).");
  const auto flat = [](const SubsheetsView& v) -> const PyAnalysis::Sub& { return v.a->subsheets[v.index]; };
  def_csr(c, "subsheet_components", [flat](const SubsheetsView& v) -> auto& { return flat(v).components; });
  def_csr(c, "subsheet_cells", [sub](const SubsheetsView& v) -> auto& { return sub(v).cells; });
  def_csr(c, "subsheet_curves", [sub](const SubsheetsView& v) -> auto& { return sub(v).curves; });
  class_arrays(c, "subsheet", [flat](const SubsheetsView& v) -> const ClassArrays& { return flat(v).classes; });
}

std::string to_vtu(const PyAnalysis& p, const std::string& path, py::object sheet, bool ascii) {
  VtuExportOptions o;
  o.ascii = ascii;
  o.sheet = optional_id(sheet, "sheet");
  py::gil_scoped_release unlocked;  // writing touches no Python object
  export_vtu(p.mesh->mesh, p.analysis, path, o);
  return vtu_graph_path(path);
}

}  // namespace

void bind_analysis(py::module_& m) {
  bind_graph(m);
  bind_complex(m);
  bind_subsheets(m);

  py::class_<PyAnalysis, PyAnalysisPtr> c(m, "Analysis",
                                          "The structure of a mesh (Mesh.analyze()): singularity graph, base complex, "
                                          "sheets, subsheets, VSG wireframe. Arrays are read-only views.");
  c.def_property_readonly("mesh", [](const PyAnalysis& p) { return p.mesh; }, "The analyzed hbc.Mesh.");
  c.def_property_readonly("level", [](const PyAnalysis& p) { return level_name(p.options.wireframe_level); });
  c.def_property_readonly("rho", [](const PyAnalysis& p) { return p.rho; },
                          "The ρ of wireframe() without one (Mesh.analyze(rho=...); presentation only: the "
                          "analysis does not depend on it).");
  c.def_property_readonly("has_sheets", [](const PyAnalysis& p) { return p.analysis.sheet_stage.has_value(); },
                          "The sheet stage ran (else the per-sheet arrays are empty).");
  c.def_property_readonly("has_subsheets",
                          [](const PyAnalysis& p) { return p.analysis.sheet_stage && p.analysis.sheet_stage->subsheets; },
                          "The subsheet stage ran (else subsheets() raises ValueError).");
  c.def_property_readonly("has_wireframe", [](const PyAnalysis& p) { return p.analysis.wireframe_stage.has_value(); },
                          "The whole-mesh wireframe stage ran (else wireframe() computes it on demand).");
  c.def_property_readonly("stats", &analysis_stats,
                          "dict: the `hbc analyze --json` keys (Table 1 and more, docs/concepts.md), timings in seconds.");
  c.def_property_readonly("graph", [](const PyAnalysisPtr& p) { return GraphView{p}; });
  c.def_property_readonly("complex", [](const PyAnalysisPtr& p) { return ComplexView{p}; });

  c.def_property_readonly("num_sheets", [](const PyAnalysis& p) { return p.sheets().size(); });
  csr(c, "sheet_components", [](const PyAnalysis& p) -> auto& { return p.sheet_components; });
  csr(c, "sheet_cells", [](const PyAnalysis& p) -> auto& { return p.sheets().sheet_cells; });
  csr(c, "sheet_curves", [](const PyAnalysis& p) -> auto& { return p.sheets().sheet_curves; });
  csr(c, "sheet_edges", [](const PyAnalysis& p) -> auto& { return p.sheets().sheet_edges; });
  csr(c, "sheet_non_hex_cells", [](const PyAnalysis& p) -> auto& { return p.sheets().sheet_non_hex_cells; });
  class_arrays(c, "sheet", [](const PyAnalysis& p) -> const ClassArrays& { return p.sheet_classes; });
  c.def_property_readonly(
      "largest_self_intersecting",
      [](const PyAnalysis& p) -> std::optional<int32_t> {
        return p.analysis.sheet_stage ? p.analysis.sheet_stage->largest_self_intersecting : std::nullopt;
      },
      "The self-intersecting sheet with most cells; None without one (or without the sheet stage).");
  prop(c, "self_intersecting_sheets", [](const PyAnalysis& p, py::handle s) { return vec(p.self_intersecting, s); });
  c.def("subsheets", &subsheets, py::arg("sheet"),
        "The subsheets of a self-intersecting sheet; ValueError for any other sheet.");
  c.def("wireframe", &wireframe, py::arg("sheet") = py::none(), py::arg("subsheet") = py::none(),
        py::arg("rho") = py::none(),
        "The VSG wireframe of the whole mesh (no arguments), or of a sheet / subsheet region (its "
        "cells plus adjacent non-hex cells), computed on demand at the analysis' level; styled "
        "(opacity, colours) at rho, else the analysis' rho. A new rho only restyles: nothing is "
        "analysed again.");

  c.def("to_vtu", &to_vtu, py::arg("path"), py::arg("sheet") = py::none(), py::arg("ascii") = false,
        "Writes the mesh with its analysis for ParaView (GIL released): `path` gets the cells with "
        "cell data component, is_hex, cell_type, sheet, sheet_count (and in_sheet, subsheet, "
        "subsheet_count for `sheet`) and point data singular, pseudo_singular, corner; "
        "<path stem>_graph.vtu the singularity graph as lines. Returns the graph file's path.");

  auto mesh_cls = py::reinterpret_borrow<py::class_<PyMesh, PyMeshPtr>>(m.attr("Mesh"));
  std::string doc = "Runs the structure analysis (GIL released) with these options (hbc/exports.hpp; "
                    "hbc._core.ANALYZE_OPTIONS):";
  for (const AnalyzeOption& o : analyze_options())
    doc += "\n  " + std::string(o.key) + " (" + option_type_name(o.type) + ", default " + std::string(o.default_text) +
           "): " + std::string(o.meaning) + ".";
  mesh_cls.def("analyze", &analyze, doc.c_str());
}

}  // namespace hbc::python
