#!/usr/bin/env python3
"""The speed a user sees: `hbc analyze FILE --json`, one cold process per run.

A user runs the command once per file, so each run here is its own process: its dynamic loading,
first-touch page faults and the kernel's work on its memory are part of the figure, as they are of
the user's wait. Variants (this build, a baseline build, this build with a setting changed through
the environment) are interleaved run by run, so that a slow minute of a shared machine falls on all
of them alike; each figure is the median over the runs, and the table gives the range beside it.
The file itself is read once before the runs, so every run finds it in the page cache (what a
second `hbc analyze` of the same file meets; a first read from disk measures the disk).

Per run: wall time (from start to exit, measured here), user and system CPU and peak RSS (from the
child's rusage, `os.wait4`), and the load and stage times the process reports in its JSON
(`timings`). Stages = the sum of the timings other than `load`.

Usage:
  cold_runs.py --runs 5 --out runs.json \
      --variant baseline=/tmp/base/bin/hbc \
      --variant new=build/bin/hbc \
      --variant 'huge=HBC_HUGE_PAGES=1 build/bin/hbc' \
      CASE.mesh [CASE2.mesh ...]
The first variant is the reference of the ratios. Prints a Markdown table; --out keeps every run.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

METRICS = [  # key, column title, format
    ("wall", "wall s", "{:.3f}"),
    ("user", "user s", "{:.3f}"),
    ("sys", "kernel s", "{:.3f}"),
    ("load", "load s", "{:.3f}"),
    ("stages", "stages s", "{:.3f}"),
    ("rss_mb", "peak RSS MB", "{:.0f}"),
]


def parse_variant(text: str) -> tuple[str, dict[str, str], list[str]]:
    """`NAME=[VAR=VALUE ...] CLI [ARGS...]` -> (name, environment additions, command)."""
    name, _, rest = text.partition("=")
    if not name or not rest:
        raise SystemExit(f"--variant expects NAME=[VAR=VALUE ...] CLI, got {text!r}")
    env: dict[str, str] = {}
    words = rest.split()
    while words and "=" in words[0] and not words[0].startswith(("/", ".")):
        k, _, v = words.pop(0).partition("=")
        env[k] = v
    if not words:
        raise SystemExit(f"--variant {name}: no command")
    return name, env, words


def one_run(cmd: list[str], env: dict[str, str], case: Path) -> dict[str, float]:
    full_env = {**os.environ, **env}
    start = time.perf_counter()
    child = subprocess.Popen([*cmd, "analyze", str(case), "--json"], stdout=subprocess.PIPE, env=full_env)
    out = child.stdout.read()
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} analyze {case} exited {child.returncode}")
    timings = json.loads(out)["timings"]
    return {
        "wall": wall,
        "user": usage.ru_utime,
        "sys": usage.ru_stime,
        "rss_mb": usage.ru_maxrss / 1024.0,
        "load": timings["load"],
        "stages": sum(v for k, v in timings.items() if k != "load"),
    }


def table(cases: list[Path], names: list[str], runs: dict) -> str:
    ref = names[0]
    head = ["case", "variant"] + [m[1] for m in METRICS] + [f"load ×{ref}", f"wall ×{ref}"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for case in cases:
        med = {n: {k: statistics.median(r[k] for r in runs[case.name][n]) for k, *_ in METRICS} for n in names}
        for n in names:
            cells = [case.name, n]
            for key, _, fmt in METRICS:
                vals = [r[key] for r in runs[case.name][n]]
                cells.append(fmt.format(med[n][key]) + " (" + fmt.format(min(vals)) + "–" + fmt.format(max(vals)) + ")")
            # A ratio above 1 means faster than the reference variant.
            cells.append(f"{med[ref]['load'] / med[n]['load']:.2f}")
            cells.append(f"{med[ref]['wall'] / med[n]['wall']:.2f}")
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=5, help="cold runs per case and variant (default 5)")
    ap.add_argument("--variant", action="append", required=True, help="NAME=[VAR=VALUE ...] CLI")
    ap.add_argument("--out", type=Path, help="write every run as JSON here")
    ap.add_argument("cases", nargs="+", type=Path)
    args = ap.parse_args()
    variants = [parse_variant(v) for v in args.variant]
    names = [v[0] for v in variants]
    runs: dict = {c.name: {n: [] for n in names} for c in args.cases}
    for case in args.cases:
        case.read_bytes()  # into the page cache before the first measured run
        for i in range(args.runs):
            # Rotate the order too, so that no variant always runs right after another's cache misses.
            for name, env, cmd in variants[i % len(variants):] + variants[:i % len(variants)]:
                runs[case.name][name].append(one_run(cmd, env, case))
            print(f"{case.name}: run {i + 1}/{args.runs}", file=sys.stderr)
    if args.out:
        args.out.write_text(json.dumps({"variants": args.variant, "runs": runs}, indent=1))
    print(table(args.cases, names, runs))
    return 0


if __name__ == "__main__":
    sys.exit(main())
