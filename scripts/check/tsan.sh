#!/usr/bin/env bash
# Builds the library and the GoogleTest suite with ThreadSanitizer (build-tsan/) and runs the
# tests that exercise the parallel parts: every load step with 1, 2 and 3 threads and small
# grains (LoadParallel, LoadSteps, LoadParse), the base complex, sheets and VSG wireframe with 1, 2
# and 3 threads (ComplexThreads, WireframeThreads), the readers and formats, the generated and
# shared meshes loaded and analysed with the machine's threads. Any data race fails the run.
# usage: scripts/check/tsan.sh [extra gtest arguments]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build-tsan}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHBC_TSAN=ON -DHBC_BUILD_BENCHMARKS=OFF \
  -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target hbc_tests
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
"$BUILD/tests/hbc_tests" --gtest_brief=1 \
  --gtest_filter='Load*:Io*:Formats*:Malformed*:MeshCore*:Generate*:Shared*:Paper*:ComplexThreads*:WireframeThreads*:StatsMemory*:Table1*' "$@"
