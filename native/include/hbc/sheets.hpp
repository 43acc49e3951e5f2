#pragma once
// Sheets of the hybrid base complex (paper §4; docs/concepts.md): extraction, classification as
// perfect, type 1 (non-hex), type 2 (self-parallel) or type 3 (self-intersecting) with a maximum
// cardinality matching, and the decomposition of self-intersecting sheets into subsheets (§4.3).
//
// Sheets are computed at one of two levels, and a block is what a sheet is made of. At the complex
// level (the paper's) the blocks are the base complex's components of hex cells (cube-like, ring or
// other), the curves its curves and the quads its quad patches. At the mesh level the blocks are
// the hex cells, the curves the mesh edges and the quads the cells' faces.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "hbc/base_complex.hpp"
#include "hbc/csr.hpp"
#include "hbc/level.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

// Perfect, or the highest imperfect configuration present (type 3 > type 2 > type 1).
enum class SheetType : uint8_t { Perfect = 0, Type1 = 1, Type2 = 2, Type3 = 3 };
// The machine name ("perfect", "type1", ...: JSON values) and the label in words
// ("type 3 (self-intersecting)"), the one spelling every output and the add-on use.
const char* sheet_type_name(SheetType t);
const char* sheet_type_label(SheetType t);

// Classification of one set of parallel curves over a set of blocks, shared by sheets and subsheets.
struct SheetClass {
  SheetType type = SheetType::Perfect;
  bool type1 = false, type2 = false, type3 = false;  // every configuration present
  std::vector<int32_t> unmatched_vertices;   // mesh vertices left uncovered by a maximum matching
  std::vector<int32_t> shared_vertices;      // curve ends shared by two parallel curves (any type)
  std::vector<int32_t> self_parallel_curves; // curves of type 2 pairs
  std::vector<int32_t> self_intersecting_blocks;  // blocks holding two parallel curves sharing an end

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const SheetClass&) const = default;
};

// The curve/block structure sheets are computed on (see the file comment). Curves are given by
// their mesh edges; blocks by their mesh cells.
struct SheetDomain {
  Level level = Level::Complex;
  std::vector<int32_t> cell_block;        // nc: block of a hex cell's component / the hex cell, -1 for non-hex
  Csr<int32_t> block_cells;               // nblock rows: mesh cells of each block
  Csr<int32_t> block_curves;              // nblock rows: curves each block holds, sorted
  Csr<int32_t> block_adjacency;           // nblock rows: face-adjacent blocks, sorted
  Csr<int32_t> curve_edges;              // ncurve rows: mesh edges of the curve
  std::vector<std::array<int32_t, 2>> curve_ends;  // mesh vertex ids; {-1,-1} for a closed curve
  Csr<int32_t> curve_blocks;              // ncurve rows: blocks holding the curve, sorted
  Csr<int32_t> curve_parallels;          // ncurve rows: curves parallel to it (one quad, no shared end)
  Csr<int32_t> curve_non_hex_cells;      // ncurve rows: non-hex cells containing an edge of the curve
  std::vector<int32_t> block_component;   // nblock: base complex component of the block
  // nf: faces across which the direction orthogonal to the face continues from one hex cell to
  // the other (complex level: non-separation faces inside a component; mesh level: none).
  std::vector<uint8_t> face_joins;

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const SheetDomain&) const = default;
};

// `threads`: see threads.hpp; the result is the same for any thread count.
SheetDomain sheet_domain(const Mesh& mesh, const BaseComplex& bc, Level level, const Threads& threads = {});

struct Sheets {
  Level level = Level::Complex;
  // Per sheet (numbered by their lowest block):
  Csr<int32_t> sheet_blocks;          // blocks (hex components or hex cells), sorted
  Csr<int32_t> sheet_cells;          // mesh hex cells, sorted
  Csr<int32_t> sheet_curves;         // E_P: parallel curves, sorted
  Csr<int32_t> sheet_edges;          // mesh edges of E_P, sorted
  Csr<int32_t> sheet_non_hex_cells;  // adjacent non-hex cells (touching E_P), sorted
  std::vector<SheetClass> classes;   // classification per sheet

  size_t size() const { return classes.size(); }
  size_t count(SheetType t) const;

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const Sheets&) const = default;
};

Sheets extract_sheets(const Mesh& mesh, const SheetDomain& domain, const Threads& threads = {});

// Classifies the curves `curves` (sorted) of a sheet or subsheet over the blocks `blocks` (sorted).
SheetClass classify_sheet(const SheetDomain& domain, const std::vector<int32_t>& curves,
                          const std::vector<int32_t>& blocks);

// How a self-intersecting sheet is split into subsheets (docs/validation.md).
//  - Layers: the rule of the paper's authors. From each curve not yet covered, a layer grows
//    depth-first over parallel curves block by block; a curve meeting the layer inside one block
//    takes its blocks out of the layer. Subsheets may share blocks and curves.
//  - Fewest: a split of the sheet's curves into as few subsheets as possible, each connected over
//    parallel curves and without two curves that meet in one block (so never type 3), with a
//    lower bound that proves it minimal when the two meet.
enum class SubsheetRule : uint8_t { Layers = 0, Fewest = 1 };
const char* subsheet_rule_name(SubsheetRule r);  // "layers", "fewest"
std::optional<SubsheetRule> subsheet_rule_from_name(std::string_view name);

struct SubsheetOptions {
  SubsheetRule rule = SubsheetRule::Layers;
  // Fewest: steps of the exact search per sheet (under a second per sheet on the paper's meshes).
  // A count of steps, not a time, so that the answer does not depend on the machine's load.
  int64_t node_budget = 100'000;
};

struct Subsheets {
  int32_t sheet = -1;
  SubsheetRule rule = SubsheetRule::Layers;
  Csr<int32_t> curves;   // per subsheet, sorted
  Csr<int32_t> blocks;    // per subsheet, sorted
  Csr<int32_t> cells;    // per subsheet, mesh hex cells, sorted
  std::vector<SheetClass> classes;
  // Fewest: no split has fewer subsheets than lower_bound; proven when the count meets it (the
  // search either met the bound or ruled out every smaller split). Layers: 0 and false.
  int32_t lower_bound = 0;
  bool proven = false;
  size_t size() const { return classes.size(); }

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const Subsheets&) const = default;
};

// The subsheets of one self-intersecting sheet by `options.rule` (subsheets.cpp).
Subsheets decompose_sheet(const SheetDomain& domain, const Sheets& sheets, int32_t sheet,
                          const SubsheetOptions& options = {});

// The self-intersecting sheet with most cells (ties: lowest id); none without such a sheet.
std::optional<int32_t> largest_self_intersecting(const Sheets& sheets);

}  // namespace hbc
