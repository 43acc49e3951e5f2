#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan) into build-fuzz/, writes the seed corpora
# and runs every harness for SECONDS each, JOBS at a time, printing executions and findings.
# usage: tests/fuzz/run_fuzzers.sh SECONDS [harness...]   (env: JOBS=1, BUILD=build-fuzz)
# Findings (crash-*, leak-*, timeout-*, oom-* files) land in $BUILD/findings/<harness>/; the
# growing corpus in $BUILD/corpus/<harness>/ is kept between runs. Exit status 1 on any finding.
set -euo pipefail
SECONDS_EACH=${1:?usage: run_fuzzers.sh SECONDS [harness...]}
shift
HARNESSES=("$@")
[ ${#HARNESSES[@]} -eq 0 ] && HARNESSES=(ovm ovmb medit hybrid hedra msh vtk vtu foam foam_decomposed su2 ugrid fluent abaqus nastran lsdyna analyze)
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${BUILD:-$ROOT/build-fuzz}
JOBS=${JOBS:-1}

CC=clang CXX=clang++ cmake -S "$ROOT" -B "$BUILD" -DHBC_BUILD_FUZZERS=ON -DHBC_BUILD_TESTS=OFF \
  -DHBC_BUILD_BENCHMARKS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPython_EXECUTABLE=/usr/bin/python3 \
  -Dpybind11_DIR="$(bash "$ROOT/scripts/env/pybind11.sh")" >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target hbc_cli $(printf 'fuzz_%s ' "${HARNESSES[@]}") >/dev/null
"$ROOT/tests/fuzz/make_corpus.sh" "$BUILD/bin/hbc" "$BUILD/corpus-seed" >/dev/null

run_one() {
  local h=$1
  local corpus=$BUILD/corpus/$h findings=$BUILD/findings/$h dict=()
  mkdir -p "$corpus" "$findings"
  [ -f "$ROOT/tests/fuzz/$h.dict" ] && dict=(-dict="$ROOT/tests/fuzz/$h.dict")
  # Leaks are findings; UBSan already aborts (-fno-sanitize-recover). 10 s per input is a hang,
  # 2 GB of RSS (or one allocation that large) a memory blow-up.
  # lsan.supp: the HDF5 library's own allocations kept past exit (the Exodus II and CGNS readers).
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0 LSAN_OPTIONS=suppressions=$ROOT/tests/fuzz/lsan.supp \
    "$BUILD/fuzz/fuzz_$h" "$corpus" "$BUILD/corpus-seed/$h" "${dict[@]}" \
    -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$findings/" -print_final_stats=1 >"$BUILD/findings/$h.log" 2>&1 || true
  local execs found
  execs=$(grep -m1 '^stat::number_of_executed_units' "$BUILD/findings/$h.log" | awk '{print $2}')
  found=$(find "$findings" -type f | wc -l)
  printf '%-8s %10s executions  corpus %5s files  findings %s\n' "$h" "${execs:-?}" \
    "$(ls "$corpus" | wc -l)" "$found"
}

pids=()
for h in "${HARNESSES[@]}"; do
  run_one "$h" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$JOBS" ]; then
    wait "${pids[0]}"
    pids=("${pids[@]:1}")
  fi
done
wait
total=$(find "$BUILD/findings" -mindepth 2 -type f | wc -l)
echo "findings in total: $total (logs: $BUILD/findings/<harness>.log)"
[ "$total" -eq 0 ]
