// Structural complexity metrics (metrics.hpp; definitions and rationale in docs/metrics.md).
// Every metric is a count or a share over arrays the analysis already holds, plus one pass over the
// cells for volumes and the scaled Jacobian, so the whole costs a small part of the analysis.
#include "hbc/metrics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <tuple>

#include "hbc/cell_quality.hpp"
#include "parallel/parallel.hpp"
#include "parallel/union_find.hpp"

namespace hbc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The index of each metric in kFields (same order).
enum M : int {
  // census
  kCells, kHexCells, kPrismCells, kPyramidCells, kTetCells, kPolyCells, kHexRatio, kHexVolumeRatio,
  // singular
  kSingEdgesInterior, kSingEdgesBoundary, kPseudoSingEdges, kSingCurves, kSingCurvesClosed,
  kSingCurvesBoundaryEnds, kSingCurvesNodeEnds, kSingCurvesOnBoundary, kSingCurveEdgesMean, kSingCurveEdgesMax,
  kSingLength, kSingNodes,
  // complex
  kComponents, kBlocks, kCubeComponents, kRingComponents, kOtherComponents, kNonHexComponents,
  kCorners, kCurves, kPatches, kSelfAdjacentFaces, kCompCellsMin, kCompCellsMedian, kCompCellsMax,
  kLargestTenthShare,
  // sheets
  kSheets, kSheetsPerfect, kSheetsType1, kSheetsType2, kSheetsType3, kPerfectCellShare, kSubsheetsMean,
  kSubsheetsMax, kSelfIntersections, kSheetComplexity,
  // non_hex
  kNonHexCells, kNonHexRegions, kNonHexRegionMax, kNonHexRegionMean, kNonHexBoundaryShare, kNonHexPerComponent,
  // quality
  kSjMin, kSjMean, kInverted, kSjMinHex, kSjMinPrism, kSjMinPyramid, kSjMinTet, kSjMinPoly, kWorstComponent,
  kWorstComponentSj, kWorstSheet, kWorstSheetSj,
  // summary
  kScore,
  kFieldCount
};

