#!/usr/bin/env bash
# Whether two builds give the same results: runs both `hbc` binaries on each mesh with one and two
# threads (analyze, sheets and wireframe JSON at both levels, the OBJ of the whole complete
# wireframe, the VTU export) and compares the outputs byte for byte, timings removed. A speed-up or refactor
# must leave every one of them unchanged (see the README's Correctness section). JSON keys the new build
# adds (JSON keys are added; a renamed key keeps its old name as an alias: docs/concepts.md, Glossary)
# are listed, not counted as a change: every value of the old output must still be there, the same,
# at the same place.
#
#   bash scripts/compare_outputs.sh OLD_HBC NEW_HBC [MESH...]
#
# Without meshes: every mesh under $HBC_DATA_DIR (default ../shared/data). Exit status 1 when any
# output differs; the outputs are kept under $HBC_COMPARE_DIR (default: a fresh temporary directory).
set -euo pipefail
[ $# -ge 2 ] || { sed -n 2,10p "$0"; exit 2; }
old=$(realpath "$1"); new=$(realpath "$2"); shift 2
source "$(dirname "$0")/env/common.sh"
if [ $# -eq 0 ]; then
  mapfile -t meshes < <(hbc_mesh_files)
else
  meshes=("$@")
fi
out=${HBC_COMPARE_DIR:-$(mktemp -d)}
mkdir -p "$out/old" "$out/new"

# JSON without its timings (the only part of an output that may change from run to run).
strip_timings() {
  "$HBC_PYTHON" -c '
import json, sys
def drop(x):
    if isinstance(x, dict):
        return {k: drop(v) for k, v in x.items() if k not in ("timings", "timing") and not k.startswith("seconds")}
    if isinstance(x, list):
        return [drop(v) for v in x]
    return x
print(json.dumps(drop(json.load(open(sys.argv[1]))), sort_keys=True))' "$1" > "$1.cmp"
}

run_all() {  # BIN SIDE MESH TAG THREADS
  local bin=$1 dir=$out/$2/$4.t$5 mesh=$3 t=$5
  mkdir -p "$dir"
  "$bin" analyze --json --threads "$t" "$mesh" > "$dir/analyze.json"
  "$bin" analyze --json --level mesh --threads "$t" "$mesh" > "$dir/analyze_mesh.json"
  "$bin" sheets --json --threads "$t" "$mesh" > "$dir/sheets.json"
  "$bin" sheets --json --level mesh --threads "$t" "$mesh" > "$dir/sheets_mesh.json"
  "$bin" wireframe --json --threads "$t" "$mesh" > "$dir/wire.json"
  "$bin" wireframe --json --level mesh --threads "$t" "$mesh" > "$dir/wire_mesh.json"
  "$bin" wireframe --obj --all --threads "$t" "$mesh" > "$dir/wire.obj"
  "$bin" export-vtu --threads "$t" "$mesh" -o "$dir/cells.vtu" > /dev/null
  for j in "$dir"/*.json; do strip_timings "$j"; rm "$j"; done
}

# Whether every JSON file that differs only adds keys to the old one (prints the added key paths).
only_added_keys() {  # OLD_DIR NEW_DIR
  "$HBC_PYTHON" - "$1" "$2" <<'PY'
import filecmp, json, pathlib, sys
old, new = map(pathlib.Path, sys.argv[1:])
added = set()
def within(a, b, path):
    if isinstance(a, dict) and isinstance(b, dict):
        added.update(f"{path}.{k}" for k in b if k not in a)
        return all(k in b and within(v, b[k], f"{path}.{k}") for k, v in a.items())
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(within(x, y, path + "[]") for x, y in zip(a, b))
    return a == b
names = sorted({p.name for p in old.iterdir()} | {p.name for p in new.iterdir()})
for n in names:
    a, b = old / n, new / n
    if a.is_file() and b.is_file() and filecmp.cmp(a, b, shallow=False):
        continue
    if not (n.endswith(".cmp") and a.is_file() and b.is_file()) or not within(json.load(open(a)), json.load(open(b)), n):
        sys.exit(1)
print(" ".join(sorted(added)))
PY
}

status=0
for mesh in "${meshes[@]}"; do
  tag=$(basename "$(dirname "$mesh")")_$(basename "$mesh")
  for t in 1 2; do
    run_all "$old" old "$mesh" "$tag" "$t"
    run_all "$new" new "$mesh" "$tag" "$t"
    if diff -rq "$out/old/$tag.t$t" "$out/new/$tag.t$t" > /dev/null; then
      echo "same       $tag (threads $t)"
    elif added=$(only_added_keys "$out/old/$tag.t$t" "$out/new/$tag.t$t"); then
      echo "same       $tag (threads $t), keys added: $added"
    else
      echo "DIFFERENT  $tag (threads $t)"; diff -rq "$out/old/$tag.t$t" "$out/new/$tag.t$t" || true
      status=1
    fi
  done
done
echo "outputs in $out"
exit $status
