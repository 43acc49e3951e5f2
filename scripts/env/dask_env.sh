#!/usr/bin/env bash
# Makes (once) the virtual environment of the Dask and submitit tests of hbc.compare and prints its Python:
#   scripts/env/dask_env.sh        -> $HBC_ENV_DIR/py-dask/bin/python (default ~/.cache/hbc-envs)
# Dask's `distributed` (a LocalCluster of worker processes, Client.get_executor()), submitit (its
# executor, the SLURM one, run with cluster="local"), NumPy and pytest,
# on the CPython the binding is built for ($HBC_PYTHON, Debian's 3.11), so that the build's module
# imports in it. Made under a lock; the stamp names what was asked for (common.sh, hbc_stamped_venv).
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
VENV=$HBC_ENV_DIR/py-dask
PACKAGES="numpy distributed submitit pytest"
hbc_stamped_venv "$VENV" "$PACKAGES" "import distributed, numpy, submitit"
echo "$VENV/bin/python"
