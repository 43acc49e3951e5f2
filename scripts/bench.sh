#!/usr/bin/env bash
# Load and analysis benchmark, printed as a Markdown table: every figure of a row, and every ratio
# between rows, comes from the same run. Per case and per variant (this build with 1 and with 2
# threads, and the baseline when given):
#   - hbc_bench_load (BM_LoadFile, one process per case and variant): the time to read the file
#     into memory (read_file_bytes: the hardware's pace), read+parse (read_input) and topology
#     (build_mesh) wall times of the fastest of HBC_BENCH_REPS (default 5) loads, from which parse
#     MB/s, load cells/s and load / read (and the fastest load's user and system CPU and faults);
#   - `hbc analyze --json` under /usr/bin/time: the stage times, the stages' sum against the load,
#     and the peak RSS of the process (and bytes per cell);
#   - the same `hbc analyze` of a one-hex mesh: the process's own footprint (binary, libraries,
#     threads), which the case's peak less it leaves the memory of load + analysis alone.
# With a baseline, the load speed-up and the peak-memory ratios (whole process; load + analysis)
# against it, case by case.
# Cases: armadillo (real, 29,935 cells); rockerarm refined to 678,400 hexes; three 10^6-cell meshes
# from hbc generate: the grid, a hex-dominant cylinder with prism columns, and the all-singleton
# worst case (the grid with 1 % of its cells split into 6 pyramids each); and the grid again with
# its vertices numbered at random (scripts/bench/shuffle_medit_vertices.py), no spatial order at all.
# Usage: scripts/bench.sh [build-dir]
# Environment: HBC_BENCH_DIR keeps the generated meshes (default: a fresh temporary folder);
# HBC_BENCH_BASELINE=DIR compares with the build folder DIR of an earlier commit whose source tree
# is DIR/.. (its bench_load is compiled here from this tree's source against its library);
# HBC_BENCH_LARGE=1 adds the 10^7-cell cases: the 216^3 grid (10,077,696 hexes) and a
# hex-dominant cylinder of about 10^7 cells (minutes per variant), and a second table of linear
# growth (each figure per cell at 10^7 over per cell at 10^6, the load's user and system CPU and
# page faults apart).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target hbc_bench_load hbc_cli >/dev/null

if [[ -z "${HBC_BENCH_DIR:-}" ]]; then
  HBC_BENCH_DIR=$(mktemp -d)
  trap 'rm -rf "$HBC_BENCH_DIR"' EXIT
fi
export HBC_BENCH_DIR
D=$HBC_BENCH_DIR
HBC=$BUILD/bin/hbc
make_case() {  # FILE COMMAND...: generate FILE once
  local f=$1
  shift
  [[ -f "$f" ]] || "$@" -o "$f" >/dev/null
}
make_case "$D/grid_1000000.mesh" "$HBC" generate grid --size 100 100 100
make_case "$D/cylinder_988240.mesh" "$HBC" generate cylinder --radius-cells 50 --layers 110
make_case "$D/split_1050000.mesh" "$HBC" generate split --size 100 100 100 --split pyramids --random 10000
[[ -f "$D/rockerarm_x64.mesh" ]] ||
  /usr/bin/python3 scripts/bench/refine_medit_hexes.py ../shared/data/cinolib/rockerarm.mesh "$D/rockerarm_x64.mesh" 4 >/dev/null
[[ -f "$D/grid_1000000_shuffled.mesh" ]] ||
  /usr/bin/python3 scripts/bench/shuffle_medit_vertices.py "$D/grid_1000000.mesh" "$D/grid_1000000_shuffled.mesh" >/dev/null
cases=(../shared/data/hexalab-edge-cone-rectification/armadillo_out.mesh "$D/rockerarm_x64.mesh" "$D/grid_1000000.mesh"
       "$D/grid_1000000_shuffled.mesh" "$D/cylinder_988240.mesh" "$D/split_1050000.mesh")
if [[ "${HBC_BENCH_LARGE:-0}" == 1 ]]; then
  make_case "$D/grid_10077696.mesh" "$HBC" generate grid --size 216 216 216
  make_case "$D/cylinder_10m.mesh" "$HBC" generate cylinder --radius-cells 160 --layers 110
  cases+=("$D/grid_10077696.mesh" "$D/cylinder_10m.mesh")
