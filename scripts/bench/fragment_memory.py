#!/usr/bin/env python3
"""Fragment the machine's free memory, then hold it, for benchmarks of the 2 MiB page advice.

Transparent huge pages cost nothing when free 2 MiB blocks are at hand; when none are, an advised
fault compacts memory synchronously in the faulting process (THP `defrag` = `madvise`). To measure
that case this fills memory with 512 KiB anonymous maps until LEAVE bytes are left, frees every
other map (the free memory then lies in 512 KiB holes), prints /proc/buddyinfo and sleeps until
killed or SECONDS have passed. Run the cold benchmark while it sleeps:

  python3 scripts/bench/fragment_memory.py --seconds 3600 & PID=$!
  ... wait for "fragmented" on stdout, run scripts/bench/cold_runs.py ...
  kill $PID
"""
import argparse
import mmap
import time

MAP_SIZE = 512 * 1024
PAGE = 4096


def available_bytes() -> int:
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) * 1024
    raise RuntimeError("no MemAvailable in /proc/meminfo")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--leave", type=float, default=1.5, help="GB left before freeing (default 1.5)")
    ap.add_argument("--seconds", type=float, default=3600.0, help="how long to hold the memory")
    args = ap.parse_args()
    maps = []
    while available_bytes() > args.leave * 1024**3:
        for _ in range(256):
            m = mmap.mmap(-1, MAP_SIZE)
            m[::PAGE] = b"x" * (MAP_SIZE // PAGE)  # touch every page so it is really allocated
            maps.append(m)
    for i in range(0, len(maps), 2):
        maps[i].close()
        maps[i] = None
    print(f"fragmented: {len(maps) * MAP_SIZE / 1024**3:.1f} GB mapped, every other map freed", flush=True)
    with open("/proc/buddyinfo") as f:
        print(f.read(), flush=True)
    time.sleep(args.seconds)


if __name__ == "__main__":
    main()
