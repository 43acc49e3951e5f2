#!/usr/bin/env bash
# Runs the analysis-stage benchmark (native/bench/bench_stages.cpp) on one core and prints a Markdown table:
# per mesh, graph + complex (T_GS + T_GB), sheets (T_GSH) and subsheets (T_GSH*) in CPU ms, the
# growth between the generated sizes measured in the same run, and the speed-up over the times
# quoted for the paper's Python implementation in the project's issues (quoted, not re-measured).
# Usage: scripts/bench_stages.sh [build-dir]   (the table itself: scripts/bench/stages_table.py)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env/common.sh
BUILD=${1:-build}
hbc_use_pybind11
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DHBC_BUILD_BENCHMARKS=ON "${HBC_CMAKE_ARGS[@]}" >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target hbc_bench_stages >/dev/null
out=$(mktemp)
trap 'rm -f "$out"' EXIT
taskset -c 0 "$BUILD/bin/hbc_bench_stages" --benchmark_min_time=0.5 --benchmark_format=json >"$out"
"$HBC_PYTHON" scripts/bench/stages_table.py "$out"
