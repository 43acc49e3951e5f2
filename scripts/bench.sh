#!/usr/bin/env bash
# Load and analysis benchmark, printed as two Markdown tables: every figure of a row, and every
# ratio between rows, comes from the same run.
# 1. Cold, the headline (scripts/bench/cold_runs.py): `hbc analyze FILE --json` as a user runs it,
#    one process per run, HBC_BENCH_RUNS (default 5) runs per case and variant, interleaved;
#    medians (and ranges) of wall, user and kernel CPU, load, stages and peak RSS. Variants: the
#    baseline when given, this build (as a user runs it: no 2 MiB page advice), and this build with
#    HBC_HUGE_PAGES=1 (the advice, opt-in),
#    every core.
# 2. Warm, marked as such: per case and per variant (this build with 1 and with 2 threads, and the
#    baseline when given):
#   - hbc_bench_load (BM_LoadFile, one process per case and variant): the time to read the file
#     into memory (read_file_bytes: the hardware's pace), read+parse (read_input) and topology
#     (build_mesh) wall times of the fastest of HBC_BENCH_REPS (default 5) loads, from which parse
#     MB/s, load cells/s and load / read (and the fastest load's user and system CPU and faults);
#   - `hbc analyze --json` under /usr/bin/time: the stage times, the stages' sum against the load,
#     and the peak RSS of the process (and bytes per cell);
#   - the same `hbc analyze` of a one-hex mesh: the process's own footprint (binary, libraries,
#     threads), which the case's peak less it leaves the memory of load + analysis alone.
# With a baseline, the load speed-up and the peak-memory ratios (whole process; load + analysis)
# against it, case by case.
# Cases: armadillo (real, 29,935 cells); rockerarm refined to 678,400 hexes; three 10^6-cell meshes
# from hbc generate: the grid, a hex-dominant cylinder with prism columns, and the all-singleton
# worst case (the grid with 1 % of its cells split into 6 pyramids each); and the grid again with
# its vertices numbered at random (scripts/bench/shuffle_medit_vertices.py), no spatial order at all.
# Usage: scripts/bench.sh [build-dir]   (the table itself: scripts/bench/bench_table.py)
# Environment: HBC_DATA_DIR, HBC_PYTHON (scripts/env/common.sh); HBC_BENCH_DIR keeps the generated meshes (default: a fresh temporary folder);
# HBC_BENCH_BASELINE=DIR compares with the build folder DIR of an earlier commit whose source tree
# is DIR/.. (its bench_load is compiled here from this tree's source against its library);
# HBC_BENCH_LARGE=1 adds the 10^7-cell cases: the 216^3 grid (10,077,696 hexes) and a
# hex-dominant cylinder of about 10^7 cells (minutes per variant), and a second table of linear
# growth (each figure per cell at 10^7 over per cell at 10^6, the load's user and system CPU and
# page faults apart).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env/common.sh
DATA=$HBC_DATA_DIR
BUILD=${1:-build}
hbc_use_pybind11
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DHBC_BUILD_BENCHMARKS=ON "${HBC_CMAKE_ARGS[@]}" >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target hbc_bench_load hbc_cli >/dev/null

if [[ -z "${HBC_BENCH_DIR:-}" ]]; then
  HBC_BENCH_DIR=$(mktemp -d)
  trap 'rm -rf "$HBC_BENCH_DIR"' EXIT
fi
export HBC_BENCH_DIR
D=$HBC_BENCH_DIR
HBC=$BUILD/bin/hbc
make_case() {  # FILE COMMAND...: generate FILE once
  local f=$1
  shift
  [[ -f "$f" ]] || "$@" -o "$f" >/dev/null
}
make_case "$D/grid_1000000.mesh" "$HBC" generate grid --size 100 100 100
make_case "$D/cylinder_988240.mesh" "$HBC" generate cylinder --radius-cells 50 --layers 110
make_case "$D/split_1050000.mesh" "$HBC" generate split --size 100 100 100 --split pyramids --random 10000
[[ -f "$D/rockerarm_x64.mesh" ]] ||
  "$HBC_PYTHON" scripts/bench/refine_medit_hexes.py "$DATA/cinolib/rockerarm.mesh" "$D/rockerarm_x64.mesh" 4 >/dev/null
