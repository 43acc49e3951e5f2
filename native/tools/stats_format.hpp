#pragma once
// Table 1 statistics as JSON (SPEC §5 keys), CSV and a human-readable table.
#include <string>

#include "hbc/analysis.hpp"
#include "json.hpp"

namespace hbc::cli {

// Writes the stats keys into an open JSON object.
void write_stats_json(JsonWriter& w, const Stats& s);
std::string stats_csv_header();
std::string stats_csv_row(const std::string& name, const Stats& s);
std::string stats_table(const std::string& name, const Stats& s);

}  // namespace hbc::cli