using R = Refinement;
using K = FieldKind;
constexpr MetricField kFields[] = {
    {{"cells", "Cells", "", "", "cells of every type", "cells", K::Count}, "census", R::Cells},
    {{"hexahedra", "Hexahedra", "", "", "hexahedral cells", "cells", K::Count}, "census", R::Cells},
    {{"prisms", "Prisms", "", "", "prism (wedge) cells", "cells", K::Count}, "census", R::Cells},
    {{"pyramids", "Pyramids", "", "", "pyramid cells", "cells", K::Count}, "census", R::Cells},
    {{"tetrahedra", "Tetrahedra", "", "", "tetrahedral cells", "cells", K::Count}, "census", R::Cells},
    {{"polyhedra", "Polyhedra", "", "", "general polyhedra (by face count in polyhedra_by_faces)", "cells", K::Count}, "census", R::Cells},
    {{"hex_ratio", "Hex ratio", "", "", "hexahedra / cells", "ratio", K::Ratio}, "census", R::Invariant},
    {{"hex_volume_ratio", "Hex volume ratio", "", "", "volume of the hexahedra / volume of the mesh", "ratio", K::Ratio}, "census",
     R::Invariant},
    {{"edges_interior", "Interior singular edges", "", "",
     "all-hex interior edges of valence other than 4", "edges", K::Count}, "singular", R::Edges},
    {{"edges_boundary", "Boundary singular edges", "", "",
     "all-hex boundary edges of valence other than 2", "edges", K::Count}, "singular", R::Edges},
    {{"pseudo_singular_edges", "Pseudo-singular edges", "", "", "edges touching a non-hex cell", "edges", K::Count}, "singular",
     R::None},
    {{"singularities", "Singularities", "", "",
     "maximal chains of singular edges of one valence", "singularities", K::Count}, "singular", R::Invariant},
    {{"singularities_closed", "Closed singularities", "", "", "singularities that are closed loops", "singularities", K::Count}, "singular",
     R::Invariant},
    {{"singularities_boundary_ends", "Singularities ending on the boundary", "", "",
     "open singularities with both ends on the boundary", "singularities", K::Count}, "singular", R::Invariant},
    {{"singularities_interior_ends", "Singularities ending inside", "", "",
     "open singularities with an end inside the volume (a singular vertex or a non-hex cell)", "singularities", K::Count}, "singular", R::Invariant},
    {{"singularities_on_boundary", "Singularities on the boundary", "", "",
     "singularities made of boundary edges only", "singularities", K::Count}, "singular", R::Invariant},
    {{"singularity_edges_mean", "Mean singularity length", "", "", "mean mesh edges per singularity", "edges", K::Value}, "singular",
     R::Edges},
    {{"singularity_edges_max", "Longest singularity", "", "", "mesh edges of the longest singularity", "edges", K::Count}, "singular",
     R::Edges},
    {{"length", "Singular length", "", "",
     "total length of the singular edges / the diagonal of the bounding box", "ratio", K::Ratio}, "singular", R::Invariant},
    {{"singular_vertices", "Singular vertices", "", "",
     "singularity ends that are not pseudo-singular (where singularities meet or stop)", "vertices", K::Count}, "singular", R::Invariant},
    {{"components", "Components", "", "", "components of the hybrid base complex", "components", K::Count}, "complex", R::Invariant},
    {{"blocks", "Blocks", "", "",
     "components made of hexahedra (cube, ring or other): the blocks sheets run through", "components", K::Count}, "complex", R::Invariant},
    {{"hex_components", "Hex components", "", "", "|H_B|: cube-like components of hexahedra", "components", K::Count}, "complex",
     R::Invariant},
    {{"ring_components", "Ring components", "", "", "components of hexahedra cut into a ring", "components", K::Count}, "complex",
     R::Invariant},
    {{"other_components", "Other components", "", "", "components of hexahedra of any other shape", "components", K::Count}, "complex",
     R::Invariant},
    {{"non_hex_components", "Non-hex components", "", "", "components of one non-hex cell each", "components", K::Count}, "complex",
     R::Cells},
    {{"corners", "Corners", "", "", "V_B: corners of the base complex", "vertices", K::Count}, "complex", R::Invariant},
    {{"curves", "Curves", "", "", "E_B: curves of the base complex", "curves", K::Count}, "complex", R::Invariant},
    {{"patches", "Patches", "", "", "F_B: patches of the base complex", "patches", K::Count}, "complex", R::Invariant},
    {{"self_adjacent_faces", "Self-adjacent faces", "", "",
     "interior separation faces with one component on both sides", "faces", K::Count}, "complex", R::Faces},
    {{"component_cells_min", "Smallest component", "", "", "cells of the smallest component of hexahedra", "cells", K::Count}, "complex",
     R::Cells},
    {{"component_cells_median", "Median component", "", "",
     "cells of the median component of hexahedra (the lower one of an even count)", "cells", K::Count}, "complex", R::Cells},
    {{"component_cells_max", "Largest component", "", "", "cells of the largest component of hexahedra", "cells", K::Count}, "complex",
     R::Cells},
    {{"largest_tenth_share", "Largest tenth's share", "", "",
     "share of the hexahedra of components that lie in the largest tenth of them (rounded up)", "ratio", K::Ratio}, "complex", R::Invariant},
    {{"sheets", "Sheets", "", "", "|G_SH|: sheets of the base complex", "sheets", K::Count}, "sheets", R::Invariant},
    {{"perfect", "Perfect sheets", "", "", "sheets of none of the imperfect configurations", "sheets", K::Count}, "sheets", R::Invariant},
    {{"type1", "Type 1 sheets", "", "", "sheets whose highest configuration is non-hex (type 1)", "sheets", K::Count}, "sheets",
     R::Invariant},
    {{"type2", "Type 2 sheets", "", "", "sheets whose highest configuration is self-parallel (type 2)", "sheets", K::Count}, "sheets",
     R::Invariant},
    {{"type3", "Type 3 sheets", "", "", "self-intersecting sheets (type 3)", "sheets", K::Count}, "sheets", R::Invariant},
    {{"perfect_cell_share", "Cells in perfect sheets", "", "",
     "share of the hexahedra that lie in at least one perfect sheet", "ratio", K::Ratio}, "sheets", R::Invariant},
    {{"subsheets_mean", "Subsheets per self-intersecting sheet", "", "",
     "mean subsheet count over the decomposed self-intersecting sheets", "subsheets", K::Value}, "sheets", R::Invariant},
    {{"subsheets_max", "Most subsheets", "", "", "subsheets of the most divided sheet", "subsheets", K::Count}, "sheets", R::Invariant},
    {{"self_intersections", "Self-intersections", "", "",
     "blocks holding two parallel curves of one sheet that share an end, summed over the sheets", "blocks", K::Count}, "sheets", R::Invariant},
    {{"connectivity_complexity", "Sheet connectivity complexity", "", "",
     "Xu and Chen's sheet connectivity on the hex part: pairs of sheets that intersect or neighbour", "pairs", K::Count}, "sheets", R::Invariant},
    {{"cells", "Non-hex cells", "", "", "cells that are not hexahedra", "cells", K::Count}, "non_hex", R::Cells},
    {{"regions", "Non-hex regions", "", "", "face-connected regions of non-hex cells", "regions", K::Count}, "non_hex", R::Invariant},
    {{"region_cells_max", "Largest non-hex region", "", "", "cells of the largest non-hex region", "cells", K::Count}, "non_hex",
     R::Cells},
    {{"region_cells_mean", "Mean non-hex region", "", "", "mean cells per non-hex region", "cells", K::Value}, "non_hex", R::Cells},
    {{"boundary_share", "Non-hex cells on the boundary", "", "",
     "share of the non-hex cells with a boundary face", "ratio", K::Ratio}, "non_hex", R::None},
    {{"per_block", "Non-hex cells per block", "", "",
     "non-hex cells / blocks (components of hexahedra)", "cells", K::Value}, "non_hex", R::Cells},
    {{"sj_min", "Minimum scaled Jacobian", "", "", "lowest scaled Jacobian over all cells", "ratio", K::Ratio}, "quality", R::None},
    {{"sj_mean", "Mean scaled Jacobian", "", "", "mean scaled Jacobian over all cells", "ratio", K::Ratio}, "quality", R::None},
    {{"inverted", "Inverted cells", "", "", "cells with a negative scaled Jacobian", "cells", K::Count}, "quality", R::None},
    {{"sj_min_hexahedron", "Minimum SJ, hexahedra", "", "", "lowest scaled Jacobian of a hexahedron", "ratio", K::Ratio}, "quality",
     R::None},
    {{"sj_min_prism", "Minimum SJ, prisms", "", "", "lowest scaled Jacobian of a prism", "ratio", K::Ratio}, "quality", R::None},
    {{"sj_min_pyramid", "Minimum SJ, pyramids", "", "", "lowest scaled Jacobian of a pyramid", "ratio", K::Ratio}, "quality", R::None},
    {{"sj_min_tetrahedron", "Minimum SJ, tetrahedra", "", "", "lowest scaled Jacobian of a tetrahedron", "ratio", K::Ratio}, "quality",
     R::None},
    {{"sj_min_polyhedron", "Minimum SJ, polyhedra", "", "", "lowest scaled Jacobian of a polyhedron", "ratio", K::Ratio}, "quality",
     R::None},
    {{"worst_component", "Worst component", "", "",
     "the component of hexahedra holding the lowest scaled Jacobian (lowest id on ties)", "id", K::Count}, "quality", R::None},
    {{"worst_component_sj", "Worst component's SJ", "", "", "its lowest scaled Jacobian", "ratio", K::Ratio}, "quality", R::None},
    {{"worst_sheet", "Worst sheet", "", "", "the sheet holding the lowest scaled Jacobian (lowest id on ties)", "id", K::Count}, "quality",
     R::None},
    {{"worst_sheet_sj", "Worst sheet's SJ", "", "", "its lowest scaled Jacobian", "ratio", K::Ratio}, "quality", R::None},
    {{"score", "Structural complexity score", "", "",
     "sum of summary.vector: 0 for one perfect block of hexahedra, larger for a more complex structure", "ratio", K::Ratio}, "summary",
     R::Invariant},
};
static_assert(std::size(kFields) == kFieldCount);

