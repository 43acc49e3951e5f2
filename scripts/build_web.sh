#!/usr/bin/env bash
# Builds the browser viewer (web/) into one self-contained HTML file:
#   bash scripts/build_web.sh [OUT]        (default OUT: build/web)
# OUT/viewer.html (= OUT/index.html) holds the page's JS (three.js), the worker with the
# WebAssembly core, the layer plan's colours and words (asked of that core: hbc/layer_plan.hpp, the
# add-on's source too; no Python runs) and the CSS; it fetches nothing. `hbc export-html` fills the same file with a mesh (docs/web.md).
# Runs scripts/build_wasm.sh first when build-wasm/ is missing or older than native/ or the
# script; `npm ci` only when web/node_modules does not match the lockfile (so an offline machine
# that has node_modules builds). HBC_WASM_DIR:
# a folder holding hbc_core.js (+ .wasm) built elsewhere, taken as it is (no rebuild).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OUT=$(realpath -m "${1:-$ROOT/build/web}")

if [[ -n ${HBC_WASM_DIR:-} ]]; then
  WASM_DIR=$(realpath "$HBC_WASM_DIR")
  [[ -f $WASM_DIR/hbc_core.js ]] || { echo "build_web: no hbc_core.js in HBC_WASM_DIR=$WASM_DIR" >&2; exit 2; }
else
  WASM_DIR=$ROOT/build-wasm/web
  stamp=$WASM_DIR/hbc_core.js
  if [[ ! -f $stamp ]] || [[ -n $(find "$ROOT/native" "$ROOT/scripts/build_wasm.sh" -newer "$stamp" -type f -print -quit 2>/dev/null) ]]; then
    echo "build_web: building the WebAssembly core (scripts/build_wasm.sh)"
    bash "$ROOT/scripts/build_wasm.sh"
  fi
fi

cd "$ROOT/web"
if [[ ! -f node_modules/.package-lock.json ]] || [[ package-lock.json -nt node_modules/.package-lock.json ]]; then
  npm ci --no-audit --no-fund --prefer-offline
fi

node build.mjs --out "$OUT" --wasm "$WASM_DIR"
