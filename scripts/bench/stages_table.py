#!/usr/bin/env python3
"""The table of scripts/bench_stages.sh, in Markdown, from hbc_bench_stages' JSON (the file given):
per mesh, graph + complex, sheets and subsheets in CPU ms, the speed-up over the times quoted for
the paper's Python implementation, and the growth between the generated sizes."""
import json, sys
data = json.load(open(sys.argv[1]))
cpu = {}
cells = {}
for b in data["benchmarks"]:
    stage, mesh = b["name"].split("/", 1)
    cpu[(stage, mesh)] = b["cpu_time"] * {"ms": 1.0, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]
    cells[mesh] = int(b["cells"])
# Seconds quoted for the paper's Python code (issues 3 and 4): both first stages, and the sheet stage.
python = {"teapot.hedra": (3.9, 0.26), "twistcube_s.mesh": (None, 0.5), "cube_twist-comp.obj.HYBRID": (0.5, None)}
print("| mesh | cells | graph + complex (ms) | sheets (ms) | subsheets (ms) | vs Python: graph + complex | vs Python: sheets + subsheets |")
print("|---|---:|---:|---:|---:|---:|---:|")
for mesh in sorted(cells, key=lambda m: (m.startswith("cyl"), m.startswith("split"), cells[m])):
    gc, sh, sub = cpu.get(("GraphAndComplex", mesh)), cpu.get(("Sheets", mesh)), cpu.get(("Subsheets", mesh))
    py = python.get(mesh, (None, None))
    r1 = f"{py[0] / (gc / 1e3):,.0f}×" if py[0] and gc else ""
    r2 = f"{py[1] / ((sh + (sub or 0)) / 1e3):,.0f}×" if py[1] and sh else ""
    fmt = lambda v: "" if v is None else f"{v:.3f}"
    print(f"| {mesh} | {cells[mesh]:,} | {fmt(gc)} | {fmt(sh)} | {fmt(sub)} | {r1} | {r2} |")
print()
for family in ("cyl", "split"):
    gen = sorted([m for m in cells if m.startswith(family)], key=lambda m: cells[m])
    for a, b in zip(gen, gen[1:]):
        for stage in ("GraphAndComplex", "Sheets"):
            t = cpu[(stage, b)] / cpu[(stage, a)]
            n = cells[b] / cells[a]
            print(f"- {family} {stage}: {cells[a]:,} -> {cells[b]:,} cells ({n:.1f}x) took {t:.1f}x the time")
