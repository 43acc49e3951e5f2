#pragma once
// The layer plans every front end draws from (the Blender add-on, its figures, the web viewer): the
// layers and their titles, every colour by its role, the legend entries an analysis shows with
// their words, and the short words of the sheet list. Pure functions of the analysis' facts; the
// front ends hold no colour or legend word of their own (docs/architecture.md).
//
// Colours are linear RGBA (the scene-linear values Blender holds; the web page converts to sRGB
// for CSS). They are doubles holding what the add-on always drew: a colour the add-on kept as a
// float32 array (the palette, the cell types) is rounded to float32 here too.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

using Rgba = std::array<double, 4>;

// A layer the front ends build, in building order: its key and its title (the add-on's collection
// `<mesh> / <title>`, the web page's layer row).
struct LayerTitle {
  std::string key, title;
  bool operator==(const LayerTitle&) const = default;
};
std::vector<LayerTitle> layer_titles();

// Every colour by its role.
struct LayerPalette {
  // One colour per owner (component, sheet, subsheet, wireframe class): well-separated hues.
  std::vector<Rgba> cycle;               // kPaletteSize
  Rgba non_hex{};                        // non-hex components; a negative palette index
  double ring_darken = 0;                // ring-like hex components: their colour times this
  std::array<Rgba, 5> cell_type{};       // by CellType; [0] is the hex boundary's grey
  std::vector<std::pair<int, Rgba>> valence;  // singularities of these valences, ascending
  Rgba other_valence{};                  // any other valence
  Rgba pseudo{}, non_manifold{};         // the graph's pseudo-singular and non-manifold edges
  Rgba unmatched{}, shared{}, self_parallel{}, self_intersecting{};  // a picked sheet's highlights
  Rgba wire_several{}, wire_hex{};       // a chain at non-hex cells of several types; at hexes only
  bool operator==(const LayerPalette&) const = default;
};
inline constexpr int kPaletteSize = 24;
LayerPalette layer_palette();

// Owner `id`'s palette entry: consecutive ids (often neighbours) far apart in the cycle. Periodic
// in kPaletteSize; a negative id takes the entry of the same residue.
int32_t spread_id(int64_t id);
// A palette entry by index; a negative index is the non-hex grey.
Rgba palette_color(const LayerPalette& p, int64_t index);
Rgba valence_color(const LayerPalette& p, int valence);
// Component `id` of `kind`: its spread entry, rings darker, non-hex grey.
Rgba component_color(const LayerPalette& p, int64_t id, ComponentKind kind);
// Subsheet k: the sheets' order walked from its other end (the entry sheet -1-k takes), so that
// subsheet k is never drawn in sheet k's colour (7k and -7(k+1) differ by an odd number mod 24).
Rgba subsheet_color(const LayerPalette& p, int64_t k);

// Every colour a legend entry can name, by key, in the legend panel's order.
std::vector<std::pair<std::string, Rgba>> legend_colors(const LayerPalette& p);

// What a mesh and its analysis show that a legend names.
struct LegendFacts {
  std::vector<int> non_hex_types;  // CellType values present other than hex, ascending
  std::vector<int> valences;       // singularity valences, ascending (analysed only)
  bool has_pseudo = false, has_non_manifold = false;
  bool has_non_hex_components = true;  // unknown (not analysed) counts as present
  bool operator==(const LegendFacts&) const = default;
};
// `analysis` null: the mesh's facts alone.
LegendFacts legend_facts(const Mesh& mesh, const Analysis* analysis);
// The same from the arrays themselves (Mesh::cell_type, SingularityGraph::edge_class and
// chain_valence, BaseComplex::component_kind), for a front end holding copies of them.
LegendFacts legend_facts(std::span<const CellType> cell_type, std::span<const EdgeClass> edge_class,
                         std::span<const int32_t> chain_valence, std::span<const ComponentKind> component_kind);

struct LegendEntry {
  std::string key;    // a key of legend_colors
  std::string words;  // at most kLegendMaxWords characters
  bool operator==(const LegendEntry&) const = default;
};
inline constexpr int kLegendMaxWords = 19;

// The picked sheet's (and its subsheets') highlights in legend order.
std::vector<LegendEntry> sheet_highlights();

// The legend of a wireframe coloured by non-hex kind: one entry per non-hex type, then chains at
// several types and at hexes only.
std::vector<LegendEntry> wire_kind_legend(const std::vector<int>& non_hex_types);

// What each colour, dot and edge of the shown layers means. highlights: the sheet highlights drawn
// (keys of sheet_highlights), nullopt for all; wire_by_kind: the wireframes are coloured by non-hex
// kind (their class colours then mean nothing beyond telling chains apart).
std::vector<LegendEntry> legend(const std::vector<std::string>& layers, const LegendFacts& facts,
                                const std::optional<std::vector<std::string>>& highlights, bool wire_by_kind);

// What the palette colours of the shown layers mean ("a colour a sheet"); the wireframe's class
// colours only when it is coloured by class. Each entry once.
std::vector<LegendEntry> palette_legend(const std::vector<std::string>& layers, bool wire_by_kind);

// A sheet type for narrow list rows ("type 1"), by SheetType.
std::vector<std::string> sheet_type_short();
// Why the subsheets layer cannot be built for a picked sheet of this SheetType (nullopt: no sheet
// picked), or nullopt when it can.
std::optional<std::string> subsheets_unavailable(std::optional<int> sheet_type);

// Defaults the front ends share: the wireframe's faintest opacity, the gap between copies laid
// side by side (a fraction of the model's width).
inline constexpr double kWireOpacityFloor = 0.15;
inline constexpr double kSpreadGap = 0.25;

}  // namespace hbc
