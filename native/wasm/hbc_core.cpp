// The JavaScript binding (embind): the same names as the Python binding (native/python/hbc/_core.pyi),
// typed arrays in place of numpy arrays. Every array is registered by a name of the library's table
// (hbc/exports.hpp), which tests/wasm/binding_test.mjs checks this module and hbc_core.d.ts against. Every array is a copy (a view into the wasm heap would be
// invalidated when the heap grows). Errors are JS Errors whose message is the CLI's text
// ("file:line: expected ..."). hbc_core.d.ts documents each function and array shape.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "hbc/error.hpp"
#include "hbc/exports.hpp"
#include "hbc/generate.hpp"
#include "hbc/io.hpp"
#include "hbc/json.hpp"
#include "hbc/region.hpp"
#include "hbc/render_geometry.hpp"
#include "hbc/report.hpp"
#include "hbc/schema.hpp"
#include "hbc/version.hpp"
#include "hbc/wireframe_style.hpp"

using emscripten::val;

namespace hbc::js {
namespace {

template <class T> const char* array_name();
template <> const char* array_name<float>() { return "Float32Array"; }
template <> const char* array_name<double>() { return "Float64Array"; }
template <> const char* array_name<int32_t>() { return "Int32Array"; }
template <> const char* array_name<uint8_t>() { return "Uint8Array"; }

// A JS typed array holding a copy of n values at p.
template <class T>
val copy(const T* p, size_t n) {
  return val::global(array_name<T>()).new_(emscripten::typed_memory_view(n, p));
}
template <class T>
val copy(const std::vector<T>& v) {
  if constexpr (std::is_enum_v<T>) return copy(reinterpret_cast<const uint8_t*>(v.data()), v.size());
  else return copy(v.data(), v.size());
}
template <class T, size_t K>
val copy_flat(const std::vector<std::array<T, K>>& v) { return copy(reinterpret_cast<const T*>(v.data()), v.size() * K); }

// `name` when the table (hbc/exports.hpp) lists it for JavaScript on `holder`; else std::logic_error,
// which stops the module's load (EMSCRIPTEN_BINDINGS) or the call that would hand it out.
const char* js_name(const char* holder, const char* name) {
  const ExportedArray* e = find_exported_array(holder, name);
  if (!e || !(e->surfaces & kJs))
    throw std::logic_error(std::string("hbc_core: ") + holder + "." + name + " is not an exported JavaScript array of hbc/exports.hpp");
  return name;
}
// o[name] = v on a plain object (Wireframe, BlockSoup, Subsheets, GeneratedMesh) through the table.
void set(val& o, const char* holder, const char* name, val v) { o.set(js_name(holder, name), std::move(v)); }

[[noreturn]] void throw_js(const std::string& message) { val::global("Error").new_(message).throw_(); }

// Runs f, turning C++ exceptions into JS Errors with the same text the CLI prints.
template <class F>
auto guarded(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw_js("out of memory");
  } catch (const std::exception& e) {
    throw_js(e.what());
  }
}

struct LoadedMesh {
  Mesh mesh;
  std::vector<DroppedCell> dropped;
  bool skip_invalid = false;
  std::string name;
};

class JsAnalysis;

class JsMesh {
 public:
  explicit JsMesh(std::shared_ptr<LoadedMesh> m) : m_(std::move(m)) {}
  int num_vertices() const { return static_cast<int>(mesh().num_vertices()); }
  int num_edges() const { return static_cast<int>(mesh().num_edges()); }
  int num_faces() const { return static_cast<int>(mesh().num_faces()); }
  int num_cells() const { return static_cast<int>(mesh().num_cells()); }
  std::string source() const { return m_->name; }
  val points() const {  // float32 (3 nv), as the Python binding's points
    const auto& p = mesh().points;
    std::vector<float> f(p.begin(), p.end());
    return copy(f);
  }
  val points64() const { return copy(mesh().points); }
  val edges() const { return copy_flat(mesh().edge_verts); }
  val face_vertices_offsets() const { return copy(mesh().face_verts.offsets); }
  val face_vertices_items() const { return copy(mesh().face_verts.items); }
  val face_cells() const { return copy_flat(mesh().face_cells); }
  val cell_faces_offsets() const { return copy(mesh().cell_faces.offsets); }
  val cell_faces_items() const { return copy(mesh().cell_faces.items); }
  val cell_types() const { return copy(mesh().cell_type); }
  val face_boundary() const { return copy(mesh().face_boundary); }
  // What reading said beside the mesh (cells dropped by skip_invalid, unused faces dropped...): the
  // CLI prints each as "hbc: warning: FILE: TEXT"; here the TEXTs.
  val warnings() const {
    val out = val::array();
    for (const std::string& w : mesh().warnings) out.call<void>("push", w);
    return out;
  }
  // `hbc info --json` of this mesh, the same text ("file" is the name given to load); the Python
  // binding's info() is the same object without "file".
  std::string info_json() const;
  JsAnalysis analyze(val options) const;
  const Mesh& mesh() const { return m_->mesh; }
  const std::shared_ptr<LoadedMesh>& loaded() const { return m_; }

