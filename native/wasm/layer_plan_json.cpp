// The layer plans (hbc/layer_plan.hpp) for the web viewer. layer_plan_json(): the layers, colours
// and words as one JSON text, which scripts/build_web.sh asks the core for (web/build.mjs, under
// node) and inlines in the page as web/src/colors.js' `L`, so the page draws with the colours and
// words the add-on draws with and the web build runs no Python. legends_json(): a mesh's legend
// for every set of shown layers, which the worker asks for once the mesh is analysed.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "hbc/json.hpp"
#include "hbc/layer_plan.hpp"

namespace {

using namespace hbc;

// Six decimals: the page's colours stay the values it was always given (the build's JSON rounded
// them so), and the text stays short.
double round6(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", x);
  return std::strtod(buf, nullptr);
}

Json color(const Rgba& c) {
  Json j = Json::array();
  for (double x : c) j.push_back(round6(x));
  return j;
}

Json entries(const std::vector<LegendEntry>& es) {
  Json j = Json::array();
  for (const auto& e : es) j.push_back(Json::array({e.key, e.words}));
  return j;
}

// The highest valence the page has a colour for: far beyond any real mesh.
constexpr int kMaxValence = 16;

Json colors_json(const LayerPalette& p) {
  Json j;
  Json types = Json::array(), cycle = Json::array(), spread = Json::array(), sub = Json::array(), valence;
  for (const auto& c : p.cell_type) types.push_back(color(c));
  for (const auto& c : p.cycle) cycle.push_back(color(c));
  for (int i = 0; i < kPaletteSize; ++i) {
    spread.push_back(spread_id(i));
    sub.push_back(spread_id(-1 - i));
  }
  for (int v = 0; v <= kMaxValence; ++v) valence[std::to_string(v)] = color(valence_color(p, v));
  j["cell_type_colors"] = types;
  j["palette"] = cycle;
  j["spread"] = spread;
  j["subsheet_spread"] = sub;
  j["ring_darken"] = p.ring_darken;
  j["non_hex_color"] = color(p.non_hex);
  j["valence_colors"] = valence;
  j["pseudo_color"] = color(p.pseudo);
  j["non_manifold_color"] = color(p.non_manifold);
  j["unmatched_color"] = color(p.unmatched);
  j["shared_color"] = color(p.shared);
  j["self_parallel_color"] = color(p.self_parallel);
  j["self_intersecting_color"] = color(p.self_intersecting);
  j["wire_several_color"] = color(p.wire_several);
  j["wire_hex_color"] = color(p.wire_hex);
  Json legend_swatches;
  for (const auto& [k, c] : legend_colors(p)) legend_swatches[k] = color(c);
  j["legend_colors"] = legend_swatches;
  return j;
}

std::string layer_plan_json() {
  const LayerPalette p = layer_palette();
  Json j = colors_json(p);
  j["colors_are"] = "linear RGBA (the page converts to sRGB for CSS swatches)";
  Json layers = Json::array(), names = Json::array(), unavailable;
  for (const auto& l : layer_titles()) layers.push_back(Json::array({l.key, l.title}));
  for (int t = 0; t < 5; ++t) names.push_back(cell_type_name(static_cast<CellType>(t)));
  for (int t = 0; t < 4; ++t) {
    const auto why = subsheets_unavailable(t);
    unavailable[std::to_string(t)] = why ? Json(*why) : Json(nullptr);
  }
  j["layers"] = layers;
  j["cell_type_names"] = names;
  j["sheet_type_short"] = sheet_type_short();
  j["wire_floor"] = kWireOpacityFloor;
  j["spread_gap"] = kSpreadGap;
  j["subsheets_unavailable"] = unavailable;
  return json_text(j);
}

// Every layer's parts (hbc::layer_requests) as a JSON array of objects with PartRequest's field
// names, which web/build.mjs inlines beside the layer plan for the worker to draw from.
std::string layer_requests_json() {
  Json j = Json::array();
  for (const auto& r : layer_requests())
    j.push_back({{"layer", r.layer}, {"part", r.part}, {"geometry", r.geometry}, {"source", r.source},
                 {"select", r.select}, {"edge_class", r.edge_class}, {"sheet", r.sheet}, {"shrink", r.shrink},
                 {"color", r.color}, {"role", r.role}, {"split", r.split}, {"when", r.when},
                 {"default_on", r.default_on}, {"optional", r.optional}});
  return json_text(j);
}

template <class T>
std::vector<T> as(const emscripten::val& a) {
  const auto bytes = emscripten::convertJSArrayToNumberVector<uint8_t>(a);
  std::vector<T> out(bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) out[i] = static_cast<T>(bytes[i]);
  return out;
}

// A mesh's facts and its legend for every set of shown layers, so that the page shows what the
// library's legend() lists without composing it: "legends" keyed by the shown layers' keys in
// building order joined by "," then "|1" (wireframes coloured by non-hex kind) or "|0", each
// legend() then palette_legend(). The arrays: Mesh.cell_types, the graph's edge_class and
// chain_valence, the complex's component_kind, as the worker holds them.
std::string legends_json(const emscripten::val& cell_type, const emscripten::val& edge_class,
                         const emscripten::val& chain_valence, const emscripten::val& component_kind) {
  const auto types = as<CellType>(cell_type);
  const auto classes = as<EdgeClass>(edge_class);
  const auto valences = emscripten::convertJSArrayToNumberVector<int32_t>(chain_valence);
  const auto kinds = as<ComponentKind>(component_kind);
  const LegendFacts f = legend_facts(types, classes, valences, kinds);
  const auto layers = layer_titles();
  Json legends;
  for (unsigned set = 1; set < (1u << layers.size()); ++set) {
    std::vector<std::string> shown;
    for (size_t i = 0; i < layers.size(); ++i)
      if (set >> i & 1) shown.push_back(layers[i].key);
    std::string key;
    for (const auto& l : shown) key += (key.empty() ? "" : ",") + l;
    for (bool by_kind : {false, true}) {
      auto es = legend(shown, f, std::nullopt, by_kind);
      for (auto& e : palette_legend(shown, by_kind)) es.push_back(std::move(e));
      legends[key + (by_kind ? "|1" : "|0")] = entries(es);
    }
  }
  Json j;
  j["facts"] = {{"non_hex_types", f.non_hex_types}, {"valences", f.valences}, {"has_pseudo", f.has_pseudo},
                {"has_non_manifold", f.has_non_manifold}, {"has_non_hex_blocks", f.has_non_hex_components}};
  j["legends"] = legends;
  return j.dump();
}

}  // namespace

EMSCRIPTEN_BINDINGS(hbc_layer_plan) {
  emscripten::function("layer_plan_json", &layer_plan_json);
  emscripten::function("legends_json", &legends_json);
  emscripten::function("layer_requests_json", &layer_requests_json);
}
