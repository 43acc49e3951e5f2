#!/usr/bin/env bash
# Writes hex2_binary/ and hex2_gzip/ from the hand-written hex2_ascii/ with OpenFOAM's own
# foamFormatConvert (Debian's openfoam, v1912): the same mesh as OpenFOAM writes it in binary
# (faces as a faceCompactList, arch "LSB;label=32;scalar=64") and gzip-compressed ASCII; and
# hex2_ascii split by decomposePar (method simple, 2 processors along x, one cell each):
# hex2_decomposed/ in ASCII with constant/polyMesh kept, hex2_decomposed_binary/ in binary and
# hex2_decomposed_gzip/ in gzip'd ASCII with the processor folders only. Run once by hand; the results are checked in, so the tests need no
# OpenFOAM.
#   tests/data/formats/foam/make_foam_cases.sh
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
set +eu
export WM_PROJECT_DIR=/usr/share/openfoam
source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1
set -eu
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# case_from_hex2 NAME FORMAT COMPRESSION: $TMP/NAME, a case of hex2_ascii's mesh whose controlDict
# writes FORMAT with COMPRESSION.
case_from_hex2() {
  local C=$TMP/$1
  mkdir -p "$C/system" "$C/constant"
  cp -r "$HERE/hex2_ascii/constant/polyMesh" "$C/constant/"
  cat >"$C/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application none; startFrom startTime; startTime 0; stopAt endTime; endTime 0; deltaT 1;
writeControl timeStep; writeInterval 1; writeFormat $2; writePrecision 17; writeCompression $3;
timeFormat general; timePrecision 6;
DICT
}
convert() {  # name format compression
  local C=$TMP/$1
  case_from_hex2 "$@"
  (cd "$C" && foamFormatConvert -constant >log.foamFormatConvert 2>&1) || { cat "$C/log.foamFormatConvert"; exit 1; }
  rm -rf "${HERE:?}/$1"
  mkdir -p "$HERE/$1/constant"
  cp -r "$C/constant/polyMesh" "$HERE/$1/constant/"
  touch "$HERE/$1/$1.foam"
}
decompose() {  # name format compression keep-constant
  local C=$TMP/$1
  case_from_hex2 "$1" "$2" "$3"
  echo 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2; method simple; coeffs { n (2 1 1); }' >"$C/system/decomposeParDict"
  for f in fvSchemes fvSolution; do
    echo "FoamFile { version 2.0; format ascii; class dictionary; object $f; }" >"$C/system/$f"
  done
  (cd "$C" && decomposePar -force >log.decomposePar 2>&1) || { cat "$C/log.decomposePar"; exit 1; }
  rm -rf "${HERE:?}/$1"
  mkdir -p "$HERE/$1"
  for p in processor0 processor1; do
    mkdir -p "$HERE/$1/$p/constant"
    cp -r "$C/$p/constant/polyMesh" "$HERE/$1/$p/constant/"
    rm -f "$HERE/$1/$p/constant/polyMesh/boundaryProcAddressing"*
  done
  [ "$4" = keep ] && mkdir -p "$HERE/$1/constant" && cp -r "$C/constant/polyMesh" "$HERE/$1/constant/"
  touch "$HERE/$1/$1.foam"
}
convert hex2_binary binary off
convert hex2_gzip ascii on
decompose hex2_decomposed ascii off keep
decompose hex2_decomposed_binary binary off drop
decompose hex2_decomposed_gzip ascii on drop
