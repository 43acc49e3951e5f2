#!/usr/bin/env python3
"""`hbc analyze` natively on one thread (HBC_THREADS=1), one cold process per run, against the
WebAssembly build (docs/wasm.md) four ways, all interleaved per run so that a busy machine slows
every column alike; medians of REPEATS, each column's ratio to native:

  cli        `node hbc.js analyze MESH`, a cold process (its wall time)
  node warm  the binding in node, warmed up as the viewer's worker does (web/src/warmup.js), then the
             mesh read, analysed and written as JSON in-process (wasm_warm.mjs)
  page cold  the built viewer in Debian's chromium, a fresh page opening the mesh by ?mesh= at start
             (no warm-up); the page's own time from the file's bytes reaching its worker to the
             counts (#hbc-results[data-open-seconds]; wasm_page.mjs)
  page warm  the same, the mesh given to the file picker once the page's warm-up is over: what a
             user who opens the page and then picks a file waits for

  scripts/bench/wasm_vs_native.py NATIVE_HBC WASM_HBC_JS [--repeats 5] [--big]
      [--core BUILD_WASM/web/hbc_core.js] [--viewer build/web/viewer.html] [--no-page]

Meshes: armadillo (shared data), a 46x46x47 grid (99,452 cells, `hbc generate`), rockerarm refined
x64 (678,400 hexes, refine_medit_hexes.py); --big adds the 10^6-cell grid (100^3), whose load under
node must not run out of memory. Writes the generated meshes to a temporary folder."""
import argparse, datetime, json, os, pathlib, statistics, subprocess, sys, tempfile, time

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("HBC_DATA_DIR", ROOT.parent / "shared" / "data"))


def run(cmd, env):
    t = time.perf_counter()
    r = subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t
    if r.returncode != 0:
        sys.exit(f"{' '.join(map(str, cmd))} failed: {r.stderr[-500:]}")
    return wall


def node_warm(core, mesh, env):
    r = subprocess.run(["node", ROOT / "scripts/bench/wasm_warm.mjs", core, mesh], env=env, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"wasm_warm.mjs {mesh} failed: {r.stderr[-500:]}")
    return json.loads(r.stdout.strip().splitlines()[-1])


class Page:
    """wasm_page.mjs: one browser for the whole run, a fresh page (own context) per request."""

    def __init__(self, viewer):
        self.p = subprocess.Popen(["node", ROOT / "scripts/bench/wasm_page.mjs", viewer], stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, text=True)

    def __call__(self, mode, mesh):
        self.p.stdin.write(f"{mode} {mesh}\n")
        self.p.stdin.flush()
        r = json.loads(self.p.stdout.readline())
        if "error" in r:
            sys.exit(f"the page ({mode}) on {mesh}: {r['error']}")
        return r

    def close(self):
        self.p.stdin.close()
        self.p.wait()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native")
    ap.add_argument("wasm")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--big", action="store_true")
    ap.add_argument("--core", help="the binding, hbc_core.js (default: beside hbc.js, ../web/hbc_core.js)")
    ap.add_argument("--viewer", default=ROOT / "build/web/viewer.html", help="the built page (scripts/build_web.sh)")
    ap.add_argument("--no-page", action="store_true", help="leave out chromium")
    a = ap.parse_args()
    core = pathlib.Path(a.core) if a.core else pathlib.Path(a.wasm).resolve().parent.parent / "web/hbc_core.js"
    env = dict(os.environ, HBC_THREADS="1")
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="hbc-wasm-bench-"))
    grid = tmp / "grid_46_46_47.mesh"
    subprocess.run([a.native, "generate", "grid", "--size", "46", "46", "47", "-o", grid], check=True)
    rocker = tmp / "rockerarm_x64.mesh"
    subprocess.run([sys.executable, ROOT / "scripts/bench/refine_medit_hexes.py", DATA / "cinolib/rockerarm.mesh",
                    rocker, "4"], check=True, stdout=subprocess.DEVNULL)
    meshes = [DATA / "hexalab-edge-cone-rectification/armadillo_out.mesh", grid, rocker]
    if a.big:
        big = tmp / "grid_100.mesh"
        subprocess.run([a.native, "generate", "grid", "--size", "100", "100", "100", "-o", big], check=True)
        meshes.append(big)
    page = None if a.no_page else Page(a.viewer)
    cols = ["cli", "node warm"] + ([] if a.no_page else ["page cold", "page warm"])
    print(f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, load average "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}, {os.cpu_count()} cores; medians of {a.repeats} runs, "
          f"seconds (ratio to native)")
    print("| mesh | native | " + " | ".join(cols) + " |")
    print("|---|---:|" + "---:|" * len(cols))
    warm_ups = {"node": [], "page": []}
    for m in meshes:
        t = {c: [] for c in ["native"] + cols}
        for _ in range(a.repeats):
            t["native"].append(run([a.native, "analyze", "--threads", "1", m], env))
            t["cli"].append(run(["node", a.wasm, "analyze", m], env))
            r = node_warm(core, m, env)
            t["node warm"].append(r["open_seconds"])
            warm_ups["node"].append(r["warm_up_seconds"])
            if page:
                t["page cold"].append(page("cold", m)["open_seconds"])
                r = page("warm", m)
                t["page warm"].append(r["open_seconds"])
                warm_ups["page"].append(r["warm_up_seconds"])
        med = {c: statistics.median(v) for c, v in t.items()}
        n = med["native"]
        print(f"| {m.name} | {n:.3f} | " + " | ".join(f"{med[c]:.3f} ({med[c] / n:.2f}x)" for c in cols) + " |", flush=True)
    if page:
        page.close()
    print("warm-up (median): " + ", ".join(f"{k} {statistics.median(v):.3f} s" for k, v in warm_ups.items() if v))


if __name__ == "__main__":
    main()
