#include "hbc/schema.hpp"

#include <array>

namespace hbc {
namespace {

using K = FieldKind;

// One table per result; a getter beside each entry keeps name and value together.
struct StatEntry {
  Field field;
  std::optional<double> (*get)(const Stats&);
};

template <class T>
std::optional<double> some(T v) {
  return static_cast<double>(v);
}
template <class T>
std::optional<double> some(const std::optional<T>& v) {
  return v ? std::optional<double>(static_cast<double>(*v)) : std::nullopt;
}

#define HBC_STAT(member) [](const Stats& s) { return some(s.member); }
const std::array<StatEntry, 23> kStats = {{
    {{"cells", "Cells", "|C|", "$|C|$", "cells of the mesh", "cells", K::Count}, HBC_STAT(cells)},
    {{"hex_ratio", "Hex ratio", "|H|/|C|", "$\\frac{|H|}{|C|}$", "share of the cells that are hexahedra",
      "ratio", K::Ratio}, HBC_STAT(hex_ratio)},
    {{"singular_edges", "Singular edges", "", "",
      "irregular edges all of whose cells are hexahedra", "edges", K::Count}, HBC_STAT(singular_edges)},
    {{"singularities", "Singularities", "", "",
      "chains of singular edges of one valence (paper section 3.2)", "chains", K::Count}, HBC_STAT(singularities)},
    {{"pseudo_singular_edges", "Pseudo-singular edges", "", "", "edges of at least one non-hex cell",
      "edges", K::Count}, HBC_STAT(pseudo_singular_edges)},
    {{"non_manifold_edges", "Non-manifold edges", "", "",
      "other edges at a non-manifold vertex, treated as pseudo-singular", "edges", K::Count},
     HBC_STAT(non_manifold_edges)},
    {{"singular_vertices", "Singular vertices", "", "",
      "ends of singularities that are not pseudo-singular", "vertices", K::Count}, HBC_STAT(singular_vertices)},
    {{"components", "Components", "|C_B|", "$|C_B|$",
      "components of the hybrid base complex (paper section 3.3)", "components", K::Count}, HBC_STAT(components)},
    {{"hex_components", "Hex components", "|H_B|", "$|H_B|$", "components that are cube-like blocks of hexahedra",
      "components", K::Count}, HBC_STAT(hex_components)},
    {{"hex_component_ratio", "Hex component ratio", "|H_B|/|C_B|", "$\\frac{|H_B|}{|C_B|}$",
      "share of the components that are hex components", "ratio", K::Ratio}, HBC_STAT(hex_component_ratio)},
    {{"patches", "Patches", "", "", "faces of the base complex", "patches", K::Count}, HBC_STAT(patches)},
    {{"curves", "Curves", "", "", "edges of the base complex", "curves", K::Count}, HBC_STAT(curves)},
    {{"corners", "Corners", "", "", "vertices of the base complex", "vertices", K::Count}, HBC_STAT(corners)},
    {{"self_adjacent_faces", "Self-adjacent faces", "", "",
      "interior separation faces with one component on both sides", "faces", K::Count},
     HBC_STAT(self_adjacent_faces)},
    {{"sheets", "Sheets", "|G_SH|", "$|G_{SH}|$", "sheets of the base complex (paper section 4)", "sheets",
      K::Count}, HBC_STAT(sheets)},
    {{"sheets_perfect", "Perfect sheets", "", "", "sheets whose parallel curves share no corner", "sheets",
      K::Count}, HBC_STAT(sheets_perfect)},
    {{"sheets_type1", "Type 1 sheets", "T1", "$|G_{SH}^{T1}|$",
      "imperfect sheets neither self-parallel nor self-intersecting (paper section 4.2)", "sheets", K::Count},
     HBC_STAT(sheets_type1)},
    {{"sheets_type2", "Type 2 sheets", "T2", "$|G_{SH}^{T2}|$", "self-parallel sheets that do not self-intersect",
      "sheets", K::Count}, HBC_STAT(sheets_type2)},
    {{"sheets_type3", "Type 3 sheets", "T3", "$|G_{SH}^{T3}|$", "self-intersecting sheets", "sheets", K::Count},
     HBC_STAT(sheets_type3)},
    {{"subsheets_of_largest_self_intersecting", "Subsheets", "|G_SH*|", "$|G_{SH*}|$",
      "subsheets of the largest self-intersecting sheet (paper section 4.3)", "subsheets", K::Count},
     HBC_STAT(subsheets_of_largest_self_intersecting)},
    {{"vsg_edges", "VSG edges", "", "", "edges of the valence singularity graph of the whole mesh (paper section 5)",
      "edges", K::Count}, HBC_STAT(vsg_edges)},
    {{"wireframe_edges", "Wireframe edges", "", "", "edges (chains) of the complete VSG wireframe", "chains",
      K::Count}, HBC_STAT(wireframe_edges)},
    {{"wireframe_edges_simplified", "Simplified wireframe edges", "", "",
      "edges (chains) of the simplified VSG wireframe (paper section 5.1)", "chains", K::Count},
     HBC_STAT(wireframe_edges_simplified)},
}};
#undef HBC_STAT

struct TimingEntry {
  Field field;
  double Timings::*member;
};
const std::array<TimingEntry, 6> kTimings = {{
    {{"load", "Load", "", "", "reading the file and building the mesh", "s", K::Seconds}, &Timings::load},
    {{"singularity_graph", "Singularity graph", "T_GS", "$T_{G_S}$", "the hybrid singularity graph", "s",
      K::Seconds}, &Timings::singularity_graph},
    {{"base_complex", "Base complex", "T_GB", "$T_{G_B}$", "the hybrid base complex", "s", K::Seconds},
     &Timings::base_complex},
    {{"sheets", "Sheets", "T_GSH", "$T_{G_{SH}}$", "extracting and classifying the sheets", "s", K::Seconds},
     &Timings::sheets},
    {{"subsheets", "Subsheets", "T_GSH*", "$T_{G_{SH*}}$", "decomposing the self-intersecting sheets", "s",
      K::Seconds}, &Timings::subsheets},
    {{"vsg_wireframe", "VSG wireframe", "T_VSGW", "$T_{VSGW}$", "the whole mesh's VSG wireframe and its style",
      "s", K::Seconds}, &Timings::vsg_wireframe},
}};

// In the order of `hbc wireframe --json`.
struct WireEntry {
  Field field;
  int64_t (*get)(const VsgWireframe&);
};
const std::array<WireEntry, 10> kWireCounts = {{
    {{"vsg_edges", "VSG edges", "", "", "edges of the VSG", "edges", K::Count},
     [](const VsgWireframe& w) { return w.vsg_edges; }},
    {{"vsg_chains", "VSG chains", "", "", "chains of VSG edges of one valence", "chains", K::Count},
     [](const VsgWireframe& w) { return w.vsg_chains; }},
    {{"singular_vertices", "Wireframe singular vertices", "", "",
      "ends of VSG chains, where the wireframe's traces start", "vertices", K::Count},
     [](const VsgWireframe& w) { return static_cast<int64_t>(w.singular_vertices.size()); }},
    {{"wireframe_edges", "Wireframe edges", "", "", "edges (chains) of the complete wireframe", "chains", K::Count},
     [](const VsgWireframe& w) { return w.wireframe_edges(); }},
    {{"wireframe_edges_simplified", "Simplified wireframe edges", "", "",
      "edges (chains) of the simplified wireframe", "chains", K::Count},
     [](const VsgWireframe& w) { return w.wireframe_edges_simplified(); }},
    {{"vsg_mesh_edges", "VSG mesh edges", "", "", "distinct mesh edges the VSG covers", "edges", K::Count},
     [](const VsgWireframe& w) { return w.vsg_mesh_edges; }},
    {{"wireframe_mesh_edges", "Wireframe mesh edges", "", "", "distinct mesh edges the complete wireframe covers",
      "edges", K::Count}, [](const VsgWireframe& w) { return w.wireframe_mesh_edges; }},
    {{"wireframe_mesh_edges_simplified", "Simplified wireframe mesh edges", "", "",
      "distinct mesh edges the simplified wireframe covers", "edges", K::Count},
     [](const VsgWireframe& w) { return w.simplified_mesh_edges; }},
    {{"wireframe_components", "Wireframe pieces", "", "",
      "connected components of the complete wireframe", "components", K::Count},
     [](const VsgWireframe& w) { return w.components; }},
    {{"wireframe_components_simplified", "Simplified wireframe pieces", "", "",
      "connected components of the simplified wireframe", "components", K::Count},
     [](const VsgWireframe& w) { return w.simplified_components; }},
}};

template <class Entry, size_t N>
std::span<const Field> fields_of(const std::array<Entry, N>& entries) {
  static const std::array<Field, N> fields = [&] {
    std::array<Field, N> f{};
    for (size_t i = 0; i < N; ++i) f[i] = entries[i].field;
    return f;
  }();
  return fields;
}

}  // namespace

std::span<const Field> stat_fields() { return fields_of(kStats); }
std::optional<double> stat_value(const Stats& s, size_t i) { return kStats.at(i).get(s); }

std::span<const Field> timing_fields() { return fields_of(kTimings); }
double timing_value(const Timings& t, size_t i) { return t.*kTimings.at(i).member; }

std::span<const Table1Column> table1_columns() {
  static const std::array<Table1Column, 14> columns = [] {
    auto stat = [](std::string_view k) { return Table1Column{find_field(stat_fields(), k), false}; };
    auto time = [](std::string_view k) { return Table1Column{find_field(timing_fields(), k), true}; };
    return std::array<Table1Column, 14>{
        stat("cells"), stat("hex_ratio"), stat("components"), stat("hex_component_ratio"),
        stat("sheets"), stat("sheets_type1"), stat("sheets_type2"), stat("sheets_type3"),
        stat("subsheets_of_largest_self_intersecting"), time("singularity_graph"), time("base_complex"),
        time("vsg_wireframe"), time("sheets"), time("subsheets")};
  }();
  return columns;
}

std::span<const Field> wireframe_count_fields() { return fields_of(kWireCounts); }
int64_t wireframe_count(const VsgWireframe& w, size_t i) { return kWireCounts.at(i).get(w); }

// The keys' older words ("reference" for complete, "shown" for simplified), written beside the new
// keys for the scripts that read them.
constexpr FieldAlias kWireCountAliases[] = {
    {"reference_components", "wireframe_components"},
    {"shown_components", "wireframe_components_simplified"},
};

std::span<const FieldAlias> wireframe_count_aliases() { return kWireCountAliases; }

const Field* find_field(std::span<const Field> fields, std::string_view key) {
  for (const Field& f : fields)
    if (f.key == key) return &f;
  return nullptr;
}

const char* field_kind_name(FieldKind k) {
  switch (k) {
    case FieldKind::Count: return "count";
    case FieldKind::Ratio: return "ratio";
    case FieldKind::Seconds: return "seconds";
    case FieldKind::Value: return "value";
  }
  return "?";
}

}  // namespace hbc
