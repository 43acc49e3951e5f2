#!/usr/bin/env bash
# Creates (once) a virtual environment per Blender of the test matrix holding the `bpy` wheel of
# that version and pytest, and prints one line per environment: "<version> <python>".
#   scripts/env/blender_envs.sh            every version of BPY_VERSIONS below
#   scripts/env/blender_envs.sh 4.5 5.2    only these
# Environments live in $HBC_ENV_DIR (default ~/.cache/hbc-envs), outside any checkout, so fresh
# clones and CI reuse them; a stamp names the installed bpy so a second run downloads nothing.
# bpy 4.2-5.0 are built for CPython 3.11 (Debian's /usr/bin/python3); 5.1+ for 3.13, which
# scripts/env/python313.sh builds from Debian 13's source.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
ENV_DIR=${HBC_ENV_DIR:-$HOME/.cache/hbc-envs}
BPY_VERSIONS=(4.2 4.5 5.0 5.2)
# pytest runs the suites; meshio is the independent VTU reader of the export tests.
EXTRAS="pytest meshio"
[ $# -gt 0 ] && BPY_VERSIONS=("$@")
mkdir -p "$ENV_DIR"

python_for() {
  case "$1" in
    4.*|5.0) echo /usr/bin/python3 ;;
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

for v in "${BPY_VERSIONS[@]}"; do
  venv=$ENV_DIR/bpy-$v
  stamp=$venv/.hbc-bpy
  if [ -f "$stamp" ] && [ -x "$venv/bin/python" ]; then
    # Packages the tests need beside bpy, added to an existing environment when the list grows.
    if [ "$(cat "$venv/.hbc-extras" 2>/dev/null)" != "$EXTRAS" ]; then
      "$venv/bin/python" -m pip install -q $EXTRAS "$(numpy_for "$v")" >&2
      echo "$EXTRAS" > "$venv/.hbc-extras"
    fi
    echo "$v $venv/bin/python"; continue
  fi
  py=$(python_for "$v")
  ensure_venv_module "$py"
  rm -rf "$venv"
  "$py" -m venv "$venv" >&2
  "$venv/bin/python" -m pip install -q --upgrade pip >&2
  # The newest patch release PyPI serves of that minor version (PyPI drops old ones).
  "$venv/bin/python" -m pip install -q "bpy==$v.*" "$(numpy_for "$v")" $EXTRAS >&2
  echo "$EXTRAS" > "$venv/.hbc-extras"
  "$venv/bin/python" -c "import bpy; print(bpy.app.version_string)" > "$stamp"
  echo "$v $venv/bin/python"
done
