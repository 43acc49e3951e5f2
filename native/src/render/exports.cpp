#include "hbc/exports.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "hbc/level.hpp"
#include "hbc/sheets.hpp"

namespace hbc {
namespace {

using D = Dtype;
constexpr uint8_t P = kPython, J = kJs, B = kBoth;

// Holder by holder, in the order the Python classes list them. Meanings are one line each; the
// concepts are docs/concepts.md's.
const ExportedArray kArrays[] = {
    // Mesh
    {"Mesh", "points", D::Float32, false, "nv", 3, B, "", "vertex positions (a float32 copy)"},
    {"Mesh", "points64", D::Float64, false, "nv", 3, B, "", "vertex positions as stored"},
    {"Mesh", "edges", D::Int32, false, "ne", 2, B, "", "edge end vertices, lower id first"},
    {"Mesh", "face_vertices", D::Int32, true, "nf", 0, B, "", "the vertex loop of each face"},
    {"Mesh", "face_edges", D::Int32, true, "nf", 0, P, "",
     "aligned with face_vertices_items: entry i is the edge joining loop vertices i and i+1"},
    {"Mesh", "face_cells", D::Int32, false, "nf", 2, B, "", "the cells on both sides of each face; the second is -1 on the boundary"},
    {"Mesh", "cell_faces", D::Int32, true, "nc", 0, B, "", "the face ids of each cell"},
    {"Mesh", "cell_face_flip", D::UInt8, false, "ncf", 0, P, "",
     "aligned with cell_faces_items: 1 when the cell sees the face loop reversed"},
    {"Mesh", "cell_types", D::UInt8, false, "nc", 0, B, "", "0 hex, 1 tet, 2 prism, 3 pyramid, 4 polyhedron"},
    {"Mesh", "face_boundary", D::Bool, false, "nf", 0, B, "", "a cell on one side only"},
    {"Mesh", "edge_boundary", D::Bool, false, "ne", 0, P, "", "the edge lies on a boundary face"},
    {"Mesh", "vertex_boundary", D::Bool, false, "nv", 0, P, "", "the vertex lies on a boundary face"},
    {"Mesh", "vertex_non_manifold", D::Bool, false, "nv", 0, P, "",
     "non-manifold vertex: its cells are not face-connected around it, or one meets it in fewer than 3 faces"},
    {"Mesh", "edge_valence", D::Int32, false, "ne", 0, P, "", "cells around each edge (a new array each call)"},
    // SingularityGraph (paper section 3.2)
    {"SingularityGraph", "edge_class", D::UInt8, false, "ne", 0, B, "", "0 regular, 1 singular, 2 pseudo-singular, 3 non-manifold"},
    {"SingularityGraph", "edge_irregular", D::Bool, false, "ne", 0, P, "", "valence other than 4 inside / 2 on the boundary"},
    {"SingularityGraph", "edge_chain", D::Int32, false, "ne", 0, B, "", "singularity of a singular edge, else -1"},
    {"SingularityGraph", "chain_vertices", D::Int32, true, "ns", 0, B, "",
     "ordered vertices of each singularity (a closed chain does not repeat its first vertex)"},
    {"SingularityGraph", "chain_edges", D::Int32, true, "ns", 0, B, "",
     "ordered edges of each singularity; edge i joins chain vertices i and i+1 (mod n)"},
    {"SingularityGraph", "chain_valence", D::Int32, false, "ns", 0, B, "", "valence of each singularity"},
    {"SingularityGraph", "chain_boundary", D::Bool, false, "ns", 0, B, "", "all its edges on the boundary"},
    {"SingularityGraph", "chain_closed", D::Bool, false, "ns", 0, B, "", "a closed loop"},
    {"SingularityGraph", "singular_vertices", D::Int32, false, "k", 0, B, "",
     "sorted singularity ends that are not pseudo-singular (not the wireframe's singular vertices)"},
    {"SingularityGraph", "pseudo_singular_vertices", D::Int32, false, "k", 0, B, "",
     "sorted ends of pseudo-singular and non-manifold edges"},
    {"SingularityGraph", "pseudo_singular_edges", D::Int32, false, "k", 0, P, "", "sorted edges touching a non-hex cell"},
    {"SingularityGraph", "non_manifold_edges", D::Int32, false, "k", 0, P, "",
     "sorted edges touching a non-manifold vertex (neither singular nor pseudo-singular)"},
    // BaseComplex (paper section 3.3)
    {"BaseComplex", "cell_component", D::Int32, false, "nc", 0, B, "", "component of each cell"},
    {"BaseComplex", "component_kind", D::UInt8, false, "ncomp", 0, B, "", "0 cube, 1 ring, 2 other, 3 non-hex"},
    {"BaseComplex", "component_cells", D::Int32, true, "ncomp", 0, B, "", "sorted cells of each component"},
    {"BaseComplex", "component_adjacency", D::Int32, true, "ncomp", 0, P, "",
     "sorted components sharing a separation face with each component"},
    {"BaseComplex", "face_separation", D::Bool, false, "nf", 0, P, "", "separation face"},
    {"BaseComplex", "face_patch", D::Int32, false, "nf", 0, B, "", "patch of a separation face, else -1"},
    {"BaseComplex", "patch_faces", D::Int32, true, "npatch", 0, P, "", "sorted mesh faces of each patch"},
    {"BaseComplex", "curve_vertices", D::Int32, true, "ncurve", 0, B, "",
     "mesh vertex polyline of each curve (a closed curve does not repeat its first vertex)"},
    {"BaseComplex", "curve_edges", D::Int32, true, "ncurve", 0, P, "", "ordered mesh edges of each curve"},
    {"BaseComplex", "curve_closed", D::Bool, false, "ncurve", 0, B, "", "a closed curve (no corner on it)"},
    {"BaseComplex", "edge_curve", D::Int32, false, "ne", 0, P, "", "curve of a complex edge, else -1"},
    {"BaseComplex", "corners", D::Int32, false, "k", 0, B, "", "sorted corner vertices"},
    {"BaseComplex", "self_adjacent_faces", D::Int32, false, "k", 0, P, "",
     "interior separation faces with one component on both sides"},
    // Analysis: the sheets (paper section 4)
    {"Analysis", "sheet_type", D::UInt8, false, "num_sheets", 0, B, "",
     "0 perfect, 1 type 1 (non-hex), 2 type 2 (self-parallel), 3 type 3 (self-intersecting)"},
    {"Analysis", "sheet_types", D::UInt8, false, "num_sheets", 0, J, "sheet_type", "sheet_type under its old JavaScript name"},
    {"Analysis", "sheet_flags", D::Bool, false, "num_sheets", 3, P, "", "type 1, type 2, type 3 configurations present"},
    {"Analysis", "sheet_components", D::Int32, true, "num_sheets", 0, B, "", "sorted base-complex components of each sheet"},
    {"Analysis", "sheet_blocks", D::Int32, true, "num_sheets", 0, J, "sheet_components",
     "sorted ids of the sheet domain's blocks of each sheet (hex components at level complex, hex cells at level mesh)"},
    {"Analysis", "sheet_cells", D::Int32, true, "num_sheets", 0, B, "", "sorted mesh hex cells of each sheet"},
    {"Analysis", "sheet_curves", D::Int32, true, "num_sheets", 0, P, "",
     "sorted parallel curves E_P of each sheet (complex curves, or mesh edges at level mesh)"},
    {"Analysis", "sheet_edges", D::Int32, true, "num_sheets", 0, P, "", "sorted mesh edges of each sheet's parallel curves"},
    {"Analysis", "sheet_non_hex_cells", D::Int32, true, "num_sheets", 0, P, "", "sorted non-hex cells adjacent to each sheet"},
    {"Analysis", "sheet_unmatched_vertices", D::Int32, true, "num_sheets", 0, B, "",
     "mesh vertices left unmatched by a maximum matching"},
    {"Analysis", "sheet_shared_vertices", D::Int32, true, "num_sheets", 0, B, "", "mesh vertices shared by two parallel curves"},
    {"Analysis", "sheet_self_parallel_curves", D::Int32, true, "num_sheets", 0, B, "", "curves of type 2 (self-parallel) pairs"},
    {"Analysis", "sheet_self_intersecting_components", D::Int32, true, "num_sheets", 0, B, "",
     "components holding two parallel curves sharing an end (type 3 pairs)"},
    {"Analysis", "self_intersecting_sheets", D::Int32, false, "k", 0, P, "",
     "the sheets with a subsheet decomposition, increasing"},
    // Subsheets: of one self-intersecting sheet (paper section 4.3)
    {"Subsheets", "subsheet_type", D::UInt8, false, "count", 0, B, "",
     "0 perfect, 1 type 1 (non-hex), 2 type 2 (self-parallel), 3 type 3 (self-intersecting)"},
    {"Subsheets", "subsheet_types", D::UInt8, false, "count", 0, J, "subsheet_type", "subsheet_type under its old JavaScript name"},
    {"Subsheets", "subsheet_flags", D::Bool, false, "count", 3, P, "", "type 1, type 2, type 3 configurations present"},
    {"Subsheets", "subsheet_components", D::Int32, true, "count", 0, B, "", "sorted base-complex components of each subsheet"},
    {"Subsheets", "subsheet_blocks", D::Int32, true, "count", 0, J, "subsheet_components",
     "sorted ids of the sheet domain's blocks of each subsheet (hex components at level complex, hex cells at level mesh)"},
    {"Subsheets", "subsheet_cells", D::Int32, true, "count", 0, B, "", "sorted mesh hex cells of each subsheet"},
    {"Subsheets", "subsheet_curves", D::Int32, true, "count", 0, P, "",
     "sorted parallel curves of each subsheet (complex curves, or mesh edges at level mesh)"},
    {"Subsheets", "subsheet_unmatched_vertices", D::Int32, true, "count", 0, B, "",
     "mesh vertices left unmatched by a maximum matching"},
    {"Subsheets", "subsheet_shared_vertices", D::Int32, true, "count", 0, B, "", "mesh vertices shared by two parallel curves"},
    {"Subsheets", "subsheet_self_parallel_curves", D::Int32, true, "count", 0, B, "", "curves of type 2 (self-parallel) pairs"},
    {"Subsheets", "subsheet_self_intersecting_components", D::Int32, true, "count", 0, B, "",
     "components holding two parallel curves sharing an end (type 3 pairs)"},
    // Wireframe (paper section 5; its style, section 6.2)
    {"Wireframe", "polylines", D::Int32, true, "count", 0, B, "",
     "mesh vertices along each polyline of the complete wireframe (a closed VSG chain repeats its first vertex)"},
    {"Wireframe", "point_opacity", D::Float32, false, "npp", 0, B, "", "aligned with polylines_items: opacity in [floor, 1]"},
    {"Wireframe", "kind", D::UInt8, false, "count", 0, B, "", "0 chain of VSG (irregular) edges only, 1 other chain"},
    {"Wireframe", "valence", D::Int32, false, "count", 0, P, "", "region valence of the chain's first edge"},
    {"Wireframe", "stop", D::UInt8, false, "count", 0, P, "",
     "the chain's last vertex: 0 closed chain, 1 singular vertex of the wireframe, 2 boundary, 3 neither"},
    {"Wireframe", "shown", D::Bool, false, "count", 0, B, "", "every edge of the chain lies on the simplified wireframe"},
    {"Wireframe", "non_important", D::UInt8, false, "count", 0, P, "",
     "0 kept, 1 both ends redundant, 2 in a removable pair at a singular vertex"},
    {"Wireframe", "reactivated", D::Bool, false, "count", 0, P, "", "non-important but kept: it continues a kept chain"},
    {"Wireframe", "simplified_polylines", D::Int32, true, "nsimp", 0, B, "",
     "mesh vertices along each simplified polyline (kept chains re-chained)"},
    {"Wireframe", "color", D::Int32, false, "count", 0, B, "", "palette index"},
    {"Wireframe", "color_class", D::Int32, false, "count", 0, B, "",
     "colour class (lowest polyline of a set of partially parallel ones)"},
    {"Wireframe", "non_hex", D::Int32, true, "count", 0, B, "",
     "non-hex kinds of each polyline, sorted: code >> 16 indexes CELL_TYPES, code & 0xffff is the face count"},
    {"Wireframe", "simplified_non_hex", D::Int32, true, "nsimp", 0, B, "", "non-hex kinds of each simplified polyline, as non_hex"},
    // BlockSoup: block_soup(), kept_surface_soup()
    {"BlockSoup", "positions", D::Float32, false, "np", 3, B, "", "point positions, each owner with its own copies"},
    {"BlockSoup", "point_vertex", D::Int32, false, "np", 0, B, "", "mesh vertex of each point"},
    {"BlockSoup", "face_vertices", D::Int32, true, "nsf", 0, B, "", "point ids of each face, loops outward"},
    {"BlockSoup", "face_owner", D::Int32, false, "nsf", 0, B, "", "owner of each face; faces grouped by increasing owner"},
    {"BlockSoup", "face_source", D::Int32, false, "nsf", 0, B, "", "mesh face of each face"},
    {"BlockSoup", "face_cell", D::Int32, false, "nsf", 0, B, "", "mesh cell on the owner's side (the face points out of it)"},
    // GeneratedMesh: JavaScript's generate_cylinder(), a generator's output before any reader
    {"GeneratedMesh", "points", D::Float64, false, "nv", 3, J, "", "vertex positions"},
    {"GeneratedMesh", "faces", D::Int32, true, "nf", 0, J, "", "the vertex loop of each face, 0-based"},
    {"GeneratedMesh", "cells", D::Int32, true, "nc", 0, J, "",
     "2 entries per face of each cell: the face and a flip (1: the cell sees the face's loop reversed)"},
};

const Dimension kDimensions[] = {
    {"nv", "vertices of the mesh (Mesh.num_vertices)"},
    {"ne", "edges of the mesh (Mesh.num_edges)"},
    {"nf", "faces of the mesh (Mesh.num_faces)"},
    {"nc", "cells of the mesh (Mesh.num_cells)"},
    {"ncf", "face entries of all cells (cell_faces_offsets[nc])"},
    {"ns", "singularities (SingularityGraph.num_singularities)"},
    {"ncomp", "components of the base complex (BaseComplex.num_components)"},
    {"npatch", "patches of the base complex (BaseComplex.num_patches)"},
    {"ncurve", "curves of the base complex (BaseComplex.num_curves)"},
    {"num_sheets", "sheets (Analysis.num_sheets)"},
    {"count", "rows of the holder: subsheets (Subsheets.count), polylines (Wireframe.count)"},
    {"npp", "points of a wireframe's polylines (polylines_offsets[count])"},
    {"nsimp", "polylines of the simplified wireframe (Wireframe.counts['wireframe_edges_simplified'])"},
    {"np", "points of a block soup"},
    {"nsf", "faces of a block soup"},
    {"k", "a list of ids, as long as it is"},
};

// Defaults as Python writes them; each equals AnalyzeSettings{}'s member (a test checks it).
const AnalyzeOption kOptions[] = {
    {"rho", OptionType::Real, "0.8", "", 0, 1,
     "threshold of the wireframes' colour classes (paper section 6.2) when wireframe() is given none; no count depends on it"},
    {"level", OptionType::Choice, "complex", "complex|mesh", 0, 0,
     "level of the sheets and the wireframe: complex (the paper's) or mesh"},
    {"sheets", OptionType::Bool, "true", "", 0, 0, "run the sheet stage (sheets and their classes)"},
    {"subsheets", OptionType::Bool, "true", "", 0, 0, "decompose every self-intersecting sheet (with sheets only)"},
    {"wireframe", OptionType::Bool, "true", "", 0, 0, "run the whole-mesh VSG wireframe stage"},
    {"threads", OptionType::Int, "none", "", 1, 2147483647,
     "threads the stages may use (none: HBC_THREADS, else every core); results do not depend on it"},
    {"subsheet_rule", OptionType::Choice, "layers", "layers|fewest", 0, 0,
     "decomposition of self-intersecting sheets: layers (the paper's authors' rule) or fewest (with a lower bound)"},
    {"search_steps", OptionType::Int, "100000", "", 0, 9.0e15, "the fewest rule's exact search steps per sheet"},
};

std::string value_text(const OptionValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  if (const int64_t* i = std::get_if<int64_t>(&v)) return std::to_string(*i);
  if (const double* d = std::get_if<double>(&v)) {
    // JavaScript's 2 arrives as 2.0: said as the caller wrote it.
    if (*d == std::floor(*d) && std::fabs(*d) < 1e15) return std::to_string(static_cast<int64_t>(*d));
    std::string s = std::to_string(*d);
    while (s.size() > 1 && s.back() == '0' && s[s.size() - 2] != '.') s.pop_back();
    return s;
  }
  return "'" + std::get<std::string>(v) + "'";
}

[[noreturn]] void bad_value(const AnalyzeOption& o, const std::string& wants, const OptionValue& v) {
  throw std::invalid_argument(std::string(o.key) + " must be " + wants + ", not " + value_text(v));
}

bool as_bool(const AnalyzeOption& o, const OptionValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b;
  bad_value(o, "true or false", v);
}

std::string range_text(const AnalyzeOption& o) {
  const auto num = [](double x) { return x == std::floor(x) ? std::to_string(static_cast<int64_t>(x)) : std::to_string(x); };
  if (o.max >= 2147483647) return "an integer >= " + num(o.min);
  return (o.type == OptionType::Int ? "an integer in [" : "in [") + num(o.min) + ", " + num(o.max) + "]";
}

double as_number(const AnalyzeOption& o, const OptionValue& v) {
  double x;
  if (const int64_t* i = std::get_if<int64_t>(&v)) x = static_cast<double>(*i);
  else if (const double* d = std::get_if<double>(&v)) x = *d;
  else bad_value(o, range_text(o), v);
  const bool integral = o.type != OptionType::Int || x == std::floor(x);
  if (!(x >= o.min && x <= o.max) || !integral) bad_value(o, range_text(o), v);
  return x;
}

std::string as_choice(const AnalyzeOption& o, const OptionValue& v) {
  std::string wants = "one of";
  if (const std::string* s = std::get_if<std::string>(&v)) {
    for (size_t b = 0; b <= o.choices.size();) {
      const size_t e = std::min(o.choices.find('|', b), o.choices.size());
      if (o.choices.substr(b, e - b) == *s) return *s;
      b = e + 1;
    }
  }
  for (size_t b = 0; b <= o.choices.size();) {
    const size_t e = std::min(o.choices.find('|', b), o.choices.size());
    wants += (b ? ", '" : " '") + std::string(o.choices.substr(b, e - b)) + "'";
    b = e + 1;
  }
  bad_value(o, wants, v);
}

void apply(AnalyzeSettings& s, const AnalyzeOption& o, const OptionValue& v) {
  AnalysisOptions& a = s.options;
  const std::string_view k = o.key;
  if (k == "rho") s.rho = as_number(o, v);
  else if (k == "level") a.sheet_level = a.wireframe_level = level_from_name(as_choice(o, v));
  else if (k == "sheets") a.sheets = as_bool(o, v);
  else if (k == "subsheets") a.subsheets = as_bool(o, v);
  else if (k == "wireframe") a.wireframe = as_bool(o, v);
  else if (k == "threads") a.threads = static_cast<int>(as_number(o, v));
  else if (k == "subsheet_rule") a.subsheet_options.rule = *subsheet_rule_from_name(as_choice(o, v));
  else if (k == "search_steps") a.subsheet_options.node_budget = static_cast<int64_t>(as_number(o, v));
  else throw std::logic_error("analyze option '" + std::string(k) + "' is described but never read");
}

}  // namespace

const char* dtype_name(Dtype d) {
  switch (d) {
    case Dtype::Bool: return "bool";
    case Dtype::UInt8: return "uint8";
    case Dtype::Int32: return "int32";
    case Dtype::Float32: return "float32";
    case Dtype::Float64: return "float64";
  }
  return "";
}

std::span<const ExportedArray> exported_arrays() { return kArrays; }
std::span<const Dimension> dimensions() { return kDimensions; }

const ExportedArray* find_exported_array(std::string_view holder, std::string_view name) {
  for (const ExportedArray& a : kArrays) {
    if (a.holder != holder) continue;
    if (a.name == name) return &a;
    if (a.csr && name.size() > a.name.size() && name.substr(0, a.name.size()) == a.name) {
      const std::string_view tail = name.substr(a.name.size());
      if (tail == "_offsets" || tail == "_items") return &a;
    }
  }
  return nullptr;
}

std::string numpy_shape_text(const ExportedArray& a) {
  std::string rows(a.rows);
  if (a.csr) rows = std::string(a.name) + "_offsets[-1]";
  const std::string shape = a.width ? "(" + rows + ", " + std::to_string(a.width) + ")" : "(" + rows + ",)";
  return std::string(dtype_name(a.dtype)) + " " + shape;
}

const char* option_type_name(OptionType t) {
  switch (t) {
    case OptionType::Bool: return "bool";
    case OptionType::Int: return "int";
    case OptionType::Real: return "float";
    case OptionType::Choice: return "choice";
  }
  return "";
}

std::span<const AnalyzeOption> analyze_options() { return kOptions; }

const AnalyzeOption* find_analyze_option(std::string_view key) {
  for (const AnalyzeOption& o : kOptions)
    if (o.key == key) return &o;
  return nullptr;
}

AnalyzeSettings analyze_settings(std::span<const OptionSetting> settings, const AnalyzeSettings& defaults) {
  AnalyzeSettings s = defaults;
  for (const OptionSetting& kv : settings) {
    const AnalyzeOption* o = find_analyze_option(kv.key);
    if (!o) {
      std::string known;
      for (const AnalyzeOption& x : kOptions) known += (known.empty() ? "" : ", ") + std::string(x.key);
      throw UnknownOptionError("analyze takes no option '" + kv.key + "' (its options: " + known + ")");
    }
    apply(s, *o, kv.value);
  }
  s.options.subsheets = s.options.subsheets && s.options.sheets;
  return s;
}

}  // namespace hbc
