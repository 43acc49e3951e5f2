#pragma once
// Structural complexity metrics of a hex-dominant mesh (docs/metrics.md): the census of cell types,
// the singular structure, the hybrid base complex, the sheets, how the non-hex cells cluster, the
// scaled Jacobian beside the structure, and one summary that does not change under uniform
// refinement. A pure function of the mesh and its analysis.
//
// Every scalar is described once in metric_fields() (key, label, unit, meaning and how it behaves
// under uniform refinement), in the style of schema.hpp: the CLI's text, JSON and CSV, the Python
// binding and docs/metrics.md read that list, and a comparison of meshes can too.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/mesh.hpp"
#include "hbc/schema.hpp"
#include "hbc/threads.hpp"

namespace hbc {

// How a metric changes when every cell is split into 8 (hex into 8 hexes, prism into 8 prisms):
// unchanged, times 8 (cell counts), times 2 (lengths counted in mesh edges, edge counts), times 4
// (face counts), or no rule (geometry-dependent: quality, boundary shares).
enum class Refinement : uint8_t { Invariant, Cells, Edges, Faces, None };
const char* refinement_name(Refinement r);  // "invariant", "x8", "x2", "x4", "none"

// A metric is a reported number like the statistics (a Field of schema.hpp: key, label, notation,
// meaning, unit, kind) that also has a group and a rule under refinement.
struct MetricField : Field {
  std::string_view group;    // census, singular, complex, sheets, non_hex, quality, summary; the JSON
                             // key is group.key, the CSV column "group.key"
  Refinement refinement;
};

// Every scalar metric in output order.
std::span<const MetricField> metric_fields();
// A key renamed to the word of docs/concepts.md, its old key kept as a deprecated alias: written
// beside the new key in the JSON (and as a last CSV column) and accepted by metric_index. Also the
// distributions' keys (singular.curve_edges), which are no metric_fields() entry.
struct MetricAlias {
  std::string_view group;
  std::string_view old_key;  // deprecated
  std::string_view key;      // the glossary's word
};
std::span<const MetricAlias> metric_aliases();
// The index of group.key (or of a deprecated alias) in metric_fields(); -1 when there is none.
int metric_index(std::string_view group, std::string_view key);

struct Metrics {
  // One value per metric_fields() entry; NaN where it is undefined (a stage that did not run, a
  // minimum over no cell, the worst sheet of a mesh without sheets).
  std::vector<double> values;
  // Distributions behind the scalars.
  std::vector<int64_t> polyhedra_by_faces;       // [k]: polyhedron cells with k faces
  std::vector<int64_t> singular_valence_interior;  // [v]: interior singular edges of valence v
  std::vector<int64_t> singular_valence_boundary;  // [v]: boundary singular edges of valence v
  std::vector<int32_t> singularity_edges;        // per singularity: its mesh edges
  std::vector<int32_t> component_cells;          // per component of hex cells (kind != NonHex): cells
  std::vector<int32_t> non_hex_region_cells;     // per face-connected region of non-hex cells, largest first
  std::vector<int32_t> subsheets_per_sheet;      // per decomposed (self-intersecting) sheet
  std::vector<double> summary_vector;            // the refinement-invariant vector (summary_fields())

  // The value of group.key; NaN when there is no such metric.
  double value(std::string_view group, std::string_view key) const;
};

// The names of summary_vector's entries, in order (docs/metrics.md gives the rationale).
std::span<const std::string_view> summary_fields();

struct MetricsOptions {
  // The quality group (a scaled Jacobian per cell: most of the metrics' time at 10^6 cells); off,
  // its values are NaN.
  bool quality = true;
};

// Needs the mesh's points (not a mesh given to release_unanalyzed). Sheet metrics are NaN when
// the analysis has no sheet stage. O(mesh size); the per-cell volumes and scaled Jacobians are
// split over `threads`, the same result for any count.
Metrics compute_metrics(const Mesh& mesh, const Analysis& analysis, const Threads& threads = {},
                        const MetricsOptions& options = {});

}  // namespace hbc
