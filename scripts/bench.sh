#!/usr/bin/env bash
# Builds and runs the load benchmark (read + topology build) and prints a Markdown table.
# Each case runs in its own process with its grid file written beforehand by `hbc generate`, so
# peak RSS (getrusage ru_maxrss) is the load's own. Usage: scripts/bench.sh [build-dir]
# Environment: HBC_BENCH_DIR keeps the generated grids (default: a fresh temporary folder).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target hbc_bench_load hbc_cli >/dev/null

if [[ -z "${HBC_BENCH_DIR:-}" ]]; then
  HBC_BENCH_DIR=$(mktemp -d)
  trap 'rm -rf "$HBC_BENCH_DIR"' EXIT
fi
export HBC_BENCH_DIR
gen() {  # cells n m k
  local f="$HBC_BENCH_DIR/hbc_bench_grid_$1.mesh"
  [[ -f "$f" ]] || "$BUILD/bin/hbc" generate grid --size "$2" "$3" "$4" -o "$f" >/dev/null
}
gen 10000 25 20 20
gen 100000 50 50 40
gen 1000000 100 100 100

results=()
for name in BM_LoadArmadillo BM_LoadGrid/10000 BM_LoadGrid/100000 BM_LoadGrid/1000000; do
  out="$HBC_BENCH_DIR/$(echo "$name" | tr '/' '_').json"
  "$BUILD/bin/hbc_bench_load" --benchmark_filter="^${name}\$" --benchmark_format=json \
    --benchmark_out="$out" --benchmark_out_format=json >/dev/null
  results+=("$out")
done

/usr/bin/python3 - "${results[@]}" <<'PY'
import json, sys
print("| benchmark | cells | load+build wall (s) | CPU (s) | parse wall (s) | build wall (s) | cells/s (CPU) | peak RSS (MB) | file (MB) |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for path in sys.argv[1:]:
    data = json.load(open(path))
    for b in data["benchmarks"]:
        if b.get("error_occurred"):
            print(f"| {b['name']} | error: {b.get('error_message', '?')} ||||||||")
            continue
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
        print(f"| {b['name']} | {int(b['cells'])} | {b['real_time'] * scale:.3f} | {b['cpu_time'] * scale:.3f} | {b['parse_s']:.3f} | "
              f"{b['build_s']:.3f} | {b['cells_per_second']:.3g} | {b['peak_rss_MB']:.0f} | {b['file_MB']:.1f} |")
print()
print(f"host: {data['context'].get('host_name', '?')}, {data['context'].get('num_cpus', '?')} CPUs, "
      f"load average {open('/proc/loadavg').read().split()[0]}; single-threaded load; wall times grow when other "
      f"processes share the cores, CPU time less so; peak RSS per process (one case per process).")
PY
