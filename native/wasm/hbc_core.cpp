// The JavaScript binding (embind): the same names as the Python binding (native/python/hbc/_core.pyi),
// typed arrays in place of numpy arrays. Every array is a copy (a view into the wasm heap would be
// invalidated when the heap grows). Errors are JS Errors whose message is the CLI's text
// ("file:line: expected ..."). hbc_core.d.ts documents each function and array shape.
#include <emscripten/bind.h>
#include <emscripten/val.h>

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
    if (a_->sheet_stage)
      sheet_classes_ = std::make_shared<ClassArrays>(flatten_classes(a_->sheet_stage->domain, a_->sheet_stage->sheets.classes));
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
  val sheet_blocks_offsets() const { return copy(sheets().sheet_blocks.offsets); }
  val sheet_blocks_items() const { return copy(sheets().sheet_blocks.items); }
  val sheet_types() const { return copy(classes().type); }
  // The picked sheet's highlights (Analysis.sheet_* CSRs in _core.pyi), one row per sheet.
  val sheet_unmatched_vertices_offsets() const { return copy(classes().unmatched_vertices.offsets); }
  val sheet_unmatched_vertices_items() const { return copy(classes().unmatched_vertices.items); }
  val sheet_shared_vertices_offsets() const { return copy(classes().shared_vertices.offsets); }
  val sheet_shared_vertices_items() const { return copy(classes().shared_vertices.items); }
  val sheet_self_parallel_curves_offsets() const { return copy(classes().self_parallel_curves.offsets); }
  val sheet_self_parallel_curves_items() const { return copy(classes().self_parallel_curves.items); }
  val sheet_self_intersecting_components_offsets() const { return copy(classes().self_intersecting_components.offsets); }
  val sheet_self_intersecting_components_items() const { return copy(classes().self_intersecting_components.items); }
  // The subsheets of one self-intersecting sheet: {count, subsheet_cells_offsets, _items, subsheet_types};
  // null when the sheet has none.
  val subsheets(int sheet) const {
    sheets();
    const Subsheets* s = a_->sheet_stage->subsheets_of(sheet);
    if (!s) return val::null();
    val o = val::object();
    o.set("sheet", s->sheet);
    o.set("count", static_cast<int>(s->size()));
    o.set("subsheet_cells_offsets", copy(s->cells.offsets));
    o.set("subsheet_cells_items", copy(s->cells.items));
    o.set("subsheet_blocks_offsets", copy(s->blocks.offsets));
    o.set("subsheet_blocks_items", copy(s->blocks.items));
    const ClassArrays c = flatten_classes(a_->sheet_stage->domain, s->classes);
    o.set("subsheet_types", copy(c.type));
    const std::pair<const char*, const Csr<int32_t>*> rows[] = {
        {"unmatched_vertices", &c.unmatched_vertices}, {"shared_vertices", &c.shared_vertices},
        {"self_parallel_curves", &c.self_parallel_curves},
        {"self_intersecting_components", &c.self_intersecting_components}};
    for (const auto& [name, csr] : rows) {
      o.set(std::string("subsheet_") + name + "_offsets", copy(csr->offsets));
      o.set(std::string("subsheet_") + name + "_items", copy(csr->items));
    }
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
    o.set("polylines_offsets", copy(w.polylines.offsets));
    o.set("polylines_items", copy(w.polylines.items));
    o.set("point_opacity", copy(style.point_opacity));
    o.set("kind", copy(w.kind));
    o.set("shown", copy(w.shown));
    o.set("color", copy(style.color));
    o.set("color_class", copy(style.color_class));
    o.set("non_hex_offsets", copy(w.non_hex.offsets));
    o.set("non_hex_items", copy(w.non_hex.items));
    o.set("simplified_polylines_offsets", copy(w.simplified_polylines.offsets));
    o.set("simplified_polylines_items", copy(w.simplified_polylines.items));
    o.set("simplified_non_hex_offsets", copy(w.simplified_non_hex.offsets));
    o.set("simplified_non_hex_items", copy(w.simplified_non_hex.items));
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
    o.set("positions", copy(b.positions));
    o.set("point_vertex", copy(b.point_vertex));
    o.set("face_vertices_offsets", copy(b.face_vertices.offsets));
    o.set("face_vertices_items", copy(b.face_vertices.items));
    o.set("face_owner", copy(b.face_owner));
    o.set("face_source", copy(b.face_source));
    o.set("face_cell", copy(b.face_cell));
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
  std::shared_ptr<LoadedMesh> m_;
  std::shared_ptr<Analysis> a_;
  Level level_;
  double rho_;  // the wireframes' rho without one (analyze's option; presentation only)
  std::shared_ptr<const ClassArrays> sheet_classes_;  // computed once, as the Python binding does
};

std::string JsMesh::info_json() const { return json_text(mesh_info_json(mesh(), m_->name)); }

