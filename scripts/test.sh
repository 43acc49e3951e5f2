#!/usr/bin/env bash
# Runs every test; CI runs this (.ci/run). Its parts:
#   deps          the Debian packages (scripts/env/deps.sh; apt-get, only what is missing)
#   bpy_envs      a virtual environment per bpy wheel of the matrix, 4.2 4.5 5.0 on CPython 3.11 and
#                 5.2 on 3.13 (scripts/env/blender_envs.sh: made once under ~/.cache/hbc-envs, then reused)
#   asan_build    the C++ suite with ASan + UBSan (scripts/check/asan_ubsan.sh, build-asan/)
#   asan_run      ... and its run: the whole C++ suite, leaks and undefined behaviour failing it
#   tsan_build    the C++ suite with TSan (scripts/check/tsan.sh, build-tsan/)
#   tsan_run      ... and its run over the parallel parts
#   release_build the Release build (scripts/build.sh, build/), configured for the whole matrix
#   wasm_build    the library, CLI, C++ suite and JS binding in WebAssembly (scripts/build_wasm.sh, build-wasm/)
#   wasm_tests    ... run under node: the C++ suite, the CLI against the native one on every shared mesh,
#                 the binding (ctest --test-dir build-wasm; docs/wasm.md)
#   web_build     the browser viewer, build/web/viewer.html (scripts/build_web.sh, WebAssembly core included)
#   wheels        the hbc wheels for CPython 3.11 and 3.13 and the Blender extension (scripts/wheels.sh)
#   ctest         the Release build's suite: GoogleTest, pytest, and the Blender-side suites in every
#                 Blender of the matrix (Debian's blender and each bpy wheel)
# Parts that do not need each other overlap on the machine's cores: the bpy downloads run while the
# C++ trees compile, and each sanitizer run beside the next build. Each part writes its output to
# build/test-logs/<part>.log (ctest's is shown as well); a failing part's last lines are printed, the
# parts that need it are skipped, the others go on. At the end a table gives each part's status,
# start, wall time and CPU time; the exit status is non-zero when any part failed.
#   HBC_QUICK=1              the inner loop: the Release build and ctest with Debian's blender only
#                            (no sanitizers, no bpy wheels, no hbc wheels or extension)
#   HBC_SKIP_SANITIZED=1     leaves out the four sanitizer parts
#   HBC_BPY_VERSIONS="4.5"   only these bpy wheels in the matrix (default: every one)
#   HBC_CTEST_ARGS="-R foo"  extra ctest arguments
#   HBC_SKIP_WASM=1          leaves out wasm_build and wasm_tests
#   HBC_SKIP_WEB=1           leaves out the browser viewer's build (web_build); its browser tests skip
#   HBC_DATA_DIR, HBC_PYTHON, HBC_ENV_DIR: see scripts/env/common.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env/common.sh
ROOT=$PWD
# The tests read the shared meshes and fail without them: say so now, not after the builds.
if [ ! -d "$HBC_DATA_DIR" ]; then
  echo "test.sh: the shared meshes are not at $HBC_DATA_DIR; set HBC_DATA_DIR to their folder" >&2
  exit 1
