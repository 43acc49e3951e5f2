// hbc generate KIND [options] -o FILE: synthetic meshes with known structure (see generate.hpp).
#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/generate.hpp"

namespace hbc::cli {
namespace {

const char* kGenerateUsage =
    "usage: hbc generate KIND [options] -o FILE [--format F]\n"
    "  grid     --size N M K [--spacing S]\n"
    "  split    --size N M K --split pyramids|prisms|tets [--axis x|y|z] [--spacing S]\n"
    "           (--cells \"i,j,k;i,j,k...\" | --random COUNT [--seed S])\n"
    "  sector   --valence N --rings R --layers L\n"
    "  cylinder --radius-cells R --layers L\n";

int to_int(const std::string& s, const std::string& what) {
  size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || used == 0 || v < -2147483647LL || v > 2147483647LL)
    throw std::invalid_argument(what + " must be an integer, got '" + s + "'");
  return static_cast<int>(v);
}

double to_real(const std::string& s, const std::string& what) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || used == 0) throw std::invalid_argument(what + " must be a number, got '" + s + "'");
  return v;
}

int required_int(Args& args, const std::string& opt) {
  auto v = take_option(args, opt);
  if (!v) throw std::invalid_argument(std::string("missing ") + opt + "\n" + kGenerateUsage);
  return to_int(*v, opt);
}

// "--size N M K": three values after the option.
std::array<int, 3> take_size(Args& args) {
  auto it = std::find(args.begin(), args.end(), "--size");
  if (it == args.end()) throw std::invalid_argument(std::string("missing --size N M K\n") + kGenerateUsage);
  if (args.end() - it < 4) throw std::invalid_argument("--size needs three values N M K");
  std::array<int, 3> s{to_int(it[1], "--size"), to_int(it[2], "--size"), to_int(it[3], "--size")};
  args.erase(it, it + 4);
  return s;
}

// "i,j,k;i,j,k": cells by grid coordinates.
std::vector<std::array<int32_t, 3>> parse_cells(const std::string& text) {
  std::vector<std::array<int32_t, 3>> out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(';', start);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(start, end - start);
    if (!item.empty()) {
      std::array<int32_t, 3> c{};
      size_t p = 0;
      for (int d = 0; d < 3; ++d) {
        size_t q = d < 2 ? item.find(',', p) : item.size();
        if (q == std::string::npos) throw std::invalid_argument("--cells entries are i,j,k, got '" + item + "'");
        c[d] = to_int(item.substr(p, q - p), "--cells coordinate");
        p = q + 1;
      }
      out.push_back(c);
    }
    start = end + 1;
  }
  if (out.empty()) throw std::invalid_argument("--cells lists no cell");
  return out;
}

}  // namespace

int cmd_generate(const Args& args_in) {
  Args args = args_in;
  if (args.empty()) throw std::invalid_argument(kGenerateUsage);
  const std::string kind = args[0];
  args.erase(args.begin());
  auto out = take_option(args, "-o");
  const Format format = take_format(args);
  if (!out) throw std::invalid_argument(std::string("missing -o FILE\n") + kGenerateUsage);
  auto spacing_opt = take_option(args, "--spacing");
  const double spacing = spacing_opt ? to_real(*spacing_opt, "--spacing") : 1.0;

  MeshInput in;
  if (kind == "grid") {
    const auto s = take_size(args);
    in = generate_grid(s[0], s[1], s[2], spacing);
  } else if (kind == "split") {
    const auto s = take_size(args);
    auto how = take_option(args, "--split");
    if (!how) throw std::invalid_argument(std::string("missing --split\n") + kGenerateUsage);
    SplitKind sk;
    if (*how == "pyramids") sk = SplitKind::Pyramids;
    else if (*how == "prisms") sk = SplitKind::Prisms;
    else if (*how == "tets") sk = SplitKind::Tets;
    else throw std::invalid_argument("--split must be pyramids, prisms or tets, got '" + *how + "'");
    auto axis_opt = take_option(args, "--axis");
    int axis = 2;
    if (axis_opt) {
      if (*axis_opt == "x") axis = 0;
      else if (*axis_opt == "y") axis = 1;
      else if (*axis_opt == "z") axis = 2;
      else throw std::invalid_argument("--axis must be x, y or z");
    }
    auto cells_opt = take_option(args, "--cells");
    auto random_opt = take_option(args, "--random");
    auto seed_opt = take_option(args, "--seed");
    if (cells_opt.has_value() == random_opt.has_value())
      throw std::invalid_argument("split needs exactly one of --cells and --random");
    std::vector<std::array<int32_t, 3>> cells;
    if (cells_opt) {
      cells = parse_cells(*cells_opt);
    } else {
      const int seed = seed_opt ? to_int(*seed_opt, "--seed") : 0;
      cells = random_cells(s[0], s[1], s[2], to_int(*random_opt, "--random"), static_cast<uint32_t>(seed));
    }
    in = generate_split(s[0], s[1], s[2], sk, cells, axis, spacing);
  } else if (kind == "sector") {
    const int valence = required_int(args, "--valence");
    const int rings = required_int(args, "--rings");
    const int layers = required_int(args, "--layers");
    in = generate_sector(valence, rings, layers);
  } else if (kind == "cylinder") {
    const int radius = required_int(args, "--radius-cells");
    const int layers = required_int(args, "--layers");
    in = generate_cylinder(radius, layers);
  } else {
    throw std::invalid_argument("unknown kind '" + kind + "'\n" + kGenerateUsage);
  }
  if (!args.empty()) throw std::invalid_argument("unexpected argument '" + args[0] + "'\n" + kGenerateUsage);

  const Mesh mesh = build_mesh(std::move(in));
  write_mesh(mesh, *out, format);
  std::printf("wrote %s: %zu vertices, %zu faces, %zu cells (%zu hex)\n", out->c_str(), mesh.num_vertices(),
              mesh.num_faces(), mesh.num_cells(), mesh.num_hex_cells());
  return 0;
}

}  // namespace hbc::cli
