#!/usr/bin/env python3
"""The subsheet stage of two builds side by side: `hbc analyze FILE --json`, one cold process per
run, runs of the two builds interleaved so that a busy minute of a shared machine falls on both.
The wireframe stage is skipped (the subsheet stage does not read it). Each figure is the median
of the stage time the process reports (`timings.subsheets`, seconds) over the runs; the ratio is
NEW / OLD. Meshes without a self-intersecting sheet have no
decomposition to time (the stage is a loop over zero sheets): they are listed with their figures
all the same, and left out of the summary.

Usage: subsheets.py OLD_HBC NEW_HBC [--runs 5] MESH...
(e.g. OLD_HBC built from the commit before the authors' rule became the default.)
"""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess


def stage_seconds(hbc: str, mesh: str) -> float:
    out = subprocess.run([hbc, "analyze", mesh, "--json", "--threads", "1", "--no-wireframe"], check=True,
                         capture_output=True, text=True).stdout
    return float(json.loads(out)["timings"]["subsheets"])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--runs", type=int, default=5)
    a = ap.parse_args()
    print("| mesh | old ms | new ms | new / old |")
    print("|---|---:|---:|---:|")
    worst = 0.0
    for mesh in a.meshes:
        old, new = [], []
        for _ in range(a.runs):
            old.append(stage_seconds(a.old, mesh))
            new.append(stage_seconds(a.new, mesh))
        mo, mn = statistics.median(old), statistics.median(new)
        ratio = mn / mo if mo > 0 else float("nan")
        if mo >= 1e-4:  # a self-intersecting sheet was decomposed
            worst = max(worst, ratio)
        print(f"| {mesh.split('/')[-1]} | {mo * 1e3:.3f} | {mn * 1e3:.3f} | {ratio:.2f} |")
    print(f"\nlargest ratio over meshes with a self-intersecting sheet: {worst:.2f}")


if __name__ == "__main__":
    main()
