#!/usr/bin/env python3
"""What the non-hex kinds of the wireframe's chains cost (docs/performance.md): the wireframe
stage (`timings.vsg_wireframe` of `hbc analyze --json`, the paper's T_VSGW: the view, the graph with
its kinds, the style) of two builds, one cold process per run, the two builds interleaved run by
run so that a slow moment of a shared machine falls on both; medians over the runs, and their ratio.

Usage:
  wireframe_kinds.py OLD_HBC NEW_HBC [--runs 7] [--threads 1] [--levels complex,mesh] [MESH ...]
Without meshes: every mesh under $HBC_DATA_DIR (default ../shared/data). Prints a Markdown table.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
from pathlib import Path

SUFFIXES = {".mesh", ".ovm", ".ovmb", ".hybrid", ".hedra", ".msh", ".vtk", ".vtu"}


def stage_seconds(cli: str, mesh: Path, level: str, threads: int) -> float:
    out = subprocess.run([cli, "analyze", str(mesh), "--json", "--no-sheets", "--level", level,
                          "--threads", str(threads)], capture_output=True, text=True, check=True).stdout
    return float(json.loads(out)["timings"]["vsg_wireframe"])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("meshes", nargs="*")
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--levels", default="complex,mesh")
    args = ap.parse_intermixed_args()
    meshes = [Path(m) for m in args.meshes]
    if not meshes:
        root = Path(os.environ.get("HBC_DATA_DIR", Path(__file__).resolve().parents[3] / "shared" / "data"))
        meshes = sorted(p for p in root.rglob("*") if p.is_file() and p.suffix.lower() in SUFFIXES)
    print(f"Medians of {args.runs} cold runs, {args.threads} thread{'s' if args.threads > 1 else ''}:\n")
    print("| mesh | level | old T_VSGW ms | new T_VSGW ms | new / old |")
    print("|---|---|---:|---:|---:|")
    for mesh in meshes:
        mesh.read_bytes()  # in the page cache for every run
        for level in args.levels.split(","):
            old, new = [], []
            for _ in range(args.runs):
                old.append(stage_seconds(args.old, mesh, level, args.threads))
                new.append(stage_seconds(args.new, mesh, level, args.threads))
            a, b = statistics.median(old) * 1e3, statistics.median(new) * 1e3
            print(f"| {mesh.parent.name}/{mesh.name} | {level} | {a:.2f} | {b:.2f} | {b / a:.2f} |", flush=True)


if __name__ == "__main__":
    main()
