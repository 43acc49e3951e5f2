// hbc generate KIND [options] -o FILE: synthetic meshes with known structure (see generate.hpp).
#include <CLI/CLI.hpp>
#include <array>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>

#include "commands.hpp"
#include "hbc/generate.hpp"

namespace hbc::cli {
namespace {

// The options of every kind (only the chosen kind's are parsed).
struct GenerateArgs {
  std::string out;
  std::string format;
  std::vector<int> size;  // N M K
  double spacing = 1.0;
  std::string split, axis = "z", cells;
  std::optional<int> random;
  uint32_t seed = 0;
  int valence = 0, rings = 0, layers = 0, radius_cells = 0;
  int section = 0, sections = 0, quarter_turns = 0;
  bool prisms = false, spread = false;
};

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

void write_generated(const GenerateArgs& args, MeshInput in) {
  const Mesh mesh = build_mesh(std::move(in));
  write_mesh(mesh, args.out, args.format.empty() ? Format::Auto : format_from_name(args.format));
  std::printf("wrote %s: %zu vertices, %zu faces, %zu cells (%zu hex)\n", args.out.c_str(), mesh.num_vertices(),
              mesh.num_faces(), mesh.num_cells(), mesh.num_hex_cells());
}

// --size takes up to three values so that a missing one is a usage error, not "-o" read as a size.
std::array<int, 3> size_of(const GenerateArgs& a) {
  if (a.size.size() != 3) throw CLI::ArgumentMismatch("--size", 3, a.size.size());
  return {a.size[0], a.size[1], a.size[2]};
}

MeshInput split_mesh(const GenerateArgs& a) {
  const auto s = size_of(a);
  const SplitKind kind = a.split == "pyramids" ? SplitKind::Pyramids
                         : a.split == "prisms" ? SplitKind::Prisms
                                               : SplitKind::Tets;
  const int axis = a.axis == "x" ? 0 : a.axis == "y" ? 1 : 2;
  if (a.cells.empty() && !a.random) throw std::invalid_argument("split needs one of --cells and --random");
  const auto cells = a.random ? random_cells(s[0], s[1], s[2], *a.random, a.seed) : parse_cells(a.cells);
  return generate_split(s[0], s[1], s[2], kind, cells, axis, a.spacing);
}

// One sub-subcommand per kind, each with the output options and `make` building its mesh.
CLI::App* add_kind(CLI::App& generate, const std::shared_ptr<GenerateArgs>& args, const char* name,
                   const char* help, std::function<MeshInput(const GenerateArgs&)> make) {
  CLI::App* kind = generate.add_subcommand(name, help);
  kind->add_option("-o", args->out, "output mesh file")->required();
  add_format(*kind, args->format);
  kind->callback([args, make] { write_generated(*args, make(*args)); });
  return kind;
}

void add_size(CLI::App& kind, GenerateArgs& args) {
  kind.add_option("--size", args.size, "cells along x, y and z")->required()->expected(1, 3)->check(at_least(1));
  kind.add_option("--spacing", args.spacing, "edge length")->check(CLI::Validator(
          [](std::string& v) {
            double x = 0;
            return CLI::detail::lexical_cast(v, x) && x > 0 ? std::string() : "must be a positive number, got " + v;
          },
          "POSITIVE"))
      ->capture_default_str();
}

}  // namespace

void add_generate(CLI::App& app) {
  auto args = std::make_shared<GenerateArgs>();
  CLI::App* cmd = app.add_subcommand("generate", "synthetic meshes with known structure (see generate.hpp)");
  cmd->require_subcommand(1);
  auto* grid = add_kind(*cmd, args, "grid", "an N x M x K hex grid",
                        [](const GenerateArgs& a) {
                          const auto s = size_of(a);
                          return generate_grid(s[0], s[1], s[2], a.spacing);
                        });
  add_size(*grid, *args);
  auto* split = add_kind(*cmd, args, "split", "a hex grid with chosen cells split into pyramids, prisms or tets", split_mesh);
  add_size(*split, *args);
  split->add_option("--split", args->split, "what the chosen cells become")
      ->required()
      ->check(CLI::IsMember({"pyramids", "prisms", "tets"}));
  split->add_option("--axis", args->axis, "prism axis")->check(CLI::IsMember({"x", "y", "z"}))->capture_default_str();
  auto* cells = split->add_option("--cells", args->cells, "chosen cells by grid coordinates: \"i,j,k;i,j,k...\"");
  auto* random = split->add_option("--random", args->random, "that many cells chosen at random")->check(at_least(0));
  split->add_option("--seed", args->seed, "seed of --random")->capture_default_str();
  cells->excludes(random);
  auto* sector = add_kind(*cmd, args, "sector", "hex rings around one edge of valence N",
                          [](const GenerateArgs& a) { return generate_sector(a.valence, a.rings, a.layers); });
  sector->add_option("--valence", args->valence, "valence of the central edge")->required()->check(at_least(3));
  sector->add_option("--rings", args->rings, "rings of cells around it")->required()->check(at_least(1));
  sector->add_option("--layers", args->layers, "layers along it")->required()->check(at_least(1));
  auto* cylinder = add_kind(*cmd, args, "cylinder", "a hex-dominant cylinder (prisms at the axis)",
                            [](const GenerateArgs& a) { return generate_cylinder(a.radius_cells, a.layers); });
  cylinder->add_option("--radius-cells", args->radius_cells, "cells across the radius")->required()->check(at_least(1));
  cylinder->add_option("--layers", args->layers, "layers along the axis")->required()->check(at_least(1));
  auto* ring = add_kind(*cmd, args, "twisted-ring", "a ring whose square section turns on the way round",
                        [](const GenerateArgs& a) {
                          return generate_twisted_ring(a.section, a.sections, a.quarter_turns, a.prisms, a.spread);
                        });
  ring->add_option("--section", args->section, "cells across the square section")->required()->check(at_least(1));
  ring->add_option("--sections", args->sections, "layers round the ring")->required()->check(at_least(3));
  ring->add_option("--quarter-turns", args->quarter_turns, "turns of the section, in quarter turns")
      ->check(CLI::Range(0, 3))
      ->capture_default_str();
  ring->add_flag("--prisms", args->prisms, "columns of prisms: through the middle of an odd section, else off the middle");
  ring->add_flag("--spread", args->spread, "the prism columns off the middle even in an odd section");
  auto* pair = add_kind(*cmd, args, "twisted-pair",
                        "two concentric rings turning a quarter and a half turn, a hex of each split into pyramids: "
                        "self-intersecting and self-parallel sheets",
                        [](const GenerateArgs& a) { return generate_twisted_pair(a.section, a.sections); });
  pair->add_option("--section", args->section, "cells across the square section (even)")
      ->required()
      ->check(CLI::Validator(
          [](std::string& v) {
            int x = 0;
            return CLI::detail::lexical_cast(v, x) && x >= 2 && x % 2 == 0 ? std::string()
                                                                        : "must be an even number of at least 2, got " + v;
          },
          "EVEN"));
  pair->add_option("--sections", args->sections, "layers round each ring")->required()->check(at_least(3));
}

}  // namespace hbc::cli
