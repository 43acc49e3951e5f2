#!/usr/bin/env bash
# Builds the library, the hbc CLI, the GoogleTest suite and the JavaScript binding to WebAssembly
# with Debian's emscripten (docs/wasm.md):
#
#   bash scripts/build_wasm.sh [BUILD_DIR]      (default: build-wasm/ at the repository root)
#
# zlib and pugixml come from Debian's source packages (fetched once into BUILD_DIR/deps through a
# private apt sources list: the system's apt state is not touched). Outputs: BUILD_DIR/bin/hbc.js
# (run as `node BUILD_DIR/bin/hbc.js analyze FILE`), BUILD_DIR/tests/wasm/hbc_tests.js,
# BUILD_DIR/web/hbc_core.js + .wasm. HBC_WASM_TARGETS narrows what is built (default: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath -m "${1:-$root/build-wasm}")
command -v emcmake >/dev/null || { echo "emscripten is missing: apt-get install -y emscripten libfast-float-dev" >&2; exit 2; }
mkdir -p "$build/deps"

# Debian's zlib and pugixml sources (the versions of Debian 12, whose binary packages the native
# build links).
deps=$build/deps
if [ ! -f "$deps/zlib/zlib.h" ] || [ ! -f "$deps/pugixml/src/pugixml.hpp" ]; then
  apt=$deps/apt
  mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial"
  mirror=$( { sed -n 's/^URIs: *//p' /etc/apt/sources.list.d/*.sources; sed -n 's/^deb \(\[[^]]*\] \)\?\([^ ]*\) .*/\2/p' /etc/apt/sources.list; } 2>/dev/null | grep -v security | head -1 || true)
  echo "deb-src ${mirror:-http://deb.debian.org/debian} bookworm main" > "$apt/sources.list"
  opts=(-o Dir::Etc::sourcelist="$apt/sources.list" -o Dir::Etc::sourceparts=/nonexistent
        -o Dir::State::Lists="$apt/lists" -o Dir::Cache="$apt/cache")
  apt-get "${opts[@]}" update > "$apt/update.log" 2>&1
  (cd "$deps" && apt-get "${opts[@]}" source --download-only zlib pugixml > "$apt/source.log" 2>&1)
  mkdir -p "$deps/zlib" "$deps/pugixml"
  tar -xf "$deps"/zlib_*.orig.tar.* -C "$deps/zlib" --strip-components=1
  tar -xf "$deps"/pugixml_*.orig.tar.* -C "$deps/pugixml" --strip-components=1
fi

# emscripten's JS optimizer needs Debian's node-acorn, which a node other than Debian's (nodesource)
# does not look for in /usr/share/nodejs.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
emcmake cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHBC_BUILD_BENCHMARKS=OFF \
  -DHBC_WASM_DEPS_DIR="$deps" "${launcher[@]}" > "$build/configure.log"
cmake --build "$build" -j"${HBC_WASM_JOBS:-2}" ${HBC_WASM_TARGETS:+--target $HBC_WASM_TARGETS}
