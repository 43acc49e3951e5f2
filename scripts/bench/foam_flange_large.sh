#!/usr/bin/env bash
# A large real snappyHexMesh mesh for the benchmark: Debian's flange tutorial
# (openfoam-examples, mesh/snappyHexMesh/flange) with blockMesh's resolution multiplied by FACTOR
# in each direction (default 3.7: (20 16 12) becomes (74 59 44)), then snappyHexMesh -overwrite as
# the tutorial runs it. The cell count grows about as FACTOR^2.2, the surface refinement dominating
# (19,314 cells at 1, 344,571 at 3.7 after 22 minutes of snappyHexMesh on a busy 2-core machine;
# about 10^6 needs a factor near 6). Not part of the test suite; docs/performance.md has the run.
#   scripts/bench/foam_flange_large.sh OUT_DIR [FACTOR]
# OUT_DIR becomes a case folder with OUT_DIR/<name>.foam; an existing complete one is kept.
set -euo pipefail
OUT=${1:?usage: foam_flange_large.sh OUT_DIR [FACTOR]}
FACTOR=${2:-3.7}
TUTORIALS=/usr/share/doc/openfoam-examples/examples
[ -f "$OUT/.hbc-done" ] && { echo "$OUT"; exit 0; }
[ -d "$TUTORIALS/mesh/snappyHexMesh/flange" ] || { echo "needs Debian's openfoam and openfoam-examples (scripts/env/deps.sh)" >&2; exit 1; }
set +eu
export WM_PROJECT_DIR=/usr/share/openfoam
source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1
set -eu
rm -rf "$OUT"
mkdir -p "$(dirname "$OUT")"
cp -r "$TUTORIALS/mesh/snappyHexMesh/flange" "$OUT"
chmod -R u+w "$OUT"
find "$OUT" -name '*.gz' -exec gunzip -f {} +
mkdir -p "$OUT/constant/triSurface"
cp "$TUTORIALS/resources/geometry/flange.stl.gz" "$OUT/constant/triSurface/"
# The block's divisions "(20 16 12)" scaled, rounded to whole cells.
cells=$(awk -v f="$FACTOR" 'BEGIN { printf "(%d %d %d)", 20*f+0.5, 16*f+0.5, 12*f+0.5 }')
sed -i "s/(20 16 12)/$cells/" "$OUT/system/blockMeshDict"
grep -q "$cells" "$OUT/system/blockMeshDict"
cd "$OUT"
for step in blockMesh surfaceFeatureExtract "snappyHexMesh -overwrite"; do
  log=log.${step%% *}
  start=$(date +%s)
  $step >"$log" 2>&1 || { tail -30 "$log" >&2; exit 1; }
  echo "$step: $(( $(date +%s) - start )) s" >&2
done
touch "$(basename "$OUT").foam" .hbc-done
echo "$OUT"
