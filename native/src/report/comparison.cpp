#include "hbc/comparison.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "hbc/analysis.hpp"
#include "hbc/cell_quality.hpp"
#include "hbc/report.hpp"
#include "hbc/version.hpp"

namespace hbc {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// A histogram indexed by value (valence, face count) as {"value": count} without the empty bins.
Json by_value(const std::vector<int64_t>& hist) {
  Json j = Json::object();
  for (size_t i = 0; i < hist.size(); ++i)
    if (hist[i] != 0) j[std::to_string(i)] = hist[i];
  return j;
}

// Scaled Jacobian histograms per cell type, with the bins of QualitySummary (20 bins of 0.1 over
// [-1, 1]; below -1 to the first, 1.0 to the last), for the report's per-type histograms.
Json sj_histograms(const Mesh& mesh, const Threads& threads) {
  const std::vector<double> sj = scaled_jacobians(mesh, threads);
  std::vector<std::vector<int64_t>> bins(5, std::vector<int64_t>(20, 0));
  std::vector<int64_t> count(5, 0);
  for (size_t c = 0; c < sj.size(); ++c) {
    const int t = static_cast<int>(mesh.cell_type[c]);
    const double v = std::isfinite(sj[c]) ? sj[c] : -1.0;
    const int b = std::clamp(static_cast<int>(std::floor((v + 1.0) / 0.1 + 1e-9)), 0, 19);
    ++bins[t][b];
    ++count[t];
  }
  Json by_type = Json::object();
  for (int t = 0; t < 5; ++t)
    if (count[t] > 0) by_type[cell_type_name(static_cast<CellType>(t))] = bins[t];
  return by_type;
}

// The value of group.key in a column (NaN when the column failed or the value is null).
double value_of(const ComparisonColumn& c, const MetricField& f) {
  if (!c.error.empty()) return std::nan("");
  const Json& v = c.metrics.at(std::string(f.group)).at(std::string(f.key));
  return v.is_number() ? v.get<double>() : std::nan("");
}

std::string field_key(const MetricField& f) { return std::string(f.group) + "." + std::string(f.key); }

Json field_json(const MetricField& f) {
  return {{"key", field_key(f)}, {"group", std::string(f.group)}, {"label", std::string(f.label)},
          {"unit", std::string(f.unit)}, {"meaning", std::string(f.meaning)},
          {"refinement", refinement_name(f.refinement)}};
}

std::string latex_escaped(const std::string& s) {
  std::string o;
  for (char ch : s) {
    switch (ch) {
      case '\\': o += "\\textbackslash{}"; break;
      case '~': o += "\\textasciitilde{}"; break;
      case '^': o += "\\textasciicircum{}"; break;
      case '&': case '%': case '$': case '#': case '_': case '{': case '}': o += '\\'; o += ch; break;
      default: o += ch;
    }
  }
  return o;
}

// A cell of the LaTeX table: counts as integers with thin-space thousands, ratios with 3 decimals.
std::string latex_number(double v, const MetricField& f) {
  if (!std::isfinite(v)) return "--";
  char buf[48];
  if (f.unit == "ratio" || v != std::floor(v)) {
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.0f", std::fabs(v));
  std::string digits = buf, o;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) o += "\\,";
    o += digits[i];
  }
  return (v < 0 ? "-" : "") + o;
}

// The headings of docs/metrics.md's groups.
constexpr const char* kGroupTitles[][2] = {{"census", "Census"},
                                           {"singular", "Singular structure"},
                                           {"complex", "Hybrid base complex"},
                                           {"sheets", "Sheets"},
                                           {"non_hex", "Non-hex clustering"},
                                           {"quality", "Quality beside structure"},
                                           {"summary", "Summary"}};

std::string group_title(std::string_view g) {
  for (const auto& t : kGroupTitles)
    if (g == t[0]) return t[1];
  return std::string(g);
}

}  // namespace

