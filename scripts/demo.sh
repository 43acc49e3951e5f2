#!/usr/bin/env bash
# The main job on the bundled defaults: build, generate the demo meshes, analyze them (Table 1
# rows), and render their figure sets (the paper's pipeline panels and a labelled contact sheet)
# into out/. The first default, a twisted pair (`hbc generate twisted-pair`: two concentric rings
# of a 4x4 section, one hex of each split into pyramids), fills all seven panels: its outer ring
# turns a quarter turn, so its sheets cross themselves (self-intersecting, with subsheets: panels d
# and g) through the pyramids, where their VSG chains end (panels e, f); its inner ring turns a
# half turn, so one sheet comes back beside itself (self-parallel). The second, a hex-dominant
# cylinder with prism columns like the paper's teaser, has only perfect sheets: no subsheets (g).
# When the shared data is there, teapot.hedra (LoopyCuts) is a third subject. Each also gets a short
# animation (render_figures.py --animate explode) with a strip of its frames.
#
# The figures are rendered by the newest Blender here that loads this build's hbc module: a `bpy`
# wheel of the test matrix (scripts/env/blender_envs.sh, made by scripts/test.sh; not made here)
# when one is there, whose Cycles denoises with OpenImageDenoise; else Debian's blender (3.4,
# without a denoiser). The demo says which one it used.
#
# Environment: HBC_DEMO_ENGINE (cycles | eevee | workbench, default cycles),
# HBC_DEMO_RESOLUTION ("480 360"), HBC_DEMO_SAMPLES (12), HBC_DATA_DIR (../shared/data),
# HBC_DEMO_BLENDER (auto: the newest, as above; debian: Debian's blender).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/env/deps.sh
bash scripts/build.sh
source scripts/env/common.sh

ENGINE=${HBC_DEMO_ENGINE:-cycles}
read -r W H <<<"${HBC_DEMO_RESOLUTION:-480 360}"
SAMPLES=${HBC_DEMO_SAMPLES:-12}
DATA=$HBC_DATA_DIR
OUT=out
FIG=$OUT/figures
mkdir -p "$FIG"
start=$SECONDS

./build/bin/hbc generate twisted-pair --section 4 --sections 24 -o "$OUT/twisted_pair.ovm"
./build/bin/hbc generate cylinder --radius-cells 6 --layers 10 -o "$OUT/cylinder.ovm"
meshes=("$OUT/twisted_pair.ovm" "$OUT/cylinder.ovm")
teapot=$DATA/hybrid-base-complex/teapot.hedra
[ -f "$teapot" ] && meshes+=("$teapot")

echo
echo "== Table 1 (hbc table --md)"
./build/bin/hbc table --md "${meshes[@]}"

# Blender keeps its own user folders out of this: nothing of the user's configuration is read.
export BLENDER_USER_CONFIG=$PWD/$OUT/.blender/config BLENDER_USER_SCRIPTS=$PWD/$OUT/.blender/scripts
export HBC_ADDON_DIR=$PWD/build/addon/hybrid_base_complex

# RENDER: the command that runs render_figures.py (its arguments follow); RENDERER: its name.
pick_renderer() {
  local version python
  if [ "${HBC_DEMO_BLENDER:-auto}" != debian ]; then
    while read -r version python; do
      # Usable when the wheel starts and the add-on's hbc module is built for its Python (4.2-5.0
      # share Debian's CPython 3.11; 5.1+ need a build for 3.13).
      [ -x "$python" ] && "$python" -c "import sys; sys.path.insert(0, sys.argv[1]); import bpy, hbc" \
        "$HBC_ADDON_DIR" >/dev/null 2>&1 || continue
      RENDER=("$python" blender_scripts/render_figures.py)
      RENDERER="Blender $version (the bpy wheel in $(dirname "$(dirname "$python")"))"
      return
    done < <(bash scripts/env/blender_envs.sh --paths | sort -k1,1 -V -r)
  fi
  RENDER=(blender -b --factory-startup --python-exit-code 1 --python blender_scripts/render_figures.py --)
  RENDERER="Debian's $(blender --version 2>/dev/null | head -n 1)"
  [ "${HBC_DEMO_BLENDER:-auto}" = debian ] || RENDERER+=" (fallback: no bpy wheel of the test matrix loads this build)"
}
pick_renderer
echo
echo "== Renderer: $RENDERER"

for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh"); name=${name%.*}
  log=$FIG/$name.log
  echo
  echo "== Figures of $mesh ($ENGINE, ${W}x${H}; full log: $log)"
  if ! "${RENDER[@]}" "$mesh" --out "$FIG" --engine "$ENGINE" --resolution "$W" "$H" --samples "$SAMPLES" >"$log" 2>&1; then
    tail -n 30 "$log"
    echo "demo: rendering the figures of $mesh failed (see $log)" >&2
    exit 1
  fi
  sed -n -e 's/^render_figures: //p' -e 's/^wrote /  wrote /p' "$log"
done

# One short animation per mesh beside its figures: the base complex exploded and back (Workbench,
# 2 s), with a strip of six of its frames (the README's picture is teapot's).
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh"); name=${name%.*}
  log=$FIG/${name}_animation.log
  echo
  echo "== Animation of $mesh (explode, Workbench 480x270, 48 frames; full log: $log)"
  if ! "${RENDER[@]}" "$mesh" --out "$FIG" --animate explode --engine workbench --resolution 480 270 \
      --frames 48 --fps 24 --strip 6 >"$log" 2>&1; then
    tail -n 30 "$log"
    echo "demo: rendering the animation of $mesh failed (see $log)" >&2
    exit 1
  fi
  sed -n -e 's/^render_figures: //p' -e 's/^wrote /  wrote /p' "$log"
done

echo
echo "demo: done in $((SECONDS - start)) s after the build, rendered by $RENDERER. Figures (one PNG per panel, *_contact.png all of them):"
ls -1 "$FIG"/*_contact.png | sed 's/^/  /'
echo "Animations (MP4, and a strip of frames each):"
ls -1 "$FIG"/*_explode.mp4 "$FIG"/*_explode_strip.png | sed 's/^/  /'
echo "  all panels: $FIG/"
