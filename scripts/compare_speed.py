#!/usr/bin/env python3
"""New against old in one run: `hbc analyze --json` of two builds on one mesh, alternating.

    python3 scripts/compare_speed.py OLD/hbc NEW/hbc MESH [--threads 2] [--runs 7] [--load-only]

Each round runs the old build, then the new one, so that a slow spell of a shared machine
falls on both; the table gives, per stage (the timings `hbc analyze` reports itself), the
fastest and the median time of each build and their ratios (new / old, below 1 = faster),
then the peak RSS of each build's largest run. The load average is printed before and after:
ratios from a busy machine are rougher. Compare only builds that give the same results
(scripts/compare_outputs.sh checks that). Standard library only.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

STAGES = ["load", "singularity_graph", "base_complex", "sheets", "subsheets", "vsg_wireframe"]


def run_once(hbc, mesh, threads, load_only):
    """Timings of one `hbc analyze --json` and its peak RSS in MB."""
    cmd = [hbc, "analyze", "--json", "--threads", str(threads), mesh]
    if load_only:
        cmd[2:2] = ["--no-sheets", "--no-wireframe"]
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(cmd, stdout=out, stderr=err)
        _, status, usage = os.wait4(proc.pid, 0)  # the child's own rusage: its peak RSS
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        if proc.returncode != 0:
            sys.exit(f"{hbc} failed on {mesh}: {err.read().decode(errors='replace')[-500:]}")
        timings = json.loads(out.read())["timings"]
    timings["stages"] = sum(timings.get(k, 0.0) for k in STAGES if k != "load")
    return timings, usage.ru_maxrss / 1024  # Linux: kilobytes


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("mesh")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--load-only", action="store_true", help="--no-sheets --no-wireframe")
    a = ap.parse_args()
    print(f"load average before: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    runs = {"old": [], "new": []}
    rss = {"old": 0.0, "new": 0.0}
    for _ in range(a.runs):
        for tag in ("old", "new"):
            t, mb = run_once(getattr(a, tag), a.mesh, a.threads, a.load_only)
            runs[tag].append(t)
            rss[tag] = max(rss[tag], mb)
    print(f"load average after:  {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print(f"{os.path.basename(a.mesh)}, {a.threads} thread(s), {a.runs} runs of each build, alternating")
    print(f"{'stage':18s} {'old min':>9s} {'new min':>9s} {'ratio':>6s} {'old med':>9s} {'new med':>9s} {'ratio':>6s}")
    for k in STAGES + ["stages"]:
        o = [t.get(k, 0.0) for t in runs["old"]]
        n = [t.get(k, 0.0) for t in runs["new"]]
        if max(o) == 0 and max(n) == 0:
            continue
        ratio = lambda x, y: f"{y / x:6.3f}" if x > 0 else "     -"
        print(f"{k:18s} {min(o):9.4f} {min(n):9.4f} {ratio(min(o), min(n))} "
              f"{statistics.median(o):9.4f} {statistics.median(n):9.4f} {ratio(statistics.median(o), statistics.median(n))}")
    print(f"peak RSS (MB): old {rss['old']:.1f}, new {rss['new']:.1f}, ratio {rss['new'] / rss['old']:.3f}")


if __name__ == "__main__":
    main()
