#pragma once
// Table 1 statistics as JSON, CSV and a human-readable table, from the schema (hbc/schema.hpp),
// and the CSV field rules the other commands' tables (hbc metrics, hbc compare) share.
#include <string>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "json.hpp"

namespace hbc::cli {

// Adds the stats keys (and "timings") to a JSON object.
void add_stats_json(Json& j, const Stats& s);
// j["dropped"]: what --skip-invalid dropped, {"count", "by_reason": {key: n}, "cells": [{"id",
// "reason", "line" or "byte"}]} (docs/check.md); nothing when `skip` is false.
void add_dropped_json(Json& j, bool skip, const std::vector<DroppedCell>& dropped);
std::string stats_csv_header();
std::string stats_csv_row(const std::string& name, const Stats& s);
std::string stats_table(const std::string& name, const Stats& s);

// A metric's value as CSV and text print it: "%.10g"; empty when it is not finite (not measured).
std::string number_text(double v);
// A CSV field (RFC 4180): quoted, with its quotes doubled, when it holds a comma, a quote, CR or LF.
std::string csv_quoted(const std::string& s);

}  // namespace hbc::cli
