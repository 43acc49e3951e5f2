#!/usr/bin/env bash
# Runs every test: the C++ suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/),
# the parallel load under ThreadSanitizer (build-tsan/),
# then the Release build's whole suite through ctest (GoogleTest, pytest, and the Blender-side
# suites in every Blender of the matrix: Debian's 3.4 binary and the bpy wheels 4.2, 4.5, 5.0 and
# 5.2 in virtual environments that scripts/env/blender_envs.sh makes once and reuses).
#   HBC_SKIP_SANITIZED=1      skips the sanitized passes for a quicker local run
#   HBC_BPY_VERSIONS="4.5"    restricts the bpy wheels of the matrix (default: all of them)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/env/deps.sh
if [ "${HBC_SKIP_SANITIZED:-0}" != 1 ]; then
  echo "== C++ suite under ASan + UBSan"
  bash scripts/check/asan_ubsan.sh
  echo "== parallel parts under ThreadSanitizer"
  bash scripts/check/tsan.sh
fi
echo "== Blender environments (bpy wheels)"
# shellcheck disable=SC2086
pairs=$(bash scripts/env/blender_envs.sh ${HBC_BPY_VERSIONS:-} | awk '{printf "%s%s=%s", sep, $1, $2; sep=";"}')
echo "$pairs" | tr ';' '\n'
echo "== Release build, all tests"
bash scripts/build.sh -DHBC_BPY_PYTHONS="$pairs"
echo "== hbc wheels and the Blender extension"
py313=()
case "$pairs" in *5.[1-9]=*|*[6-9].[0-9]=*) py313=("$(bash scripts/env/python313.sh)") ;; esac
bash scripts/wheels.sh /usr/bin/python3 "${py313[@]}"
cd build
ctest --output-on-failure -j"$(nproc)"
