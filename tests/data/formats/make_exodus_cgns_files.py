#!/usr/bin/env python3
"""Regenerates the Exodus II and CGNS twins under real/ with the formats' own tools.

Run with the Python of scripts/env/meshio_env.sh (meshio 5.3.5 from PyPI with netCDF4); needs
Debian's netcdf-bin (nccopy) and cgns-convert (aflr3_to_cgns, hdf2adf). The files are committed (each < 100 KB) so the
tests need none of these tools. Each holds the same mesh as its MEDIT original, so `hbc analyze`
must give identical results (tests/cpp/test_exodus_cgns.cpp):
  slab_hdf5.exo   meshio's Exodus writer as it is (netCDF-4/HDF5, the old `coord` array, int64 ids)
  slab_cdf5.e     slab_hdf5.exo through netCDF's nccopy -k cdf5 -u (the classic format's 64-bit data
                  variant; meshio's writer cannot write classic netCDF itself: it makes two unlimited
                  dimensions, and its int64 attribute rules out the 64-bit offset variant)
(libexodus writes the 64-bit offset files of test_exodus_cgns.cpp.)
  mixed4.exo      mixed4.mesh (one hexahedron, prism, pyramid, tetrahedron), meshio's writer (HDF5)
  slab.cgns       meshio's big-endian UGRID of slab_41.msh (volumes and the boundary's quadrangles and
                  triangles) through CGNS's aflr3_to_cgns (HDF5; boundary sections to skip)
  slab_adf.cgns   slab.cgns through CGNS's hdf2adf (the ADF storage)
  mixed4.cgns     mixed4.mesh through UGRID and aflr3_to_cgns (TETRA_4, PYRA_5, PENTA_6, HEXA_8)
"""
import os
import subprocess
import sys
import tempfile

import meshio

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "real")


def write_exodus(mesh, path):
    """meshio's Exodus writer (netCDF-4/HDF5)."""
    meshio.write(path, mesh, file_format="exodus")


def nccopy(src, dst, kind):
    """netCDF's own converter; -u makes the unlimited dimensions fixed (classic allows one)."""
    subprocess.run(["nccopy", "-k", kind, "-u", src, dst], check=True)


def write_cgns(mesh, path):
    """meshio's big-endian binary UGRID, then CGNS's own converter (its default: that UGRID form)."""
    with tempfile.TemporaryDirectory() as tmp:
        ugrid = os.path.join(tmp, "mesh.b8.ugrid")
        meshio.write(ugrid, mesh)
        subprocess.run(["aflr3_to_cgns", ugrid, path], check=True, stdout=subprocess.DEVNULL)


def volumes(mesh):
    return meshio.Mesh(mesh.points, [b for b in mesh.cells if b.type in ("hexahedron", "wedge", "pyramid", "tetra")])


def main():
    slab = meshio.read(os.path.join(OUT, "slab.mesh"))
    slab = meshio.Mesh(slab.points, slab.cells)
    write_exodus(slab, os.path.join(OUT, "slab_hdf5.exo"))
    nccopy(os.path.join(OUT, "slab_hdf5.exo"), os.path.join(OUT, "slab_cdf5.e"), "cdf5")
    mixed = volumes(meshio.read(os.path.join(HERE, "mixed4.mesh")))
    write_exodus(mixed, os.path.join(OUT, "mixed4.exo"))
    # gmsh's .msh of the slab has its boundary too (quadrangles, triangles): CGNS boundary sections.
    msh = meshio.read(os.path.join(OUT, "slab_41.msh"))
    keep = ("hexahedron", "wedge", "quad", "triangle")
    write_cgns(meshio.Mesh(msh.points, [b for b in msh.cells if b.type in keep]), os.path.join(OUT, "slab.cgns"))
    adf = os.path.join(OUT, "slab_adf.cgns")
    if os.path.exists(adf):
        os.remove(adf)
    subprocess.run(["hdf2adf", os.path.join(OUT, "slab.cgns"), adf], check=True, stdout=subprocess.DEVNULL)
    write_cgns(mixed, os.path.join(OUT, "mixed4.cgns"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
