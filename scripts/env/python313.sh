#!/usr/bin/env bash
# Prints the path of a CPython 3.13 (for the cp313 bpy wheels of Blender 5.1+ and the cp313 hbc
# module) with the modules the venvs and wheels need, trying in turn:
#   1. $HBC_PYTHON313, when set (it must work, or the script fails);
#   2. a pyenv CPython 3.13 (the machine image has 3.13.0 under $(pyenv root)/versions);
#   3. the one this script built before, in $HBC_ENV_DIR/python3.13;
#   4. a build from the source of Debian 13's python3.13 package (about 5 minutes on 2 cores), into
#      that prefix. Debian 12 packages no 3.13; its registry serves the trixie source through a
#      sources list of our own (the system's apt state is not touched).
set -euo pipefail
source "$(dirname "$0")/common.sh"
ENV_DIR=$HBC_ENV_DIR
PREFIX=$ENV_DIR/python3.13
usable() { [ -x "$1" ] && "$1" -c "import ssl, sqlite3, zlib, lzma, bz2, ctypes, venv, ensurepip" 2>/dev/null; }
if [ -n "${HBC_PYTHON313:-}" ]; then
  usable "$HBC_PYTHON313" || { echo "python313.sh: HBC_PYTHON313=$HBC_PYTHON313 lacks ssl/sqlite3/zlib/lzma/bz2/ctypes/venv" >&2; exit 1; }
  echo "$HBC_PYTHON313"; exit 0
fi
PYENV_ROOT=${PYENV_ROOT:-$(pyenv root 2>/dev/null || echo "$HOME/.pyenv")}
find_one() {
  local py
  for py in $(ls -d "$PYENV_ROOT"/versions/3.13.*/bin/python3.13 2>/dev/null | sort -rV) "$PREFIX/bin/python3.13"; do
    if usable "$py"; then echo "$py"; return 0; fi
  done
  return 1
}
find_one && exit 0
# The build, under a lock: the bpy 5.2 environment and the wheels may ask for it at the same time.
mkdir -p "$ENV_DIR"
exec 9>"$ENV_DIR/python3.13.lock"
flock 9
find_one && exit 0
echo "python313.sh: no CPython 3.13 found; building one from Debian 13's source into $PREFIX (about 5 minutes)" >&2
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
BUILD_DEPS=(libssl-dev zlib1g-dev libffi-dev libbz2-dev libsqlite3-dev liblzma-dev libreadline-dev xz-utils)
missing=()
for p in "${BUILD_DEPS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get update >&2
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "${missing[@]}" >&2
fi
WORK=$ENV_DIR/python3.13-src
mkdir -p "$WORK/lists/partial" "$WORK/cache/archives/partial"
# The machine's own Debian mirror, from whichever sources format it uses.
MIRROR=$( (cat /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '/^[[:space:]]*URIs:/ {print $2}';
           cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null \
             | awk '/^[[:space:]]*deb[[:space:]]/ {for (i = 2; i <= NF; i++) if ($i ~ /^https?:/) {print $i; break}}') \
         | grep -v security | head -1 || true)
MIRROR=${MIRROR:-http://deb.debian.org/debian}
echo "deb-src ${MIRROR%/} trixie main" > "$WORK/sources.list"
APT_OPTS=(-o Dir::Etc::sourcelist="$WORK/sources.list" -o Dir::Etc::sourceparts=/nonexistent
          -o Dir::State::Lists="$WORK/lists" -o Dir::Cache="$WORK/cache" -o APT::Get::List-Cleanup=0)
cd "$WORK"
if ! ls python3.13_*.orig.tar.xz >/dev/null 2>&1; then
  apt-get "${APT_OPTS[@]}" update >&2
  apt-get "${APT_OPTS[@]}" source --download-only python3.13 >&2
fi
tarball=$(ls python3.13_*.orig.tar.xz | head -1)
rm -rf src && mkdir src && tar xf "$tarball" -C src --strip-components=1
cd src
./configure --prefix="$PREFIX" --with-ensurepip=install >&2
make -j"$(nproc)" >&2
make install >&2
cd "$WORK" && rm -rf src
echo "$PREFIX/bin/python3.13"
