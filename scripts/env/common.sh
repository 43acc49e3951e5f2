# Settings every script shares (sourced, not run): which Python the build uses, where the shared
# meshes and the test environments are, and the cmake arguments every build tree gets.
#   HBC_PYTHON    the Python the binding is built for and tested with (default /usr/bin/python3:
#                 Debian's CPython 3.11, which Debian's Blender embeds and which has numpy and
#                 pytest; a bare search would find the pyenv Python first on PATH, which has neither)
#   HBC_DATA_DIR  the shared real meshes (default ../shared/data beside the checkout)
#   HBC_ENV_DIR   the bpy virtual environments, CPython 3.13, the checks' Python and the pinned
#                 pybind11 (default ~/.cache/hbc-envs)
# Compiles go through ccache when it is installed (scripts/env/deps.sh installs it), into ccache's
# own persistent cache (~/.cache/ccache, 5 GB by default; all five trees of scripts/test.sh took
# 0.19 GB, compressed, so it holds many versions of them; CCACHE_DIR and CCACHE_MAXSIZE change it).
HBC_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
HBC_PYTHON=${HBC_PYTHON:-/usr/bin/python3}
HBC_DATA_DIR=$(realpath -m "${HBC_DATA_DIR:-$HBC_ROOT/../shared/data}")
HBC_ENV_DIR=${HBC_ENV_DIR:-$HOME/.cache/hbc-envs}
export HBC_PYTHON HBC_DATA_DIR HBC_ENV_DIR
HBC_CMAKE_ARGS=(-DPython_EXECUTABLE="$HBC_PYTHON" -DHBC_DATA_DIR="$HBC_DATA_DIR")
if command -v ccache >/dev/null; then
  HBC_CMAKE_ARGS+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# Every script that configures a tree (the Python module is part of every tree) calls this first:
# it adds -Dpybind11_DIR= for the pinned PyPI pybind11 of scripts/env/pybind11.sh (made once under
# $HBC_ENV_DIR), which reads NumPy 2's arrays; Debian's 2.10.3 does not (native/python/CMakeLists.txt).
hbc_use_pybind11() {
  local dir
  dir=$(bash "$HBC_ROOT/scripts/env/pybind11.sh") || return 1
  HBC_CMAKE_ARGS+=(-Dpybind11_DIR="$dir")
}
# hbc_stamped_venv VENV PACKAGES [CHECK]: makes (once) a virtual environment of $HBC_PYTHON at VENV
# holding PACKAGES (one pip argument string) and returns; CHECK, Python code, must then run in it.
# Made under VENV.lock so two runs never build the same folder; the stamp (VENV/.hbc-stamp) holds
# PACKAGES and is written last, so a half-made or outdated environment is made again. pip's output
# goes to stderr: the callers print a path on stdout.
hbc_stamped_venv() {
  local venv=$1 packages=$2 check=${3:-}
  mkdir -p "$(dirname "$venv")"
  (
    exec 9>"$venv.lock"
    flock 9
    [ "$(cat "$venv/.hbc-stamp" 2>/dev/null)" = "$packages" ] && [ -x "$venv/bin/python" ] && exit 0
    if ! "$HBC_PYTHON" -c "import ensurepip, venv" 2>/dev/null; then
      echo "$HBC_PYTHON has no venv module: run scripts/env/deps.sh (python3-venv)" >&2
      exit 1
    fi
    rm -rf "$venv"
    "$HBC_PYTHON" -m venv "$venv" >&2
    # shellcheck disable=SC2086
    "$venv/bin/python" -m pip install -q --disable-pip-version-check $packages >&2
    [ -z "$check" ] || "$venv/bin/python" -c "$check" >&2
    echo "$packages" >"$venv/.hbc-stamp"
  )
}
# Debian packages scripts/env/deps.sh installs; hbc_missing_packages prints those not installed.
# openfoam and openfoam-examples make the real snappyHexMesh cases (scripts/env/foam_cases.sh).
# pybind11-dev (2.10.3) no longer builds the module (hbc_use_pybind11); the test of the module's
# NumPy 2 refusal compiles its probe with it (tests/numpy_abi/).
HBC_DEBIAN_PACKAGES=(cmake g++ make pkg-config python3-dev python3-numpy python3-pytest pybind11-dev
  python3-pybind11 libopenmesh-dev libeigen3-dev libboost-dev libboost-graph-dev libgtest-dev
  libbenchmark-dev blender libpugixml-dev zlib1g-dev python3-meshio libcli11-dev nlohmann-json3-dev
  python3-venv ccache openfoam openfoam-examples
  xvfb xauth  # Blender with its window: the add-on's window test (tests/addon/window), panel_screenshot.py
  nodejs  # the web viewer's build and its browser tests (tests/web/; npm comes with it or as Debian's npm)
  python3-matplotlib python3-rich chromium  # hbc gallery's progress bar; hbc compare's report.html: its plots; the browser test
  emscripten libfast-float-dev  # the WebAssembly build (scripts/build_wasm.sh, docs/wasm.md)
  ffmpeg  # ffprobe checks the animations' videos (tests/figures); ffmpeg makes their GIFs
  gmsh  # writes the .su2 and .msh test files (tests/data/formats/make_real_files.py)
  libnetcdf-dev libexodusii-dev libcgns-dev libhdf5-dev  # the Exodus II and CGNS readers; libexodus and cgnslib write test inputs
  netcdf-bin cgns-convert  # nccopy, aflr3_to_cgns, hdf2adf: tests/data/formats/make_exodus_cgns_files.py
  gmsh hyperfine)  # the decks' twins (tests/data/formats/make_deck_files.py); timing readers against MEDIT
hbc_missing_packages() {
  local p
  for p in "${HBC_DEBIAN_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
# The mesh files under DIR (default $HBC_DATA_DIR), one a line, sorted: every file whose extension
# names a mesh format (OpenFOAM case folders are not files; tests reach them by name).
hbc_mesh_files() {
  find "${1:-$HBC_DATA_DIR}" -type f \
    \( -name '*.mesh' -o -name '*.ovm' -o -name '*.ovmb' -o -name '*.HYBRID' -o -name '*.hedra' \
       -o -name '*.msh' -o -name '*.vtk' -o -name '*.vtu' \) | sort
}
