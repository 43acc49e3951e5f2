#!/usr/bin/python3
"""Regenerates the real-tool files under real/ from slab.geo (needs Debian's gmsh and python3-meshio).

The files are committed (each < 100 KB) so the tests need neither tool; rerun this after changing
slab.geo. Every file holds the same mesh, so `hbc analyze` must give identical results for all:
  slab_22.msh, slab_22_bin.msh, slab_41.msh, slab_41_bin.msh  gmsh's own .msh writers
  slab_41_order2.msh                                          gmsh's second-order elements (hex27, prism18)
  slab_gmsh.vtk                                               gmsh's legacy VTK writer (2.0, with surfaces)
  slab.mesh                                                   meshio's MEDIT writer (gmsh's drops prisms)
  slab_42_ascii.vtk, slab_42_bin.vtk, slab_51_ascii.vtk,
  slab_51_bin.vtk                                             meshio's legacy VTK writers
  slab_ascii.vtu, slab_zlib.vtu, slab_b64.vtu                 meshio's VTU writer (ascii, zlib, plain base64)
  slab_poly.vtk, slab_poly_bin.vtk                            every cell as VTK_POLYHEDRON (written here)
"""
import os
import subprocess
import sys

import meshio
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "real")

# Outward faces of VTK's hexahedron and of meshio's VTK wedge (the mirror image of VTK 9.7's
# vtkWedge, after VTK's older documentation) in their corner orders.
VTK_FACES = {
    "hexahedron": [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]],
    "wedge": [[0, 1, 2], [3, 5, 4], [0, 3, 4, 1], [1, 4, 5, 2], [2, 5, 3, 0]],
}
# meshio keeps wedges in gmsh's order and swaps corners 1-2 and 4-5 when writing VTK.
MESHIO_TO_VTK = {"hexahedron": [0, 1, 2, 3, 4, 5, 6, 7], "wedge": [0, 2, 1, 3, 5, 4]}


def gmsh(fmt, name, binary=False, order=1):
    cmd = ["gmsh", "-3", os.path.join(HERE, "slab.geo"), "-format", fmt, "-o", os.path.join(OUT, name)]
    if binary:
        cmd.append("-bin")
    if order > 1:
        cmd += ["-order", str(order)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def write_poly_vtk(mesh, path, binary=False):
    """Every hex and wedge as a VTK_POLYHEDRON face stream in the old CELLS layout (VTK 4.2)."""
    cells = [(b.type, c) for b in mesh.cells if b.type in VTK_FACES for c in b.data]
    streams = []
    for kind, c in cells:
        v = [int(c[k]) for k in MESHIO_TO_VTK[kind]]
        faces = VTK_FACES[kind]
        streams.append([len(faces)] + [x for f in faces for x in [len(f)] + [v[k] for k in f]])
    flat = [x for s in streams for x in [len(s)] + s]

    def block(rows, dtype):
        """One text line per row, or the rows' values as big-endian binary (legacy VTK's order)."""
        if binary:
            flat_values = [x for r in rows for x in r]
            return np.asarray(flat_values, dtype=dtype).astype(np.dtype(dtype).newbyteorder(">")).tobytes() + b"\n"
        show = (lambda x: repr(float(x))) if dtype == np.float64 else str
        return "".join(" ".join(show(x) for x in r) + "\n" for r in rows).encode()

    with open(path, "wb") as f:
        f.write(b"# vtk DataFile Version 4.2\nslab as polyhedra\n" + (b"BINARY" if binary else b"ASCII") +
                b"\nDATASET UNSTRUCTURED_GRID\n")
        f.write(f"POINTS {len(mesh.points)} double\n".encode() + block(mesh.points, np.float64))
        f.write(f"CELLS {len(streams)} {len(flat)}\n".encode() + block([[len(st)] + st for st in streams], np.int32))
        f.write(f"CELL_TYPES {len(streams)}\n".encode() + block([[42]] * len(streams), np.int32))


def main():
    os.makedirs(OUT, exist_ok=True)
    gmsh("msh22", "slab_22.msh")
    gmsh("msh22", "slab_22_bin.msh", binary=True)
    gmsh("msh41", "slab_41.msh")
    gmsh("msh41", "slab_41_bin.msh", binary=True)
    gmsh("msh41", "slab_41_order2.msh", order=2)
    gmsh("vtk", "slab_gmsh.vtk")
    m = meshio.read(os.path.join(OUT, "slab_41.msh"))
    m = meshio.Mesh(m.points, m.cells)  # without gmsh's cell sets, which meshio's VTK writer trips on
    vol = meshio.Mesh(m.points, [b for b in m.cells if b.type in VTK_FACES])
    meshio.write(os.path.join(OUT, "slab.mesh"), vol, file_format="medit")
    meshio.write(os.path.join(OUT, "slab_42_ascii.vtk"), m, file_format="vtk42", binary=False)
    meshio.write(os.path.join(OUT, "slab_42_bin.vtk"), m, file_format="vtk42", binary=True)
    meshio.write(os.path.join(OUT, "slab_51_ascii.vtk"), m, file_format="vtk", binary=False)
    meshio.write(os.path.join(OUT, "slab_51_bin.vtk"), m, file_format="vtk", binary=True)
    meshio.write(os.path.join(OUT, "slab_ascii.vtu"), m, binary=False)
    meshio.write(os.path.join(OUT, "slab_zlib.vtu"), m, binary=True, compression="zlib")
    meshio.write(os.path.join(OUT, "slab_b64.vtu"), m, binary=True, compression=None, header_type="UInt64")
    write_poly_vtk(m, os.path.join(OUT, "slab_poly.vtk"))
    write_poly_vtk(m, os.path.join(OUT, "slab_poly_bin.vtk"), binary=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
