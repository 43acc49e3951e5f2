#!/usr/bin/env bash
# Runs every test: the C++ suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/),
# then the Release build's whole suite through ctest (GoogleTest, pytest, Blender background mode).
# HBC_SKIP_SANITIZED=1 skips the sanitized pass for a quicker local run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
if [ "${HBC_SKIP_SANITIZED:-0}" != 1 ]; then
  echo "== C++ suite under ASan + UBSan"
  bash scripts/test_sanitized.sh
fi
echo "== Release build, all tests"
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
