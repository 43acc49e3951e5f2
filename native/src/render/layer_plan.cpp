#include "hbc/layer_plan.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "hbc/sheets.hpp"

namespace hbc {
namespace {

// The add-on drew these as float32 arrays: the same values here.
// Through memory: GCC 12 at -O3 dropped a plain double -> float -> double round trip here (the
// palette came out unrounded).
double f32(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}
Rgba as_float32(const Rgba& c) { return {f32(c[0]), f32(c[1]), f32(c[2]), f32(c[3])}; }

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// HSV to RGB as Python's colorsys computes it, step by step, so that the palette's values are the
// ones the add-on always drew.
std::array<double, 3> hsv_to_rgb(double h, double s, double v) {
  const int i = static_cast<int>(h * 6.0);
  const double f = h * 6.0 - i;
  const double p = v * (1.0 - s), q = v * (1.0 - s * f), t = v * (1.0 - s * (1.0 - f));
  switch (i % 6) {
    case 0: return {v, t, p};
    case 1: return {q, v, p};
    case 2: return {p, v, t};
    case 3: return {p, q, v};
    case 4: return {t, p, v};
    default: return {v, p, q};
  }
}

// n saturated colours: hue by the golden ratio (neighbouring entries far apart), two saturations
// and two values alternating so that close hues still differ.
std::vector<Rgba> hsv_cycle(int n) {
  std::vector<Rgba> out(n);
  for (int i = 0; i < n; ++i) {
    const double h = std::fmod(i * 0.618033988749895, 1.0);
    const double s = i % 2 == 0 ? 0.85 : 0.6;
    const double v = (i / 2) % 2 == 0 ? 0.95 : 0.7;
    const auto rgb = hsv_to_rgb(h, s, v);
    out[i] = as_float32({srgb_to_linear(rgb[0]), srgb_to_linear(rgb[1]), srgb_to_linear(rgb[2]), 1.0});
  }
  return out;
}

bool shown(const std::vector<std::string>& layers, std::string_view layer) {
  return std::find(layers.begin(), layers.end(), layer) != layers.end();
}

std::string capitalized(std::string s) {
  if (!s.empty()) s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

}  // namespace

std::vector<LayerTitle> layer_titles() {
  return {{"direct", "Direct view"}, {"graph", "Singularity graph"}, {"components", "Components"}, {"sheets", "Sheets"},
          {"sheet", "Picked sheet"}, {"subsheets", "Subsheets"}, {"wireframe", "Wireframe"}};
}

namespace {

PartRequest soup(std::string layer, std::string part, std::string kind, std::string color, std::string role = "") {
  PartRequest r;
  r.layer = std::move(layer);
  r.part = std::move(part);
  r.geometry = "soup";
  r.source = std::move(kind);
  r.color = std::move(color);
  r.role = std::move(role);
  return r;
}

PartRequest with(PartRequest r, std::string geometry, std::string source) {
  r.geometry = std::move(geometry);
  r.source = std::move(source);
  return r;
}

}  // namespace

std::vector<PartRequest> layer_requests() {
  std::vector<PartRequest> out;
  auto add = [&out](PartRequest r, auto&&... set) {
    (set(r), ...);
    out.push_back(std::move(r));
  };
  auto shrunk = [](PartRequest& r) { r.shrink = true; };
  auto picked = [](PartRequest& r) { r.sheet = true; };
  auto per_owner = [](PartRequest& r) { r.split = "owner"; };
  auto optional = [](PartRequest& r) { r.optional = true; };
  auto setting = [](bool on) { return [on](PartRequest& r) {
      r.when = "setting";
      r.default_on = on;
    }; };
  // The direct view: the boundary in the hex grey (its owners are cell types, not cells), each
  // non-hex cell by its type, the hex region's surface on request.
  add(soup("direct", "boundary", "boundary", "role", "hex"), setting(true));
  add(soup("direct", "non_hex", "non_hex", "cell_type"), shrunk, [](PartRequest& r) { r.when = "non_hex_cells"; });
  add(soup("direct", "hex", "hex", "role", "hex"), setting(false));
  // The hybrid singularity graph: singularities by valence, then pseudo-singular and non-manifold edges.
  add(with(soup("graph", "singularities", "", "valence"), "lines", "chains"));
  add(with(soup("graph", "pseudo", "", "role", "pseudo"), "lines", "edges"), optional,
      [](PartRequest& r) { r.edge_class = static_cast<int>(EdgeClass::PseudoSingular); });
  add(with(soup("graph", "non_manifold", "", "role", "non_manifold"), "lines", "edges"), optional,
      [](PartRequest& r) { r.edge_class = static_cast<int>(EdgeClass::NonManifold); });
  add(soup("components", "components", "components", "component"), shrunk);
  add(soup("sheets", "sheets", "sheets", "spread"), shrunk);
  // The picked sheet by component, then its highlights (sheet_highlights' keys).
  add(soup("sheet", "sheet", "sheet", "sheet_shaded"), picked, shrunk);
  add(with(soup("sheet", "unmatched", "", "role", "unmatched"), "dots", "sheet_unmatched_vertices"), picked, optional);
  add(with(soup("sheet", "shared", "", "role", "shared"), "dots", "sheet_shared_vertices"), picked, optional);
  add(with(soup("sheet", "self_parallel", "", "role", "self_parallel"), "lines", "curves"), picked, optional,
      [](PartRequest& r) { r.select = "sheet_self_parallel_curves"; });
  add(soup("sheet", "self_intersecting", "components", "role", "self_intersecting"), picked, optional,
      [](PartRequest& r) { r.select = "sheet_self_intersecting_components"; });
  // The picked sheet's subsheets, each with its unmatched vertices and its wireframe.
  add(soup("subsheets", "subsheets", "subsheets", "subsheet"), picked, shrunk, per_owner);
  add(with(soup("subsheets", "unmatched", "", "role", "unmatched"), "dots", "subsheet_unmatched_vertices"), picked,
      per_owner, optional);
  add(with(soup("subsheets", "wireframe", "", "wire"), "lines", "wireframe"), picked, per_owner);
  // The wireframe of the mesh or (the front end's scope setting) of the picked sheet.
  add(with(soup("wireframe", "wireframe", "", "wire"), "lines", "wireframe"));
  return out;
}

LayerPalette layer_palette() {
  LayerPalette p;
  p.cycle = hsv_cycle(kPaletteSize);
  p.non_hex = {0.35, 0.35, 0.38, 1.0};
  p.ring_darken = 0.6;
  p.cell_type = {as_float32({0.80, 0.80, 0.80, 1.0}), as_float32({0.90, 0.25, 0.20, 1.0}),
                 as_float32({0.20, 0.55, 0.90, 1.0}), as_float32({0.95, 0.70, 0.15, 1.0}),
                 as_float32({0.60, 0.30, 0.80, 1.0})};
  // Valence 3 and 5 (the usual ones) in blue and red as the paper's figures; 2 as 3 (both fewer
  // cells than 4 around the edge).
  p.valence = {{1, {0.0, 0.8, 0.8, 1.0}}, {2, {0.1, 0.3, 1.0, 1.0}}, {3, {0.1, 0.3, 1.0, 1.0}},
               {5, {1.0, 0.15, 0.1, 1.0}}, {6, {1.0, 0.0, 0.9, 1.0}}};
  p.other_valence = {1.0, 0.85, 0.0, 1.0};
  p.pseudo = {0.1, 0.8, 0.2, 1.0};
  p.non_manifold = {1.0, 0.5, 0.0, 1.0};
  p.unmatched = {1.0, 0.0, 0.0, 1.0};
  p.shared = {1.0, 0.85, 0.0, 1.0};
  p.self_parallel = {1.0, 0.55, 0.0, 1.0};
  p.self_intersecting = {0.85, 0.1, 0.85, 1.0};
  p.wire_several = {0.05, 0.05, 0.05, 1.0};
  p.wire_hex = {0.62, 0.62, 0.62, 1.0};
  return p;
}

int32_t spread_id(int64_t id) {
  const int64_t r = (id * 7) % kPaletteSize;
  return static_cast<int32_t>(r < 0 ? r + kPaletteSize : r);
}

Rgba palette_color(const LayerPalette& p, int64_t index) {
  if (index < 0) return p.non_hex;
  return p.cycle[static_cast<size_t>(index % kPaletteSize)];
}

Rgba valence_color(const LayerPalette& p, int valence) {
  for (const auto& [v, c] : p.valence)
    if (v == valence) return c;
  return p.other_valence;
}

Rgba component_color(const LayerPalette& p, int64_t id, ComponentKind kind) {
  if (kind == ComponentKind::NonHex) return p.non_hex;
  Rgba c = p.cycle[spread_id(id)];
  if (kind == ComponentKind::Ring)
    // In float32, as the add-on darkened its float32 colours.
    for (int i = 0; i < 3; ++i) c[i] = f32(static_cast<float>(c[i]) * static_cast<float>(p.ring_darken));
  return c;
}

Rgba subsheet_color(const LayerPalette& p, int64_t k) { return p.cycle[spread_id(-1 - k)]; }

std::vector<std::pair<std::string, Rgba>> legend_colors(const LayerPalette& p) {
  std::vector<std::pair<std::string, Rgba>> out;
  out.emplace_back("hex", Rgba{0.80, 0.80, 0.80, 1.0});  // the add-on's legend kept the unrounded grey
  for (int t = 1; t < 5; ++t) out.emplace_back(cell_type_name(static_cast<CellType>(t)), p.cell_type[t]);
  for (const auto& [v, c] : p.valence) out.emplace_back("valence" + std::to_string(v), c);
  out.emplace_back("valence_other", p.other_valence);
  out.emplace_back("pseudo", p.pseudo);
  out.emplace_back("non_manifold", p.non_manifold);
  out.emplace_back("non_hex_component", p.non_hex);
  out.emplace_back("unmatched", p.unmatched);
  out.emplace_back("shared", p.shared);
  out.emplace_back("self_parallel", p.self_parallel);
  out.emplace_back("self_intersecting", p.self_intersecting);
  out.emplace_back("wire_several", p.wire_several);
  out.emplace_back("wire_hex", p.wire_hex);
  // The palette's layers: a swatch for "a colour of its own each", a faint one for distance, and
  // the picked sheet's (sheet 0's; the add-on's panel shows the picked sheet's own).
  Rgba faint = p.cycle[0];
  faint[3] = 0.3;
  out.emplace_back("palette", p.cycle[0]);
  out.emplace_back("faint", faint);
  out.emplace_back("picked_sheet", p.cycle[spread_id(0)]);
  return out;
}

namespace {

std::vector<int> non_hex_types(std::span<const CellType> cell_type) {
  std::array<bool, 5> seen{};
  for (CellType t : cell_type) seen[static_cast<size_t>(t)] = true;
  std::vector<int> out;
  for (int t = 1; t < 5; ++t)
    if (seen[t]) out.push_back(t);
  return out;
}

}  // namespace

LegendFacts legend_facts(std::span<const CellType> cell_type, std::span<const EdgeClass> edge_class,
                         std::span<const int32_t> chain_valence, std::span<const ComponentKind> component_kind) {
  LegendFacts f;
  f.non_hex_types = non_hex_types(cell_type);
  f.valences.assign(chain_valence.begin(), chain_valence.end());
  std::sort(f.valences.begin(), f.valences.end());
  f.valences.erase(std::unique(f.valences.begin(), f.valences.end()), f.valences.end());
  f.has_pseudo = std::find(edge_class.begin(), edge_class.end(), EdgeClass::PseudoSingular) != edge_class.end();
  f.has_non_manifold = std::find(edge_class.begin(), edge_class.end(), EdgeClass::NonManifold) != edge_class.end();
  f.has_non_hex_components =
      std::find(component_kind.begin(), component_kind.end(), ComponentKind::NonHex) != component_kind.end();
  return f;
}

LegendFacts legend_facts(const Mesh& mesh, const Analysis* analysis) {
  if (!analysis) {
    LegendFacts f;
    f.non_hex_types = non_hex_types(mesh.cell_type);
    return f;
  }
  return legend_facts(mesh.cell_type, analysis->graph.edge_class, analysis->graph.chain_valence,
                      analysis->complex.component_kind);
}

std::vector<LegendEntry> sheet_highlights() {
  return {{"unmatched", "Dot: unmatched"}, {"shared", "Dot: shared vertex"},
          {"self_parallel", "Self-parallel edge"}, {"self_intersecting", "Self-intersecting"}};
}

std::vector<LegendEntry> wire_kind_legend(const std::vector<int>& non_hex_types) {
  std::vector<LegendEntry> out;
  for (int t : non_hex_types) {
    const std::string name = cell_type_name(static_cast<CellType>(t));
    out.push_back({name, "Wire at " + name});
  }
  out.push_back({"wire_several", "Wire at 2+ types"});
  out.push_back({"wire_hex", "Wire at hexes only"});
  return out;
}

std::vector<LegendEntry> legend(const std::vector<std::string>& layers, const LegendFacts& facts,
                                const std::optional<std::vector<std::string>>& highlights, bool wire_by_kind) {
  const LayerPalette p = layer_palette();
  std::vector<LegendEntry> out;
  if (shown(layers, "direct")) {
    out.push_back({"hex", "Boundary, hex cells"});
    for (int t : facts.non_hex_types) {
      const std::string name = cell_type_name(static_cast<CellType>(t));
      out.push_back({name, capitalized(name) + " cells"});
    }
  }
  if (shown(layers, "graph")) {
    for (int v : facts.valences) {
      const bool own = std::any_of(p.valence.begin(), p.valence.end(), [v](const auto& e) { return e.first == v; });
      out.push_back({own ? "valence" + std::to_string(v) : "valence_other", "Valence " + std::to_string(v) + " edge"});
    }
    if (facts.has_pseudo) out.push_back({"pseudo", "Pseudo-singular"});
    if (facts.has_non_manifold) out.push_back({"non_manifold", "Non-manifold edge"});
  }
  if (shown(layers, "components") && facts.has_non_hex_components) out.push_back({"non_hex_component", "Non-hex component"});
  if (shown(layers, "sheet") || shown(layers, "subsheets"))
    for (auto& e : sheet_highlights())
      if (!highlights || shown(*highlights, e.key)) out.push_back(std::move(e));
  if (wire_by_kind && (shown(layers, "wireframe") || shown(layers, "subsheets")))
    for (auto& e : wire_kind_legend(facts.non_hex_types)) out.push_back(std::move(e));
  return out;
}

std::vector<LegendEntry> palette_legend(const std::vector<std::string>& layers, bool wire_by_kind) {
  std::vector<LegendEntry> out;
  auto add = [&out](LegendEntry e) {
    if (std::find(out.begin(), out.end(), e) == out.end()) out.push_back(std::move(e));
  };
  for (const auto& layer : layers) {
    if (layer == "components") add({"palette", "Hex-cell component"});
    if (layer == "sheets") add({"palette", "A colour a sheet"});
    if (layer == "sheet") add({"picked_sheet", "Picked sheet"});
    if (layer == "subsheets") add({"palette", "A colour a subsheet"});
    if (layer == "wireframe" && !wire_by_kind) {
      add({"palette", "Wire: chain class"});
      add({"faint", "Faint: far away"});
    }
  }
  return out;
}

std::vector<std::string> sheet_type_short() { return {"perfect", "type 1", "type 2", "type 3"}; }

std::optional<std::string> subsheets_unavailable(std::optional<int> sheet_type) {
  if (!sheet_type) return "Pick a sheet in the list first";
  if (*sheet_type != static_cast<int>(SheetType::Type3))
    return std::string("Sheet is ") + sheet_type_label(static_cast<SheetType>(*sheet_type)) +
           ": only self-intersecting (type 3) sheets have subsheets";
  return std::nullopt;
}

}  // namespace hbc
