// hbc wireframe: the VSG wireframe (paper §5) of a whole mesh or of one sheet, as JSON (the complete
// wireframe's polylines with colours, opacities and simplification flags) or as OBJ line objects,
// one per colour class.
#include <CLI/CLI.hpp>
#include <chrono>
#include <memory>
#include <optional>
#include <span>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "hbc/schema.hpp"
#include "hbc/analysis.hpp"
#include "hbc/region.hpp"
#include "hbc/json.hpp"
#include "hbc/wireframe_style.hpp"

namespace hbc::cli {
namespace {

struct WireframeArgs {
  InputArgs input;
  std::string level = "complex";
  double rho = WireframeStyleOptions{}.rho;
  std::optional<int32_t> sheet;
  bool all = false, json = false, obj = false;
  std::optional<std::string> out;
};

const char* stop_name(TraceStop s) {
  switch (s) {
    case TraceStop::None: return "none";
    case TraceStop::SingularVertex: return "vsg_vertex";
    case TraceStop::Boundary: return "boundary";
    case TraceStop::NoContinuation: return "no_continuation";
  }
  return "?";
}

void append_real(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  out += buf;
}

// A chain's non-hex kinds (docs/concepts.md): each as its cell type's name and its face count.
Json non_hex_json(std::span<const int32_t> kinds) {
  Json out = Json::array();
  for (int32_t k : kinds)
    out.push_back(Json{{"type", cell_type_name(non_hex_kind_type(k))}, {"faces", non_hex_kind_faces(k)}});
  return out;
}

Json edge_json(const Mesh& m, const VsgWireframe& w, const WireframeStyle& style, size_t i) {
  const auto poly = w.polylines[i];
  Json points = Json::array();
  for (int32_t v : poly)
    for (int d = 0; d < 3; ++d) points.push_back(m.points[3 * static_cast<size_t>(v) + d]);
  const auto first = style.point_opacity.begin() + w.polylines.offsets[i];
  return {{"kind", w.kind[i] == WireKind::Vsg ? "vsg" : "trace"},
          {"valence", w.valence[i]},
          {"stop", stop_name(w.stop[i])},
          {"non_important", int(w.non_important[i])},
          {"reactivated", bool(w.reactivated[i])},
          {"shown", bool(w.shown[i])},
          {"color_class", style.color_class[i]},
          {"color", style.color[i]},
          {"vertices", Json(std::vector<int32_t>(poly.begin(), poly.end()))},
          {"points", std::move(points)},
          {"opacity", Json(std::vector<double>(first, first + static_cast<std::ptrdiff_t>(poly.size())))},
          {"non_hex", non_hex_json(w.non_hex[i])}};
}

// The simplified wireframe's polylines (mesh vertices) with their non-hex kinds.
Json simplified_json(const VsgWireframe& w) {
  Json out = Json::array();
  for (size_t i = 0; i < w.simplified_polylines.rows(); ++i) {
    const auto poly = w.simplified_polylines[i];
    out.push_back(Json{{"vertices", Json(std::vector<int32_t>(poly.begin(), poly.end()))},
                       {"non_hex", non_hex_json(w.simplified_non_hex[i])}});
  }
  return out;
}

std::string json_text(const Mesh& m, const WireframeArgs& args, const WireframeStyleOptions& opt, const VsgWireframe& w,
                      const WireframeStyle& style, double seconds) {
  Json edges = Json::array();
  for (size_t i = 0; i < w.size(); ++i) edges.push_back(edge_json(m, w, style, i));
  Json j = {{"file", args.input.file},
            {"level", args.level},
            {"sheet", args.sheet.value_or(-1)},
            {"rho", opt.rho},
            {"opacity_floor", opt.opacity_floor},
            {"palette_size", opt.palette_size}};
  const auto counts = wireframe_count_fields();
  for (size_t i = 0; i < counts.size(); ++i) j[std::string(counts[i].key)] = wireframe_count(w, i);
  for (const FieldAlias& a : wireframe_count_aliases()) j[std::string(a.old_key)] = Json(j[std::string(a.key)]);
  j["seconds_vsg_wireframe"] = seconds;
  j["edges"] = std::move(edges);
  j["simplified_polylines"] = simplified_json(w);
  return hbc::json_text(j);
}

std::string obj_text(const Mesh& m, const VsgWireframe& w, const WireframeStyle& style, bool all) {
  std::string o = "# hbc wireframe: one object per colour class; l = polylines of mesh vertices\n";
  std::vector<int32_t> index(m.num_vertices(), 0);
  int32_t n = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    if (!all && !w.shown[i]) continue;
    for (int32_t p : w.polylines[i]) {
      if (index[p]) continue;
      index[p] = ++n;
      o += "v";
      for (int d = 0; d < 3; ++d) (o += ' '), append_real(o, m.points[3 * static_cast<size_t>(p) + d]);
      o += '\n';
    }
  }
  // Classes in order of their id (the lowest wire edge), each wire edge listed under its class.
  std::vector<std::vector<int32_t>> members(w.size());
  for (size_t i = 0; i < w.size(); ++i)
    if (all || w.shown[i]) members[style.color_class[i]].push_back(static_cast<int32_t>(i));
  for (size_t c = 0; c < members.size(); ++c) {
    if (members[c].empty()) continue;
    o += "o class_" + std::to_string(c) + "_color_" + std::to_string(style.color[c]) + "\n";
    for (int32_t i : members[c]) {
      o += "l";
      for (int32_t p : w.polylines[i]) o += ' ' + std::to_string(index[p]);
      o += '\n';
    }
  }
  return o;
}

void run_wireframe(const WireframeArgs& args) {
  const Mesh m = load_for_cli(args.input);
  // --sheet picks a complex-level sheet at either level (the paper's sheets).
  const AnalysisOptions analysis_opt = analysis_options(
      args.input, {{"sheets", args.sheet.has_value()}, {"subsheets", false}, {"wireframe", false}});
  const Analysis a = analyze(m, analysis_opt);
  check_sheet_option(a, args.sheet);
  WireframeStyleOptions opt;
  opt.rho = args.rho;
  // The time of what this command computes: the wireframe and its style.
  const auto t1 = std::chrono::steady_clock::now();
  const WireframeStage st = region_wireframe_stage(m, a, level_from_name(args.level), {}, args.sheet);
  const WireframeStyle style = wireframe_style(st.view, st.wireframe, opt);
  const auto t2 = std::chrono::steady_clock::now();
  write_output(args.obj ? obj_text(m, st.wireframe, style, args.all)
                        : json_text(m, args, opt, st.wireframe, style, std::chrono::duration<double>(t2 - t1).count()),
               args.out);
}

}  // namespace

void add_wireframe(CLI::App& app) {
  auto args = std::make_shared<WireframeArgs>();
  CLI::App* cmd = add_mesh_command(app, "wireframe", "VSG wireframe (paper §5) of the mesh or of one sheet", args->input,
                                   args->json, "JSON: polylines with colours, opacities, flags (the default)");
  add_level(*cmd, args->level, "complex (the paper's) or mesh");
  cmd->add_option("--rho", args->rho, "partial-parallel threshold of the colour classes (presentation only)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  add_sheet_option(*cmd, args->sheet, "restrict to sheet N (complex-level sheets) and its adjacent non-hex cells");
  cmd->add_flag("--obj", args->obj, "OBJ line objects, one per colour class")->excludes("--json");
  cmd->add_flag("--all", args->all, "OBJ: every chain of the complete wireframe, not only those on the simplified one");
  cmd->add_option("-o", args->out, "output file (default: stdout)");
  cmd->callback([args] { run_wireframe(*args); });
}

}  // namespace hbc::cli
