#!/usr/bin/env bash
# Creates (once) a virtual environment per Blender of the test matrix holding the `bpy` wheel of
# that version and pytest, and prints one line per environment: "<version> <python>".
#   scripts/env/blender_envs.sh                every version of BPY_VERSIONS below
#   scripts/env/blender_envs.sh 4.5 5.2        only these
#   scripts/env/blender_envs.sh --paths [...]  only print the lines, making nothing (scripts/test.sh
#                                              configures the build while the environments are made)
# Environments live in $HBC_ENV_DIR (default ~/.cache/hbc-envs), outside any checkout, so fresh
# clones and CI reuse them; a stamp names the installed bpy so a second run downloads nothing.
# bpy 4.2-5.0 are built for CPython 3.11: $HBC_PYTHON (Debian's /usr/bin/python3), whose hbc module
# the build tree holds; 5.1+ for 3.13, which scripts/env/python313.sh finds (pyenv) or builds.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
ENV_DIR=$HBC_ENV_DIR
BPY_VERSIONS=(4.2 4.5 5.0 5.2)
# pytest runs the suites; meshio is the independent VTU reader of the export tests.
EXTRAS="pytest meshio"
paths_only=0
[ "${1:-}" = --paths ] && { paths_only=1; shift; }
[ $# -gt 0 ] && BPY_VERSIONS=("$@")
if [ $paths_only = 1 ]; then
  for v in "${BPY_VERSIONS[@]}"; do echo "$v $ENV_DIR/bpy-$v/bin/python"; done
  exit 0
fi
mkdir -p "$ENV_DIR"

python_for() {
  case "$1" in
    4.*|5.0) echo "$HBC_PYTHON" ;;
    *) bash "$HERE/python313.sh" ;;
  esac
}

# Blender's own builds of 4.2-5.0 bundle numpy 1.26; the 4.2 wheel does not pin it, and with
# numpy 2 its foreach_set no longer takes numpy arrays.
numpy_for() {
  case "$1" in
    4.*|5.0) echo "numpy<2" ;;
    *) echo numpy ;;
  esac
}

ensure_venv_module() {
  # Debian splits venv/ensurepip out of python3 into python3-venv.
  "$1" -c "import ensurepip, venv" 2>/dev/null && return 0
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update >&2
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y python3-venv >&2
}

# One environment, made under a lock so that two runs (two clones, two people) never build the same
# folder at once; the stamp is written last, so a half-made environment is made again.
make_env() {
  local v=$1 venv=$ENV_DIR/bpy-$1
  local stamp=$venv/.hbc-bpy
  exec 9>"$ENV_DIR/bpy-$v.lock"
  flock 9
  if [ -f "$stamp" ] && [ -x "$venv/bin/python" ]; then
    # Packages the tests need beside bpy, added to an existing environment when the list grows.
    if [ "$(cat "$venv/.hbc-extras" 2>/dev/null)" != "$EXTRAS" ]; then
      "$venv/bin/python" -m pip install -q $EXTRAS "$(numpy_for "$v")"
      echo "$EXTRAS" > "$venv/.hbc-extras"
    fi
    return 0
  fi
  local py
  py=$(python_for "$v")
  ensure_venv_module "$py"
  rm -rf "$venv"
  "$py" -m venv "$venv"
  "$venv/bin/python" -m pip install -q --upgrade pip
  # The newest patch release PyPI serves of that minor version (PyPI drops old ones).
  "$venv/bin/python" -m pip install -q "bpy==$v.*" "$(numpy_for "$v")" $EXTRAS
  echo "$EXTRAS" > "$venv/.hbc-extras"
  "$venv/bin/python" -c "import bpy; print(bpy.app.version_string)" > "$stamp"
}

# The environments are downloads (a few hundred MB each) and unpacking: made side by side, each
# with its log in $ENV_DIR/bpy-<version>.log, shown when it fails.
ready() { [ -f "$ENV_DIR/bpy-$1/.hbc-bpy" ] && [ "$(cat "$ENV_DIR/bpy-$1/.hbc-extras" 2>/dev/null)" = "$EXTRAS" ]; }
pids=()
for v in "${BPY_VERSIONS[@]}"; do
  if ready "$v"; then pids+=(""); continue; fi
  echo "blender_envs: making the bpy $v environment (log: $ENV_DIR/bpy-$v.log)" >&2
  make_env "$v" >"$ENV_DIR/bpy-$v.log" 2>&1 &
  pids+=($!)
done
status=0
for i in "${!BPY_VERSIONS[@]}"; do
  v=${BPY_VERSIONS[$i]}
  [ -z "${pids[$i]}" ] && continue
  if ! wait "${pids[$i]}"; then
    echo "blender_envs: the bpy $v environment failed; the end of its log:" >&2
    tail -n 20 "$ENV_DIR/bpy-$v.log" >&2
    status=1
  fi
done
[ $status -eq 0 ] || exit $status
for v in "${BPY_VERSIONS[@]}"; do
  echo "$v $ENV_DIR/bpy-$v/bin/python"
done
