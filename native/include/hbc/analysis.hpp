#pragma once
// The whole pipeline on one mesh, with per-stage timings, and the Table 1 statistics (SPEC §5).
// The CLI, the Python binding and the table command all go through here.
#include <cstdint>
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
  Level sheet_level = Level::Complex;
  bool wireframe = true;  // whole-mesh VSG wireframe
  Level wireframe_level = Level::Complex;
  WireframeOptions wireframe_options;
};

// Wall-clock seconds per stage; `load` is filled by whoever loaded the mesh.
struct Timings {
  double load = 0, singularity_graph = 0, base_complex = 0, sheets = 0, subsheets = 0, vsg_wireframe = 0;
};

struct Analysis {
  SingularityGraph graph;
  BaseComplex complex;
  SheetDomain domain;
  Sheets sheets;
  std::vector<Subsheets> subsheets;        // one per self-intersecting sheet, in sheet order
  int32_t largest_self_intersecting = -1;  // sheet id, or -1
  CellComplex wire_complex;                // the view the whole-mesh wireframe was computed on
  VsgWireframe wireframe;
  Timings timings;
  bool has_sheets = false;     // the sheet stage ran
  bool has_subsheets = false;  // the subsheet stage ran
  bool has_wireframe = false;  // the wireframe stage ran

  // The decomposition of sheet s, or nullptr when s is not self-intersecting.
  const Subsheets* subsheets_of(int32_t s) const;
};

Analysis analyze(const Mesh& mesh, const AnalysisOptions& options = {});

// The SPEC §5 statistics. Counts are -1 for stages that were not run.
struct Stats {
  int64_t cells = 0, hex_cells = 0;
  double hex_ratio = 0;
  int64_t singular_edges = 0, singularities = 0, pseudo_singular_edges = 0, non_manifold_edges = 0;
  int64_t singular_vertices = 0;
  int64_t components = 0, hex_components = 0;
  double hex_component_ratio = 0;
  int64_t patches = 0, curves = 0, corners = 0, self_adjacent_faces = 0;
  int64_t sheets = -1, sheets_perfect = -1, sheets_type1 = -1, sheets_type2 = -1, sheets_type3 = -1;
  int64_t subsheets_of_largest_self_intersecting = -1;
  int64_t vsg_edges = -1, wireframe_edges = -1, wireframe_edges_simplified = -1;
  Timings timings;
};

Stats compute_stats(const Mesh& mesh, const Analysis& analysis);

}  // namespace hbc
