#!/usr/bin/env python3
"""`hbc analyze` natively on one thread (HBC_THREADS=1) against the same under node (the
WebAssembly build, docs/wasm.md): cold runs, one process each, native and wasm interleaved so that
a busy machine slows both alike; the median of REPEATS wall times per side and their ratio.

  scripts/bench/wasm_vs_native.py NATIVE_HBC WASM_HBC_JS [--repeats 5] [--big]

Meshes: armadillo (shared data), a 46x46x47 grid (99,452 cells, `hbc generate`), rockerarm refined
x64 (678,400 hexes, refine_medit_hexes.py); --big adds the 10^6-cell grid (100^3), whose load under
node must not run out of memory. Writes the generated meshes to a temporary folder."""
import argparse, os, pathlib, statistics, subprocess, sys, tempfile, time

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("HBC_DATA_DIR", ROOT.parent / "shared" / "data"))


def run(cmd, env):
    t = time.perf_counter()
    r = subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t
    if r.returncode != 0:
        sys.exit(f"{' '.join(map(str, cmd))} failed: {r.stderr[-500:]}")
    return wall


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("native")
    ap.add_argument("wasm")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--big", action="store_true")
    a = ap.parse_args()
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
    print(f"{'mesh':28s} {'native s':>9s} {'wasm s':>9s} {'ratio':>6s}   (medians of {a.repeats} cold runs)")
    for m in meshes:
        nat, was = [], []
        for _ in range(a.repeats):
            nat.append(run([a.native, "analyze", "--threads", "1", m], env))
            was.append(run(["node", a.wasm, "analyze", m], env))
        n, w = statistics.median(nat), statistics.median(was)
        print(f"{m.name:28s} {n:9.3f} {w:9.3f} {w / n:6.2f}")


if __name__ == "__main__":
    main()
