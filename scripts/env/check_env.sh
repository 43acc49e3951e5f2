#!/usr/bin/env bash
# Makes (once) the virtual environment of the independent checks and prints its Python:
#   scripts/env/check_env.sh        -> $HBC_ENV_DIR/py-check/bin/python (default ~/.cache/hbc-envs)
# It holds the newest NumPy (2.x), VTK's wheel (vtkMeshQuality, vtkCellSizeFilter: Verdict, as
# ParaView computes quality and volume) and pytest, on the CPython the binding is built for
# ($HBC_PYTHON, Debian's 3.11): the build's module imports in it, so the tests read the same module
# under NumPy 2 here and under Debian's NumPy 1.x in $HBC_PYTHON itself. Made under a lock; the stamp
# names what was asked for (scripts/env/common.sh, hbc_stamped_venv).
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
VENV=$HBC_ENV_DIR/py-check
# What the checks need; the stamp holds this line, so adding a package remakes the environment.
PACKAGES="numpy>=2 vtk>=9.4 pytest"
hbc_stamped_venv "$VENV" "$PACKAGES" "import numpy, vtk; assert int(numpy.__version__.split('.')[0]) >= 2"
echo "$VENV/bin/python"
