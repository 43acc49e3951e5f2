#!/usr/bin/env python3
"""Renumbers the vertices of an all-hex MEDIT file by a seeded random permutation (same cells,
same points, new ids), for load benchmarks that must not depend on how a mesher numbers its
vertices: a file numbered in no spatial order is the worst case for any grouping by vertex id.
Usage: shuffle_medit_vertices.py IN.mesh OUT.mesh [seed]"""
import sys

import numpy as np

from refine_medit_hexes import read_medit_hexes, write_medit_hexes


def main():
    src, dst = sys.argv[1], sys.argv[2]
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    pts, hexes = read_medit_hexes(src)
    new_id = np.random.default_rng(seed).permutation(len(pts))  # vertex v becomes new_id[v]
    moved = np.empty_like(pts)
    moved[new_id] = pts
    cells = new_id[hexes]
    write_medit_hexes(dst, moved, cells)
    print(f"wrote {dst}: {len(pts)} vertices renumbered, {len(cells)} hexahedra")


if __name__ == "__main__":
    main()
