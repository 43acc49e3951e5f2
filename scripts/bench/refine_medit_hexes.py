#!/usr/bin/env python3
"""Refines every hexahedron of an all-hex MEDIT file into n^3 (trilinear subdivision), for load
benchmarks on real geometry at large sizes: rockerarm.mesh (10,600 hexes) with n = 4 gives
678,400 hexes. Shared points are merged after rounding (the subdivision of a shared face is the
same from both sides up to round-off). Usage: refine_medit_hexes.py IN.mesh OUT.mesh [n]"""
import sys

import numpy as np


def read_medit_hexes(path):
    tokens = open(path).read().split()
    lower = [t.lower() for t in tokens]
    i = lower.index("vertices")
    nv = int(tokens[i + 1])
    pts = np.array(tokens[i + 2:i + 2 + 4 * nv], dtype=float).reshape(nv, 4)[:, :3]
    j = lower.index("hexahedra")
    nh = int(tokens[j + 1])
    hexes = np.array(tokens[j + 2:j + 2 + 9 * nh], dtype=np.int64).reshape(nh, 9)[:, :8] - 1
    return pts, hexes


def refine(pts, hexes, n):
    # MEDIT corner order: bottom 0 1 2 3 counter-clockwise, top 4 5 6 7 above them.
    corner = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])
    t = np.arange(n + 1) / n
    u, v, w = np.meshgrid(t, t, t, indexing="ij")
    uvw = np.stack([u.ravel(), v.ravel(), w.ravel()], axis=1)  # (n+1)^3 local points
    weights = np.prod(np.where(corner[None, :, :] == 1, uvw[:, None, :], 1 - uvw[:, None, :]), axis=2)
    local = np.einsum("pc,hcd->hpd", weights, pts[hexes])  # per hex, its (n+1)^3 points
    flat = local.reshape(-1, 3)
    scale = np.abs(flat).max() or 1.0
    keys = np.round(flat / scale * 1e9).astype(np.int64)
    _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    ids = inverse.reshape(len(hexes), -1)
    def at(i, j, k):
        return (i * (n + 1) + j) * (n + 1) + k
    cells = []
    for i in range(n):
        for j in range(n):
            for k in range(n):
                cells.append([at(i + a, j + b, k + c) for a, b, c in corner])
    cells = np.array(cells)
    out = ids[:, cells].reshape(-1, 8)
    return flat[first], out


def write_medit_hexes(path, pts, hexes):
    """pts: (nv, 3) floats; hexes: (nh, 8) 0-based vertex ids in MEDIT corner order."""
    with open(path, "w") as f:
        f.write(f"MeshVersionFormatted 1\nDimension 3\nVertices\n{len(pts)}\n")
        np.savetxt(f, np.column_stack([pts, np.zeros(len(pts))]), fmt="%.17g %.17g %.17g %d")
        f.write(f"Hexahedra\n{len(hexes)}\n")
        np.savetxt(f, np.column_stack([hexes + 1, np.zeros(len(hexes), dtype=np.int64)]), fmt="%d")
        f.write("End\n")


def main():
    src, dst = sys.argv[1], sys.argv[2]
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 4
    pts, hexes = read_medit_hexes(src)
    p, h = refine(pts, hexes, n)
    write_medit_hexes(dst, p, h)
    print(f"wrote {dst}: {len(p)} vertices, {len(h)} hexahedra")


if __name__ == "__main__":
    main()
