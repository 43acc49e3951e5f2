#pragma once
// The whole pipeline on one mesh, with per-stage timings, and the statistics of the paper's Table 1
// (§7.3; docs/concepts.md).
// The CLI, the Python binding and the table command all go through here.
#include <cstdint>
#include <optional>
#include <vector>

#include "hbc/base_complex.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/mesh.hpp"
#include "hbc/sheets.hpp"
#include "hbc/singularity_graph.hpp"
#include "hbc/vsg_wireframe.hpp"

namespace hbc {

struct AnalysisOptions {
  bool sheets = true;     // sheets and their classification
  bool subsheets = true;  // decomposition of every self-intersecting sheet (needs sheets)
  SubsheetOptions subsheet_options;  // which decomposition (the authors' layers by default)
  Level sheet_level = Level::Complex;
  bool wireframe = true;  // whole-mesh VSG wireframe
  Level wireframe_level = Level::Complex;
  WireframeOptions wireframe_options;
  // Threads the stages may split their work over (results are identical for any number); 0: as
  // Threads::count = 0 (HBC_THREADS, else every core).
  int threads = 0;
};

// Wall-clock seconds per stage; `load` is filled by whoever loaded the mesh.
struct Timings {
  double load = 0, singularity_graph = 0, base_complex = 0, sheets = 0, subsheets = 0, vsg_wireframe = 0;
};

// The sheet stage (paper §4): the curve/block domain, the sheets on it and, when the subsheet
// stage ran too, the decomposition of every self-intersecting sheet.
struct SheetStage {
  SheetDomain domain;
  Sheets sheets;
  std::optional<int32_t> largest_self_intersecting;  // the sheet id, when there is such a sheet
  // The subsheet stage ran: one decomposition per self-intersecting sheet, in sheet order.
  std::optional<std::vector<Subsheets>> subsheets;
  std::vector<double> subsheet_seconds;  // wall-clock seconds of each decomposition, in the same order

  // The decomposition of sheet s; nullptr when s is not self-intersecting or the subsheet stage
  // did not run.
  const Subsheets* subsheets_of(int32_t s) const;
};

// The whole-mesh VSG wireframe stage (paper §5).
struct WireframeStage {
  CellComplex view;  // the view (at wireframe_level) the wireframe was computed on
  VsgWireframe wireframe;
};

// The graph and the base complex are always computed; a stage that may be skipped
// (AnalysisOptions) is an optional that holds a value exactly when it ran.
struct Analysis {
  SingularityGraph graph;
  BaseComplex complex;  // the hybrid base complex (not a CellComplex view, whatever its level)
  std::optional<SheetStage> sheet_stage;
  std::optional<WireframeStage> wireframe_stage;
  Timings timings;
};

Analysis analyze(const Mesh& mesh, const AnalysisOptions& options = {});

// The statistics: Table 1's and more (docs/concepts.md). The counts of a stage that did not run
// hold no value.
struct Stats {
  int64_t cells = 0, hex_cells = 0;
  double hex_ratio = 0;
  int64_t singular_edges = 0, singularities = 0, pseudo_singular_edges = 0, non_manifold_edges = 0;
  int64_t singular_vertices = 0;  // of the singularity graph (SingularityGraph::singular_vertices)
  int64_t components = 0, hex_components = 0;
  double hex_component_ratio = 0;
  int64_t patches = 0, curves = 0, corners = 0, self_adjacent_faces = 0;
  std::optional<int64_t> sheets, sheets_perfect, sheets_type1, sheets_type2, sheets_type3;
  std::optional<int64_t> subsheets_of_largest_self_intersecting;
  std::optional<int64_t> vsg_edges, wireframe_edges, wireframe_edges_simplified;
  Timings timings;
};

Stats compute_stats(const Mesh& mesh, const Analysis& analysis);

// A self-intersecting sheet and how many subsheets it splits into.
struct SubsheetCount {
  int32_t sheet = -1, blocks = 0;  // blocks: hex components (level complex) or hex cells (level mesh)
  int64_t subsheets = 0;
};

// What analyze_stats keeps: the statistics and the subsheet counts of the self-intersecting
// sheets (in sheet order; empty unless the subsheet stage ran).
struct StatsRun {
  Stats stats;
  std::vector<SubsheetCount> subsheet_counts;
};

// compute_stats(mesh, analyze(mesh, options)) without holding every stage at once: each stage's
// results and each base complex array are dropped once the last reader is done, and the sheets run
// before the wireframe, whose complex-level view is built from the base complex alone (what it
// needs of the mesh taken beforehand, base_view_facts). Peak memory is then the mesh and the base
// complex plus the sheet domain, instead of the sum of the stages (the CLI's analyze on 10^7 cells).
StatsRun analyze_stats(const Mesh& mesh, const AnalysisOptions& options = {});
// The same, freeing the mesh once only the view is still to be built: the peak of the wireframe
// stage is then the view without the mesh.
StatsRun analyze_stats(Mesh&& mesh, const AnalysisOptions& options = {});

}  // namespace hbc
