// The layer plans (hbc/layer_plan.hpp) for the web viewer, as one JSON text: layer_plan_json().
// scripts/build_web.sh asks the core for it (web/build.mjs, under node) and inlines it in the page
// as web/src/colors.js' `L`, so the page draws with the colours and words the add-on draws with and
// the web build runs no Python. The legend is given per fact (one valence, one cell type ...),
// each in the order legend() lists it, so that the page composes a mesh's legend from its facts.
#include <emscripten/bind.h>

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

// The highest valence the page names: far beyond any real mesh.
constexpr int kMaxValence = 16;

Json legend_per_fact() {
  const std::optional<std::vector<std::string>> all;
  auto one = [&](std::vector<std::string> layers, const LegendFacts& f) {
    return legend(layers, f, all, false);
  };
  Json g;
  g["direct"] = entries(one({"direct"}, {}));
  Json types, valences, kinds;
  for (int t = 1; t < 5; ++t) {
    auto es = one({"direct"}, {{t}, {}, false, false, true});
    es.erase(es.begin());  // the hex boundary's entry, given by "direct"
    types[std::to_string(t)] = entries(es);
    kinds[std::to_string(t)] = entries({wire_kind_legend({t}).front()});
  }
  for (int v = 0; v <= kMaxValence; ++v) valences[std::to_string(v)] = entries(one({"graph"}, {{}, {v}, false, false, true}));
  g["cell_type"] = types;
  g["valence"] = valences;
  g["pseudo"] = entries(one({"graph"}, {{}, {}, true, false, true}));
  g["non_manifold"] = entries(one({"graph"}, {{}, {}, false, true, true}));
  g["blocks"] = entries(one({"blocks"}, {}));
  g["highlights"] = entries(one({"sheet"}, {}));
  g["wire_kind_type"] = kinds;
  g["wire_kind_rest"] = entries(wire_kind_legend({}));
  Json palette;
  for (const auto& l : layer_titles()) palette[l.key] = entries(palette_legend({l.key}, false));
  g["palette"] = palette;
  return g;
}

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
  j["legend"] = legend_per_fact();
  j["subsheets_unavailable"] = unavailable;
  return json_text(j);
}

}  // namespace

EMSCRIPTEN_BINDINGS(hbc_layer_plan) { emscripten::function("layer_plan_json", &layer_plan_json); }
