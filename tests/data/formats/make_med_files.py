#!/usr/bin/env python3
"""Regenerates the Salome MED twins under real/ with meshio's MED writer.

Run with the Python of scripts/env/meshio_env.sh (meshio 5.3.5 from PyPI, with h5py). The files
are committed (each < 100 KB) so the tests need neither. Each holds the same mesh as its MEDIT
original, so `hbc analyze` must give identical results (tests/cpp/test_med.cpp):
  slab_meshio.med        real/slab.mesh (hexahedra and prisms) by meshio's MED writer as it is:
                         meshio stores VTK's corner order in NOD, not MED's (nschloe/meshio#144)
  mixed4_meshio.med      mixed4.mesh (one hexahedron, prism, pyramid, tetrahedron), the same way
  mixed4_med_order.med   mixed4_meshio.med with each volume type's NOD rewritten by h5py in MED's
                         own corner order, the order Salome writes (its "nodal connectivity of
                         elements": the mirror images of VTK's, SMESH's interlaces TETRA 0 2 1 3,
                         PYRA 0 3 2 1 4, PENTA 0 2 1 3 5 4, HEXA 0 3 2 1 4 7 6 5), as no writer of
                         MED's order installs here (Salome, gmsh built with MED)
"""
import os

import h5py
import meshio
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "real")
STEP = "-0000000000000000001-0000000000000000001"
# VTK (MEDIT) corner k is MED node ORDER[k]; each is its own inverse.
TO_MED = {"TE4": [0, 2, 1, 3], "PY5": [0, 3, 2, 1, 4], "PE6": [0, 2, 1, 3, 5, 4], "HE8": [0, 3, 2, 1, 4, 7, 6, 5]}


def volumes(mesh):
    return meshio.Mesh(mesh.points, [b for b in mesh.cells if b.type in ("hexahedron", "wedge", "pyramid", "tetra")])


def to_med_order(path):
    """NOD is stored by node column (all first nodes, then all second nodes ...)."""
    with h5py.File(path, "r+") as f:
        for mesh in f["ENS_MAA"].values():
            for name, group in mesh[STEP]["MAI"].items():
                if name in TO_MED:
                    nod = group["NOD"]
                    n = int(nod.attrs["NBR"])
                    cols = nod[()].reshape(-1, n)
                    nod[...] = cols[TO_MED[name]].reshape(-1)


def main():
    slab = meshio.read(os.path.join(OUT, "slab.mesh"))
    meshio.write(os.path.join(OUT, "slab_meshio.med"), meshio.Mesh(slab.points, slab.cells))
    mixed = volumes(meshio.read(os.path.join(HERE, "mixed4.mesh")))
    meshio.write(os.path.join(OUT, "mixed4_meshio.med"), mixed)
    meshio.write(os.path.join(OUT, "mixed4_med_order.med"), mixed)
    to_med_order(os.path.join(OUT, "mixed4_med_order.med"))


if __name__ == "__main__":
    main()
