#!/usr/bin/env bash
# `hbc compare` against `hbc table` on the same 20 meshes of about 10^5 cells (hex grids of 46^3
# cells with a different number of cells split into pyramids each, so that every mesh has its own
# non-hex regions). Both run their meshes 2 at a time (-j 2, one child process per mesh);
# compare does more per mesh (the metrics with a scaled Jacobian per cell, where table runs the
# analysis with its wireframe) and then draws report.html in Python (matplotlib). Runs alternate
# (table, compare, table, ...) so that a busy minute of a shared machine falls on both; prints each
# run's wall time, the medians and their ratio.
#
# Usage: scripts/bench/compare_vs_table.sh [HBC] [RUNS]   (defaults: build/bin/hbc, 3)
# Environment: HBC_PYTHON as for hbc compare (a Python with the hbc package's needs: matplotlib).
set -euo pipefail
HBC=${1:-build/bin/hbc}
RUNS=${2:-3}
DIR=$(mktemp -d /tmp/hbc-compare-bench-XXXXXX)
trap 'rm -rf "$DIR"' EXIT

files=()
for i in $(seq 1 20); do
  f=$DIR/grid_$i.mesh
  "$HBC" generate split --size 46 46 46 --random $((i * 50)) --seed "$i" --split pyramids -o "$f" >/dev/null
  files+=("$f")
done
cat "${files[@]}" >/dev/null  # in the page cache before the first run
echo "20 meshes of $("$HBC" info "${files[0]}" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["cells"])') cells (the first; the others alike)"

now() { date +%s.%N; }
table_times=()
compare_times=()
for r in $(seq 1 "$RUNS"); do
  t0=$(now)
  "$HBC" table -j 2 "${files[@]}" >/dev/null
  t1=$(now)
  "$HBC" compare -j 2 "${files[@]}" -o "$DIR/out" 2>/dev/null
  t2=$(now)
  table_times+=("$(awk "BEGIN{print $t1 - $t0}")")
  compare_times+=("$(awk "BEGIN{print $t2 - $t1}")")
  echo "run $r: table ${table_times[-1]} s, compare ${compare_times[-1]} s"
done
python3 - "${table_times[*]}" "${compare_times[*]}" <<'EOF'
import statistics, sys
t = statistics.median(map(float, sys.argv[1].split()))
c = statistics.median(map(float, sys.argv[2].split()))
print(f"median: table {t:.2f} s, compare {c:.2f} s, ratio compare/table {c / t:.2f}")
EOF
