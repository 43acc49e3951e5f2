// Timings of the analysis stages (load excluded): hybrid singularity graph + base complex (T_GS +
// T_GB), sheets (T_GSH), subsheets of every self-intersecting sheet (T_GSH*), the whole-mesh VSG
// wireframe at the complex level (view + graph + style, T_VSGW), on the paper's meshes we hold and
// on generated hex-dominant meshes of 10^4..10^6 cells, so that growth with the cell count is
// measured in one run. HBC_BENCH_LARGE=1 adds the 10^7-cell cylinder and split grid (about 2.5 GB
// each, loaded once).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "hbc/analysis.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/cell_depth.hpp"
#include "hbc/cell_quality.hpp"
#include "hbc/generate.hpp"
#include "hbc/io.hpp"
#include "hbc/wireframe_style.hpp"

namespace {

using namespace hbc;

// Meshes are loaded once per process and kept for all benchmarks that use them.
const Mesh& mesh_named(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Mesh>> cache;
  auto& slot = cache[name];
  if (!slot) {
    if (name.rfind("cyl", 0) == 0) {  // cylR_L: radius R cells, L layers
      const auto us = name.find('_');
      slot = std::make_unique<Mesh>(build_mesh(generate_cylinder(std::stoi(name.substr(3, us - 3)), std::stoi(name.substr(us + 1)))));
    } else if (name.rfind("split", 0) == 0) {
      const int n = std::stoi(name.substr(5));  // cells per axis
      const auto cells = random_cells(n, n, n, n * n * n / 100, 1);
      slot = std::make_unique<Mesh>(build_mesh(generate_split(n, n, n, SplitKind::Pyramids, cells)));
    } else {
      slot = std::make_unique<Mesh>(load_mesh(std::string(HBC_DATA_DIR) + "/hybrid-base-complex/" + name));
    }
  }
  return *slot;
}

void set_counters(benchmark::State& st, const Mesh& m) {
  st.counters["cells"] = static_cast<double>(m.num_cells());
  st.counters["cells_per_s"] =
      benchmark::Counter(static_cast<double>(m.num_cells()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_GraphAndComplex(benchmark::State& st, const std::string& name) {
  const Mesh& m = mesh_named(name);
  for (auto _ : st) {
    SingularityGraph g = singularity_graph(m);
    BaseComplex bc = base_complex(m, g);
    benchmark::DoNotOptimize(bc.cell_component.data());
  }
  set_counters(st, m);
}

void BM_Sheets(benchmark::State& st, const std::string& name) {
  const Mesh& m = mesh_named(name);
  const SingularityGraph g = singularity_graph(m);
  const BaseComplex bc = base_complex(m, g);
  for (auto _ : st) {
    SheetDomain d = sheet_domain(m, bc, Level::Complex);
    Sheets s = extract_sheets(m, d);
    benchmark::DoNotOptimize(s.classes.data());
  }
  set_counters(st, m);
}

void BM_Subsheets(benchmark::State& st, const std::string& name) {
  const Mesh& m = mesh_named(name);
  const SingularityGraph g = singularity_graph(m);
  const BaseComplex bc = base_complex(m, g);
  const SheetDomain d = sheet_domain(m, bc, Level::Complex);
  const Sheets s = extract_sheets(m, d);
  for (auto _ : st) {
    size_t total = 0;
    for (size_t i = 0; i < s.size(); ++i)
      if (s.classes[i].type3) total += decompose_sheet(d, s, static_cast<int32_t>(i)).size();
    benchmark::DoNotOptimize(total);
  }
  set_counters(st, m);
}

// The whole-mesh VSG wireframe as a viewer gets it: the base complex as a coarse mesh, the graph
// (analyze()'s stage) and its style (the render layer's step), as the history of T_VSGW measured.
void BM_Wireframe(benchmark::State& st, const std::string& name) {
  const Mesh& m = mesh_named(name);
  const BaseComplex bc = base_complex(m, singularity_graph(m));
  for (auto _ : st) {
    const CellComplex cx = complex_from_base(m, bc);
    VsgWireframe w = vsg_wireframe(cx);
    WireframeStyle style = wireframe_style(cx, w);
    benchmark::DoNotOptimize(w.polylines.items.data());
    benchmark::DoNotOptimize(style.color.data());
  }
  set_counters(st, m);
}

// Per-cell scaled Jacobian and edge ratio, then cell depth (the add-on's filter attributes).
void BM_Quality(benchmark::State& st, const std::string& name) {
  const Mesh& m = mesh_named(name);
  for (auto _ : st) {
    CellQuality q = cell_quality(m);
    benchmark::DoNotOptimize(q.scaled_jacobian.data());
  }
  set_counters(st, m);
}

void BM_Depth(benchmark::State& st, const std::string& name) {
  const Mesh& m = mesh_named(name);
  for (auto _ : st) {
    std::vector<int32_t> d = cell_depth(m);
    benchmark::DoNotOptimize(d.data());
  }
  set_counters(st, m);
}

const char* kPaper[] = {"teapot.hedra", "twistcube_s.mesh", "cube_twist-comp.obj.HYBRID"};
// Hex-dominant cylinders with prism columns (like the paper's teaser) of ~1e4, ~1e5, ~1e6 cells,
// and the worst case for the base complex: grids with 1% of the cells, at random, cut into
// pyramids, whose separation planes then cut every cell into a component of its own.
const char* kGenerated[] = {"cyl8_42", "cyl16_107", "cyl40_174", "split22", "split47", "split100"};
// 10^7 cells: the cylinder of the issue (radius 160, 110 layers) and a 216^3 split grid.
const char* kLarge[] = {"cyl160_110", "split216"};

void register_generated(const char* n) {
  benchmark::RegisterBenchmark((std::string("GraphAndComplex/") + n).c_str(), BM_GraphAndComplex, n)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark((std::string("Sheets/") + n).c_str(), BM_Sheets, n)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark((std::string("Subsheets/") + n).c_str(), BM_Subsheets, n)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark((std::string("Wireframe/") + n).c_str(), BM_Wireframe, n)->Unit(benchmark::kMillisecond);
}

int register_all() {
  for (const char* n : kPaper) {
    benchmark::RegisterBenchmark((std::string("GraphAndComplex/") + n).c_str(), BM_GraphAndComplex, n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("Sheets/") + n).c_str(), BM_Sheets, n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("Subsheets/") + n).c_str(), BM_Subsheets, n)->Unit(benchmark::kMillisecond);
  }
  for (const char* n : kGenerated) register_generated(n);
  if (const char* large = std::getenv("HBC_BENCH_LARGE"); large && std::string(large) == "1")
    for (const char* n : kLarge) register_generated(n);
  for (const char* n : {"teapot.hedra", "split100"}) {
    benchmark::RegisterBenchmark((std::string("Quality/") + n).c_str(), BM_Quality, n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("Depth/") + n).c_str(), BM_Depth, n)->Unit(benchmark::kMillisecond);
  }
  return 0;
}
const int registered = register_all();

}  // namespace

BENCHMARK_MAIN();
