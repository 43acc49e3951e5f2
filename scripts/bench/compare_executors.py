"""hbc.compare() on a thread pool against a process pool and against the `hbc compare` command, on
the same meshes: whether threads measure meshes at once (the compiled module releases the GIL
during the load, the analysis and the metrics) or a process pool is needed.

    PYTHONPATH=build/python python3 scripts/bench/compare_executors.py [--meshes 8] [--size 40]
        [--runs 3] [--threads 1]

Generates the meshes (hex grids of SIZE^3 cells with cells split into pyramids, each its own, by
`hbc generate split`) into a temporary folder, then runs, alternated so that a busy minute of a
shared machine falls on each: hbc.compare() with its default executor (a ThreadPoolExecutor of 2),
with a ProcessPoolExecutor of 2, and `hbc compare -j 2 --no-report`; all without the report. Prints
each run's wall time and the medians. --threads: threads per mesh (default 1: two meshes at once
then keep two cores busy; None leaves each mesh every core).
"""

import argparse
import concurrent.futures
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import hbc
from hbc import locate


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--meshes", type=int, default=8)
    ap.add_argument("--size", type=int, default=40)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", default="1", help="threads per mesh, or 'none'")
    args = ap.parse_args()
    threads = None if args.threads.lower() == "none" else int(args.threads)
    cli = locate.hbc_command()
    with tempfile.TemporaryDirectory(prefix="hbc-executors-") as tmp:
        tmp = Path(tmp)
        files = []
        for i in range(1, args.meshes + 1):
            f = tmp / f"grid_{i}.mesh"
            subprocess.run([cli, "generate", "split", "--size", *[str(args.size)] * 3, "--random", str(50 * i),
                            "--seed", str(i), "--split", "pyramids", "-o", str(f)], check=True, capture_output=True)
            files.append(str(f))
        print(f"{len(files)} meshes of about {args.size ** 3} cells, threads per mesh: {threads}")
        runs = {"threads": [], "processes": [], "cli": []}
        for r in range(args.runs):
            t = time.perf_counter()
            hbc.compare(files, tmp / "t", report=False, threads=threads)
            runs["threads"].append(time.perf_counter() - t)
            t = time.perf_counter()
            with concurrent.futures.ProcessPoolExecutor(2) as pool:
                hbc.compare(files, tmp / "p", report=False, threads=threads, executor=pool)
            runs["processes"].append(time.perf_counter() - t)
            t = time.perf_counter()
            extra = [] if threads is None else ["--threads", str(threads)]
            subprocess.run([cli, "compare", *files, "-o", str(tmp / "c"), "-j", "2", "--no-report", *extra],
                           check=True, capture_output=True)
            runs["cli"].append(time.perf_counter() - t)
            print(f"run {r + 1}: " + ", ".join(f"{k} {v[-1]:.2f} s" for k, v in runs.items()), flush=True)
        med = {k: statistics.median(v) for k, v in runs.items()}
        print("medians: " + ", ".join(f"{k} {v:.2f} s" for k, v in med.items()) +
              f"; threads / processes {med['threads'] / med['processes']:.2f}, threads / cli {med['threads'] / med['cli']:.2f}")


if __name__ == "__main__":
    main()
