#pragma once
// What hbc reports, described once. Each reported number has a key (a contract: the JSON key and
// the CSV column; a renamed key keeps its old name as an alias), a label in words, the paper's
// notation where its Table 1 has a column for it, a one-line meaning and a unit. The CLI's text,
// JSON, CSV, Markdown and LaTeX output, the Python binding (hbc.STAT_FIELDS, Analysis.stats()) and
// the Blender add-on's panel read these lists instead of retyping them; docs/concepts.md defines
// the concepts behind them.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "hbc/analysis.hpp"

namespace hbc {

// Count: a whole number of its unit; Ratio: a share or a ratio; Seconds: a time; Value: another real
// number in its unit (a mean).
enum class FieldKind : uint8_t { Count, Ratio, Seconds, Value };

struct Field {
  std::string_view key;       // JSON key, CSV column
  std::string_view label;     // in words, for panels and the text output ("Sheets")
  std::string_view notation;  // the paper's Table 1 symbol ("|G_SH|"); empty when it has none
  std::string_view latex;     // the same in LaTeX ("$|G_{SH}|$"); empty when it has none
  std::string_view meaning;   // one line
  std::string_view unit;      // what is counted ("cells", "edges", ...), "ratio" or "s"
  FieldKind kind;
};

// The statistics of an analysis (Stats), in output order.
std::span<const Field> stat_fields();
// The value of stat_fields()[i] in s; nothing when the stage that counts it did not run.
std::optional<double> stat_value(const Stats& s, size_t i);

// The stages' wall-clock times (Timings): in JSON under "timings" by key, in CSV as "t_" + key.
std::span<const Field> timing_fields();
double timing_value(const Timings& t, size_t i);

// The columns of the paper's Table 1 in its order. Each is a stat field or a timing field.
struct Table1Column {
  const Field* field;
  bool timing;  // a timing_fields() entry (CSV key "t_" + key), else a stat_fields() one
};
std::span<const Table1Column> table1_columns();

// The counts of a VSG wireframe (`hbc wireframe --json`, Wireframe.counts in Python).
std::span<const Field> wireframe_count_fields();
int64_t wireframe_count(const VsgWireframe& w, size_t i);

// A key renamed to the word of docs/concepts.md; its old key stays, deprecated, written beside the
// new one with the same value.
struct FieldAlias {
  std::string_view old_key;  // deprecated
  std::string_view key;      // the glossary's word
};
std::span<const FieldAlias> wireframe_count_aliases();

// The field of `fields` with this key; nullptr when there is none.
const Field* find_field(std::span<const Field> fields, std::string_view key);

const char* field_kind_name(FieldKind k);

}  // namespace hbc
