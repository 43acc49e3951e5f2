#!/usr/bin/env bash
# Makes (once) the virtual environment of the independent checks and prints its Python:
#   scripts/env/check_env.sh        -> $HBC_ENV_DIR/py-check/bin/python (default ~/.cache/hbc-envs)
# It holds the newest NumPy (2.x), VTK's wheel (vtkMeshQuality, vtkCellSizeFilter: Verdict, as
# ParaView computes quality and volume) and pytest, on the CPython the binding is built for
# ($HBC_PYTHON, Debian's 3.11): the build's module imports in it, so the tests read the same module
# under NumPy 2 here and under Debian's NumPy 1.x in $HBC_PYTHON itself. Made under a lock; the stamp
# names what was asked for and is written last, so a half-made or outdated environment is made again.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
VENV=$HBC_ENV_DIR/py-check
# What the checks need; the stamp holds this line, so adding a package remakes the environment.
PACKAGES="numpy>=2 vtk>=9.4 pytest"
mkdir -p "$HBC_ENV_DIR"
exec 9>"$VENV.lock"
flock 9
if [ "$(cat "$VENV/.hbc-check" 2>/dev/null)" = "$PACKAGES" ] && [ -x "$VENV/bin/python" ]; then
  echo "$VENV/bin/python"
  exit 0
fi
if ! "$HBC_PYTHON" -c "import ensurepip, venv" 2>/dev/null; then
  echo "check_env.sh: $HBC_PYTHON has no venv module: run scripts/env/deps.sh (python3-venv)" >&2
  exit 1
fi
rm -rf "$VENV"
"$HBC_PYTHON" -m venv "$VENV" >&2
# shellcheck disable=SC2086
"$VENV/bin/python" -m pip install -q --disable-pip-version-check $PACKAGES >&2
"$VENV/bin/python" -c "import numpy, vtk; assert int(numpy.__version__.split('.')[0]) >= 2" >&2
echo "$PACKAGES" >"$VENV/.hbc-check"
echo "$VENV/bin/python"