// options: {level: "complex"|"mesh", subsheet_rule: "layers"|"fewest", rho, sheets, subsheets, wireframe}.
JsAnalysis JsMesh::analyze(val options) const {
  return guarded([&] {
    AnalysisOptions opt;
    opt.threads = 1;
    auto get = [&](const char* k) { return options.isUndefined() || options.isNull() ? val::undefined() : options[k]; };
    if (val v = get("level"); !v.isUndefined()) opt.sheet_level = opt.wireframe_level = level_from_name(v.as<std::string>());
    if (val v = get("subsheet_rule"); !v.isUndefined()) {
      const auto rule = subsheet_rule_from_name(v.as<std::string>());
      if (!rule) throw std::invalid_argument("subsheet_rule: 'layers' or 'fewest', not '" + v.as<std::string>() + "'");
      opt.subsheet_options.rule = *rule;
    }
    double rho = WireframeStyleOptions{}.rho;  // not the analysis': the wireframes' style
    if (val v = get("rho"); !v.isUndefined()) rho = v.as<double>();
    if (val v = get("sheets"); !v.isUndefined()) opt.sheets = v.as<bool>();
    if (val v = get("subsheets"); !v.isUndefined()) opt.subsheets = v.as<bool>();
    if (val v = get("wireframe"); !v.isUndefined()) opt.wireframe = v.as<bool>();
    return JsAnalysis(m_, std::make_shared<Analysis>(hbc::analyze(m_->mesh, opt)), opt, rho);
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
    o.set("points", copy(in.points));
    o.set("faces_offsets", copy(in.faces.offsets));
    o.set("faces_items", copy(in.faces.items));
    o.set("cells_offsets", copy(in.cells.offsets));
    o.set("cells_items", copy(in.cells.items));
    return o;
  });
}

std::string version_string() { return std::string(version()); }

}  // namespace
}  // namespace hbc::js

EMSCRIPTEN_BINDINGS(hbc_core) {
  using namespace emscripten;
  using namespace hbc::js;
  class_<JsMesh>("Mesh")
      .property("num_vertices", &JsMesh::num_vertices)
      .property("num_edges", &JsMesh::num_edges)
      .property("num_faces", &JsMesh::num_faces)
      .property("num_cells", &JsMesh::num_cells)
      .property("source", &JsMesh::source)
      .property("points", &JsMesh::points)
      .property("points64", &JsMesh::points64)
      .property("edges", &JsMesh::edges)
      .property("face_vertices_offsets", &JsMesh::face_vertices_offsets)
      .property("face_vertices_items", &JsMesh::face_vertices_items)
      .property("face_cells", &JsMesh::face_cells)
      .property("cell_faces_offsets", &JsMesh::cell_faces_offsets)
      .property("cell_faces_items", &JsMesh::cell_faces_items)
      .property("cell_types", &JsMesh::cell_types)
      .property("face_boundary", &JsMesh::face_boundary)
      .property("warnings", &JsMesh::warnings)
      .function("info_json", &JsMesh::info_json)
      .function("analyze", &JsMesh::analyze);
  class_<JsAnalysis>("Analysis")
      .function("stats_json", &JsAnalysis::stats_json)
      .property("edge_class", &JsAnalysis::edge_class)
      .property("edge_chain", &JsAnalysis::edge_chain)
      .property("chain_vertices_offsets", &JsAnalysis::chain_vertices_offsets)
      .property("chain_vertices_items", &JsAnalysis::chain_vertices_items)
      .property("chain_edges_offsets", &JsAnalysis::chain_edges_offsets)
      .property("chain_edges_items", &JsAnalysis::chain_edges_items)
      .property("chain_valence", &JsAnalysis::chain_valence)
      .property("chain_boundary", &JsAnalysis::chain_boundary)
      .property("chain_closed", &JsAnalysis::chain_closed)
      .property("singular_vertices", &JsAnalysis::singular_vertices)
      .property("pseudo_singular_vertices", &JsAnalysis::pseudo_singular_vertices)
      .property("num_singularities", &JsAnalysis::num_singularities)
      .property("cell_component", &JsAnalysis::cell_component)
      .property("component_kind", &JsAnalysis::component_kind)
      .property("component_cells_offsets", &JsAnalysis::component_cells_offsets)
      .property("component_cells_items", &JsAnalysis::component_cells_items)
      .property("face_patch", &JsAnalysis::face_patch)
      .property("curve_vertices_offsets", &JsAnalysis::curve_vertices_offsets)
      .property("curve_vertices_items", &JsAnalysis::curve_vertices_items)
      .property("curve_closed", &JsAnalysis::curve_closed)
      .property("corners", &JsAnalysis::corners)
      .property("num_components", &JsAnalysis::num_components)
      .property("num_curves", &JsAnalysis::num_curves)
      .property("num_patches", &JsAnalysis::num_patches)
      .property("num_sheets", &JsAnalysis::num_sheets)
      .property("sheet_cells_offsets", &JsAnalysis::sheet_cells_offsets)
      .property("sheet_cells_items", &JsAnalysis::sheet_cells_items)
      .property("sheet_blocks_offsets", &JsAnalysis::sheet_blocks_offsets)
      .property("sheet_blocks_items", &JsAnalysis::sheet_blocks_items)
      .property("sheet_types", &JsAnalysis::sheet_types)
      .property("sheet_unmatched_vertices_offsets", &JsAnalysis::sheet_unmatched_vertices_offsets)
      .property("sheet_unmatched_vertices_items", &JsAnalysis::sheet_unmatched_vertices_items)
      .property("sheet_shared_vertices_offsets", &JsAnalysis::sheet_shared_vertices_offsets)
      .property("sheet_shared_vertices_items", &JsAnalysis::sheet_shared_vertices_items)
      .property("sheet_self_parallel_curves_offsets", &JsAnalysis::sheet_self_parallel_curves_offsets)
      .property("sheet_self_parallel_curves_items", &JsAnalysis::sheet_self_parallel_curves_items)
      .property("sheet_self_intersecting_components_offsets", &JsAnalysis::sheet_self_intersecting_components_offsets)
      .property("sheet_self_intersecting_components_items", &JsAnalysis::sheet_self_intersecting_components_items)
      .function("subsheets", &JsAnalysis::subsheets)
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
  function("version", &version_string);
}
