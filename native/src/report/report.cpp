#include "hbc/report.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "hbc/schema.hpp"

namespace hbc {
namespace {

std::string fmt_real(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// A statistic's value as text: counts as integers, ratios with 4 decimals; empty when the stage
// that counts it did not run (its key is then left out of JSON rather than given a fake number).
std::string value_text(const Field& f, std::optional<double> v) {
  if (!v) return {};
  if (f.kind == FieldKind::Count) return std::to_string(static_cast<long long>(*v));
  return fmt_real(*v, 4);
}

}  // namespace

MeshCounts mesh_counts(const Mesh& m) {
  MeshCounts c;
  for (CellType t : m.cell_type) ++c.cell_types[static_cast<size_t>(t)];
  for (uint8_t b : m.face_boundary) c.boundary_faces += b;
  for (uint8_t b : m.vert_non_manifold) c.non_manifold_vertices += b;
  const auto nc = static_cast<double>(m.num_cells());
  c.hex_ratio = nc > 0 ? static_cast<double>(c.cell_types[0]) / nc : 0.0;
  return c;
}

Json mesh_info_json(const Mesh& m, const std::string& file) {
  const MeshCounts c = mesh_counts(m);
  Json types = Json::object();
  for (size_t t = 0; t < c.cell_types.size(); ++t) types[cell_type_name(static_cast<CellType>(t))] = c.cell_types[t];
  return {{"file", file},
          {"vertices", m.num_vertices()},
          {"edges", m.num_edges()},
          {"faces", m.num_faces()},
          {"cells", static_cast<int64_t>(m.num_cells())},
          {"hex_cells", c.cell_types[0]},
          {"hex_ratio", c.hex_ratio},
          {"cell_types", types},
          {"boundary_faces", c.boundary_faces},
          {"non_manifold_vertices", c.non_manifold_vertices},
          {"dropped_faces", m.dropped_faces},
          {"dropped_edges", m.dropped_edges}};
}

void add_stats_json(Json& j, const Stats& s) {
  const auto fields = stat_fields();
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::optional<double> v = stat_value(s, i);
    if (!v) continue;
    const std::string key(fields[i].key);
    if (fields[i].kind == FieldKind::Count) j[key] = static_cast<int64_t>(*v);
    else j[key] = *v;
  }
  Json& t = j["timings"];
  const auto timings = timing_fields();
  for (size_t i = 0; i < timings.size(); ++i) t[std::string(timings[i].key)] = timing_value(s.timings, i);
}

std::string stats_csv_header() {
  std::string h = "mesh";
  for (const Field& f : stat_fields()) h.append(",").append(f.key);
  for (const Field& f : timing_fields()) h.append(",t_").append(f.key);
  return h;
}

std::string stats_csv_row(const std::string& name, const Stats& s) {
  std::string r = csv_quoted(name);  // a path may hold a comma; the numbers never do
  const auto fields = stat_fields();
  for (size_t i = 0; i < fields.size(); ++i) r.append(",").append(value_text(fields[i], stat_value(s, i)));
  for (size_t i = 0; i < timing_fields().size(); ++i) r.append(",").append(fmt_real(timing_value(s.timings, i), 6));
  return r;
}

std::string stats_table(const std::string& name, const Stats& s) {
  std::string out = name;
  out.push_back('\n');
  char buf[160];
  const auto fields = stat_fields();
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string v = value_text(fields[i], stat_value(s, i));
    if (v.empty()) continue;
    std::snprintf(buf, sizeof buf, "  %-40s %s\n", std::string(fields[i].key).c_str(), v.c_str());
    out += buf;
  }
  const auto timings = timing_fields();
  for (size_t i = 0; i < timings.size(); ++i) {
    std::snprintf(buf, sizeof buf, "  time %-35s %.3f ms\n", std::string(timings[i].key).c_str(),
                  timing_value(s.timings, i) * 1e3);
    out += buf;
  }
  return out;
}

std::string number_text(double v) {
  if (!std::isfinite(v)) return "";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string csv_quoted(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void add_dropped_json(Json& j, bool skip, const std::vector<DroppedCell>& dropped) {
  if (!skip) return;
  Json by = Json::object(), cells = Json::array();
  for (const DroppedCell& d : dropped) {
    const char* key = defect_key(d.reason);
    by[key] = by.value(key, 0) + 1;
    Json c = {{"id", d.cell}, {"reason", key}};
    if (d.loc.line >= 0) c["line"] = d.loc.line;
    if (d.loc.byte_offset >= 0) c["byte"] = d.loc.byte_offset;
    cells.push_back(std::move(c));
  }
  j["dropped"] = {{"count", dropped.size()}, {"by_reason", by}, {"cells", cells}};
}

}  // namespace hbc
