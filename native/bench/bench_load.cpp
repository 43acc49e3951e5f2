// Load + topology build (read_input + build_mesh) of real and generated MEDIT files.
// Counters: cells, cells_per_second, parse_s / build_s (mean wall time per iteration),
// parse_cpu_s / build_cpu_s (CPU time of every thread, which a busy machine does not inflate),
// load_user_s / load_sys_s / load_faults (the load's user and kernel CPU seconds and minor page
// faults: the kernel's share is mostly the zeroing of fresh pages, whose cost per page varies with
// the host, so a growth in it is the machine's and a growth in user time the code's), peak_rss_MB
// (getrusage ru_maxrss of the whole process: run one benchmark per process, as scripts/bench.sh
// does, and have the grid files written beforehand, or the peak includes writing them:
// grid_written_here = 1 says so).
// BM_LoadFile loads $HBC_BENCH_FILE and also reports read_s, the time to read the same file into
// memory (read_file_bytes, measured in the same process just before), as the hardware's pace.
// Threads: HBC_THREADS (the library's default options read it). The file uses only the API of
// the first release, so scripts/bench.sh compiles it against a baseline build as well.
// Grid files go to $HBC_BENCH_DIR (default: the system temporary folder) as
// hbc_bench_grid_<cells>.mesh and are reused when present.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "hbc/generate.hpp"
#include "hbc/io.hpp"
#include "process_usage.hpp"

namespace {

namespace fs = std::filesystem;

using hbc_bench::Usage;
using hbc_bench::usage_now;

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

fs::path bench_dir() {
  const char* d = std::getenv("HBC_BENCH_DIR");
  return d && *d ? fs::path(d) : fs::temp_directory_path();
}

void load_file(benchmark::State& state, const std::string& path, bool written_here) {
  if (!fs::exists(path)) {
    state.SkipWithError(("missing " + path).c_str());
    return;
  }
  double parse_s = 0, build_s = 0, parse_cpu = 0, build_cpu = 0;
  Usage load;  // summed over the loads
  size_t cells = 0;
  for (auto _ : state) {
    const Usage u0 = usage_now();
    const auto t0 = std::chrono::steady_clock::now();
    hbc::MeshInput in = hbc::read_input(path);
    const auto t1 = std::chrono::steady_clock::now();
    const Usage u1 = usage_now();
    hbc::Mesh m = hbc::build_mesh(std::move(in));
    const auto t2 = std::chrono::steady_clock::now();
    const Usage u2 = usage_now();
    build_cpu += u2.cpu() - u1.cpu();
    parse_cpu += u1.cpu() - u0.cpu();
    load.user += u2.user - u0.user;
    load.sys += u2.sys - u0.sys;
    load.faults += u2.faults - u0.faults;
    parse_s += std::chrono::duration<double>(t1 - t0).count();
    build_s += std::chrono::duration<double>(t2 - t1).count();
    cells = m.num_cells();
    benchmark::DoNotOptimize(m.cell_faces.items.data());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["cells_per_second"] =
      benchmark::Counter(static_cast<double>(cells), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["parse_s"] = parse_s / n;
  state.counters["build_s"] = build_s / n;
  state.counters["parse_cpu_s"] = parse_cpu / n;
  state.counters["build_cpu_s"] = build_cpu / n;
  state.counters["load_user_s"] = load.user / n;
  state.counters["load_sys_s"] = load.sys / n;
  state.counters["load_faults"] = load.faults / n;
  state.counters["file_MB"] = static_cast<double>(fs::file_size(path)) / (1024.0 * 1024.0);
  state.counters["peak_rss_MB"] = peak_rss_mb();
  state.counters["grid_written_here"] = written_here ? 1 : 0;
}

void BM_LoadFile(benchmark::State& state) {
  const char* path = std::getenv("HBC_BENCH_FILE");
  if (!path || !fs::exists(path)) {
    state.SkipWithError("set HBC_BENCH_FILE to a mesh file");
    return;
  }
  // Best of three plain reads: the page cache is warm after the first.
  double read_s = 1e300;
  for (int i = 0; i < 3; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::string bytes = hbc::read_file_bytes(path);
    benchmark::DoNotOptimize(bytes.data());
    read_s = std::min(read_s, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  load_file(state, path, false);
  state.counters["read_s"] = read_s;
}

void BM_LoadArmadillo(benchmark::State& state) {
  load_file(state, std::string(HBC_DATA_DIR) + "/hexalab-edge-cone-rectification/armadillo_out.mesh", false);
}

// arg = number of cells: 10^4 = 25x20x20, 10^5 = 50x50x40, 10^6 = 100x100x100.
void BM_LoadGrid(benchmark::State& state) {
  const int64_t cells = state.range(0);
  int n = 25, m = 20, k = 20;
  if (cells == 100000) n = 50, m = 50, k = 40;
  else if (cells == 1000000) n = m = k = 100;
  else if (cells != 10000) {
    state.SkipWithError("grid sizes: 10000, 100000, 1000000");
    return;
  }
  const fs::path path = bench_dir() / ("hbc_bench_grid_" + std::to_string(cells) + ".mesh");
  bool written_here = false;
  if (!fs::exists(path)) {
    hbc::write_mesh(hbc::build_mesh(hbc::generate_grid(n, m, k)), path.string());
    written_here = true;
  }
  load_file(state, path.string(), written_here);
}

BENCHMARK(BM_LoadFile)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadArmadillo)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadGrid)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
