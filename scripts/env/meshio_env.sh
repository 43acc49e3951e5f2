#!/usr/bin/env bash
# Makes (once) the virtual environment whose meshio writes the engineering formats' twins of meshes
# hbc already reads, and prints its Python:
#   scripts/env/meshio_env.sh   -> $HBC_ENV_DIR/py-meshio/bin/python (default ~/.cache/hbc-envs)
# meshio from PyPI (5.3.x; Debian's 5.0 has no Exodus writer for every cell type) with netCDF4, which
# its Exodus writer needs (classic and NETCDF4/HDF5 files), h5py, and pytest. Made under a lock;
# the stamp names what was asked for (scripts/env/common.sh, hbc_stamped_venv).
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
VENV=$HBC_ENV_DIR/py-meshio
PACKAGES="meshio==5.3.5 netCDF4 h5py pytest"
hbc_stamped_venv "$VENV" "$PACKAGES" "import meshio, netCDF4, h5py; assert meshio.__version__.startswith('5.3')"
echo "$VENV/bin/python"
