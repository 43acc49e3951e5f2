#!/usr/bin/env python3
"""Writes the CFD-format files under real/ from the slab (slab.geo): SU2, AFLR3 UGRID, Fluent.

Run with a Python holding PyPI's meshio 5.3 and NumPy 1 (meshio 5.3.5 writes ASCII UGRID counts as
"np.int64(192)" under NumPy 2), where Debian's gmsh and openfoam (v1912) are installed:
  source scripts/env/common.sh; hbc_stamped_venv ~/.cache/hbc-envs/py-meshio53 "meshio==5.3.5 numpy<2"
  ~/.cache/hbc-envs/py-meshio53/bin/python tests/data/formats/make_cfd_files.py
The files are committed, so the tests need none of them.
Every file holds the mesh of real/slab_41.msh (82 hexahedra, 28 prisms):
  slab_gmsh.su2                      gmsh's SU2 writer (with its boundary markers)
  slab_meshio.su2                    meshio's SU2 writer
  slab.ugrid, slab.b8.ugrid, slab.lb8.ugrid, slab.r8.ugrid, slab.lr8.ugrid
                                     meshio's UGRID writer in each encoding (with the bottom's faces)
  slab_fluent.msh                    OpenFOAM's foamMeshToFluent of gmshToFoam's case of slab_22.msh
"""
import os
import shutil
import subprocess
import sys
import tempfile

import meshio
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "real")
FOAM_ENV = "export WM_PROJECT_DIR=/usr/share/openfoam; source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1; "


def merged(mesh, types):
    """One block per cell type (meshio's UGRID writer takes one block of a type)."""
    blocks = {}
    for b in mesh.cells:
        if b.type in types:
            blocks.setdefault(b.type, []).append(b.data)
    return meshio.Mesh(mesh.points, [(t, np.concatenate(d)) for t, d in blocks.items()])


def fluent(tmp):
    """gmshToFoam, then foamMeshToFluent: the Fluent mesh OpenFOAM writes of the slab."""
    case = os.path.join(tmp, "slab")
    os.makedirs(os.path.join(case, "system"))
    os.makedirs(os.path.join(case, "constant"))
    with open(os.path.join(case, "system", "controlDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }\n"
                "application none; startFrom startTime; startTime 0; stopAt endTime; endTime 0; deltaT 1;\n"
                "writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 17;\n"
                "writeCompression off; timeFormat general; timePrecision 6;\n")
    run = FOAM_ENV + f"cd {case} && gmshToFoam {os.path.join(OUT, 'slab_22.msh')} && foamMeshToFluent"
    subprocess.run(["bash", "-c", run], check=True, stdout=subprocess.DEVNULL)
    shutil.copy(os.path.join(case, "fluentInterface", "slab.msh"), os.path.join(OUT, "slab_fluent.msh"))


def main():
    subprocess.run(["gmsh", "-3", os.path.join(HERE, "slab.geo"), "-format", "su2", "-o",
                    os.path.join(OUT, "slab_gmsh.su2")], check=True, stdout=subprocess.DEVNULL)
    m = meshio.read(os.path.join(OUT, "slab_41.msh"))
    meshio.write(os.path.join(OUT, "slab_meshio.su2"), merged(m, {"hexahedron", "wedge"}), file_format="su2")
    with_faces = merged(m, {"hexahedron", "wedge", "triangle", "quad"})
    for enc in ["", ".b8", ".lb8", ".r8", ".lr8"]:
        meshio.write(os.path.join(OUT, f"slab{enc}.ugrid"), with_faces, file_format="ugrid")
    with tempfile.TemporaryDirectory() as tmp:
        fluent(tmp)
    return 0


if __name__ == "__main__":
    sys.exit(main())
