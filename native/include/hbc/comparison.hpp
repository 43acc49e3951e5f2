#pragma once
// What `hbc compare` writes (docs/compare.md), one writer for every front end: the CLI (one child
// process per mesh) and the Python package (hbc.compare: one work unit per mesh on any
// concurrent.futures executor) measure each mesh with comparison_measurement, hand its JSON text
// back, and write the same metrics.json, metrics.csv and metrics.tex from the columns.
#include <string>
#include <vector>

#include "hbc/check.hpp"
#include "hbc/json.hpp"
#include "hbc/mesh.hpp"
#include "hbc/metrics.hpp"
#include "hbc/threads.hpp"

namespace hbc {

// `hbc metrics --json`'s object: {"file", one object per metric group (keys of metric_fields())
// with its distributions, "summary", "timings"}; counts as JSON integers.
Json metrics_json(const std::string& file, const Metrics& m, const Json& timings);

// One mesh measured for a comparison: the analysis of `hbc metrics` (no wireframe, the authors'
// subsheet rule) on `threads` (AnalysisOptions::threads: 0 for HBC_THREADS, else every core), then
// {"metrics": metrics_json(file, ..., {"load", "analysis", "metrics"} seconds),
//  "scaled_jacobian_by_type": {cell type: 20 counts over [-1, 1]}} and, with skip_invalid,
// "dropped" (what the load dropped, as `hbc analyze --skip-invalid --json` says it).
Json comparison_measurement(const Mesh& mesh, const std::string& file, int threads, double load_seconds,
                            bool skip_invalid, const std::vector<DroppedCell>& dropped);

// One column of a comparison: a mesh and its measurement, or why it has none.
struct ComparisonColumn {
  std::string name, file;
  Json metrics;       // the measurement's "metrics" (null when it failed)
  Json sj_by_type;    // its "scaled_jacobian_by_type"
  Json dropped;       // its "dropped" (null without skip_invalid or when it failed)
  std::string error;  // empty when the mesh was measured
};

// The columns of `files` named by `names` (one per file; empty: the file names), a repeated name
// made unique with " (2)", " (3)", ... Throws std::invalid_argument when the counts differ.
std::vector<ComparisonColumn> comparison_columns(const std::vector<std::string>& files,
                                                 const std::vector<std::string>& names);
// Fills a column from the JSON text of comparison_measurement's document (as a child process or a
// worker hands it back); text that is not such a document becomes the column's error
// ("unreadable result: ...").
void set_measurement(ComparisonColumn& column, const std::string& text);

// metrics.json: {"hbc_version", "meshes", "fields", "values", "metrics",
// "scaled_jacobian_histograms", "errors"} (docs/compare.md); "dropped" per mesh with skip_invalid.
Json comparison_json(const std::vector<ComparisonColumn>& columns, bool skip_invalid);
// metrics.csv: one row per mesh, `hbc metrics --csv`'s columns between its name and its error.
std::string comparison_csv(const std::vector<ComparisonColumn>& columns);
// metrics.tex: a booktabs table, one column per mesh, one row per metric grouped as in metrics.md.
std::string comparison_tex(const std::vector<ComparisonColumn>& columns);

}  // namespace hbc
