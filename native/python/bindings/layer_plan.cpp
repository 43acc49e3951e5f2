// The layer plans (hbc/layer_plan.hpp) for Python: the layers and their titles, every colour by its
// role, the legend entries and their words. The add-on's planning and its figures read these and
// hold no colour or legend word of their own; the web viewer reads the same through the wasm core.
#include <pybind11/stl.h>  // lists, optional arguments and results as None

#include "bindings.hpp"
#include "hbc/layer_plan.hpp"

namespace hbc::python {
namespace {

py::tuple rgba(const Rgba& c) { return py::make_tuple(c[0], c[1], c[2], c[3]); }

// (n, 4) float32 colours, f(i) the i-th.
template <class F>
py::array colors(size_t n, F f) {
  std::vector<float> out(4 * n);
  for (size_t i = 0; i < n; ++i) {
    const Rgba c = f(i);
    for (int k = 0; k < 4; ++k) out[4 * i + k] = static_cast<float>(c[k]);
  }
  return adopt(std::move(out), {ssize(n), 4});
}

using Ids = py::array_t<int64_t, py::array::c_style | py::array::forcecast>;

py::list entries(const std::vector<LegendEntry>& es) {
  py::list out;
  for (const auto& e : es) out.append(py::make_tuple(e.key, e.words));
  return out;
}

py::dict palette_dict(const LayerPalette& p) {
  py::dict d;
  d["cycle"] = colors(p.cycle.size(), [&](size_t i) { return p.cycle[i]; });
  d["cell_type"] = colors(p.cell_type.size(), [&](size_t i) { return p.cell_type[i]; });
  py::dict valence;
  for (const auto& [v, c] : p.valence) valence[py::int_(v)] = rgba(c);
  d["valence"] = valence;
  d["ring_darken"] = p.ring_darken;
  const std::pair<const char*, const Rgba*> named[] = {
      {"non_hex", &p.non_hex}, {"other_valence", &p.other_valence}, {"pseudo", &p.pseudo},
      {"non_manifold", &p.non_manifold}, {"unmatched", &p.unmatched}, {"shared", &p.shared},
      {"self_parallel", &p.self_parallel}, {"self_intersecting", &p.self_intersecting},
      {"wire_several", &p.wire_several}, {"wire_hex", &p.wire_hex}};
  for (const auto& [name, c] : named) d[name] = rgba(*c);
  return d;
}

// The facts as legend()'s keyword arguments; the analysis' facts only when there is one (a mesh
// alone does not know them).
py::dict facts_dict(const LegendFacts& f, bool analysed) {
  py::dict d;
  d["non_hex_types"] = py::cast(f.non_hex_types);
  if (!analysed) return d;
  d["valences"] = py::cast(f.valences);
  d["has_pseudo"] = f.has_pseudo;
  d["has_non_manifold"] = f.has_non_manifold;
  d["has_non_hex_components"] = f.has_non_hex_components;
  return d;
}

// The fields of a PartRequest by their C++ names.
py::dict request_dict(const PartRequest& r) {
  py::dict d;
  d["layer"] = r.layer;
  d["part"] = r.part;
  d["geometry"] = r.geometry;
  d["source"] = r.source;
  d["select"] = r.select;
  d["edge_class"] = r.edge_class;
  d["sheet"] = r.sheet;
  d["shrink"] = r.shrink;
  d["color"] = r.color;
  d["role"] = r.role;
  d["split"] = r.split;
  d["when"] = r.when;
  d["default_on"] = r.default_on;
  d["optional"] = r.optional;
  return d;
}

}  // namespace

void bind_layer_plan(py::module_& m) {
  py::list layers;
  for (const auto& l : layer_titles()) layers.append(py::make_tuple(l.key, l.title));
  m.attr("LAYERS") = py::tuple(layers);
  m.attr("PALETTE_SIZE") = kPaletteSize;
  m.attr("LEGEND_MAX_WORDS") = kLegendMaxWords;
  m.attr("WIRE_OPACITY_FLOOR") = kWireOpacityFloor;
  m.attr("SPREAD_GAP") = kSpreadGap;
  m.attr("SHEET_TYPE_SHORT") = py::tuple(py::cast(sheet_type_short()));
  m.attr("SHEET_HIGHLIGHTS") = py::tuple(entries(sheet_highlights()));
  py::list requests;
  for (const auto& r : layer_requests()) requests.append(request_dict(r));
  m.attr("LAYER_REQUESTS") = py::tuple(requests);

  m.def("layer_palette", [] { return palette_dict(layer_palette()); },
        "Every colour of the layers by its role (linear RGBA): cycle (24, 4) float32, the colours a "
        "owner each; cell_type (5, 4) float32 by CellType; valence {valence: rgba}; ring_darken; and "
        "non_hex, other_valence, pseudo, non_manifold, unmatched, shared, self_parallel, "
        "self_intersecting, wire_several, wire_hex as (r, g, b, a).");
  m.def("legend_colors", [] {
        py::dict d;
        for (const auto& [k, c] : legend_colors(layer_palette())) d[py::str(k)] = rgba(c);
        return d;
      },
      "{key: (r, g, b, a)}: every colour a legend entry names, in the legend's order.");
  m.def("spread_ids", [](const Ids& ids) {
        std::vector<int32_t> out(static_cast<size_t>(ids.size()));
        for (size_t i = 0; i < out.size(); ++i) out[i] = spread_id(ids.data()[i]);
        return adopt(std::move(out), {ssize(out.size())});
      }, py::arg("ids"), "int32 (n,): owner ids' palette entries, consecutive ids far apart.");
  m.def("spread_colors", [](const Ids& ids) {
        const LayerPalette p = layer_palette();
        return colors(static_cast<size_t>(ids.size()), [&](size_t i) { return p.cycle[spread_id(ids.data()[i])]; });
      }, py::arg("ids"),
      "(n, 4) float32: owner ids' palette entries, consecutive ids far apart (sheets: ids 0..n-1; "
      "subsheets: -1-k, never a sheet's colour).");
  m.def("palette_colors", [](const Ids& index) {
        const LayerPalette p = layer_palette();
        return colors(static_cast<size_t>(index.size()), [&](size_t i) { return palette_color(p, index.data()[i]); });
      }, py::arg("index"), "(n, 4) float32: palette entries by index; a negative index is the non-hex grey.");
  m.def("component_colors", [](const py::array_t<uint8_t, py::array::c_style | py::array::forcecast>& kinds) {
        const LayerPalette p = layer_palette();
        return colors(static_cast<size_t>(kinds.size()), [&](size_t i) {
          return component_color(p, static_cast<int64_t>(i), static_cast<ComponentKind>(kinds.data()[i]));
        });
      }, py::arg("kinds"), "(n, 4) float32: components by id and kind: palette, rings darker, non-hex grey.");
  m.def("legend_facts", [](const PyMesh& mesh, const PyAnalysis* analysis) {
        return facts_dict(legend_facts(mesh.mesh, analysis ? &analysis->analysis : nullptr), analysis != nullptr);
      }, py::arg("mesh"), py::arg("analysis") = py::none(),
      "What a legend names of this mesh: non_hex_types; with the analysis also valences, has_pseudo, "
      "has_non_manifold, has_non_hex_components (the keyword arguments of legend()).");
  m.def("legend", [](const std::vector<std::string>& layers, const std::vector<int>& non_hex_types,
                     const std::vector<int>& valences, bool has_pseudo, bool has_non_manifold,
                     bool has_non_hex_components, std::optional<std::vector<std::string>> highlights,
                     bool wire_by_kind) {
        const LegendFacts f{non_hex_types, valences, has_pseudo, has_non_manifold, has_non_hex_components};
        return entries(legend(layers, f, highlights, wire_by_kind));
      }, py::arg("layers"), py::kw_only(), py::arg("non_hex_types") = std::vector<int>{},
      py::arg("valences") = std::vector<int>{}, py::arg("has_pseudo") = false, py::arg("has_non_manifold") = false,
      py::arg("has_non_hex_components") = true, py::arg("highlights") = py::none(), py::arg("wire_by_kind") = false,
      "[(colour key, words)]: what each colour, dot and edge of the shown layers means. highlights: "
      "the sheet highlights drawn (keys of SHEET_HIGHLIGHTS), None for all.");
  m.def("palette_legend", [](const std::vector<std::string>& layers, bool wire_by_kind) {
        return entries(palette_legend(layers, wire_by_kind));
      }, py::arg("layers"), py::arg("wire_by_kind") = false,
      "[(colour key, words)]: what the palette colours of the shown layers mean.");
  m.def("wire_kind_legend", [](const std::vector<int>& types) { return entries(wire_kind_legend(types)); },
        py::arg("non_hex_types") = std::vector<int>{},
        "[(colour key, words)]: a wireframe coloured by non-hex kind: per type, then 2+ types, hexes only.");
  m.def("subsheets_unavailable", [](std::optional<int> t) { return subsheets_unavailable(t); },
        py::arg("sheet_type"),
        "Why the subsheets layer cannot be built for a picked sheet of this type (None: no sheet "
        "picked), or None when it can.");
}

}  // namespace hbc::python
