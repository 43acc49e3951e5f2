#!/usr/bin/env bash
# Builds the library, the CLI and the GoogleTest suite with AddressSanitizer + UndefinedBehavior-
# Sanitizer (build-asan/, RelWithDebInfo so reports carry file:line) and runs the whole C++ suite,
# CLI tests included (they run the sanitized hbc binary). Leaks fail the run; so does any UB
# report (compiled with -fno-sanitize-recover, and halt_on_error below for good measure).
# usage: scripts/check/asan_ubsan.sh [--build | --run] [extra gtest arguments, e.g. --gtest_filter=Io.*]
set -euo pipefail
cd "$(dirname "$0")/../.."
source scripts/env/common.sh
# --build only builds, --run only runs (what scripts/test.sh does, to time and overlap the two).
step=all
case "${1:-}" in --build | --run) step=${1#--}; shift ;; esac
BUILD=${BUILD:-build-asan}
if [ "$step" != run ]; then
  hbc_use_pybind11
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHBC_SANITIZE=ON -DHBC_BUILD_BENCHMARKS=OFF \
    "${HBC_CMAKE_ARGS[@]}" >/dev/null
  cmake --build "$BUILD" -j"$(nproc)" --target hbc_cli hbc_tests
fi
[ "$step" = build ] && exit 0
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# The HDF5, netCDF and CGNS libraries keep allocations of their own past exit (tests/fuzz/lsan.supp).
export LSAN_OPTIONS=suppressions=$PWD/tests/fuzz/lsan.supp
"$BUILD/tests/hbc_tests" --gtest_brief=1 "$@"
