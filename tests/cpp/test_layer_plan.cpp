// The layer plan (layer_plan.hpp): the palette's spreading rule, legends composed from the facts of
// generated meshes whose structure follows from construction, and the words' width. That the
// colours and words are the ones the add-on and the page drew before the plan moved here is
// tests/addon/unit/test_layer_plan_unchanged.py's and tests/wasm/layer_plan_test.mjs' part.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "hbc/layer_plan.hpp"
#include "hbc/mesh.hpp"
#include "hbc/render_geometry.hpp"

namespace hbc {
namespace {

std::vector<std::string> keys(const std::vector<LegendEntry>& es) {
  std::vector<std::string> out;
  for (const auto& e : es) out.push_back(e.key);
  return out;
}

TEST(LayerPlan, SpreadVisitsEveryEntryAndNeverGivesSubsheetKSheetKsColour) {
  // id -> 7·id mod 24: 7 is prime to 24, so one period visits all 24 entries. Subsheet k takes
  // -7(k+1) mod 24; sheet k + subsheet k = 14k + 7 is odd, never a multiple of 24.
  std::set<int32_t> seen;
  for (int64_t id = 0; id < kPaletteSize; ++id) seen.insert(spread_id(id));
  EXPECT_EQ(seen.size(), static_cast<size_t>(kPaletteSize));
  EXPECT_EQ(spread_id(1), 7);
  EXPECT_EQ(spread_id(-1), 17);  // -7 mod 24, never negative
  const LayerPalette p = layer_palette();
  for (int64_t k = 0; k < 3 * kPaletteSize; ++k) EXPECT_NE(subsheet_color(p, k), p.cycle[spread_id(k)]) << k;
}

TEST(LayerPlan, ComponentColoursRingsDarkerNonHexGrey) {
  const LayerPalette p = layer_palette();
  EXPECT_EQ(component_color(p, 5, ComponentKind::Cube), p.cycle[spread_id(5)]);
  EXPECT_EQ(component_color(p, 5, ComponentKind::NonHex), p.non_hex);
  const Rgba ring = component_color(p, 5, ComponentKind::Ring);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(ring[i], p.cycle[spread_id(5)][i] * p.ring_darken, 1e-6);
  EXPECT_EQ(ring[3], 1.0);
  EXPECT_EQ(palette_color(p, -1), p.non_hex);
  EXPECT_EQ(palette_color(p, kPaletteSize + 2), p.cycle[2]);
}

TEST(LayerPlan, SectorOfValenceFiveNamesItsValenceAndNoNonHexComponent) {
  // One valence-5 chain along the axis, hex cells only; the edges of the outline (one hex round
  // each: boundary valence 1, as on a grid box's outline) are singular too. The graph's legend names valences 1 and 5, the direct view
  // the hex boundary alone, and no component is non-hex.
  const Mesh mesh = build_mesh(generate_sector(5, 2, 2));
  const Analysis a = analyze(mesh);
  const LegendFacts f = legend_facts(mesh, &a);
  EXPECT_EQ(f.non_hex_types, std::vector<int>{});
  EXPECT_EQ(f.valences, (std::vector<int>{1, 5}));
  EXPECT_FALSE(f.has_pseudo);
  EXPECT_FALSE(f.has_non_manifold);
  EXPECT_FALSE(f.has_non_hex_components);
  const auto entries = legend({"direct", "graph", "components"}, f, std::nullopt, false);
  EXPECT_EQ(entries, (std::vector<LegendEntry>{
                         {"hex", "Boundary, hex cells"}, {"valence1", "Valence 1 edge"}, {"valence5", "Valence 5 edge"}}));
}

TEST(LayerPlan, PyramidsNameTheirTypeThePseudoSingularEdgesAndTheNonHexComponents) {
  // A 3×1×1 row whose middle hex is split into 6 pyramids: pyramids present (type 3); the edges
  // between pyramids have non-hex cells around them, so pseudo-singular; each pyramid is a non-hex
  // component of its own.
  const std::array<int32_t, 3> middle{1, 0, 0};
  const Mesh mesh = build_mesh(generate_split(3, 1, 1, SplitKind::Pyramids, std::span(&middle, 1)));
  const Analysis a = analyze(mesh);
  const LegendFacts f = legend_facts(mesh, &a);
  EXPECT_EQ(f.non_hex_types, std::vector<int>{3});
  EXPECT_TRUE(f.has_pseudo);
  EXPECT_TRUE(f.has_non_hex_components);
  EXPECT_EQ(keys(legend({"direct", "components"}, f, std::nullopt, false)),
            (std::vector<std::string>{"hex", "pyramid", "non_hex_component"}));
  EXPECT_EQ(legend({"direct"}, f, std::nullopt, false)[1].words, "Pyramid cells");
  // Coloured by non-hex kind, the wireframe names the pyramids, then several types and hexes only.
  EXPECT_EQ(keys(legend({"wireframe"}, f, std::nullopt, true)),
            (std::vector<std::string>{"pyramid", "wire_several", "wire_hex"}));
  EXPECT_TRUE(legend({"wireframe"}, f, std::nullopt, false).empty());
  // The mesh alone knows its cell types, not the analysis' facts (unknown components count as present).
  const LegendFacts alone = legend_facts(mesh, nullptr);
  EXPECT_EQ(alone.non_hex_types, std::vector<int>{3});
  EXPECT_TRUE(alone.valences.empty());
  EXPECT_TRUE(alone.has_non_hex_components);
}

TEST(LayerPlan, HighlightsAreTheDrawnOnesInLegendOrder) {
  const std::vector<std::string> drawn{"self_intersecting", "unmatched"};
  EXPECT_EQ(keys(legend({"sheet"}, {}, drawn, false)), (std::vector<std::string>{"unmatched", "self_intersecting"}));
  EXPECT_EQ(legend({"subsheets"}, {}, std::nullopt, false), sheet_highlights());
  EXPECT_TRUE(legend({"sheets"}, {}, std::nullopt, false).empty());
}

TEST(LayerPlan, PaletteLegendOncePerEntryAndNoClassColoursWhenByKind) {
  // One swatch, the palette's, with the words of each layer; the wireframe's faint one beside.
  EXPECT_EQ(keys(palette_legend({"components", "sheets", "wireframe"}, false)),
            (std::vector<std::string>{"palette", "palette", "palette", "faint"}));
  EXPECT_EQ(palette_legend({"wireframe"}, true), std::vector<LegendEntry>{});
  EXPECT_EQ(palette_legend({"sheet", "sheet"}, false), (std::vector<LegendEntry>{{"picked_sheet", "Picked sheet"}}));
}

TEST(LayerPlan, EveryEntryFitsBesideASwatchAndHasAColour) {
  // Every layer and every fact at once: the longest legend there is.
  std::vector<std::string> layers;
  for (const auto& l : layer_titles()) layers.push_back(l.key);
  const LegendFacts all{{1, 2, 3, 4}, {1, 2, 3, 4, 5, 6, 7}, true, true, true};
  auto entries = legend(layers, all, std::nullopt, true);
  for (const auto& e : palette_legend(layers, false)) entries.push_back(e);
  std::set<std::string> colored;
  for (const auto& [k, c] : legend_colors(layer_palette())) colored.insert(k);
  for (const auto& e : entries) {
    EXPECT_LE(e.words.size(), static_cast<size_t>(kLegendMaxWords)) << e.words;
    EXPECT_TRUE(colored.count(e.key)) << e.key;
  }
}

TEST(LayerPlan, SubsheetsOnlyOfTypeThreeSheets) {
  EXPECT_EQ(subsheets_unavailable(std::nullopt), "Pick a sheet in the list first");
  EXPECT_EQ(subsheets_unavailable(1), "Sheet is type 1 (non-hex): only self-intersecting (type 3) sheets have subsheets");
  EXPECT_EQ(subsheets_unavailable(3), std::nullopt);
}

TEST(LayerPlan, EveryRequestNamesALayerAKindAndAColourTheLibraryHas) {
  // The front ends dispatch on these words: a word the library does not define would reach a
  // front end as a layer it cannot draw.
  const auto titles = layer_titles();
  const auto colors = legend_colors(layer_palette());
  const std::set<std::string> geometries{"soup", "lines", "dots"};
  const std::set<std::string> line_sources{"chains", "edges", "curves", "wireframe"};
  const std::set<std::string> rules{"role", "cell_type", "valence", "component", "spread", "sheet_shaded", "subsheet",
                                    "wire"};
  size_t layer = 0;
  std::set<std::string> drawn;
  std::set<std::pair<std::string, std::string>> parts;
  std::vector<std::string> highlights;
  for (const auto& r : layer_requests()) {
    while (layer < titles.size() && titles[layer].key != r.layer) ++layer;
    ASSERT_LT(layer, titles.size()) << r.layer << " is no layer, or out of layer_titles' order";
    drawn.insert(r.layer);
    EXPECT_TRUE(parts.insert({r.layer, r.part}).second) << r.layer << "/" << r.part;
    EXPECT_TRUE(geometries.count(r.geometry)) << r.part;
    if (r.geometry == "soup") EXPECT_NO_THROW(soup_kind_from_name(r.source)) << r.part;
    if (r.geometry == "lines") EXPECT_TRUE(line_sources.count(r.source)) << r.part;
    EXPECT_EQ(r.edge_class >= 0, r.source == "edges") << r.part;
    EXPECT_TRUE(rules.count(r.color)) << r.part;
    EXPECT_EQ(r.color == "role", std::any_of(colors.begin(), colors.end(), [&](const auto& c) { return c.first == r.role; }))
        << r.part << " " << r.role;
    if (r.layer == "sheet" && r.part != "sheet") highlights.push_back(r.part);
  }
  EXPECT_EQ(drawn.size(), titles.size()) << "a layer without parts";
  EXPECT_EQ(highlights, keys(sheet_highlights()));
}

TEST(LayerPlan, EverySoupRequestIsOneTheCoreMakes) {
  // The twisted pair has a self-intersecting sheet: every soup request, with its sheet where it
  // takes one, gives faces.
  const Mesh mesh = build_mesh(generate_twisted_pair(2, 8));
  const Analysis a = analyze(mesh);
  ASSERT_TRUE(a.sheet_stage && a.sheet_stage->largest_self_intersecting);
  const int32_t picked = *a.sheet_stage->largest_self_intersecting;
  for (const auto& r : layer_requests()) {
    if (r.geometry != "soup" || !r.select.empty() || r.source == "non_hex") continue;
    const SoupKind kind = soup_kind_from_name(r.source);
    EXPECT_EQ(r.sheet, soup_kind_needs_sheet(kind)) << r.part;
    EXPECT_GT(block_soup(mesh, a, kind, r.sheet ? std::optional<int32_t>(picked) : std::nullopt).num_faces(), 0u)
        << r.layer << "/" << r.part;
  }
}

}  // namespace
}  // namespace hbc
