#!/usr/bin/env bash
# Makes (once) the pybind11 every build tree compiles the Python module with, and prints its CMake
# folder (for -Dpybind11_DIR=...; scripts/env/common.sh's hbc_use_pybind11 passes it):
#   scripts/env/pybind11.sh        -> $HBC_ENV_DIR/pybind11/.../pybind11/share/cmake/pybind11
# PyPI's pybind11, pinned: Debian 12's 2.10.3 predates NumPy 2, and a module built with it returns
# every array with stride 0 under NumPy 2 (every element equal to the first), without an error;
# 2.12 is the first to read NumPy 2's arrays (and NumPy 1's alike). Headers and CMake files only,
# so the virtual environment's Python does not matter; $HBC_PYTHON makes it. Made under a lock; the
# stamp names the pin and is written last, so a half-made or outdated one is made again.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
VENV=$HBC_ENV_DIR/pybind11
# The pin; the stamp holds this line, so changing it remakes the environment. pyproject.toml asks
# `pip install .` for a range starting at the same minimum (2.12).
PACKAGE="pybind11==2.13.6"
hbc_stamped_venv "$VENV" "$PACKAGE"
"$VENV/bin/python" -m pybind11 --cmakedir
