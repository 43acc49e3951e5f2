#!/usr/bin/env bash
# ctest python_compare_dask: makes the Dask environment (scripts/env/dask_env.sh, once: PyPI) and runs
# test_compare_dask.py in it. Where that environment cannot be made (no venv module, PyPI out of
# reach), the test is skipped (exit 77, SKIP_RETURN_CODE) saying why; a failure of the test fails.
set -uo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
if ! py=$(bash "$HERE/../../scripts/env/dask_env.sh"); then
  echo "python_compare_dask: skipped: the Dask environment (scripts/env/dask_env.sh: distributed from PyPI in a" \
       "venv of ${HBC_PYTHON:-/usr/bin/python3} under ${HBC_ENV_DIR:-~/.cache/hbc-envs}) cannot be made here; its" \
       "message is above" >&2
  exit 77
fi
# The test file: the first argument (default test_compare_dask.py; ctest python_gallery_dask gives its own).
exec "$py" -m pytest -q -p no:cacheprovider "$HERE/${1:-test_compare_dask.py}"
