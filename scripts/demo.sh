#!/usr/bin/env bash
# The main job on the bundled default: generate the demo mesh, analyse it, print its summary.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/bin/hbc generate cylinder -o out/demo_cylinder.ovm
./build/bin/hbc info out/demo_cylinder.ovm
