#!/usr/bin/env bash
# Builds the hbc wheel (pip + scikit-build-core on the project's CMake, pyproject.toml) for each
# Python the test matrix runs Blender with — $HBC_PYTHON (Debian's CPython 3.11) and the CPython 3.13
# of scripts/env/python313.sh — into build/wheels/, puts each wheel's compiled module beside the build
# tree's own (build/python/hbc, and the add-on assembled in build/addon) so that every Blender of
# the matrix imports the same package, and packs the Blender extension (4.2+) with the wheels.
#   scripts/wheels.sh [PYTHON...]     default: $HBC_PYTHON and CPython 3.13
# Build folders persist (build/wheel-build/<tag>), so a second run only relinks; each Python has a
# virtual environment of its own for the build ($HBC_ENV_DIR/wheel-<tag>).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env/common.sh
ROOT=$PWD
ENV_DIR=$HBC_ENV_DIR
PYTHONS=("$@")
[ ${#PYTHONS[@]} -eq 0 ] && PYTHONS=("$HBC_PYTHON" "$(bash scripts/env/python313.sh)")
WHEELS=$ROOT/build/wheels
mkdir -p "$WHEELS/modules"
rm -f "$WHEELS"/*.whl
defines=()
if command -v ccache >/dev/null; then
  defines+=(--config-settings=cmake.define.CMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths under the checkout as ccache sees them relative: the library's objects, alike for every
  # Python (their build folders are at the same depth), are then compiled once, not once per wheel,
  # and hit the cache from a checkout at another path. (Not for the test trees: the tests find
  # their data from __FILE__, which must stay absolute; the library and module do not use it.)
  export CCACHE_BASEDIR=$ROOT
  # One compiler name for every wheel: Debian's CPython would otherwise pass its own
  # (x86_64-linux-gnu-g++, from its sysconfig), and ccache tells compilers apart by name.
  export CXX=${CXX:-c++}
fi
for py in "${PYTHONS[@]}"; do
  tag=$("$py" -c 'import sys; print(f"cp{sys.version_info[0]}{sys.version_info[1]}")')
  venv=$ENV_DIR/wheel-$tag
  if [ ! -x "$venv/bin/pip" ]; then
    "$py" -m venv "$venv"
    "$venv/bin/python" -m pip install -q --upgrade pip
  fi
  # The build's requirements (pyproject.toml's build-system.requires, and ninja, which an isolated
  # build adds itself) installed in this environment once, and the wheel built in it rather than in
  # an isolated one: pybind11's headers then keep one path from run to run, which ccache needs to
  # reuse the module's objects (an isolated build puts them in a new temporary folder each time, and
  # downloads them again).
  reqs=$("$venv/bin/python" -c 'import tomllib
print(" ".join(tomllib.load(open("pyproject.toml", "rb"))["build-system"]["requires"] + ["ninja"]))')
  if [ "$(cat "$venv/.hbc-build-requires" 2>/dev/null)" != "$reqs" ]; then
    # shellcheck disable=SC2086
    "$venv/bin/python" -m pip install -q $reqs
    echo "$reqs" >"$venv/.hbc-build-requires"
  fi
  echo "== hbc wheel for $tag"
  "$venv/bin/python" -m pip wheel -q . --no-deps --no-build-isolation -w "$WHEELS" \
    --config-settings=build-dir="$ROOT/build/wheel-build/$tag" "${defines[@]}"
done
# The compiled module of every other Python, beside the build tree's own (distinct ABI tags in
# their names); the build's own Python keeps the module CMake built.
rm -f "$WHEELS"/modules/*
"$HBC_PYTHON" - "$WHEELS" "$ROOT/build/python/hbc" "$ROOT/build/addon/hybrid_base_complex/hbc" <<'PY'
import glob, os, sys, sysconfig, zipfile
wheels, *targets = sys.argv[1:]
own = sysconfig.get_config_var("EXT_SUFFIX")
for whl in sorted(glob.glob(os.path.join(wheels, "*.whl"))):
    with zipfile.ZipFile(whl) as z:
        for name in z.namelist():
            if name.startswith("hbc/_core.") and name.endswith(".so") and not name.endswith(own):
                data = z.read(name)
                for d in [os.path.join(wheels, "modules"), *targets]:
                    if os.path.isdir(d) or d.endswith("modules"):
                        with open(os.path.join(d, os.path.basename(name)), "wb") as f:
                            f.write(data)
                print("module", os.path.basename(name))
PY
cmake --build build --target addon_zip extension