[[ -f "$D/grid_1000000_shuffled.mesh" ]] ||
  "$HBC_PYTHON" scripts/bench/shuffle_medit_vertices.py "$D/grid_1000000.mesh" "$D/grid_1000000_shuffled.mesh" >/dev/null
cases=("$DATA/hexalab-edge-cone-rectification/armadillo_out.mesh" "$D/rockerarm_x64.mesh" "$D/grid_1000000.mesh"
       "$D/grid_1000000_shuffled.mesh" "$D/cylinder_988240.mesh" "$D/split_1050000.mesh")
if [[ "${HBC_BENCH_LARGE:-0}" == 1 ]]; then
  make_case "$D/grid_10077696.mesh" "$HBC" generate grid --size 216 216 216
  make_case "$D/cylinder_10m.mesh" "$HBC" generate cylinder --radius-cells 160 --layers 110
  cases+=("$D/grid_10077696.mesh" "$D/cylinder_10m.mesh")
fi

variants=("new:1:$BUILD/bin/hbc_bench_load:$HBC" "new:2:$BUILD/bin/hbc_bench_load:$HBC")
if [[ -n "${HBC_BENCH_BASELINE:-}" ]]; then
  B=$HBC_BENCH_BASELINE
  g++ -std=c++20 -O2 -DNDEBUG -DHBC_DATA_DIR="\"$DATA\"" -I"$B/../native/include" \
    native/bench/bench_load.cpp "$B/native/libhbc.a" -lOpenMeshCore -lbenchmark -pthread -o "$D/bench_load_baseline"
  variants=("baseline:1:$D/bench_load_baseline:$B/bin/hbc" "${variants[@]}")
fi

# A one-hex mesh: what `hbc analyze` holds before any real mesh is (about 5-7 MB), which is most of
# armadillo's peak (16 MB) and would hide its load + analysis in the ratio. The smallest of three
# runs, once per variant.
printf 'MeshVersionFormatted 1\nDimension 3\nVertices\n8\n0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n1 1 1 0\n0 1 1 0\nHexahedra\n1\n1 2 3 4 5 6 7 8 0\nEnd\n' >"$D/one_hex.mesh"
own_rss() {  # CLI THREADS: peak RSS in KB of `hbc analyze` on the one-hex mesh
  for _ in 1 2 3; do
    HBC_THREADS=$2 /usr/bin/time -f '%M' -o "$D/own.rss" "$1" analyze "$D/one_hex.mesh" --json >/dev/null
    tail -1 "$D/own.rss"
  done | sort -n | head -1
}
cold=("--variant" "new=$HBC" "--variant" "new-huge-pages=HBC_HUGE_PAGES=1 $HBC")
[[ -n "${HBC_BENCH_BASELINE:-}" ]] && cold=("--variant" "baseline=$HBC_BENCH_BASELINE/bin/hbc" "${cold[@]}")
echo "## Cold: one \`hbc analyze --json\` process per run, median (range) of ${HBC_BENCH_RUNS:-5}"
echo
"$HBC_PYTHON" scripts/bench/cold_runs.py --runs "${HBC_BENCH_RUNS:-5}" --out "$D/cold_runs.json" "${cold[@]}" "${cases[@]}"
echo
echo "## Warm: fastest of ${HBC_BENCH_REPS:-5} loads in one process (overstates what users see)"
echo

declare -A own
for v in "${variants[@]}"; do
  IFS=: read -r name threads bench cli <<<"$v"
  own[$name.$threads]=$(own_rss "$cli" "$threads")
done

rows=()
for f in "${cases[@]}"; do
  for v in "${variants[@]}"; do
    IFS=: read -r name threads bench cli <<<"$v"
    tag="$D/$(basename "$f").$name.$threads"
    HBC_THREADS=$threads HBC_BENCH_FILE=$f "$bench" --benchmark_filter='^BM_LoadFile$' --benchmark_min_time=0.01 \
      --benchmark_repetitions="${HBC_BENCH_REPS:-5}" --benchmark_format=json >"$tag.load.json"
    HBC_THREADS=$threads /usr/bin/time -f '%M %U %S %e' -o "$tag.rss" "$cli" analyze "$f" --json >"$tag.analyze.json"
    echo "${own[$name.$threads]}" >"$tag.own"
    rows+=("$f|$name|$threads|$tag")
  done
done

"$HBC_PYTHON" scripts/bench/bench_table.py "${rows[@]}"
