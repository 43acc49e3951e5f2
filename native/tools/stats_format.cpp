#include "stats_format.hpp"

#include <cstdio>
#include <optional>

namespace hbc::cli {
namespace {

// One list of (key, value) so that JSON, CSV and the table cannot drift apart. A count of a stage
// that did not run has no value: its key is left out rather than given a fake number.
struct Field {
  const char* key;
  bool real;
  std::optional<int64_t> i;
  double d = 0;
};

std::vector<Field> fields(const Stats& s) {
  return {
      {"cells", false, s.cells},
      {"hex_ratio", true, {}, s.hex_ratio},
      {"singular_edges", false, s.singular_edges},
      {"singularities", false, s.singularities},
      {"pseudo_singular_edges", false, s.pseudo_singular_edges},
      {"non_manifold_edges", false, s.non_manifold_edges},
      {"singular_vertices", false, s.singular_vertices},
      {"components", false, s.components},
      {"hex_components", false, s.hex_components},
      {"hex_component_ratio", true, {}, s.hex_component_ratio},
      {"patches", false, s.patches},
      {"curves", false, s.curves},
      {"corners", false, s.corners},
      {"self_adjacent_faces", false, s.self_adjacent_faces},
      {"sheets", false, s.sheets},
      {"sheets_perfect", false, s.sheets_perfect},
      {"sheets_type1", false, s.sheets_type1},
      {"sheets_type2", false, s.sheets_type2},
      {"sheets_type3", false, s.sheets_type3},
      {"subsheets_of_largest_self_intersecting", false, s.subsheets_of_largest_self_intersecting},
      {"vsg_edges", false, s.vsg_edges},
      {"wireframe_edges", false, s.wireframe_edges},
      {"wireframe_edges_simplified", false, s.wireframe_edges_simplified},
  };
}

std::vector<std::pair<const char*, double>> timing_fields(const Timings& t) {
  return {{"load", t.load},
          {"singularity_graph", t.singularity_graph},
          {"base_complex", t.base_complex},
          {"sheets", t.sheets},
          {"subsheets", t.subsheets},
          {"vsg_wireframe", t.vsg_wireframe}};
}

std::string fmt_real(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

}  // namespace

void add_stats_json(Json& j, const Stats& s) {
  for (const Field& f : fields(s)) {
    if (f.real) j[f.key] = f.d;
    else if (f.i) j[f.key] = *f.i;
  }
  Json& t = j["timings"];
  for (auto [k, v] : timing_fields(s.timings)) t[k] = v;
}

std::string stats_csv_header() {
  std::string h = "mesh";
  for (const Field& f : fields(Stats{})) h.append(",").append(f.key);
  for (auto [k, v] : timing_fields(Timings{})) h.append(",t_").append(k);
  return h;
}

std::string stats_csv_row(const std::string& name, const Stats& s) {
  std::string r = name;
  for (const Field& f : fields(s)) {
    r.push_back(',');
    if (f.real) r.append(fmt_real(f.d, 4));
    else if (f.i) r.append(std::to_string(*f.i));
  }
  for (auto [k, v] : timing_fields(s.timings)) r.append(",").append(fmt_real(v, 6));
  return r;
}

std::string stats_table(const std::string& name, const Stats& s) {
  std::string out = name;
  out.push_back('\n');
  char buf[160];
  for (const Field& f : fields(s)) {
    if (!f.real && !f.i) continue;
    if (f.real) std::snprintf(buf, sizeof buf, "  %-40s %.4f\n", f.key, f.d);
    else std::snprintf(buf, sizeof buf, "  %-40s %lld\n", f.key, static_cast<long long>(*f.i));
    out += buf;
  }
  for (auto [k, v] : timing_fields(s.timings)) {
    std::snprintf(buf, sizeof buf, "  time %-35s %.3f ms\n", k, v * 1e3);
    out += buf;
  }
  return out;
}

}  // namespace hbc::cli
