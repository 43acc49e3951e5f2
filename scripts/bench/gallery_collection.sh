#!/usr/bin/env bash
# Generates a collection of synthetic meshes for measuring `hbc gallery` (docs/gallery.md,
# "Speed and size"), laid out model/mesher/file as the gallery reads tags:
#   bash scripts/bench/gallery_collection.sh DIR [COUNT] [FIRST]     (default 200 meshes, from 0)
# Kinds in turn: hex grids, grids with random cells split into pyramids, prisms or tets, cylinders
# (prisms at the axis) and twisted rings, each at sizes from about 10^4 to 10^5 cells. The model is
# the kind, the "mesher" its size; FIRST shifts the sizes and seeds, so that COUNT more meshes
# (e.g. 10 FIRST=200) are new ones. HBC_CLI: the command (default build/bin/hbc).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
HBC=${HBC_CLI:-$ROOT/build/bin/hbc}
DIR=$1; COUNT=${2:-200}; FIRST=${3:-0}
kinds=(grid pyramids prisms tets cylinder twisted-ring)
for ((i = FIRST; i < FIRST + COUNT; i++)); do
  kind=${kinds[i % 6]}
  t=$((i / 6))                          # 0, 1, 2, ... per kind
  n=$((22 + (t * 7) % 25))              # grid edge 22..46: 10 648 .. 97 336 cells
  case $kind in
    grid) size="n$n-$i"; args=(grid --size "$n" "$n" "$n") ;;
    pyramids|prisms|tets) size="n$n-$i"
      args=(split --size "$n" "$n" "$n" --split "$kind" --random $((n * n)) --seed "$i") ;;
    cylinder) l=$((20 + (t * 37) % 160)); size="r12-l$l-$i"; args=(cylinder --radius-cells 12 --layers "$l") ;;
    twisted-ring) s=$((100 + (t * 131) % 900)); size="s10-n$s-$i"
      args=(twisted-ring --section 10 --sections "$s" --quarter-turns $((1 + i % 3))) ;;
  esac
  ext=mesh; [[ $kind == tets || $kind == pyramids || $kind == prisms ]] && ext=ovm  # splits may hold polyhedra, which MEDIT cannot store
  out=$DIR/$kind/$size/$kind-$size.$ext
  mkdir -p "$(dirname "$out")"
  [[ -f $out ]] || "$HBC" generate "${args[@]}" -o "$out" >/dev/null
done
echo "$COUNT meshes in $DIR"
