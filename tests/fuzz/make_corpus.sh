#!/usr/bin/env bash
# Seed corpora for the fuzzers: the small real meshes (< 100 KB) from the shared data folder plus
# small meshes written by `hbc generate`, one folder per harness. Never writes into the repository.
# usage: tests/fuzz/make_corpus.sh HBC_BINARY OUT_DIR [DATA_DIR]
set -euo pipefail
HBC=$1
OUT=$2
DATA=${3:-"$(cd "$(dirname "$0")/../.." && pwd)/../shared/data"}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUT"/{ovm,ovmb,medit,hybrid,hedra,msh,vtk,vtu,foam,foam_decomposed,su2,ugrid,fluent,abaqus,nastran,lsdyna,analyze,exodus,cgns,med,xdmf}
GEN=$(mktemp -d)
trap 'rm -rf "$GEN"' EXIT

# Real files, by extension, when small enough to mutate quickly.
while IFS= read -r f; do
  case "${f,,}" in
    *.ovmb) dir=ovmb ;;
    *.ovm) dir=ovm ;;
    *.mesh) dir=medit ;;
    *.hybrid) dir=hybrid ;;
    *.hedra) dir=hedra ;;
    *) continue ;;
  esac
  cp "$f" "$OUT/$dir/real_$(basename "$f")"
done < <(find "$DATA" -type f -size -100k | sort)

# The element-list formats: the hand-written and tool-made files of tests/data/formats.
for f in "$HERE"/../data/formats/*.{msh,vtk,vtu} "$HERE"/../data/formats/real/*.{msh,vtk,vtu}; do
  [ -f "$f" ] || continue
  cp "$f" "$OUT/${f##*.}/src_$(basename "$f")"
done

# The CFD formats: SU2 and Fluent as they are; UGRID after the byte that picks the encoding
# (fuzz_targets.hpp: 0 ASCII, 1 b8, 2 lb8, 3 r8, 4 lr8).
R="$HERE"/../data/formats/real
cp "$R"/*.su2 "$OUT/su2/"
cp "$R"/slab_fluent.msh "$OUT/fluent/"
for e in ugrid:0 b8.ugrid:1 lb8.ugrid:2 r8.ugrid:3 lr8.ugrid:4; do
  { printf "\\x0${e#*:}"; cat "$R/slab.${e%%:*}"; } > "$OUT/ugrid/slab.${e%%:*}"
done

# Exodus II and CGNS: the tool-made twins of tests/data/formats/real (classic and HDF5 storage).
for f in "$HERE"/../data/formats/real/*.{exo,e,cgns}; do
  [ -f "$f" ] || continue
  case "$f" in *.cgns) dir=cgns ;; *) dir=exodus ;; esac
  cp "$f" "$OUT/$dir/src_$(basename "$f")"
done

# MED and XDMF: meshio's twins (the XDMF harness reads the XML; its inline-data twin holds the mesh).
for f in "$HERE"/../data/formats/real/*.{med,xdmf}; do
  [ -f "$f" ] || continue
  case "$f" in *.med) dir=med ;; *) dir=xdmf ;; esac
  cp "$f" "$OUT/$dir/src_$(basename "$f")"
done

# The finite-element decks: the tool-made twins of the slab (tests/data/formats/real).
for f in "$HERE"/../data/formats/real/*.{inp,bdf,k,key}; do
  [ -f "$f" ] || continue
  case "$f" in *.inp) dir=abaqus ;; *.bdf) dir=nastran ;; *) dir=lsdyna ;; esac
  cp "$f" "$OUT/$dir/src_$(basename "$f")"
done

# OpenFOAM cases (tests/data/formats/foam): the harness takes points, faces, owner and neighbour
# in one input, each ended by a line "#-#-#" (fuzz_targets.hpp); .gz files go in inflated.
for c in "$HERE"/../data/formats/foam/*/constant/polyMesh; do
  name=$(basename "$(dirname "$(dirname "$c")")")
  for f in points faces owner neighbour; do
    if [ -f "$c/$f" ]; then cat "$c/$f"; else gzip -dc "$c/$f.gz"; fi
    printf '\n#-#-#\n'
  done > "$OUT/foam/src_$name"
done

# Decomposed cases: each processor's eight files (fuzz_targets.hpp, foam_processors), processor
# after processor.
for c in "$HERE"/../data/formats/foam/hex2_decomposed*; do
  for p in "$c"/processor*; do
    for f in points faces owner neighbour pointProcAddressing faceProcAddressing cellProcAddressing boundary; do
      m=$p/constant/polyMesh/$f
      if [ -f "$m" ]; then cat "$m"; else gzip -dc "$m.gz"; fi
      printf '\n#-#-#\n'
    done
  done > "$OUT/foam_decomposed/src_$(basename "$c")"
done

# Generated meshes: every generator, every split kind, sizes that stay a few KB. Grids and
# pyramid/prism splits go to MEDIT and OVM; tet splits hold 7-face polyhedra MEDIT cannot express.
gen() {  # name ext args...
  local name=$1 ext=$2
  shift 2
  "$HBC" generate "$@" -o "$GEN/$name.$ext" >/dev/null
}
for ext in mesh ovm; do
  gen grid111 $ext grid --size 1 1 1
  gen grid222 $ext grid --size 2 2 2
  gen grid321 $ext grid --size 3 2 1
  gen pyr $ext split --size 2 2 2 --split pyramids --random 2 --seed 1
  gen prism $ext split --size 3 2 2 --split prisms --axis x --random 2 --seed 2
  gen sector3 $ext sector --valence 3 --rings 1 --layers 2
  gen sector5 $ext sector --valence 5 --rings 1 --layers 1
  gen cyl $ext cylinder --radius-cells 2 --layers 1
done
gen tets ovm split --size 2 2 2 --split tets --random 2 --seed 3
gen tets1 ovm split --size 1 1 2 --split tets --cells "0,0,0"
for f in "$GEN"/*.mesh; do cp "$f" "$OUT/medit/gen_$(basename "$f")"; done
for f in "$GEN"/*.ovm; do
  b=$(basename "$f" .ovm)
  cp "$f" "$OUT/ovm/gen_$b.ovm"
  /usr/bin/python3 "$HERE/ovm_convert.py" "$f" "$OUT/hedra/gen_$b.hedra"
  /usr/bin/python3 "$HERE/ovm_convert.py" "$f" "$OUT/hybrid/gen_$b.HYBRID"
done

# The analyze harness reads a selector byte (index of the reader, see fuzz_targets.hpp) and a file.
sel=0
for dir in ovm ovmb medit hybrid hedra msh vtk vtu; do
  for f in "$OUT/$dir"/*; do
    { printf "\\x$(printf %02x $sel)"; cat "$f"; } > "$OUT/analyze/$dir-$(basename "$f")"
  done
  sel=$((sel + 1))
done
for dir in ovm ovmb medit hybrid hedra msh vtk vtu foam analyze; do
  echo "corpus $dir: $(ls "$OUT/$dir" | wc -l) files, $(du -sk "$OUT/$dir" | cut -f1) KB"
done