Json metrics_json(const std::string& file, const Metrics& m, const Json& timings) {
  Json j = {{"file", file}};
  const auto fields = metric_fields();
  for (size_t i = 0; i < fields.size(); ++i) {
    Json& group = j[std::string(fields[i].group)];
    const double v = m.values[i];
    // Counts and ids as integers, so that JSON readers see 12 rather than 12.0.
    if (std::isfinite(v) && fields[i].unit != "ratio" && v == std::floor(v) && std::fabs(v) < 9e15)
      group[std::string(fields[i].key)] = static_cast<int64_t>(v);
    else
      group[std::string(fields[i].key)] = v;
  }
  j["census"]["polyhedra_by_faces"] = by_value(m.polyhedra_by_faces);
  j["singular"]["valence_interior"] = by_value(m.singular_valence_interior);
  j["singular"]["valence_boundary"] = by_value(m.singular_valence_boundary);
  j["singular"]["singularity_edges"] = m.singularity_edges;
  j["complex"]["component_cells"] = m.component_cells;
  j["sheets"]["subsheets_per_sheet"] = m.subsheets_per_sheet;
  j["non_hex"]["region_cells"] = m.non_hex_region_cells;
  Json& summary = j["summary"];
  summary["vector"] = m.summary_vector;
  summary["vector_keys"] = Json::array();
  for (std::string_view k : summary_fields()) summary["vector_keys"].push_back(std::string(k));
  // The deprecated keys (metric_aliases) beside the new ones, for readers of the old names.
  for (const MetricAlias& a : metric_aliases()) {
    Json& g = j[std::string(a.group)];
    if (g.contains(std::string(a.key))) g[std::string(a.old_key)] = Json(g[std::string(a.key)]);
  }
  j["timings"] = timings;
  return j;
}

Json comparison_measurement(const Mesh& mesh, const std::string& file, int threads, double load_seconds,
                            bool skip_invalid, const std::vector<DroppedCell>& dropped) {
  AnalysisOptions opt;
  opt.threads = threads;
  opt.wireframe = false;  // no metric reads the wireframe
  Threads split;
  split.count = threads;
  const auto t0 = Clock::now();
  const Analysis analysis = analyze(mesh, opt);
  const double t_analysis = seconds_since(t0);
  const auto t1 = Clock::now();
  const Metrics m = compute_metrics(mesh, analysis, split);
  const Json timings = {{"load", load_seconds}, {"analysis", t_analysis}, {"metrics", seconds_since(t1)}};
  Json out = {{"metrics", metrics_json(file, m, timings)}, {"scaled_jacobian_by_type", sj_histograms(mesh, split)}};
  add_dropped_json(out, skip_invalid, dropped);
  return out;
}

std::vector<ComparisonColumn> comparison_columns(const std::vector<std::string>& files,
                                                 const std::vector<std::string>& names) {
  if (!names.empty() && names.size() != files.size())
    throw std::invalid_argument("--names gives " + std::to_string(names.size()) + " names for " +
                                std::to_string(files.size()) + " files");
  std::vector<ComparisonColumn> cols(files.size());
  std::set<std::string> seen;
  for (size_t i = 0; i < cols.size(); ++i) {
    cols[i].file = files[i];
    std::string n = names.empty() ? std::filesystem::path(files[i]).filename().string() : names[i];
    // Two files of one name (a.mesh in two folders) stay two columns.
    const std::string base = n;
    for (int k = 2; seen.count(n); ++k) n = base + " (" + std::to_string(k) + ")";
    seen.insert(n);
    cols[i].name = n;
  }
  return cols;
}

void set_measurement(ComparisonColumn& c, const std::string& text) {
  try {
    Json doc = Json::parse(text);
    c.metrics = std::move(doc.at("metrics"));
    c.sj_by_type = std::move(doc.at("scaled_jacobian_by_type"));
    if (doc.contains("dropped")) c.dropped = std::move(doc.at("dropped"));
  } catch (const std::exception& e) {
    c.metrics = c.sj_by_type = c.dropped = Json();
    c.error = std::string("unreadable result: ") + e.what();
  }
}