 private:
  std::shared_ptr<LoadedMesh> m_;
};

class JsAnalysis {
 public:
  JsAnalysis(std::shared_ptr<LoadedMesh> m, std::shared_ptr<Analysis> a, const AnalysisOptions& options, double rho)
      : m_(std::move(m)), a_(std::move(a)), level_(options.wireframe_level), rho_(rho) {
    if (a_->sheet_stage) {
      const SheetStage& st = *a_->sheet_stage;
      sheet_classes_ = std::make_shared<ClassArrays>(flatten_classes(st.domain, st.sheets.classes));
      sheet_components_ = std::make_shared<Csr<int32_t>>(blocks_as_components(st.domain, st.sheets.sheet_blocks));
    }
  }
  // `hbc analyze --json` of this mesh, the same keys and values ("file" is the name given to load).
  std::string stats_json() const {
    Json j = {{"file", m_->name}};
    add_stats_json(j, compute_stats(m_->mesh, *a_));
    add_dropped_json(j, m_->skip_invalid, m_->dropped);
    return json_text(j);
  }
  // Singularity graph (SingularityGraph in _core.pyi).
  val edge_class() const { return copy(a_->graph.edge_class); }
  val edge_chain() const { return copy(a_->graph.edge_chain); }
  val chain_vertices_offsets() const { return copy(a_->graph.chain_verts.offsets); }
  val chain_vertices_items() const { return copy(a_->graph.chain_verts.items); }
  val chain_edges_offsets() const { return copy(a_->graph.chain_edges.offsets); }
  val chain_edges_items() const { return copy(a_->graph.chain_edges.items); }
  val chain_valence() const { return copy(a_->graph.chain_valence); }
  val chain_boundary() const { return copy(a_->graph.chain_boundary); }
  val chain_closed() const { return copy(a_->graph.chain_closed); }
  val singular_vertices() const { return copy(a_->graph.singular_vertices); }
  val pseudo_singular_vertices() const { return copy(a_->graph.pseudo_singular_vertices); }
  int num_singularities() const { return static_cast<int>(a_->graph.num_singularities()); }
  // Base complex (BaseComplex in _core.pyi).
  val cell_component() const { return copy(a_->complex.cell_component); }
  val component_kind() const { return copy(a_->complex.component_kind); }
  val component_cells_offsets() const { return copy(a_->complex.component_cells.offsets); }
  val component_cells_items() const { return copy(a_->complex.component_cells.items); }
  val face_patch() const { return copy(a_->complex.face_patch); }
  val curve_vertices_offsets() const { return copy(a_->complex.curve_verts.offsets); }
  val curve_vertices_items() const { return copy(a_->complex.curve_verts.items); }
  val curve_closed() const { return copy(a_->complex.curve_closed); }
  val corners() const { return copy(a_->complex.corners); }
  int num_components() const { return static_cast<int>(a_->complex.num_components()); }
  int num_curves() const { return static_cast<int>(a_->complex.curve_closed.size()); }
  int num_patches() const { return static_cast<int>(a_->complex.patch_faces.rows()); }
  // Sheets: cells per sheet and the class arrays (Analysis.sheet_* in _core.pyi).
  int num_sheets() const { return a_->sheet_stage ? static_cast<int>(a_->sheet_stage->sheets.size()) : 0; }
  val sheet_cells_offsets() const { return copy(sheets().sheet_cells.offsets); }
  val sheet_cells_items() const { return copy(sheets().sheet_cells.items); }
  val sheet_components_offsets() const { return copy(components().offsets); }
  val sheet_components_items() const { return copy(components().items); }
  val sheet_type() const { return copy(classes().type); }
  // Deprecated: the names before the Python ones (hbc_core.d.ts). sheet_blocks holds the sheet
  // domain's block ids, as it always did; sheet_components the base complex's component ids.
  val sheet_blocks_offsets() const { return copy(sheets().sheet_blocks.offsets); }
  val sheet_blocks_items() const { return copy(sheets().sheet_blocks.items); }
  val sheet_types() const { return sheet_type(); }
  // The picked sheet's highlights (Analysis.sheet_* CSRs in _core.pyi), one row per sheet.
  val sheet_unmatched_vertices_offsets() const { return copy(classes().unmatched_vertices.offsets); }
  val sheet_unmatched_vertices_items() const { return copy(classes().unmatched_vertices.items); }
  val sheet_shared_vertices_offsets() const { return copy(classes().shared_vertices.offsets); }
  val sheet_shared_vertices_items() const { return copy(classes().shared_vertices.items); }
  val sheet_self_parallel_curves_offsets() const { return copy(classes().self_parallel_curves.offsets); }
  val sheet_self_parallel_curves_items() const { return copy(classes().self_parallel_curves.items); }
  val sheet_self_intersecting_components_offsets() const { return copy(classes().self_intersecting_components.offsets); }
  val sheet_self_intersecting_components_items() const { return copy(classes().self_intersecting_components.items); }
  // The subsheets of one self-intersecting sheet (Subsheets of hbc_core.d.ts); null when the sheet
  // has none.
  val subsheets(int sheet) const {
    sheets();
    const Subsheets* s = a_->sheet_stage->subsheets_of(sheet);
    if (!s) return val::null();
    const SheetDomain& domain = a_->sheet_stage->domain;
    val o = val::object();
    o.set("sheet", s->sheet);
    o.set("count", static_cast<int>(s->size()));
    const ClassArrays c = flatten_classes(domain, s->classes);
    const Csr<int32_t> components = blocks_as_components(domain, s->blocks);
    const std::pair<const char*, const Csr<int32_t>*> rows[] = {
        {"subsheet_cells", &s->cells}, {"subsheet_components", &components},
        {"subsheet_blocks", &s->blocks},  // deprecated: the sheet domain's block ids
        {"subsheet_unmatched_vertices", &c.unmatched_vertices}, {"subsheet_shared_vertices", &c.shared_vertices},
        {"subsheet_self_parallel_curves", &c.self_parallel_curves},
        {"subsheet_self_intersecting_components", &c.self_intersecting_components}};
    for (const auto& [name, csr] : rows) {
      set(o, "Subsheets", (std::string(name) + "_offsets").c_str(), copy(csr->offsets));
      set(o, "Subsheets", (std::string(name) + "_items").c_str(), copy(csr->items));
    }
    set(o, "Subsheets", "subsheet_type", copy(c.type));
    set(o, "Subsheets", "subsheet_types", copy(c.type));  // deprecated
    return o;
  }
  // The whole-mesh VSG wireframe (Wireframe in _core.pyi), or null when it did not run; styled at
  // the analysis' rho.
  val wireframe() const { return wireframe(-1, -1, rho_); }
  // wireframe(sheet, subsheet) of _core.pyi: the wireframe of a sheet's (or one of its subsheets')
  // cells with their adjacent non-hex cells; -1 for none (both -1: the whole mesh's).
  val wireframe(int sheet, int subsheet) const { return wireframe(sheet, subsheet, rho_); }
  // The same styled at `rho` (wireframe(sheet=, subsheet=, rho=) of _core.pyi): the style is the
  // render layer's step, so another rho restyles and never analyses again.
  val wireframe(int sheet, int subsheet, double rho) const {
    if (sheet < 0 && subsheet >= 0) throw_js("a subsheet needs its sheet");
    return guarded([&]() -> val {
      WireframeStyleOptions style;
      style.rho = rho;
      if (sheet < 0) {
        if (!a_->wireframe_stage) return val::null();
        const WireframeStage& st = *a_->wireframe_stage;
        return wire_object(st.wireframe, wireframe_style(st.view, st.wireframe, style));
      }
      std::optional<int32_t> sub;
      if (subsheet >= 0) sub = subsheet;
      const WireframeStage st = region_wireframe_stage(m_->mesh, *a_, level_, {}, sheet, sub);
      return wire_object(st.wireframe, wireframe_style(st.view, st.wireframe, style));
    });
  }
  static val wire_object(const VsgWireframe& w, const WireframeStyle& style) {
    val o = val::object();
    o.set("count", static_cast<int>(w.size()));
    const auto put = [&o](const char* name, val v) { set(o, "Wireframe", name, std::move(v)); };
    put("polylines_offsets", copy(w.polylines.offsets));
    put("polylines_items", copy(w.polylines.items));
    put("point_opacity", copy(style.point_opacity));
    put("kind", copy(w.kind));
    put("shown", copy(w.shown));
    put("color", copy(style.color));
    put("color_class", copy(style.color_class));
    put("non_hex_offsets", copy(w.non_hex.offsets));
    put("non_hex_items", copy(w.non_hex.items));
    put("simplified_polylines_offsets", copy(w.simplified_polylines.offsets));
    put("simplified_polylines_items", copy(w.simplified_polylines.items));
    put("simplified_non_hex_offsets", copy(w.simplified_non_hex.offsets));
    put("simplified_non_hex_items", copy(w.simplified_non_hex.items));
    return o;
  }
  // block_soup(what, sheet, shrink) of _core.pyi: a BlockSoup object of typed arrays. sheet < 0: none.
  val block_soup(const std::string& what, int sheet, double shrink) const {
    return guarded([&] {
      const SoupKind kind = soup_kind_from_name(what);
      std::optional<int32_t> s;
      if (sheet >= 0) s = sheet;
      return soup_object(hbc::block_soup(m_->mesh, *a_, kind, s, shrink));
    });
  }
  static val soup_object(const BlockSoup& b) {
    val o = val::object();
    const auto put = [&o](const char* name, val v) { set(o, "BlockSoup", name, std::move(v)); };
    put("positions", copy(b.positions));
    put("point_vertex", copy(b.point_vertex));
    put("face_vertices_offsets", copy(b.face_vertices.offsets));
    put("face_vertices_items", copy(b.face_vertices.items));
    put("face_owner", copy(b.face_owner));
    put("face_source", copy(b.face_source));
    put("face_cell", copy(b.face_cell));
    return o;
  }

