#!/usr/bin/env python3
"""Writes the finite-element deck twins of real/slab.mesh into real/ (committed; the tests need no tool).

Run with a Python that has meshio 5.3.x from PyPI (e.g. a venv made by scripts/env/common.sh's
hbc_stamped_venv with "meshio==5.3.5") and Debian's gmsh on PATH:
  slab_gmsh.inp, slab_gmsh_order2.inp           gmsh's Abaqus writer (C3D8/C3D6; C3D20/C3D15 with
                                                 Mesh.SecondOrderIncomplete), CPS/M3D surfaces too
  slab_gmsh_free.bdf, slab_gmsh_small.bdf,
  slab_gmsh_large.bdf, slab_gmsh_order2.bdf     gmsh's Nastran writer, Mesh.BdfFieldFormat 0, 1, 2
  slab_meshio.inp, slab_meshio.bdf              meshio's Abaqus and Nastran writers (from slab.mesh)
  slab_*.k, slab_i10.key                        LS-DYNA keyword files written here (below)

No LS-DYNA writer is installable here (LS-PrePost is not packaged; meshio has none), so the .k
files come from write_k below, which follows the LS-DYNA Keyword User's Manual's card layouts:
*NODE "NID X Y Z" (i8 e16 e16 e16; I10 `%`: i10 e16; long `+`: 20 each), *ELEMENT_SOLID either
one card "EID PID N1..N8" or the card "EID PID" and the card "N1..N8", and the manual's
degenerate hexahedron for a prism (N5=N6, N7=N8). Node labels are 1000 + 7*i written in
reverse, so that the reader's label mapping is exercised, not the 1..n numbering.
"""
import os
import subprocess

import meshio

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "real")
GEO = os.path.join(HERE, "slab.geo")


def gmsh(fmt, name, *options):
    cmd = ["gmsh", "-3", GEO, "-format", fmt, "-o", os.path.join(OUT, name)]
    for o in options:
        cmd += list(o)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def label(i):
    return 1000 + 7 * i


def lsdyna_hex(kind, c):
    """The 8 node labels of a cell: a hexahedron as it is, a MEDIT prism (triangles 0-1-2 and
    3-4-5) as LS-DYNA's pentahedron N1 N2 N3 N4 N5=N6 N7=N8: quad p0 p1 p4 p3, then p2 twice
    and p5 twice (triangles N1 N2 N5 and N4 N3 N7)."""
    v = [label(int(x)) for x in c]
    return v if kind == "hexahedron" else [v[0], v[1], v[4], v[3], v[2], v[2], v[5], v[5]]


def write_k(mesh, path, form):
    iw, rw = {"standard": (8, 16), "i10": (10, 16), "long": (20, 20), "twocard": (8, 16), "free": (8, 16)}[form]
    suffix = {"i10": " %", "long": " +"}.get(form, "")
    out = ["$ slab.mesh as an LS-DYNA keyword file (" + form + "), tests/data/formats/make_deck_files.py", "*KEYWORD", "*NODE" + suffix]
    for i in reversed(range(len(mesh.points))):
        x, y, z = (float(t) for t in mesh.points[i])
        if form == "free":
            out.append(f"{label(i)},{x!r},{y!r},{z!r}")
        else:
            out.append(f"{label(i):>{iw}}" + "".join(f"{t:>{rw}.9g}" for t in (x, y, z)))
    out.append("*ELEMENT_SOLID" + suffix)
    eid = 1
    for block in mesh.cells:
        for c in block.data:
            n = lsdyna_hex(block.type, c)
            if form == "free":
                out.append(",".join(str(t) for t in [eid, 1] + n))
            elif form == "twocard":
                out.append(f"{eid:>{iw}}{1:>{iw}}")
                out.append("".join(f"{t:>{iw}}" for t in n))
            else:
                out.append("".join(f"{t:>{iw}}" for t in [eid, 1] + n))
            eid += 1
    out.append("*END")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    os.makedirs(OUT, exist_ok=True)
    order2 = (("-order", "2"), ("-string", "Mesh.SecondOrderIncomplete=1;"))
    gmsh("inp", "slab_gmsh.inp")
    gmsh("inp", "slab_gmsh_order2.inp", *order2)
    for n, name in enumerate(["free", "small", "large"]):
        gmsh("bdf", f"slab_gmsh_{name}.bdf", ("-string", f"Mesh.BdfFieldFormat={n};"))
    gmsh("bdf", "slab_gmsh_order2.bdf", *order2)
    mesh = meshio.read(os.path.join(OUT, "slab.mesh"))
    mesh = meshio.Mesh(mesh.points, [(b.type, b.data) for b in mesh.cells])
    meshio.write(os.path.join(OUT, "slab_meshio.inp"), mesh, file_format="abaqus")
    meshio.write(os.path.join(OUT, "slab_meshio.bdf"), mesh, file_format="nastran")
    for form in ["standard", "long", "twocard", "free"]:
        write_k(mesh, os.path.join(OUT, f"slab_{form}.k"), form)
    write_k(mesh, os.path.join(OUT, "slab_i10.key"), "i10")


if __name__ == "__main__":
    main()
