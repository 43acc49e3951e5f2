#!/usr/bin/env bash
# Load and analysis benchmark, printed as a Markdown table. Per case (a real mesh, rockerarm
# refined to 678,400 hexes, the 10^6-hex grid) and per variant (1 and 2 threads, and the baseline
# when given), in one run:
#   - hbc_bench_load (BM_LoadFile, one process per case and variant): the time to read the file
#     into memory (read_file_bytes, the hardware's pace), read+parse (read_input) and topology
#     (build_mesh) times, parse MB/s, load cells/s and the load / read ratio;
#   - `hbc analyze --json` under /usr/bin/time: the stage times and the peak RSS of load + analysis
#     (and bytes per cell).
# Usage: scripts/bench.sh [build-dir]
# Environment: HBC_BENCH_DIR keeps the generated meshes (default: a fresh temporary folder);
# HBC_BENCH_BASELINE=DIR compares with the build folder DIR of an earlier commit whose source tree
# is DIR/.. (its bench_load is compiled here from this tree's source against its library);
# HBC_BENCH_LARGE=1 adds the 216^3 grid (10,077,696 hexes, about 3 minutes per variant).
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
D=$HBC_BENCH_DIR
[[ -f "$D/grid_1000000.mesh" ]] || "$BUILD/bin/hbc" generate grid --size 100 100 100 -o "$D/grid_1000000.mesh" >/dev/null
[[ -f "$D/rockerarm_x64.mesh" ]] ||
  /usr/bin/python3 scripts/refine_medit_hexes.py ../shared/data/cinolib/rockerarm.mesh "$D/rockerarm_x64.mesh" 4 >/dev/null
cases=(../shared/data/hexalab-edge-cone-rectification/armadillo_out.mesh "$D/rockerarm_x64.mesh" "$D/grid_1000000.mesh")
if [[ "${HBC_BENCH_LARGE:-0}" == 1 ]]; then
  [[ -f "$D/grid_10077696.mesh" ]] || "$BUILD/bin/hbc" generate grid --size 216 216 216 -o "$D/grid_10077696.mesh" >/dev/null
  cases+=("$D/grid_10077696.mesh")
fi

variants=("new:1:$BUILD/bin/hbc_bench_load:$BUILD/bin/hbc" "new:2:$BUILD/bin/hbc_bench_load:$BUILD/bin/hbc")
if [[ -n "${HBC_BENCH_BASELINE:-}" ]]; then
  B=$HBC_BENCH_BASELINE
  g++ -std=c++20 -O2 -DNDEBUG -DHBC_DATA_DIR="\"$PWD/../shared/data\"" -I"$B/../native/include" \
    native/bench/bench_load.cpp "$B/native/libhbc.a" -lOpenMeshCore -lbenchmark -pthread -o "$D/bench_load_baseline"
  variants=("baseline:1:$D/bench_load_baseline:$B/bin/hbc" "${variants[@]}")
fi

rows=()
for f in "${cases[@]}"; do
  for v in "${variants[@]}"; do
    IFS=: read -r name threads bench cli <<<"$v"
    tag="$D/$(basename "$f").$name.$threads"
    HBC_THREADS=$threads HBC_BENCH_FILE=$f "$bench" --benchmark_filter='^BM_LoadFile$' --benchmark_min_time=0.2 \
      --benchmark_format=json >"$tag.load.json"
    HBC_THREADS=$threads /usr/bin/time -f '%M %U %S' -o "$tag.rss" "$cli" analyze "$f" --json >"$tag.analyze.json"
    rows+=("$f|$name|$threads|$tag")
  done
done

/usr/bin/python3 - "${rows[@]}" <<'PY'
import json, os, sys
print("| mesh | cells | code | threads | read (ms) | read+parse wall / CPU (s) | parse MB/s | topology wall / CPU (s) | load cells/s | "
      "load / read | base complex (s) | sheets (s) | VSG wireframe (s) | analyze wall / CPU (s) | peak RSS (MB) | bytes/cell |")
print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for row in sys.argv[1:]:
    path, name, threads, tag = row.split("|")
    b = json.load(open(tag + ".load.json"))["benchmarks"][0]
    a = json.load(open(tag + ".analyze.json"))
    t = a["timings"]
    rss_kb, user, sys_s = open(tag + ".rss").read().split()[-3:]
    rss_kb = int(rss_kb)
    mb = b["file_MB"] * 1024 * 1024 / 1e6
    read = b["read_s"]  # the baseline's binary is this tree's bench source, so it has it too
    load = b["parse_s"] + b["build_s"]
    cells = int(b["cells"])
    total = sum(v for v in t.values())
    print(f"| {os.path.basename(path)} | {cells} | {name} | {threads} | {read * 1e3:.1f} | {b['parse_s']:.3f} / {b['parse_cpu_s']:.3f} | "
          f"{mb / b['parse_s']:.0f} | {b['build_s']:.3f} / {b['build_cpu_s']:.3f} | {cells / load:.3g} | {load / read:.0f} | "
          f"{t['base_complex']:.3f} | {t['sheets'] + t['subsheets']:.3f} | {t['vsg_wireframe']:.3f} | {total:.2f} / {float(user) + float(sys_s):.2f} | "
          f"{rss_kb / 1024:.0f} | {rss_kb * 1024 / cells:.0f} |")
print()
print(f"{os.cpu_count()} CPUs, load average {' '.join(open('/proc/loadavg').read().split()[:3])} at the end. Wall times come from one "
      "process per row, and other processes on the machine inflate them; CPU = user + system time of every thread. read+parse includes reading the file; analyze = `hbc analyze --json` (its own load and "
      "every stage), peak RSS of that process.")
PY