fi
LOGS=$ROOT/build/test-logs
mkdir -p "$LOGS"
rm -f "$LOGS"/*.log "$LOGS"/*.status "$LOGS"/*.time
T0=$EPOCHREALTIME
JOBS=$(nproc)
QUICK=${HBC_QUICK:-0}
SANITIZED=1
if [ "$QUICK" = 1 ] || [ "${HBC_SKIP_SANITIZED:-0}" = 1 ]; then SANITIZED=0; fi

declare -a PARTS=()
declare -A PID=() NOTE=()
failed=0

# part_start NAME COMMAND...: runs COMMAND in the background, output to $LOGS/NAME.log; its exit
# status, start, wall and CPU seconds go to $LOGS/NAME.status.
part_start() {
  local name=$1
  shift
  PARTS+=("$name")
  : >"$LOGS/$name.log"
  (
    set +e
    start=$EPOCHREALTIME
    TIMEFORMAT='%R %U %S'
    { time "$@" >"$LOGS/$name.log" 2>&1; } 2>"$LOGS/$name.time"
    rc=$?
    read -r wall user sys <"$LOGS/$name.time"
    echo "$rc $start $wall $(awk "BEGIN { print $user + $sys }")" >"$LOGS/$name.status"
  ) &
  PID[$name]=$!
  echo "test: $name started"
}

# part_wait NAME: waits for the part; prints how it ended (the end of its log when it failed) and
# returns its exit status.
part_wait() {
  local name=$1 rc start wall cpu lines=60
  wait "${PID[$name]}" || true
  if [ ! -f "$LOGS/$name.status" ]; then
    echo "test: $name ended without a status" >&2
    failed=1
    return 1
  fi
  read -r rc start wall cpu <"$LOGS/$name.status"
  if [ "$rc" -eq 0 ]; then
    printf 'test: %s done in %.0f s\n' "$name" "$wall"
    return 0
  fi
  failed=1
  [ "$name" = ctest ] && lines=0  # already shown
  echo "test: $name FAILED (exit status $rc); log: $LOGS/$name.log" >&2
  [ $lines -gt 0 ] && tail -n $lines "$LOGS/$name.log" | sed "s/^/  $name| /" >&2
  return "$rc"
}

part_run() { part_start "$@"; part_wait "$1"; }

# part_skip NAME REASON: a part that does not run because a part it needs failed.
part_skip() {
  PARTS+=("$1")
  NOTE[$1]=$2
  echo "test: $1 skipped: $2" >&2
  failed=1
}

summary() {
  local now name rc start wall cpu status
  now=$EPOCHREALTIME
  echo
  echo "== scripts/test.sh: the parts' times (wall and CPU seconds; started = seconds after the start)"
  printf '%-14s %-22s %8s %8s %8s\n' part status started wall CPU
  for name in "${PARTS[@]}"; do
    if [ -f "$LOGS/$name.status" ]; then
      read -r rc start wall cpu <"$LOGS/$name.status"
      status=ok
      [ "$rc" -ne 0 ] && status="FAILED ($rc)"
      printf '%-14s %-22s %8.0f %8.0f %8.0f\n' "$name" "$status" "$(awk "BEGIN { print $start - $T0 }")" "$wall" "$cpu"
    elif [ -n "${NOTE[$name]:-}" ]; then
      printf '%-14s %-22s\n' "$name" "skipped: ${NOTE[$name]}"
    else
      printf '%-14s %-22s\n' "$name" "did not finish"
    fi
  done
  printf '%-14s %-22s %8s %8.0f\n' total "" "" "$(awk "BEGIN { print $now - $T0 }")"
  echo "logs: $LOGS/"
}
# The processes under PID, then PID itself.
kill_tree() {
  local child
  for child in $(ps -o pid= --ppid "$1" 2>/dev/null); do kill_tree "$child"; done
  kill "$1" 2>/dev/null || true
}
# Also when the script stops early (an error, an interrupt): the parts still running are stopped.
on_exit() {
  local status=$? name
  for name in "${!PID[@]}"; do
    [ -f "$LOGS/$name.status" ] || kill_tree "${PID[$name]}"
  done
  summary
  [ $failed -eq 0 ] && [ $status -eq 0 ] || exit 1
}
trap on_exit EXIT

part_run deps bash scripts/env/deps.sh || exit 1

# The Blenders of the matrix: the Release tree is configured with the environments' paths at once,
# while they are being made; ctest waits for them.
pairs=""
if [ "$QUICK" != 1 ]; then
  # shellcheck disable=SC2086
  pairs=$(bash scripts/env/blender_envs.sh --paths ${HBC_BPY_VERSIONS:-} | awk '{printf "%s%s=%s", sep, $1, $2; sep=";"}')
  # shellcheck disable=SC2086
  part_start bpy_envs bash scripts/env/blender_envs.sh ${HBC_BPY_VERSIONS:-}
fi

if [ $SANITIZED = 1 ]; then
  if part_run asan_build bash scripts/check/asan_ubsan.sh --build; then
    part_start asan_run bash scripts/check/asan_ubsan.sh --run
  else
    part_skip asan_run "asan_build failed"
  fi
  if part_run tsan_build bash scripts/check/tsan.sh --build; then
    part_start tsan_run bash scripts/check/tsan.sh --run
  else
    part_skip tsan_run "tsan_build failed"
  fi
fi

# WebAssembly beside the Release build; web_build waits for it (both would build build-wasm/).
WASM=1; [ "${HBC_SKIP_WASM:-0}" = 1 ] && WASM=0
if [ $WASM = 1 ]; then part_start wasm_build bash scripts/build_wasm.sh; fi
release_ok=1
part_run release_build bash scripts/build.sh -DHBC_BPY_PYTHONS="$pairs" || release_ok=0
wasm_ok=0
if [ $WASM = 1 ] && part_wait wasm_build; then wasm_ok=1; fi
# The browser viewer: scripts/build_web.sh writes build/web/viewer.html (building the WebAssembly
# core into build-wasm/ first when that is out of date: only its binding, hbc_core, unless
# HBC_WASM_TARGETS says more) beside the wheels; ctest's browser tests (tests/web/) open it in
# chromium, and with the page built here they fail rather than skip without it.
if [ "${HBC_SKIP_WEB:-0}" != 1 ]; then
  if [ $WASM = 1 ] && [ $wasm_ok = 0 ]; then
    part_skip web_build "wasm_build failed"  # its failure is shown; building the core again would not help
  else
    part_start web_build env HBC_WASM_TARGETS="${HBC_WASM_TARGETS:-hbc_core}" bash scripts/build_web.sh
  fi
fi
# The node runs compare with the Release build's hbc.
if [ $WASM = 1 ] && [ $wasm_ok = 1 ] && [ $release_ok = 1 ]; then
  part_start wasm_tests ctest --test-dir build-wasm --output-on-failure -j2
elif [ $WASM = 1 ]; then
  part_skip wasm_tests "wasm_build or release_build failed"
fi

if [ "$QUICK" != 1 ]; then
  if [ $release_ok = 1 ]; then
    # Without arguments wheels.sh builds for $HBC_PYTHON and CPython 3.13 (which the bpy 5.1+
    # wheels run on); with HBC_BPY_VERSIONS naming none of those, for $HBC_PYTHON alone.
    wheel_pythons=("$HBC_PYTHON")
    case "$pairs" in *5.[1-9]=* | *[6-9].[0-9]=*) wheel_pythons=() ;; esac
    part_run wheels bash scripts/wheels.sh "${wheel_pythons[@]}" || true
  else
    part_skip wheels "release_build failed"
  fi
  part_wait bpy_envs || true
fi

if [ -n "${PID[web_build]:-}" ]; then part_wait web_build || true; fi
if [ "${HBC_SKIP_WEB:-0}" != 1 ]; then export HBC_WEB_REQUIRED=1; fi

if [ $release_ok = 1 ]; then
  # ctest's own output is shown as it comes; a bpy environment that failed shows up as its Blender's
  # failing check (blender_check@bpy-<version>), so ctest runs anyway.
  # shellcheck disable=SC2086
  part_start ctest ctest --test-dir build --output-on-failure -j"$JOBS" ${HBC_CTEST_ARGS:-}
  tail -n +1 -f --pid="${PID[ctest]}" "$LOGS/ctest.log" | sed 's/^/  ctest| /' &
  tail_pid=$!
  wait "$tail_pid" 2>/dev/null || true  # it ends with ctest (--pid), its last lines shown
  part_wait ctest || true
else
  part_skip ctest "release_build failed"
fi

for name in asan_run tsan_run wasm_tests; do
  if [ -n "${PID[$name]:-}" ]; then part_wait "$name" || true; fi
done