// Keys renamed to the words of docs/concepts.md (its glossary's retired words): readers of the old
// key find it still, written beside the new one (metrics_json) and accepted by metric_index.
constexpr MetricAlias kAliases[] = {
    {"singular", "curves", "singularities"},
    {"singular", "curves_closed", "singularities_closed"},
    {"singular", "curves_boundary_ends", "singularities_boundary_ends"},
    {"singular", "curves_node_ends", "singularities_interior_ends"},
    {"singular", "curves_on_boundary", "singularities_on_boundary"},
    {"singular", "curve_edges_mean", "singularity_edges_mean"},
    {"singular", "curve_edges_max", "singularity_edges_max"},
    {"singular", "nodes", "singular_vertices"},
    {"singular", "curve_edges", "singularity_edges"},
    {"complex", "cube_components", "hex_components"},
};

constexpr std::string_view kSummary[] = {"non_hex_volume_share", "log10_1_plus_interior_curves",
                                         "log10_blocks", "imperfect_sheet_share", "cells_outside_perfect_sheets"};

using Vec3 = std::array<double, 3>;
Vec3 point(const Mesh& m, int32_t v) { return {m.points[3 * v], m.points[3 * v + 1], m.points[3 * v + 2]}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double triple(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// Volume of cell c by the divergence theorem over its face loops as the cell sees them (outward,
// mesh.hpp), each fanned from its first vertex, relative to one corner of the cell so that
// coordinates far from the origin lose no digits.
double cell_volume(const Mesh& m, size_t c) {
  const auto faces = m.cell_faces[c];
  const Vec3 o = point(m, m.face_verts[faces[0]][0]);
  double six = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    const auto loop = m.face_verts[faces[i]];
    const bool flip = m.cell_face_flip[m.cell_faces.offsets[c] + i];
    const size_t n = loop.size();
    auto at = [&](size_t k) { return sub(point(m, loop[flip ? (n - k) % n : k]), o); };
    const Vec3 a = at(0);
    for (size_t k = 1; k + 1 < n; ++k) six += triple(a, at(k), at(k + 1));
  }
  return six / 6;
}

void census(const Mesh& m, const Threads& threads, Metrics& out) {
  std::vector<double> volumes(m.num_cells());
  detail::parallel_ranges(volumes.size(), resolved(threads), [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) volumes[c] = cell_volume(m, c);
  });
  auto& v = out.values;
  std::array<int64_t, 5> by_type{};
  double hex_volume = 0, volume = 0;
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const CellType t = m.cell_type[c];
    ++by_type[static_cast<size_t>(t)];
    if (t == CellType::Polyhedron) {
      const size_t k = m.cell_faces.count(c);
      if (out.polyhedra_by_faces.size() <= k) out.polyhedra_by_faces.resize(k + 1, 0);
      ++out.polyhedra_by_faces[k];
    }
    const double vol = volumes[c];  // summed in cell order: the same for any thread count
    volume += vol;
    if (t == CellType::Hex) hex_volume += vol;
  }
  const double nc = static_cast<double>(m.num_cells());
  v[kCells] = nc;
  v[kHexCells] = static_cast<double>(by_type[0]);
  v[kTetCells] = static_cast<double>(by_type[1]);
  v[kPrismCells] = static_cast<double>(by_type[2]);
  v[kPyramidCells] = static_cast<double>(by_type[3]);
  v[kPolyCells] = static_cast<double>(by_type[4]);
  v[kHexRatio] = nc > 0 ? by_type[0] / nc : kNaN;
  v[kHexVolumeRatio] = volume > 0 ? hex_volume / volume : kNaN;
}

