#pragma once
// The `hbc metrics --json` object of one mesh, shared by `hbc metrics` and the per-mesh children
// of `hbc compare`, so that a comparison holds exactly what `hbc metrics --json` prints.
#include <string>

#include "hbc/metrics.hpp"
#include "hbc/json.hpp"

namespace hbc::cli {

// {"file", one object per metric group (keys of metric_fields()) with its distributions,
// "summary", "timings"}.
Json metrics_json(const std::string& file, const Metrics& m, const Json& timings);

}  // namespace hbc::cli