Json comparison_json(const std::vector<ComparisonColumn>& cols, bool skip_invalid) {
  Json j = {{"hbc_version", version()}};
  Json& meshes = j["meshes"] = Json::array();
  for (const ComparisonColumn& c : cols) {
    meshes.push_back({{"name", c.name}, {"file", c.file}, {"error", c.error.empty() ? Json() : Json(c.error)}});
    if (skip_invalid) meshes.back()["dropped"] = c.dropped;
  }
  Json& fields = j["fields"] = Json::array();
  Json& values = j["values"] = Json::object();
  for (const MetricField& f : metric_fields()) {
    fields.push_back(field_json(f));
    Json& row = values[field_key(f)] = Json::array();
    for (const ComparisonColumn& c : cols) {
      // The measurement's own JSON number (integer or double), so values equal `hbc metrics --json`.
      if (c.error.empty()) row.push_back(c.metrics.at(std::string(f.group)).at(std::string(f.key)));
      else row.push_back(nullptr);
    }
  }
  // The deprecated keys (metric_aliases) too, for readers of the old names.
  for (const MetricAlias& a : metric_aliases()) {
    const std::string key = std::string(a.group) + "." + std::string(a.key);
    if (values.contains(key)) values[std::string(a.group) + "." + std::string(a.old_key)] = Json(values[key]);
  }
  Json& per_mesh = j["metrics"] = Json::array();
  for (const ComparisonColumn& c : cols) per_mesh.push_back(c.error.empty() ? c.metrics : Json());
  Json& sj = j["scaled_jacobian_histograms"];
  sj["bin_edges"] = Json::array();
  for (int i = 0; i <= 20; ++i) sj["bin_edges"].push_back(std::round((-1.0 + 0.1 * i) * 10) / 10);
  sj["by_type"] = Json::array();
  for (const ComparisonColumn& c : cols) sj["by_type"].push_back(c.error.empty() ? c.sj_by_type : Json());
  Json& errors = j["errors"] = Json::object();
  for (const ComparisonColumn& c : cols)
    if (!c.error.empty()) errors[c.name] = c.error;
  return j;
}

std::string comparison_csv(const std::vector<ComparisonColumn>& cols) {
  std::string out = "name,mesh";
  for (const MetricField& f : metric_fields()) out.append(",").append(field_key(f));
  // The deprecated columns (metric_aliases) after the others, before the error.
  std::vector<const MetricField*> aliased;
  for (const MetricAlias& a : metric_aliases())
    if (const int i = metric_index(a.group, a.key); i >= 0) {
      out.append(",").append(a.group).append(".").append(a.old_key);
      aliased.push_back(&metric_fields()[static_cast<size_t>(i)]);
    }
  out += ",error\n";
  // Appended piece by piece: `"," + text` makes g++ 12 warn wrongly (-Wrestrict).
  for (const ComparisonColumn& c : cols) {
    out.append(csv_quoted(c.name)).append(",").append(csv_quoted(c.file));
    for (const MetricField& f : metric_fields()) out.append(",").append(number_text(value_of(c, f)));
    for (const MetricField* f : aliased) out.append(",").append(number_text(value_of(c, *f)));
    out.append(",").append(csv_quoted(c.error)).append("\n");
  }
  return out;
}

// A failed mesh's column shows "failed" and its error in the notes under the table.
std::string comparison_tex(const std::vector<ComparisonColumn>& cols) {
  const size_t ncol = 2 + cols.size();
  std::string o = "% hbc compare (hbc " + std::string(version()) + "): needs \\usepackage{booktabs}\n";
  o += "\\begin{table}[t]\n\\centering\n\\small\n\\begin{tabular}{ll" + std::string(cols.size(), 'r') + "}\n";
  o += "\\toprule\nMetric & Unit";
  for (const ComparisonColumn& c : cols) o += " & " + latex_escaped(c.name);
  o += " \\\\\n";
  std::string_view group;
  for (const MetricField& f : metric_fields()) {
    if (f.group != group) {
      group = f.group;
      o += "\\midrule\n\\multicolumn{" + std::to_string(ncol) + "}{l}{\\emph{" + group_title(group) + "}} \\\\\n";
    }
    o += latex_escaped(std::string(f.label)) + " & " + (f.unit == "ratio" ? std::string() : latex_escaped(std::string(f.unit)));
    for (const ComparisonColumn& c : cols)
      o += " & " + (c.error.empty() ? latex_number(value_of(c, f), f) : std::string("failed"));
    o += " \\\\\n";
  }
  o += "\\bottomrule\n";
  for (const ComparisonColumn& c : cols)
    if (!c.error.empty())
      o += "\\multicolumn{" + std::to_string(ncol) + "}{l}{\\footnotesize " + latex_escaped(c.name) +
           ": " + latex_escaped(c.error) + "} \\\\\n";
  o += "\\end{tabular}\n\\caption{Structural metrics (hbc compare; definitions in docs/metrics.md).}\n"
       "\\label{tab:hbc-compare}\n\\end{table}\n";
  return o;
}

}  // namespace hbc
