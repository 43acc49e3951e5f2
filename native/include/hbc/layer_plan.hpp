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

// One part of a layer, as both front ends request it from the core: which geometry, from which of
// the analysis' arrays and with which options, and how it is coloured. What a layer draws is
// decided here once; a front end only turns the arrays into its scene (the add-on's objects and
// their properties, the web page's buffers) and takes the values of the user's settings.
struct PartRequest {
  std::string layer;     // a key of layer_titles
  std::string part;      // unique in the layer; a sheet highlight's part is the highlight's key
  std::string geometry;  // "soup": block_soup faces; "lines": polylines of mesh vertices; "dots":
                         // mesh vertices
  // soup: block_soup's kind ("boundary", "non_hex", "hex", "components", "sheets", "sheet",
  // "subsheets"). lines: "chains" (the graph's chain_vertices, chain_closed), "edges" (the mesh
  // edges of class edge_class), "curves" (the base complex's curve_vertices, curve_closed),
  // "wireframe" (the VSG wireframe of the mesh, the picked sheet or each subsheet: its polylines;
  // `shown` keeps the simplified one). dots: the name of a CSR of mesh vertices
  // ("sheet_unmatched_vertices" of the analysis, "subsheet_unmatched_vertices" of its subsheets).
  std::string source;
  // The CSR (by its Python name, on the analysis) whose row of the picked sheet lists what is
  // drawn: the owners of a soup, the curves of "curves"; empty: all of them.
  std::string select;
  int edge_class = -1;   // "edges": the EdgeClass drawn
  bool sheet = false;    // asks for the picked sheet (a soup's or the wireframe's sheet argument)
  bool shrink = false;   // the layer's shrink setting applies (else 0)
  // "role": one colour, legend_colors()[role]; "cell_type": the cell type of the owner (a cell);
  // "valence": a chain's valence_color; "component": component_color of the owner and its kind;
  // "spread": the owner's spread palette entry; "sheet_shaded": the picked sheet's spread entry,
  // each owner (component) times 0.8, 0.9 or 1.0 by (7 owner mod 3); "subsheet": subsheet_color
  // of the owner; "wire": the wireframe's class colours (palette_color) or, coloured by kind, its
  // chains' non-hex kinds; alpha the wireframe's point opacity above the opacity floor.
  std::string color;
  std::string role;      // "role": a key of legend_colors
  // "merged": one piece; "owner": one piece per owner (subsheet), side by side when spread. The
  // scene's own splitting (the add-on's clickable object per component or sheet up to its
  // maximum, per valence) is the front end's.
  std::string split = "merged";
  // "": always; "non_hex_cells": the mesh has non-hex cells; "setting": a front end's switch
  // for this part (the add-on's Direct settings), on unless default_on is false (a front end
  // without the switch takes default_on).
  std::string when;
  bool default_on = true;
  bool optional = false;  // left out when it has nothing to draw (a highlight, an edge class)
  bool operator==(const PartRequest&) const = default;
};
// Every layer's parts, layers in layer_titles' order, parts in drawing order.
std::vector<PartRequest> layer_requests();

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
