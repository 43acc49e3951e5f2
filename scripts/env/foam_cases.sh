#!/usr/bin/env bash
# Makes (once) real snappyHexMesh output for the OpenFOAM reader's tests, and prints its folder.
#   scripts/env/foam_cases.sh          -> $HBC_ENV_DIR/foam-flange (default ~/.cache/hbc-envs)
# Debian's openfoam-examples tutorial mesh/snappyHexMesh/flange (blockMesh, surfaceFeatureExtract,
# snappyHexMesh -overwrite; about a minute on 2 cores), written three ways, each a case folder
# with a <name>.foam marker file:
#   ascii/    as the tutorial writes it (writeFormat ascii), plus foamToVTK -poly's internal.vtu
#             (VTK/ascii_0/internal.vtu), the independent reading the tests compare with
#   binary/   the same mesh through foamFormatConvert with writeFormat binary
#   gzip/     the same mesh through foamFormatConvert with writeFormat ascii, writeCompression on
# Made under a lock in a temporary folder and moved into place when complete, so two runs never
# build the same folder and a failed run leaves nothing half-made; a second run makes nothing.
# Needs the Debian packages openfoam and openfoam-examples (scripts/env/deps.sh installs them).
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
OUT=$HBC_ENV_DIR/foam-flange
TUTORIALS=/usr/share/doc/openfoam-examples/examples
mkdir -p "$HBC_ENV_DIR"
exec 9>"$OUT.lock"
flock 9
if [ -f "$OUT/.hbc-done" ]; then
  echo "$OUT"
  exit 0
fi
for need in /usr/share/openfoam/etc/bashrc "$TUTORIALS/mesh/snappyHexMesh/flange"; do
  [ -e "$need" ] || { echo "foam_cases.sh: $need is missing: run scripts/env/deps.sh (openfoam, openfoam-examples)" >&2; exit 1; }
done
# OpenFOAM's bashrc reads unset variables and fails commands on purpose: source it without -eu.
set +eu
export WM_PROJECT_DIR=/usr/share/openfoam
source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1
set -eu

WORK=$(mktemp -d "$HBC_ENV_DIR/foam-flange.tmp.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
run() {  # case log command...: a tool's output goes to its log, shown when it fails
  local dir=$1 log=$2
  shift 2
  (cd "$dir" && "$@") >"$dir/log.$log" 2>&1 || { tail -30 "$dir/log.$log" >&2; exit 1; }
}

A=$WORK/ascii
cp -r "$TUTORIALS/mesh/snappyHexMesh/flange" "$A"
chmod -R u+w "$A"
# Debian compresses the larger documentation files; OpenFOAM reads dictionaries uncompressed.
find "$A" -name '*.gz' -exec gunzip -f {} +
mkdir -p "$A/constant/triSurface"
cp "$TUTORIALS/resources/geometry/flange.stl.gz" "$A/constant/triSurface/"
run "$A" blockMesh blockMesh
run "$A" surfaceFeatureExtract surfaceFeatureExtract
run "$A" snappyHexMesh snappyHexMesh -overwrite
run "$A" foamToVTK foamToVTK -poly -constant -noFaceZones -noPointValues
touch "$A/ascii.foam"

# The same mesh written again by OpenFOAM: binary, and ASCII with every file gzip-compressed.
convert() {  # name format compression
  local C=$WORK/$1
  mkdir -p "$C/constant"
  cp -r "$A/system" "$C/"
  cp -r "$A/constant/polyMesh" "$C/constant/"
  foamDictionary -entry writeFormat -set "$2" "$C/system/controlDict" >/dev/null
  foamDictionary -entry writeCompression -set "$3" "$C/system/controlDict" >/dev/null
  run "$C" foamFormatConvert foamFormatConvert -constant
  touch "$C/$1.foam"
}
convert binary binary off
convert gzip ascii on

touch "$WORK/.hbc-done"
rm -rf "$OUT"
mv "$WORK" "$OUT"
trap - EXIT
echo "$OUT"
