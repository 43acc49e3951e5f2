#!/usr/bin/env bash
# Builds and runs every test (GoogleTest, pytest, Blender background mode) through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
