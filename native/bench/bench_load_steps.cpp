// The steps of build_mesh one by one (hbc/mesh_steps.hpp) on $HBC_BENCH_FILE, after reading it:
// wall seconds per step as counters (mean over iterations), to see where a load spends its time
// and how each step uses the threads (HBC_THREADS). Not for comparing with older builds: the steps
// are this version's. With HBC_BENCH_RUSAGE=1, also each step's user and system CPU seconds (all
// threads) and minor page faults (<step>_usr, _sys, _flt): on a VM the kernel's zeroing of fresh
// pages can cost more than the step's own work, and grows with the memory a step first touches.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <string>

#include "hbc/io.hpp"
#include "mesh/mesh_steps.hpp"
#include "process_usage.hpp"
#include "platform/worker_pool.hpp"

namespace {

using Clock = std::chrono::steady_clock;

using hbc_bench::Usage;
using hbc_bench::usage_now;

void BM_LoadSteps(benchmark::State& state) {
  const char* file = std::getenv("HBC_BENCH_FILE");
  if (!file) {
    state.SkipWithError("set HBC_BENCH_FILE");
    return;
  }
  using namespace hbc::mesh_steps;
  // As load_mesh, one worker pool for all the steps; HBC_BENCH_NO_POOL=1: a thread per range, as
  // before the pool, to compare.
  const hbc::detail::RunOptions run(hbc::Threads{});
  const hbc::Threads par = std::getenv("HBC_BENCH_NO_POOL") ? hbc::resolved({}) : run.get();
  const bool with_usage = std::getenv("HBC_BENCH_RUSAGE") != nullptr;
  std::map<std::string, double> total;
  for (auto _ : state) {
    auto t = Clock::now();
    Usage u = with_usage ? usage_now() : Usage{};
    auto lap = [&](const std::string& step) {
      const auto now = Clock::now();
      total[step] += std::chrono::duration<double>(now - t).count();
      t = now;
      if (!with_usage) return;
      const Usage v = usage_now();
      total[step + "_usr"] += v.user - u.user;
      total[step + "_sys"] += v.sys - u.sys;
      total[step + "_flt"] += v.faults - u.faults;
      u = v;
    };
    hbc::MeshInput in = hbc::read_input(file, hbc::Format::Auto, par);
    lap("s0_read_parse");
    validate_input(in, par);
    lap("s1_validate");
    hbc::Mesh m;
    m.points = std::move(in.points);
    std::vector<int32_t> rank = merge_faces(in, m, par);
    lap("s2_merge_faces");
    EdgeFaceCounts counts = build_edges(m, std::move(rank), par);
    lap("s3_build_edges");
    CellCheck cells = check_cells(m, in, par);
    lap("s4_check_cells");
    orient_groups(m, cells.volume, par);
    lap("s5_orient_groups");
    mark_boundary(m, par);
    lap("s6_mark_boundary");
    edge_fans(m, counts, cells, par);
    lap("s7_edge_fans");
    non_manifold_vertices(m, cells, par);
    lap("s8_non_manifold");
    benchmark::DoNotOptimize(m.cell_faces.items.data());
  }
  for (const auto& [step, s] : total) state.counters[step] = s / static_cast<double>(state.iterations());
  state.counters["threads"] = par.count;
}
BENCHMARK(BM_LoadSteps)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