fi

variants=("new:1:$BUILD/bin/hbc_bench_load:$HBC" "new:2:$BUILD/bin/hbc_bench_load:$HBC")
if [[ -n "${HBC_BENCH_BASELINE:-}" ]]; then
  B=$HBC_BENCH_BASELINE
  g++ -std=c++20 -O2 -DNDEBUG -DHBC_DATA_DIR="\"$PWD/../shared/data\"" -I"$B/../native/include" \
    native/bench/bench_load.cpp "$B/native/libhbc.a" -lOpenMeshCore -lbenchmark -pthread -o "$D/bench_load_baseline"
  variants=("baseline:1:$D/bench_load_baseline:$B/bin/hbc" "${variants[@]}")
fi

# A one-hex mesh: what `hbc analyze` holds before any real mesh is (about 5-7 MB), which is most of
# armadillo's peak (16 MB) and would hide its load + analysis in the ratio. The smallest of three
# runs, once per variant.
printf 'MeshVersionFormatted 1\nDimension 3\nVertices\n8\n0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n1 1 1 0\n0 1 1 0\nHexahedra\n1\n1 2 3 4 5 6 7 8 0\nEnd\n' >"$D/one_hex.mesh"
own_rss() {  # CLI THREADS: peak RSS in KB of `hbc analyze` on the one-hex mesh
  for _ in 1 2 3; do
    HBC_THREADS=$2 /usr/bin/time -f '%M' -o "$D/own.rss" "$1" analyze "$D/one_hex.mesh" --json >/dev/null
    tail -1 "$D/own.rss"
  done | sort -n | head -1
}
declare -A own
for v in "${variants[@]}"; do
  IFS=: read -r name threads bench cli <<<"$v"
  own[$name.$threads]=$(own_rss "$cli" "$threads")
done

rows=()
for f in "${cases[@]}"; do
  for v in "${variants[@]}"; do
    IFS=: read -r name threads bench cli <<<"$v"
    tag="$D/$(basename "$f").$name.$threads"
    HBC_THREADS=$threads HBC_BENCH_FILE=$f "$bench" --benchmark_filter='^BM_LoadFile$' --benchmark_min_time=0.01 \
      --benchmark_repetitions="${HBC_BENCH_REPS:-5}" --benchmark_format=json >"$tag.load.json"
    HBC_THREADS=$threads /usr/bin/time -f '%M %U %S %e' -o "$tag.rss" "$cli" analyze "$f" --json >"$tag.analyze.json"
    echo "${own[$name.$threads]}" >"$tag.own"
    rows+=("$f|$name|$threads|$tag")
  done
done

/usr/bin/python3 - "${rows[@]}" <<'PY'
import json, os, sys
rows = []
for row in sys.argv[1:]:
    path, name, threads, tag = row.split("|")
    # The fastest repetition: first touches of fresh memory stall at random on this machine
    # (transparent huge pages being compacted), adding up to a second to one load of 10^6 cells.
    reps = [x for x in json.load(open(tag + ".load.json"))["benchmarks"] if x.get("run_type") == "iteration"]
    b = min(reps, key=lambda x: x["parse_s"] + x["build_s"])
    a = json.load(open(tag + ".analyze.json"))
    rss_kb, user, sys_s, wall = open(tag + ".rss").read().split()[-4:]
    rows.append(dict(mesh=os.path.basename(path), code=name, threads=int(threads), b=b, t=a["timings"],
                     rss=int(rss_kb) * 1024, own=int(open(tag + ".own").read()) * 1024,
                     cpu=float(user) + float(sys_s), wall=float(wall)))
base = {r["mesh"]: r for r in rows if r["code"] == "baseline"}
print("| mesh | cells | code | threads | read (ms) | parse MB/s | load (s) | load cells/s | load / read | load speed-up | "
      "analyze's load (s) | singularity graph (s) | base complex (s) | sheets (s) | VSG wireframe (s) | stages / load | analyze wall / CPU (s) | peak RSS (MB) | RSS ratio | bytes/cell | load + analysis RSS (MB) | its ratio |")