void singular_structure(const Mesh& m, const SingularityGraph& g, Metrics& out) {
  auto& v = out.values;
  int64_t interior = 0, boundary = 0;
  for (int32_t e : g.chain_edges.items) {
    const int32_t val = m.edge_valence(e);
    auto& hist = m.edge_boundary[e] ? out.singular_valence_boundary : out.singular_valence_interior;
    if (hist.size() <= static_cast<size_t>(val)) hist.resize(val + 1, 0);
    ++hist[val];
    ++(m.edge_boundary[e] ? boundary : interior);
  }
  Vec3 lo{}, hi{};
  for (size_t i = 0; i < m.num_vertices(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = m.points[3 * i + k];
      lo[k] = i == 0 ? x : std::min(lo[k], x);
      hi[k] = i == 0 ? x : std::max(hi[k], x);
    }
  const Vec3 d = sub(hi, lo);
  const double diagonal = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  double length = 0;
  int64_t closed = 0, boundary_ends = 0, node_ends = 0, on_boundary = 0, most = 0;
  for (size_t s = 0; s < g.num_singularities(); ++s) {
    const auto edges = g.chain_edges[s];
    const auto verts = g.chain_verts[s];
    out.singularity_edges.push_back(static_cast<int32_t>(edges.size()));
    most = std::max<int64_t>(most, edges.size());
    for (int32_t e : edges) {
      const Vec3 a = sub(point(m, m.edge_verts[e][1]), point(m, m.edge_verts[e][0]));
      length += std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    }
    on_boundary += g.chain_boundary[s];
    if (g.chain_closed[s]) {
      ++closed;
    } else if (m.vert_boundary[verts.front()] && m.vert_boundary[verts.back()]) {
      ++boundary_ends;
    } else {
      ++node_ends;
    }
  }
  const double ns = static_cast<double>(g.num_singularities());
  v[kSingEdgesInterior] = static_cast<double>(interior);
  v[kSingEdgesBoundary] = static_cast<double>(boundary);
  v[kPseudoSingEdges] = static_cast<double>(g.pseudo_singular_edges.size());
  v[kSingCurves] = ns;
  v[kSingCurvesClosed] = static_cast<double>(closed);
  v[kSingCurvesBoundaryEnds] = static_cast<double>(boundary_ends);
  v[kSingCurvesNodeEnds] = static_cast<double>(node_ends);
  v[kSingCurvesOnBoundary] = static_cast<double>(on_boundary);
  v[kSingCurveEdgesMean] = ns > 0 ? static_cast<double>(g.num_singular_edges()) / ns : 0;
  v[kSingCurveEdgesMax] = static_cast<double>(most);
  v[kSingLength] = diagonal > 0 ? length / diagonal : 0;
  v[kSingNodes] = static_cast<double>(g.singular_vertices.size());
}

void base_complex_metrics(const BaseComplex& bc, Metrics& out) {
  auto& v = out.values;
  std::array<int64_t, 4> by_kind{};
  for (size_t k = 0; k < bc.num_components(); ++k) {
    ++by_kind[static_cast<size_t>(bc.component_kind[k])];
    if (bc.component_kind[k] != ComponentKind::NonHex)
      out.component_cells.push_back(static_cast<int32_t>(bc.component_cells.count(k)));
  }
  v[kComponents] = static_cast<double>(bc.num_components());
  v[kBlocks] = static_cast<double>(out.component_cells.size());
  v[kCubeComponents] = static_cast<double>(by_kind[0]);
  v[kRingComponents] = static_cast<double>(by_kind[1]);
  v[kOtherComponents] = static_cast<double>(by_kind[2]);
  v[kNonHexComponents] = static_cast<double>(by_kind[3]);
  v[kCorners] = static_cast<double>(bc.corners.size());
  v[kCurves] = static_cast<double>(bc.num_curves());
  v[kPatches] = static_cast<double>(bc.num_patches());
  v[kSelfAdjacentFaces] = static_cast<double>(bc.self_adjacent_faces.size());
  std::vector<int32_t> sizes = out.component_cells;
  if (sizes.empty()) {
    v[kCompCellsMin] = v[kCompCellsMedian] = v[kCompCellsMax] = v[kLargestTenthShare] = kNaN;
    return;
  }
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  const size_t n = sizes.size(), tenth = (n + 9) / 10;
  int64_t total = 0, top = 0;
  for (size_t i = 0; i < n; ++i) (i < tenth ? top : total) += sizes[i];
  total += top;
  v[kCompCellsMax] = sizes.front();
  v[kCompCellsMin] = sizes.back();
  v[kCompCellsMedian] = sizes[n / 2];  // descending order: the lower median of an even count
  v[kLargestTenthShare] = static_cast<double>(top) / static_cast<double>(total);
}

void sheet_metrics(const Mesh& m, const SheetStage& st, Metrics& out) {
  auto& v = out.values;
  const Sheets& sh = st.sheets;
  v[kSheets] = static_cast<double>(sh.size());
  v[kSheetsPerfect] = static_cast<double>(sh.count(SheetType::Perfect));
  v[kSheetsType1] = static_cast<double>(sh.count(SheetType::Type1));
  v[kSheetsType2] = static_cast<double>(sh.count(SheetType::Type2));
  v[kSheetsType3] = static_cast<double>(sh.count(SheetType::Type3));
  std::vector<uint8_t> in_perfect(m.num_cells(), 0);
  int64_t perfect_cells = 0, crossings = 0;
  for (size_t s = 0; s < sh.size(); ++s) {
    crossings += static_cast<int64_t>(sh.classes[s].self_intersecting_blocks.size());
    if (sh.classes[s].type != SheetType::Perfect) continue;
    for (int32_t c : sh.sheet_cells[s]) {
      perfect_cells += !in_perfect[c];
      in_perfect[c] = 1;
    }
  }
  const size_t hexes = m.num_hex_cells();
  v[kPerfectCellShare] = hexes > 0 ? static_cast<double>(perfect_cells) / static_cast<double>(hexes) : kNaN;
  v[kSelfIntersections] = static_cast<double>(crossings);
  if (st.subsheets) {
    int64_t sum = 0, most = 0;
    for (const Subsheets& d : *st.subsheets) {
      out.subsheets_per_sheet.push_back(static_cast<int32_t>(d.size()));
      sum += static_cast<int64_t>(d.size());
      most = std::max<int64_t>(most, d.size());
    }
    const size_t n = st.subsheets->size();
    v[kSubsheetsMean] = n > 0 ? static_cast<double>(sum) / static_cast<double>(n) : 0;
    v[kSubsheetsMax] = static_cast<double>(most);
  }
}

// Xu and Chen's sheet connectivity (IEEE TVCG 2019, and their code's "complexity of all sheets"):
// two sheets are connected when they intersect (hold a common block) or are neighbours (an
// interior patch lies on the boundary of both, i.e. each holds exactly one of its two sides).
// Counted as unordered pairs at the complex level, on the hex part (blocks are hex components).
double sheet_connectivity_pairs(const BaseComplex& bc, const SheetStage& st) {
  const SheetDomain& d = st.domain;
  const Sheets& sh = st.sheets;
  if (d.level != Level::Complex) return kNaN;
  Csr<int32_t> block_sheets;  // per block, the sheets holding it (increasing)
  std::vector<int32_t> count(d.block_cells.rows() + 1, 0);
  for (int32_t b : sh.sheet_blocks.items) ++count[b + 1];
  for (size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
  block_sheets.offsets = count;
  block_sheets.items.resize(sh.sheet_blocks.items.size());
  for (size_t s = 0; s < sh.size(); ++s)
    for (int32_t b : sh.sheet_blocks[s]) block_sheets.items[count[b]++] = static_cast<int32_t>(s);
  std::vector<uint64_t> pairs;
  auto all_pairs = [&](const std::vector<int32_t>& ids) {
    for (size_t i = 0; i < ids.size(); ++i)
      for (size_t j = i + 1; j < ids.size(); ++j)
        pairs.push_back(static_cast<uint64_t>(std::min(ids[i], ids[j])) << 32 | static_cast<uint32_t>(std::max(ids[i], ids[j])));
  };
  std::vector<int32_t> ids;
  for (size_t b = 0; b < block_sheets.rows(); ++b) {
    ids.assign(block_sheets[b].begin(), block_sheets[b].end());
    all_pairs(ids);
  }
  auto block_of = [&](int32_t k) { return k < 0 ? -1 : d.cell_block[bc.component_cells[k][0]]; };
  for (const auto& pc : bc.patch_components) {
    const int32_t a = block_of(pc[0]), b = block_of(pc[1]);
    if (a < 0 || b < 0 || a == b) continue;  // a boundary patch, or one beside a non-hex cell
    ids.clear();
    std::set_symmetric_difference(block_sheets[a].begin(), block_sheets[a].end(), block_sheets[b].begin(),
                                  block_sheets[b].end(), std::back_inserter(ids));
    all_pairs(ids);
  }
  std::sort(pairs.begin(), pairs.end());
  return static_cast<double>(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
}

void non_hex_clustering(const Mesh& m, const BaseComplex& bc, Metrics& out) {
  auto& v = out.values;
  const size_t nc = m.num_cells();
  detail::UnionFind uf(nc);
  for (const auto& fc : m.face_cells)
    if (fc[1] >= 0 && !m.is_hex(fc[0]) && !m.is_hex(fc[1])) uf.unite(fc[0], fc[1]);
  std::vector<int32_t> size(nc, 0);
  int64_t non_hex = 0, on_boundary = 0;
  for (size_t c = 0; c < nc; ++c) {
    if (m.is_hex(c)) continue;
    ++non_hex;
    ++size[uf.find(static_cast<int32_t>(c))];
    bool touches = false;
    for (int32_t f : m.cell_faces[c]) touches |= m.face_boundary[f] != 0;
    on_boundary += touches;
  }
  for (int32_t s : size)
    if (s > 0) out.non_hex_region_cells.push_back(s);
  std::sort(out.non_hex_region_cells.begin(), out.non_hex_region_cells.end(), std::greater<>());
  const double regions = static_cast<double>(out.non_hex_region_cells.size());
  v[kNonHexCells] = static_cast<double>(non_hex);
  v[kNonHexRegions] = regions;
  v[kNonHexRegionMax] = regions > 0 ? out.non_hex_region_cells.front() : 0;
  v[kNonHexRegionMean] = regions > 0 ? static_cast<double>(non_hex) / regions : 0;
  v[kNonHexBoundaryShare] = non_hex > 0 ? static_cast<double>(on_boundary) / static_cast<double>(non_hex) : kNaN;
  const size_t hex_components = bc.num_components() - bc.num_non_hex_components();
  v[kNonHexPerComponent] =
      hex_components > 0 ? static_cast<double>(non_hex) / static_cast<double>(hex_components) : kNaN;
}

// The owner (component or sheet) whose cells hold the lowest scaled Jacobian; ties to the lowest id.
std::pair<double, double> worst_owner(const Csr<int32_t>& owner_cells, const std::vector<double>& sj,
                                      auto&& keep) {
  double id = kNaN, worst = kNaN;
  for (size_t k = 0; k < owner_cells.rows(); ++k) {
    if (!keep(k)) continue;
    for (int32_t c : owner_cells[k])
      if (!(sj[c] >= worst)) {
        worst = sj[c];
        id = static_cast<double>(k);
      }
  }
  return {id, worst};
}

void quality_metrics(const Mesh& m, const Analysis& a, const Threads& threads, Metrics& out) {
  auto& v = out.values;
  const std::vector<double> sj = scaled_jacobians(m, threads);
  std::array<double, 5> type_min;
  type_min.fill(kNaN);
  double lowest = kNaN, sum = 0;
  int64_t inverted = 0;
  for (size_t c = 0; c < sj.size(); ++c) {
    double& tm = type_min[static_cast<size_t>(m.cell_type[c])];
    if (!(sj[c] >= tm)) tm = sj[c];
    if (!(sj[c] >= lowest)) lowest = sj[c];
    sum += sj[c];
    inverted += sj[c] < 0;
  }
  v[kSjMin] = lowest;
  v[kSjMean] = sj.empty() ? kNaN : sum / static_cast<double>(sj.size());
  v[kInverted] = static_cast<double>(inverted);
  v[kSjMinHex] = type_min[0];
  v[kSjMinTet] = type_min[1];
  v[kSjMinPrism] = type_min[2];
  v[kSjMinPyramid] = type_min[3];
  v[kSjMinPoly] = type_min[4];
  const BaseComplex& bc = a.complex;
  std::tie(v[kWorstComponent], v[kWorstComponentSj]) =
      worst_owner(bc.component_cells, sj, [&](size_t k) { return bc.component_kind[k] != ComponentKind::NonHex; });
  if (a.sheet_stage)
    std::tie(v[kWorstSheet], v[kWorstSheetSj]) =
        worst_owner(a.sheet_stage->sheets.sheet_cells, sj, [](size_t) { return true; });
}

// Each entry is 0 for one perfect block of hexahedra (a box: its 12 boundary curves are forced by
// its shape, so only curves off the boundary count) and unchanged by uniform refinement.
void summary(Metrics& out) {
  const auto& v = out.values;
  const double sheets = v[kSheets];
  out.summary_vector = {1 - v[kHexVolumeRatio],
                        std::log10(1 + v[kSingCurves] - v[kSingCurvesOnBoundary]),
                        std::log10(std::max(1.0, v[kBlocks])),
                        sheets > 0 ? 1 - v[kSheetsPerfect] / sheets : sheets == 0 ? 0 : kNaN,
                        1 - v[kPerfectCellShare]};
  // The logarithms' last bits depend on the maths library (glibc and musl, which the WebAssembly
  // build uses, differ by one ulp for some counts); rounding to 1e-12, with exact IEEE operations,
  // makes the summary the same on every platform while keeping far more digits than it means.
  const auto fixed = [](double x) { return std::isfinite(x) ? std::round(x * 1e12) / 1e12 : x; };
  double score = 0;
  for (double& x : out.summary_vector) {
    x = fixed(x);
    score += x;
  }
  out.values[kScore] = fixed(score);
}

}  // namespace

const char* refinement_name(Refinement r) {
  constexpr const char* kNames[] = {"invariant", "x8", "x2", "x4", "none"};
  return kNames[static_cast<int>(r)];
}

std::span<const MetricField> metric_fields() { return kFields; }

std::span<const std::string_view> summary_fields() { return kSummary; }

std::span<const MetricAlias> metric_aliases() { return kAliases; }

int metric_index(std::string_view group, std::string_view key) {
  for (const MetricAlias& a : kAliases)
    if (a.group == group && a.old_key == key) key = a.key;
  for (size_t i = 0; i < std::size(kFields); ++i)
    if (kFields[i].group == group && kFields[i].key == key) return static_cast<int>(i);
  return -1;
}

double Metrics::value(std::string_view group, std::string_view key) const {
  const int i = metric_index(group, key);
  return i < 0 || static_cast<size_t>(i) >= values.size() ? kNaN : values[i];
}

Metrics compute_metrics(const Mesh& mesh, const Analysis& analysis, const Threads& threads,
                        const MetricsOptions& options) {
  Metrics out;
  out.values.assign(kFieldCount, kNaN);
  census(mesh, threads, out);
  singular_structure(mesh, analysis.graph, out);
  base_complex_metrics(analysis.complex, out);
  if (analysis.sheet_stage) {
    sheet_metrics(mesh, *analysis.sheet_stage, out);
    out.values[kSheetComplexity] = sheet_connectivity_pairs(analysis.complex, *analysis.sheet_stage);
  }
  non_hex_clustering(mesh, analysis.complex, out);
  if (options.quality) quality_metrics(mesh, analysis, threads, out);
  summary(out);
  return out;
}

}  // namespace hbc
