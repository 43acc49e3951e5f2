#!/usr/bin/env python3
"""Regenerates the XDMF3 twins under real/ with meshio's XDMF writers.

Run with the Python of scripts/env/meshio_env.sh (meshio 5.3.5 from PyPI, with h5py). The files
are committed (each < 100 KB) so the tests need neither. Each holds the same mesh as its MEDIT
original, so `hbc analyze` must give identical results (tests/cpp/test_xdmf.cpp):
  slab_meshio.xdmf + .h5     real/slab.mesh (hexahedra and prisms): a Mixed topology, data in HDF5
  slab_inline.xdmf           the same with its data inline (data_format="XML")
  mixed4_meshio.xdmf + .h5   mixed4.mesh (one hexahedron, prism, pyramid, tetrahedron), Mixed, HDF5
  slab_series.xdmf + .h5     meshio's TimeSeriesWriter: a temporal collection of two steps whose
                             Grids include the mesh's Topology and Geometry from a Grid after it
                             (xi:include with an xpointer)
(Single-type topologies and dolfinx's second-order names are written by tests/cpp/test_xdmf.cpp.)
"""
import os

import meshio
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "real")


def volumes(mesh):
    return meshio.Mesh(mesh.points, [b for b in mesh.cells if b.type in ("hexahedron", "wedge", "pyramid", "tetra")])


def main():
    os.chdir(OUT)  # meshio names the .h5 as it is given: relative, beside the .xdmf
    slab = volumes(meshio.read("slab.mesh"))
    meshio.write("slab_meshio.xdmf", slab)
    meshio.xdmf.write("slab_inline.xdmf", slab, data_format="XML")
    mixed = volumes(meshio.read(os.path.join(HERE, "mixed4.mesh")))
    meshio.write("mixed4_meshio.xdmf", mixed)
    with meshio.xdmf.TimeSeriesWriter("slab_series.xdmf") as w:
        w.write_points_cells(slab.points, slab.cells)
        for t in (0.0, 1.0):
            w.write_data(t, point_data={"u": np.full(len(slab.points), t)})


if __name__ == "__main__":
    main()
