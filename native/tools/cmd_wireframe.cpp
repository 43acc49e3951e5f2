// hbc wireframe: the VSG wireframe (SPEC §4) of a whole mesh or of one sheet, as JSON (polylines
// with colours, opacities and simplification flags) or as OBJ line objects, one per colour class.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "hbc/base_complex.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/sheets.hpp"
#include "hbc/singularity_graph.hpp"
#include "hbc/vsg_wireframe.hpp"

namespace hbc::cli {
namespace {

const char* kUsage =
    "usage: hbc wireframe FILE [--level complex|mesh] [--rho R] [--sheet N] [--all] [--json|--obj]\n"
    "                          [-o OUT] [--format F]\n"
    "  --level   complex (default, the paper's) or mesh\n"
    "  --sheet N restrict to sheet N (complex-level sheets) and its adjacent non-hex cells\n"
    "  --all     OBJ: also write the hidden (non-important) edges\n";

const char* stop_name(TraceStop s) {
  switch (s) {
    case TraceStop::None: return "none";
    case TraceStop::VsgVertex: return "vsg_vertex";
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

std::string json_text(const Mesh& m, const std::string& file, Level level, int sheet,
                      const WireframeOptions& opt, const VsgWireframe& w, double seconds) {
  std::string o = "{\n";
  auto key = [&](const char* k) { (o += "  \"") += k, o += "\": "; };
  key("file");
  o += "\"";
  for (char c : file) {
    if (c == '"' || c == '\\') o += '\\';
    o += c;
  }
  o += "\",\n";
  key("level"), o += std::string("\"") + level_name(level) + "\",\n";
  key("sheet"), o += std::to_string(sheet) + ",\n";
  key("rho"), append_real(o, opt.rho), o += ",\n";
  key("opacity_floor"), append_real(o, opt.opacity_floor), o += ",\n";
  key("palette_size"), o += std::to_string(opt.palette_size) + ",\n";
  key("vsg_edges"), o += std::to_string(w.vsg_edges) + ",\n";
  key("vsg_chains"), o += std::to_string(w.vsg_chains) + ",\n";
  key("singular_vertices"), o += std::to_string(w.singular_vertices.size()) + ",\n";
  key("wireframe_edges"), o += std::to_string(w.wireframe_edges()) + ",\n";
  key("wireframe_edges_simplified"), o += std::to_string(w.wireframe_edges_simplified()) + ",\n";
  key("reference_components"), o += std::to_string(w.reference_components) + ",\n";
  key("shown_components"), o += std::to_string(w.shown_components) + ",\n";
  key("seconds_vsg_wireframe"), append_real(o, seconds), o += ",\n";
  key("edges"), o += "[";
  for (size_t i = 0; i < w.size(); ++i) {
    o += i ? ",\n    {" : "\n    {";
    o += "\"kind\": \"";
    o += w.kind[i] == WireKind::Vsg ? "vsg" : "trace";
    o += "\", \"valence\": " + std::to_string(w.valence[i]);
    o += ", \"stop\": \"" + std::string(stop_name(w.stop[i])) + "\"";
    o += ", \"non_important\": " + std::to_string(int(w.non_important[i]));
    o += std::string(", \"reactivated\": ") + (w.reactivated[i] ? "true" : "false");
    o += std::string(", \"shown\": ") + (w.shown[i] ? "true" : "false");
    o += ", \"color_class\": " + std::to_string(w.color_class[i]);
    o += ", \"color\": " + std::to_string(w.color[i]);
    o += ", \"vertices\": [";
    const auto poly = w.polylines[i];
    for (size_t k = 0; k < poly.size(); ++k) {
      if (k) o += ',';
      o += std::to_string(poly[k]);
    }
    o += "], \"points\": [";
    for (size_t k = 0; k < poly.size(); ++k)
      for (int d = 0; d < 3; ++d) {
        if (k || d) o += ',';
        append_real(o, m.points[3 * static_cast<size_t>(poly[k]) + d]);
      }
    o += "], \"opacity\": [";
    for (int32_t k = w.polylines.offsets[i]; k < w.polylines.offsets[i + 1]; ++k) {
      if (k != w.polylines.offsets[i]) o += ',';
      append_real(o, w.point_opacity[k]);
    }
    o += "]}";
  }
  o += "\n  ]\n}\n";
  return o;
}

std::string obj_text(const Mesh& m, const VsgWireframe& w, bool all) {
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
    if (all || w.shown[i]) members[w.color_class[i]].push_back(static_cast<int32_t>(i));
  for (size_t c = 0; c < members.size(); ++c) {
    if (members[c].empty()) continue;
    o += "o class_" + std::to_string(c) + "_color_" + std::to_string(w.color[c]) + "\n";
    for (int32_t i : members[c]) {
      o += "l";
      for (int32_t p : w.polylines[i]) o += ' ' + std::to_string(index[p]);
      o += '\n';
    }
  }
  return o;
}

}  // namespace

int cmd_wireframe(const Args& args_in) {
  Args args = args_in;
  const bool obj = take_flag(args, "--obj");
  const bool json = take_flag(args, "--json");
  const bool all = take_flag(args, "--all");
  const Format format = take_format(args);
  const auto level_name = take_option(args, "--level");
  const auto rho = take_option(args, "--rho");
  const auto sheet_arg = take_option(args, "--sheet");
  const auto out_path = take_option(args, "-o");
  if (args.size() != 1 || (obj && json)) throw std::invalid_argument(kUsage);
  Level level = Level::Complex;
  if (level_name) {
    if (*level_name == "mesh") level = Level::Mesh;
    else if (*level_name != "complex") throw std::invalid_argument("--level is complex or mesh, not " + *level_name);
  }
  WireframeOptions opt;
  if (rho) {
    size_t used = 0;
    opt.rho = std::stod(*rho, &used);
    if (used != rho->size() || !(opt.rho >= 0.0 && opt.rho <= 1.0))
      throw std::invalid_argument("--rho takes a number in [0, 1], not " + *rho);
  }
  int sheet = -1;
  if (sheet_arg) {
    size_t used = 0;
    sheet = std::stoi(*sheet_arg, &used);
    if (used != sheet_arg->size() || sheet < 0) throw std::invalid_argument("--sheet takes a sheet number");
  }

  const Mesh m = load_for_cli(args[0], format);
  const BaseComplex bc = base_complex(m, singularity_graph(m));
  std::vector<int32_t> region_cells;
  if (sheet >= 0) {
    const Sheets sheets = extract_sheets(m, sheet_domain(m, bc, Level::Complex));
    if (static_cast<size_t>(sheet) >= sheets.size())
      throw std::invalid_argument("--sheet " + std::to_string(sheet) + ": the mesh has " +
                                  std::to_string(sheets.size()) + " sheets");
    for (auto rows : {sheets.sheet_cells[sheet], sheets.sheet_non_hex_cells[sheet]})
      region_cells.insert(region_cells.end(), rows.begin(), rows.end());
  }
  const auto t1 = std::chrono::steady_clock::now();
  CellComplex cx;
  if (level == Level::Mesh) {
    cx = sheet >= 0 ? complex_from_mesh(m, region_cells) : complex_from_mesh(m);
  } else {
    cx = sheet >= 0 ? complex_from_base(m, bc, components_of_cells(bc, region_cells)) : complex_from_base(m, bc);
  }
  const VsgWireframe w = vsg_wireframe(cx, opt);
  const auto t2 = std::chrono::steady_clock::now();

  const std::string text = obj ? obj_text(m, w, all)
                               : json_text(m, args[0], level, sheet, opt, w,
                                           std::chrono::duration<double>(t2 - t1).count());
  if (out_path) {
    std::ofstream f(*out_path, std::ios::binary);
    if (!f || !(f << text)) throw std::runtime_error("cannot write " + *out_path);
  } else {
    std::fwrite(text.data(), 1, text.size(), stdout);
  }
  return 0;
}

}  // namespace hbc::cli