print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for r in rows:
    b, t = r["b"], r["t"]
    cells = int(b["cells"])
    mb = b["file_MB"] * 1024 * 1024 / 1e6
    load = b["parse_s"] + b["build_s"]
    stages = t["singularity_graph"] + t["base_complex"] + t["sheets"] + t["subsheets"] + t["vsg_wireframe"]
    ref = base.get(r["mesh"])
    speedup = f"{(ref['b']['parse_s'] + ref['b']['build_s']) / load:.2f}×" if ref and ref is not r else ""
    rss_ratio = f"{r['rss'] / ref['rss']:.2f}" if ref and ref is not r else ""
    work = r["rss"] - r["own"]
    work_ratio = f"{work / (ref['rss'] - ref['own']):.2f}" if ref and ref is not r else ""
    print(f"| {r['mesh']} | {cells:,} | {r['code']} | {r['threads']} | {b['read_s'] * 1e3:.1f} | {mb / b['parse_s']:.0f} | "
          f"{load:.3f} | {cells / load:.3g} | {load / b['read_s']:.0f} | {speedup} | {t['load']:.3f} | {t['singularity_graph']:.3f} | {t['base_complex']:.3f} | "
          f"{t['sheets'] + t['subsheets']:.3f} | {t['vsg_wireframe']:.3f} | {stages / t['load']:.2f} | "
          f"{r['wall']:.2f} / {r['cpu']:.2f} | {r['rss'] / 2**20:.0f} | {rss_ratio} | {r['rss'] / cells:.0f} | {work / 2**20:.1f} | {work_ratio} |")
print()
# Linear growth: each figure per cell at 10^7 over the same figure per cell at 10^6, row against
# row of the same code and threads. The load's user and system CPU are shown apart: user time is
# the code's work, system time mostly the kernel zeroing fresh pages at a cost per page that the
# host sets (and that is not constant: see the README).
pairs = [("grid_1000000.mesh", "grid_10077696.mesh"), ("cylinder_988240.mesh", "cylinder_10m.mesh")]
find = {(r["mesh"], r["code"], r["threads"]): r for r in rows}
grow = []
for small, large in pairs:
    for (mesh, code, threads), s in find.items():
        l = find.get((large, code, threads))
        if mesh != small or l is None:
            continue
        per = lambda r, v: v / r["b"]["cells"]
        ratio = lambda f: f"{per(l, f(l)) / per(s, f(s)):.2f}"
        stage = lambda key: ratio(lambda r: r["t"][key])
        grow.append(f"| {small.split('_')[0]} | {code} | {threads} | {ratio(lambda r: r['b']['parse_s'] + r['b']['build_s'])} | "
                    f"{ratio(lambda r: r['b']['load_user_s'])} | {ratio(lambda r: r['b']['load_sys_s'])} | "
                    f"{ratio(lambda r: r['b']['load_faults'])} | {stage('load')} | {stage('singularity_graph')} | "
                    f"{stage('base_complex')} | {ratio(lambda r: r['t']['sheets'] + r['t']['subsheets'])} | {stage('vsg_wireframe')} |")
if grow:
    print("Linear growth, 10^6 -> 10^7 cells: per cell at 10^7 over per cell at 10^6 (1.00 = linear).")
    print()
    print("| mesh | code | threads | load | load user CPU | load system CPU | load page faults | analyze's load | singularity graph | base complex | sheets | VSG wireframe |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    print("\n".join(grow))
    print()
print(f"{os.cpu_count()} CPUs, load average {' '.join(open('/proc/loadavg').read().split()[:3])} at the end. Wall times come from one "
      "process per row, and other processes on the machine inflate them. load = read+parse + topology (BM_LoadFile, warm: the "
      "process has loaded the file before), the fastest of " + os.environ.get("HBC_BENCH_REPS", "5") + " loads; analyze's load = the load inside the single "
      "`hbc analyze` run of the row; load speed-up and RSS ratio are against the baseline row of the same mesh; "
      "stages / load = (singularity graph + base complex + sheets + subsheets + VSG wireframe) / the load time `hbc analyze` measured itself; "
      "analyze = `hbc analyze --json` (its own load and every stage), peak RSS of that process; load + analysis RSS = that peak "
      "less the peak of the same `hbc analyze` on a one-hex mesh (the process's own footprint), its ratio against the baseline's.")
PY