 private:
  const Sheets& sheets() const {
    if (!a_->sheet_stage) throw_js("the analysis ran without sheets");
    return a_->sheet_stage->sheets;
  }
  const ClassArrays& classes() const {
    sheets();
    return *sheet_classes_;
  }
  const Csr<int32_t>& components() const {
    sheets();
    return *sheet_components_;
  }
  std::shared_ptr<LoadedMesh> m_;
  std::shared_ptr<Analysis> a_;
  Level level_;
  double rho_;  // the wireframes' rho without one (analyze's option; presentation only)
  std::shared_ptr<const ClassArrays> sheet_classes_;  // computed once, as the Python binding does
  std::shared_ptr<const Csr<int32_t>> sheet_components_;
};

std::string JsMesh::info_json() const { return json_text(mesh_info_json(mesh(), m_->name)); }

// options: analyze's options by name (hbc/exports.hpp, the AnalyzeOptions of hbc_core.d.ts), read by
// the library's one reader of them, as the CLI's and Python's are; undefined or null leaves an
// option at its default. One thread unless asked: the module has no others.
JsAnalysis JsMesh::analyze(val options) const {
  return guarded([&] {
    std::vector<OptionSetting> settings;
    if (!options.isUndefined() && !options.isNull()) {
      const val keys = val::global("Object").call<val>("keys", options);
      const int n = keys["length"].as<int>();
      for (int i = 0; i < n; ++i) {
        const std::string key = keys[i].as<std::string>();
        const val v = options[key];
        const std::string type = v.typeOf().as<std::string>();
        if (v.isUndefined() || v.isNull()) continue;
        if (type == "boolean") settings.push_back({key, v.as<bool>()});
        else if (type == "number") settings.push_back({key, v.as<double>()});
        else if (type == "string") settings.push_back({key, v.as<std::string>()});
        else throw std::invalid_argument(key + " must be a boolean, a number or a string, not a " + type);
      }
    }
    AnalyzeSettings defaults;
    defaults.options.threads = 1;
    const AnalyzeSettings set = analyze_settings(settings, defaults);
    return JsAnalysis(m_, std::make_shared<Analysis>(hbc::analyze(m_->mesh, set.options)), set.options, set.rho);
  });
}

// load(bytes, name, skip_invalid): the bytes are written to the in-memory file system under `name`
// and read by the same readers as the CLI, so the format comes from the name and messages name it.
JsMesh load(const std::string& bytes, const std::string& name, bool skip_invalid) {
  return guarded([&] {
    const std::string path = name.empty() ? std::string("mesh") : name;
    {
      std::ofstream f(path, std::ios::binary);
      if (!f) throw std::runtime_error(path + ": cannot be written to the in-memory file system");
      f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    auto m = std::make_shared<LoadedMesh>();
    m->name = path;
    m->skip_invalid = skip_invalid;
    Threads one;
    one.count = 1;
    try {
      m->mesh = skip_invalid ? load_mesh_skipping_invalid(path, m->dropped, Format::Auto, one)
                             : load_mesh(path, Format::Auto, one);
    } catch (...) {
      std::remove(path.c_str());
      throw;
    }
    std::remove(path.c_str());
    return JsMesh(m);
  });
}

// load_path(path[, skip_invalid]): a file (or an OpenFOAM case folder / owner file) already in the
// module's file system (Module.FS), read as the CLI reads a path (with --skip-invalid when asked).
JsMesh load_path_skipping(const std::string& path, bool skip_invalid) {
  return guarded([&] {
    auto m = std::make_shared<LoadedMesh>();
    m->name = path;
    m->skip_invalid = skip_invalid;
    Threads one;
    one.count = 1;
    m->mesh = skip_invalid ? load_mesh_skipping_invalid(path, m->dropped, Format::Auto, one)
                           : load_mesh(path, Format::Auto, one);
    return JsMesh(m);
  });
}
JsMesh load_path(const std::string& path) { return load_path_skipping(path, false); }

// kept_surface_soup(mesh, kept, shrink): the surface of the cells with kept[c] != 0 (nc entries).
val kept_surface_soup(const JsMesh& m, val kept, double shrink) {
  return guarded([&] {
    const auto k = emscripten::convertJSArrayToNumberVector<uint8_t>(kept);
    return JsAnalysis::soup_object(hbc::kept_surface_soup(m.mesh(), k, shrink));
  });
}

// cell_centroids(mesh): Float64Array (3 nc), the mean of each cell's distinct vertices.
val cell_centroids(const JsMesh& m) { return copy(hbc::cell_centroids(m.mesh())); }

// FORMATS: formats() as JSON [{name, alias, extension, extensions, title, writable}].
std::string formats_json() {
  Json j = Json::array();
  for (const FormatInfo& f : formats()) {
    Json all = Json::array();
    for (std::string_view e : extensions_of(f)) all.push_back(std::string(e));
    j.push_back({{"name", f.name}, {"alias", f.alias}, {"extension", f.extension}, {"extensions", all},
                 {"title", f.title}, {"writable", f.writable}});
  }
  return j.dump();
}

// TABLE1_COLUMNS_json: the paper's Table 1 columns from the schema, [{key, label, notation, meaning, timing}].
std::string table1_columns_json() {
  Json j = Json::array();
  for (const Table1Column& c : table1_columns())
    j.push_back({{"key", c.field->key}, {"label", c.field->label}, {"notation", c.field->notation},
                 {"meaning", c.field->meaning}, {"kind", field_kind_name(c.field->kind)}, {"timing", c.timing}});
  return j.dump();
}

// polylines(mesh, offsets, items) of _core.pyi: float32 positions (3 per entry).
val polylines(const JsMesh& m, val offsets, val items) {
  return guarded([&] {
    const auto o = emscripten::convertJSArrayToNumberVector<int32_t>(offsets);
    const auto i = emscripten::convertJSArrayToNumberVector<int32_t>(items);
    return copy(polyline_positions(m.mesh(), o, i));
  });
}

// generate_cylinder(radius_cells, layers): `hbc generate cylinder`'s mesh as it comes out of the
// generator, before any reader: {points (Float64Array, 3 nv), faces_offsets/_items (vertex loops),
// cells_offsets/_items (2 face + flip, flip 1 when the cell sees the loop reversed)}. The viewer
// writes it as a file and reads it back as a user's file is read (its warm-up, web/src/worker.js).
val generate_cylinder_arrays(int radius_cells, int layers) {
  return guarded([&] {
    const MeshInput in = generate_cylinder(radius_cells, layers);
    val o = val::object();
    const auto put = [&o](const char* name, val v) { set(o, "GeneratedMesh", name, std::move(v)); };
    put("points", copy(in.points));
    put("faces_offsets", copy(in.faces.offsets));
    put("faces_items", copy(in.faces.items));
    put("cells_offsets", copy(in.cells.offsets));
    put("cells_items", copy(in.cells.items));
    return o;
  });
}

// EXPORTS_json: the binding surface's description (hbc/exports.hpp) as JSON {arrays: [{holder,
// name, dtype, csr, rows, width, python, js, deprecated, meaning}], dimensions: {symbol: meaning},
// options: [{key, type, default, choices, min, max, meaning}]}, which the binding test checks the
// module's objects and hbc_core.d.ts against.
std::string exports_json() {
  Json arrays = Json::array(), options = Json::array(), dims = Json::object();
  for (const ExportedArray& a : exported_arrays())
    arrays.push_back({{"holder", a.holder}, {"name", a.name}, {"dtype", dtype_name(a.dtype)}, {"csr", a.csr},
                      {"rows", a.rows}, {"width", a.width}, {"python", (a.surfaces & kPython) != 0},
                      {"js", (a.surfaces & kJs) != 0}, {"deprecated", a.deprecated}, {"meaning", a.meaning}});
  for (const Dimension& d : dimensions()) dims[std::string(d.symbol)] = d.meaning;
  for (const AnalyzeOption& o : analyze_options()) {
    Json choices = Json::array();
    for (size_t b = 0; !o.choices.empty() && b <= o.choices.size();) {
      const size_t e = std::min(o.choices.find('|', b), o.choices.size());
      choices.push_back(o.choices.substr(b, e - b));
      b = e + 1;
    }
    options.push_back({{"key", o.key}, {"type", option_type_name(o.type)}, {"default", o.default_text},
                       {"choices", choices}, {"min", o.min}, {"max", o.max}, {"meaning", o.meaning}});
  }
  return Json{{"arrays", arrays}, {"dimensions", dims}, {"options", options}}.dump();
}

std::string version_string() { return std::string(version()); }

}  // namespace
}  // namespace hbc::js

