// VSG wireframe timings (paper §5, its Table 1's T_VSGW): building the CellComplex view plus
// vsg_wireframe, at the complex level (the paper's) and at the mesh level, on the shared
// hex-dominant meshes, on a generated 100×100×100 grid (10^6 cells) and on that grid with 1 % of its
// cells cut into pyramids (`hbc generate split --random 10000`: every cell a component, the worst
// case, 3 million wireframe chains at the complex level). Loading, the singularity
// graph and the base complex are computed once beforehand and not timed.
// Targets on one core: teapot and twistcube_s in milliseconds (<= 10 ms), 10^6 cells < 1 s.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "hbc/base_complex.hpp"
#include "hbc/cell_complex.hpp"
#include "hbc/generate.hpp"
#include "hbc/io.hpp"
#include "hbc/singularity_graph.hpp"
#include "hbc/vsg_wireframe.hpp"
#include "hbc/wireframe_style.hpp"

namespace {

struct Prepared {
  hbc::Mesh mesh;
  hbc::BaseComplex bc;
};

// Each input is prepared once per process, on first use.
const Prepared* prepared(const std::string& key) {
  static std::map<std::string, std::unique_ptr<Prepared>> cache;
  auto it = cache.find(key);
  if (it != cache.end()) return it->second.get();
  auto p = std::make_unique<Prepared>();
  if (key == "grid100") {
    p->mesh = hbc::build_mesh(hbc::generate_grid(100, 100, 100));
  } else if (key == "split100") {
    const auto cells = hbc::random_cells(100, 100, 100, 10000, 0);
    p->mesh = hbc::build_mesh(hbc::generate_split(100, 100, 100, hbc::SplitKind::Pyramids, cells));
  } else {
    const std::string path = std::string(HBC_DATA_DIR) + "/" + key;
    if (!std::filesystem::exists(path)) return nullptr;
    p->mesh = hbc::load_mesh(path);
  }
  p->bc = hbc::base_complex(p->mesh, hbc::singularity_graph(p->mesh));
  return (cache[key] = std::move(p)).get();
}

void wireframe(benchmark::State& state, const std::string& key, hbc::Level level) {
  const Prepared* p = prepared(key);
  if (!p) {
    state.SkipWithError(("missing " + key).c_str());
    return;
  }
  hbc::VsgWireframe w;
  for (auto _ : state) {
    const hbc::CellComplex cx = level == hbc::Level::Complex ? hbc::complex_from_base(p->mesh, p->bc)
                                                                    : hbc::complex_from_mesh(p->mesh);
    w = hbc::vsg_wireframe(cx);
    const hbc::WireframeStyle style = hbc::wireframe_style(cx, w);  // view + graph + style, as before the split
    benchmark::DoNotOptimize(w.polylines.items.data());
    benchmark::DoNotOptimize(style.color.data());
  }
  state.counters["cells"] = static_cast<double>(p->mesh.num_cells());
  state.counters["vsg_edges"] = static_cast<double>(w.vsg_edges);
  state.counters["wire"] = static_cast<double>(w.wireframe_edges());
  state.counters["wire_simpl"] = static_cast<double>(w.wireframe_edges_simplified());
}

const char* kInputs[] = {
    "hybrid-base-complex/teapot.hedra",
    "hybrid-base-complex/twistcube_s.mesh",
    "hybrid-base-complex/cube_twist-comp.obj.HYBRID",
    "hybrid-base-complex/test_2.HYBRID",
    "grid100",
    "split100",
};

const int kRegistered = [] {
  for (const char* key : kInputs) {
    const std::string name = std::filesystem::path(key).filename().string();
    for (auto level : {hbc::Level::Complex, hbc::Level::Mesh}) {
      auto* b = benchmark::RegisterBenchmark(
          ("vsg_wireframe/" + name + "/" + hbc::level_name(level)).c_str(),
          [key, level](benchmark::State& s) { wireframe(s, key, level); });
      b->Unit(benchmark::kMillisecond);
      if (std::string(key).ends_with("100")) b->Iterations(3);
    }
  }
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
