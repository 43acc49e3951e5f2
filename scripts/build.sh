#!/usr/bin/env bash
# Configures and builds everything but the benchmarks into build/ (Release), for $HBC_PYTHON
# (scripts/env/common.sh). Extra arguments go to cmake's configure step, e.g.
# -DHBC_BUILD_BENCHMARKS=ON or -DHBC_BLENDER=OFF. It installs no Debian package: a missing one
# stops it with the command that installs it (scripts/env/deps.sh). The module's pybind11 is PyPI's,
# pinned, made once under $HBC_ENV_DIR (scripts/env/pybind11.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env/common.sh
mapfile -t missing < <(hbc_missing_packages)
if [ ${#missing[@]} -gt 0 ]; then
  echo "build.sh: missing Debian packages: ${missing[*]}" >&2
  echo "build.sh: install them with: bash scripts/env/deps.sh   (apt-get, through sudo when not root)" >&2
  exit 1
fi
hbc_use_pybind11
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DHBC_BUILD_BENCHMARKS=OFF "${HBC_CMAKE_ARGS[@]}" "$@" >/dev/null
cmake --build build -j"$(nproc)"
