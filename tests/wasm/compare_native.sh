#!/usr/bin/env bash
# Whether the WebAssembly build computes what the native one does: runs `hbc analyze --json`,
# `hbc sheets --json`, `hbc wireframe --json` and `hbc metrics --json` with the native binary and
# with the wasm one under node (NODERAWFS: the same files) on every mesh of $HBC_DATA_DIR the native
# CLI reads, and requires the same output but the timings (compare_outputs.sh's strip_timings rule).
#
#   bash tests/wasm/compare_native.sh NATIVE_HBC WASM_HBC_JS [MESH...]
#
# Exit status 1 when any output differs (the diff is printed), 0 otherwise; ends with the count.
set -euo pipefail
[ $# -ge 2 ] || { sed -n 2,9p "$0"; exit 2; }
native=$(realpath "$1"); wasm=$(realpath "$2"); shift 2
source "$(dirname "$0")/../../scripts/env/common.sh"
if [ $# -eq 0 ]; then
  mapfile -t meshes < <(hbc_mesh_files)
else
  meshes=("$@")
fi
[ ${#meshes[@]} -gt 0 ] || { echo "compare_native: no meshes under $HBC_DATA_DIR" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# FILE: the JSON without timings, keys sorted. (hbc metrics' summary sums logarithms, whose last bit
# differs between glibc and musl; metrics.cpp rounds it to 1e-12 so that it compares equal too.)
strip() {
  "$HBC_PYTHON" -c '
import json, sys
def drop(x, key=""):
    if isinstance(x, dict):
        return {k: drop(v, k) for k, v in x.items() if k not in ("timings", "timing") and not k.startswith("seconds")}
    if isinstance(x, list):
        return [drop(v, key) for v in x]
    return x
print(json.dumps(drop(json.load(open(sys.argv[1]))), sort_keys=True, indent=1))' "$1"
}
passed=0 failed=0 skipped=0
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh")
  if ! "$native" info "$mesh" > /dev/null 2>&1; then
    skipped=$((skipped + 1)); continue  # a file the native CLI refuses is not compared
  fi
  for cmd in analyze sheets wireframe metrics; do
    "$native" $cmd --json --threads 1 "$mesh" > "$out/n.json" 2> "$out/n.err" || true
    node "$wasm" $cmd --json "$mesh" > "$out/w.json" 2> "$out/w.err" || true
    if [ ! -s "$out/n.json" ]; then
      # The native run failed: the wasm run must fail with the same message.
      if diff -q "$out/n.err" "$out/w.err" > /dev/null; then passed=$((passed + 1)); else
        echo "DIFF $cmd $name (error text)"; diff "$out/n.err" "$out/w.err" | head -5; failed=$((failed + 1)); fi
      continue
    fi
    strip "$out/n.json" > "$out/n.cmp"
    if strip "$out/w.json" > "$out/w.cmp" 2>/dev/null && cmp -s "$out/n.cmp" "$out/w.cmp"; then
      passed=$((passed + 1))
    else
      echo "DIFF $cmd $name"; diff "$out/n.cmp" "$out/w.cmp" | head -10 || true; head -3 "$out/w.err"
      failed=$((failed + 1))
    fi
  done
done
echo "compare_native: ${#meshes[@]} meshes ($skipped not read natively), 4 commands each"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
