#!/usr/bin/env python3
"""The tables of scripts/bench.sh, in Markdown, from the files its runs left. One argument per case
and variant, "MESH|CODE|THREADS|TAG", where
  TAG.load.json     hbc_bench_load's JSON (BM_LoadFile, its repetitions),
  TAG.analyze.json  `hbc analyze --json` of MESH,
  TAG.rss           /usr/bin/time's "%M %U %S %e" of that analyze,
  TAG.own           the peak RSS (KB) of the same `hbc analyze` on a one-hex mesh.
Prints the main table and, when the 10^7-cell cases ran, the linear-growth table. Environment:
HBC_BENCH_REPS (only to say how many loads the fastest was taken from). Standard library only.

    bench_table.py 'grid.mesh|new|1|/tmp/d/grid.mesh.new.1' ...
"""
import json
import os
import sys

MAIN_HEADER = (
    "| mesh | cells | code | threads | read (ms) | parse MB/s | load (s) | load cells/s | load / read | load speed-up | "
    "analyze's load (s) | singularity graph (s) | base complex (s) | sheets (s) | VSG wireframe (s) | stages / load | "
    "analyze wall / CPU (s) | peak RSS (MB) | RSS ratio | bytes/cell | load + analysis RSS (MB) | its ratio |")
MAIN_ALIGN = "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
GROWTH_HEADER = ("| mesh | code | threads | load | load user CPU | load system CPU | load page faults | analyze's load | "
                 "singularity graph | base complex | sheets | VSG wireframe |")
GROWTH_ALIGN = "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
# The 10^6-cell case and its 10^7-cell counterpart (HBC_BENCH_LARGE=1).
GROWTH_PAIRS = [("grid_1000000.mesh", "grid_10077696.mesh"), ("cylinder_988240.mesh", "cylinder_10m.mesh")]


def read_row(arg):
    """One case and variant: the fastest load, the analyze timings, its peak RSS and CPU times."""
    path, name, threads, tag = arg.split("|")
    # The fastest repetition: first touches of fresh memory stall at random on this machine
    # (transparent huge pages being compacted), adding up to a second to one load of 10^6 cells.
    with open(tag + ".load.json") as f:
        reps = [x for x in json.load(f)["benchmarks"] if x.get("run_type") == "iteration"]
    b = min(reps, key=lambda x: x["parse_s"] + x["build_s"])
    with open(tag + ".analyze.json") as f:
        a = json.load(f)
    with open(tag + ".rss") as f:
        rss_kb, user, sys_s, wall = f.read().split()[-4:]
    with open(tag + ".own") as f:
        own_kb = int(f.read())
    return dict(mesh=os.path.basename(path), code=name, threads=int(threads), b=b, t=a["timings"],
                rss=int(rss_kb) * 1024, own=own_kb * 1024, cpu=float(user) + float(sys_s), wall=float(wall))


def load_seconds(r):
    return r["b"]["parse_s"] + r["b"]["build_s"]


def main_table(rows):
    """The lines of the main table: one row per case and variant, ratios against the baseline's row
    of the same mesh when there is one."""
    base = {r["mesh"]: r for r in rows if r["code"] == "baseline"}
    lines = [MAIN_HEADER, MAIN_ALIGN]
    for r in rows:
        b, t = r["b"], r["t"]
        cells = int(b["cells"])
        mb = b["file_MB"] * 1024 * 1024 / 1e6
        load = load_seconds(r)
        stages = t["singularity_graph"] + t["base_complex"] + t["sheets"] + t["subsheets"] + t["vsg_wireframe"]
        ref = base.get(r["mesh"])
        against = ref is not None and ref is not r
        speedup = f"{load_seconds(ref) / load:.2f}×" if against else ""
        rss_ratio = f"{r['rss'] / ref['rss']:.2f}" if against else ""
        work = r["rss"] - r["own"]
        work_ratio = f"{work / (ref['rss'] - ref['own']):.2f}" if against else ""
        lines.append(
            f"| {r['mesh']} | {cells:,} | {r['code']} | {r['threads']} | {b['read_s'] * 1e3:.1f} | {mb / b['parse_s']:.0f} | "
            f"{load:.3f} | {cells / load:.3g} | {load / b['read_s']:.0f} | {speedup} | {t['load']:.3f} | "
            f"{t['singularity_graph']:.3f} | {t['base_complex']:.3f} | "
            f"{t['sheets'] + t['subsheets']:.3f} | {t['vsg_wireframe']:.3f} | {stages / t['load']:.2f} | "
            f"{r['wall']:.2f} / {r['cpu']:.2f} | {r['rss'] / 2**20:.0f} | {rss_ratio} | {r['rss'] / cells:.0f} | "
            f"{work / 2**20:.1f} | {work_ratio} |")
    return lines


def growth_rows(rows):
    """Linear growth: each figure per cell at 10^7 over the same figure per cell at 10^6, row against
    row of the same code and threads. The load's user and system CPU are shown apart: user time is
    the code's work, system time mostly the kernel zeroing fresh pages at a cost per page that the
    host sets (and that is not constant: see the README)."""
    find = {(r["mesh"], r["code"], r["threads"]): r for r in rows}
    grow = []
    for small, large in GROWTH_PAIRS:
        for (mesh, code, threads), s in find.items():
            l = find.get((large, code, threads))
            if mesh != small or l is None:
                continue

            def ratio(figure, s=s, l=l):
                return f"{(figure(l) / l['b']['cells']) / (figure(s) / s['b']['cells']):.2f}"

            def stage(key):
                return ratio(lambda r: r["t"][key])

            grow.append(f"| {small.split('_')[0]} | {code} | {threads} | {ratio(load_seconds)} | "
                        f"{ratio(lambda r: r['b']['load_user_s'])} | {ratio(lambda r: r['b']['load_sys_s'])} | "
                        f"{ratio(lambda r: r['b']['load_faults'])} | {stage('load')} | {stage('singularity_graph')} | "
                        f"{stage('base_complex')} | {ratio(lambda r: r['t']['sheets'] + r['t']['subsheets'])} | "
                        f"{stage('vsg_wireframe')} |")
    return grow


def footnote(reps):
    with open("/proc/loadavg") as f:
        load = " ".join(f.read().split()[:3])
    return (
        f"{os.cpu_count()} CPUs, load average {load} at the end. Wall times come from one "
        "process per row, and other processes on the machine inflate them. load = read+parse + topology (BM_LoadFile, warm: the "
        "process has loaded the file before), the fastest of " + reps + " loads; analyze's load = the load inside the single "
        "`hbc analyze` run of the row; load speed-up and RSS ratio are against the baseline row of the same mesh; "
        "stages / load = (singularity graph + base complex + sheets + subsheets + VSG wireframe) / the load time `hbc analyze` measured itself; "
        "analyze = `hbc analyze --json` (its own load and every stage), peak RSS of that process; load + analysis RSS = that peak "
        "less the peak of the same `hbc analyze` on a one-hex mesh (the process's own footprint), its ratio against the baseline's.")


def main(args):
    rows = [read_row(a) for a in args]
    print("\n".join(main_table(rows)))
    print()
    grow = growth_rows(rows)
    if grow:
        print("Linear growth, 10^6 -> 10^7 cells: per cell at 10^7 over per cell at 10^6 (1.00 = linear).")
        print()
        print(GROWTH_HEADER)
        print(GROWTH_ALIGN)
        print("\n".join(grow))
        print()
    print(footnote(os.environ.get("HBC_BENCH_REPS", "5")))


if __name__ == "__main__":
    main(sys.argv[1:])