EMSCRIPTEN_BINDINGS(hbc_core) {
  using namespace emscripten;
  using namespace hbc::js;
  // An array property: its name must be the table's (hbc/exports.hpp), else the module stops loading.
  const auto array = [](const auto& cls, const char* holder, const char* name, auto getter) {
    cls.property(js_name(holder, name), getter);
  };
  const auto mesh = class_<JsMesh>("Mesh");
  mesh.property("num_vertices", &JsMesh::num_vertices);
  mesh.property("num_edges", &JsMesh::num_edges);
  mesh.property("num_faces", &JsMesh::num_faces);
  mesh.property("num_cells", &JsMesh::num_cells);
  mesh.property("source", &JsMesh::source);
  array(mesh, "Mesh", "points", &JsMesh::points);
  array(mesh, "Mesh", "points64", &JsMesh::points64);
  array(mesh, "Mesh", "edges", &JsMesh::edges);
  array(mesh, "Mesh", "face_vertices_offsets", &JsMesh::face_vertices_offsets);
  array(mesh, "Mesh", "face_vertices_items", &JsMesh::face_vertices_items);
  array(mesh, "Mesh", "face_cells", &JsMesh::face_cells);
  array(mesh, "Mesh", "cell_faces_offsets", &JsMesh::cell_faces_offsets);
  array(mesh, "Mesh", "cell_faces_items", &JsMesh::cell_faces_items);
  array(mesh, "Mesh", "cell_types", &JsMesh::cell_types);
  array(mesh, "Mesh", "face_boundary", &JsMesh::face_boundary);
  mesh.property("warnings", &JsMesh::warnings);
  mesh.function("info_json", &JsMesh::info_json);
  mesh.function("analyze", &JsMesh::analyze);
  const auto analysis = class_<JsAnalysis>("Analysis");
  analysis.function("stats_json", &JsAnalysis::stats_json);
  array(analysis, "SingularityGraph", "edge_class", &JsAnalysis::edge_class);
  array(analysis, "SingularityGraph", "edge_chain", &JsAnalysis::edge_chain);
  array(analysis, "SingularityGraph", "chain_vertices_offsets", &JsAnalysis::chain_vertices_offsets);
  array(analysis, "SingularityGraph", "chain_vertices_items", &JsAnalysis::chain_vertices_items);
  array(analysis, "SingularityGraph", "chain_edges_offsets", &JsAnalysis::chain_edges_offsets);
  array(analysis, "SingularityGraph", "chain_edges_items", &JsAnalysis::chain_edges_items);
  array(analysis, "SingularityGraph", "chain_valence", &JsAnalysis::chain_valence);
  array(analysis, "SingularityGraph", "chain_boundary", &JsAnalysis::chain_boundary);
  array(analysis, "SingularityGraph", "chain_closed", &JsAnalysis::chain_closed);
  array(analysis, "SingularityGraph", "singular_vertices", &JsAnalysis::singular_vertices);
  array(analysis, "SingularityGraph", "pseudo_singular_vertices", &JsAnalysis::pseudo_singular_vertices);
  analysis.property("num_singularities", &JsAnalysis::num_singularities);
  array(analysis, "BaseComplex", "cell_component", &JsAnalysis::cell_component);
  array(analysis, "BaseComplex", "component_kind", &JsAnalysis::component_kind);
  array(analysis, "BaseComplex", "component_cells_offsets", &JsAnalysis::component_cells_offsets);
  array(analysis, "BaseComplex", "component_cells_items", &JsAnalysis::component_cells_items);
  array(analysis, "BaseComplex", "face_patch", &JsAnalysis::face_patch);
  array(analysis, "BaseComplex", "curve_vertices_offsets", &JsAnalysis::curve_vertices_offsets);
  array(analysis, "BaseComplex", "curve_vertices_items", &JsAnalysis::curve_vertices_items);
  array(analysis, "BaseComplex", "curve_closed", &JsAnalysis::curve_closed);
  array(analysis, "BaseComplex", "corners", &JsAnalysis::corners);
  analysis.property("num_components", &JsAnalysis::num_components);
  analysis.property("num_curves", &JsAnalysis::num_curves);
  analysis.property("num_patches", &JsAnalysis::num_patches);
  analysis.property("num_sheets", &JsAnalysis::num_sheets);
  array(analysis, "Analysis", "sheet_cells_offsets", &JsAnalysis::sheet_cells_offsets);
  array(analysis, "Analysis", "sheet_cells_items", &JsAnalysis::sheet_cells_items);
  array(analysis, "Analysis", "sheet_components_offsets", &JsAnalysis::sheet_components_offsets);
  array(analysis, "Analysis", "sheet_components_items", &JsAnalysis::sheet_components_items);
  array(analysis, "Analysis", "sheet_type", &JsAnalysis::sheet_type);
  // Deprecated names (hbc_core.d.ts), kept for old callers.
  array(analysis, "Analysis", "sheet_blocks_offsets", &JsAnalysis::sheet_blocks_offsets);
  array(analysis, "Analysis", "sheet_blocks_items", &JsAnalysis::sheet_blocks_items);
  array(analysis, "Analysis", "sheet_types", &JsAnalysis::sheet_types);
  array(analysis, "Analysis", "sheet_unmatched_vertices_offsets", &JsAnalysis::sheet_unmatched_vertices_offsets);
  array(analysis, "Analysis", "sheet_unmatched_vertices_items", &JsAnalysis::sheet_unmatched_vertices_items);
  array(analysis, "Analysis", "sheet_shared_vertices_offsets", &JsAnalysis::sheet_shared_vertices_offsets);
  array(analysis, "Analysis", "sheet_shared_vertices_items", &JsAnalysis::sheet_shared_vertices_items);
  array(analysis, "Analysis", "sheet_self_parallel_curves_offsets", &JsAnalysis::sheet_self_parallel_curves_offsets);
  array(analysis, "Analysis", "sheet_self_parallel_curves_items", &JsAnalysis::sheet_self_parallel_curves_items);
  array(analysis, "Analysis", "sheet_self_intersecting_components_offsets", &JsAnalysis::sheet_self_intersecting_components_offsets);
  array(analysis, "Analysis", "sheet_self_intersecting_components_items", &JsAnalysis::sheet_self_intersecting_components_items);
  analysis.function("subsheets", &JsAnalysis::subsheets)
      // Overloaded on the number of arguments: wireframe() or wireframe(sheet, subsheet).
      .function("wireframe", select_overload<val() const>(&JsAnalysis::wireframe))
      .function("wireframe", select_overload<val(int, int) const>(&JsAnalysis::wireframe))
      .function("wireframe", select_overload<val(int, int, double) const>(&JsAnalysis::wireframe))
      .function("block_soup", &JsAnalysis::block_soup);
  function("load", &load);
  function("polylines", &polylines);
  function("load_path", &load_path);
  function("load_path", &load_path_skipping);
  function("kept_surface_soup", &kept_surface_soup);
  function("cell_centroids", &cell_centroids);
  function("FORMATS", &formats_json);
  function("TABLE1_COLUMNS_json", &table1_columns_json);
  function("generate_cylinder", &generate_cylinder_arrays);
  function("EXPORTS_json", &exports_json);
  function("version", &version_string);
}
