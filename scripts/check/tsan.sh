#!/usr/bin/env bash
# Builds the library and the GoogleTest suite with ThreadSanitizer (build-tsan/) and runs the
# tests that exercise the parallel parts: every load step with 1, 2 and 3 threads and small
# grains (LoadParallel, LoadSteps, LoadParse), the base complex, sheets and VSG wireframe with 1, 2
# and 3 threads (ComplexThreads, WireframeThreads), the readers and formats, the generated and
# shared meshes loaded and analysed with the machine's threads. Any data race fails the run.
# usage: scripts/check/tsan.sh [--build | --run] [extra gtest arguments]
set -euo pipefail
cd "$(dirname "$0")/../.."
source scripts/env/common.sh
# --build only builds, --run only runs (what scripts/test.sh does, to time and overlap the two).
step=all
case "${1:-}" in --build | --run) step=${1#--}; shift ;; esac
BUILD=${BUILD:-build-tsan}
if [ "$step" != run ]; then
  hbc_use_pybind11
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHBC_TSAN=ON -DHBC_BUILD_BENCHMARKS=OFF \
    "${HBC_CMAKE_ARGS[@]}" >/dev/null
  cmake --build "$BUILD" -j"$(nproc)" --target hbc_tests
fi
[ "$step" = build ] && exit 0
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
"$BUILD/tests/hbc_tests" --gtest_brief=1 \
  --gtest_filter='Load*:Io*:Formats*:Malformed*:MeshCore*:Generate*:Shared*:Paper*:ComplexThreads*:WireframeThreads*:StatsMemory*:Table1*' "$@"
