#!/usr/bin/env python3
"""Load and analysis time per cell of real snappyHexMesh output against the 10^6 grid.

As a user runs it: one cold `hbc analyze CASE --json` process per run, the cases interleaved run by
run (a slow minute of a shared machine falls on all alike), medians over the runs. Per case: cells,
wall time, the load and the stages' sum as the process reports them (`timings`), each per cell,
and the ratio of the per-cell figures to the first case's (the grid). Prints a Markdown table.
Every file is read once before the runs, so each run finds it in the page cache.

Usage: foam_vs_grid.py HBC RUNS GRID.mesh CASE [CASE ...]
  (scripts/bench/foam_flange_large.sh makes the case; `hbc generate grid --size 100 100 100` the grid)
"""
import json
import pathlib
import statistics
import subprocess
import sys
import time


def warm(path):
    p = pathlib.Path(path)
    for f in ([p] if p.is_file() else [x for x in p.rglob("*") if x.is_file()]):
        f.read_bytes()


def run(hbc, path):
    t0 = time.perf_counter()
    out = subprocess.run([hbc, "analyze", "--json", str(path)], check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - t0
    stats = json.loads(out)
    t = stats["timings"]
    return stats["cells"], wall, t["load"], sum(v for k, v in t.items() if k != "load")


def main():
    hbc, runs, cases = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    for c in cases:
        warm(c)
    samples = {c: [] for c in cases}
    for _ in range(runs):
        for c in cases:
            samples[c].append(run(hbc, c))
    print(f"| case | cells | wall s | load s | stages s | wall µs/cell | load µs/cell | stages µs/cell | per cell / grid (wall, load, stages) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---|")
    ref = None
    for c in cases:
        cells = samples[c][0][0]
        med = [statistics.median(s[k] for s in samples[c]) for k in (1, 2, 3)]
        per = [1e6 * m / cells for m in med]
        ref = ref or per
        ratio = ", ".join(f"{a / b:.2f}" for a, b in zip(per, ref))
        print(f"| {pathlib.Path(c).name} | {cells:,} | {med[0]:.2f} | {med[1]:.2f} | {med[2]:.2f} | "
              f"{per[0]:.2f} | {per[1]:.2f} | {per[2]:.2f} | {ratio} |")


if __name__ == "__main__":
    main()
