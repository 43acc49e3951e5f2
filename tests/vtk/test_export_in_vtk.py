"""`hbc export-vtu` as VTK itself reads it: the `vtk` wheel's XML reader, vtkMeshQuality (Verdict)
and vtkCellSizeFilter, i.e. what ParaView shows. Per cell, VTK's scaled Jacobian equals `hbc
quality`'s and VTK's volume has the sign of hbc's; a file VTK writes reads in hbc as the same cells
written as MEDIT; and the Verdict quirk docs/metrics.md states (hexahedron edge ratio) holds.

Runs in the independent checks' Python (scripts/env/check_env.sh: NumPy 2 and the `vtk` wheel).
hbc's own per-cell values come from the CLI and from the binding run in a subprocess of the
binding's Python (HBC_PYTHON, Debian's NumPy 1.x), never from the binding imported here."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

HBC_CLI = os.environ["HBC_CLI"]
DATA = pathlib.Path(os.environ["HBC_DATA_DIR"])
HEX, TET, WEDGE, PYRAMID, POLYHEDRON = 12, 10, 13, 14, 42
# hbc's CellType (hex, tet, prism, pyramid, polyhedron) as the VTK type export-vtu writes.
VTK_TYPE = np.array([HEX, TET, WEDGE, PYRAMID, POLYHEDRON])

# Per cell, in the binding's Python: hbc's scaled Jacobian and edge ratio (hbc quality's values),
# its cell types, the cells whose volume hbc finds negative (inverted) or zero, and the closed cells
# that are no simple polyhedron (a vertex in two faces only: cube_twist's 5 polyhedra).
HBC_VALUES = r"""
import json, sys
import hbc
mesh = hbc.load(sys.argv[1])
q = hbc.cell_quality(mesh)
defects = hbc.check(sys.argv[1], first=1 << 30)["defects"]
print(json.dumps({"sj": q["scaled_jacobian"].tolist(), "edge_ratio": q["edge_ratio"].tolist(),
                  "types": mesh.cell_types.tolist(),
                  "inverted": [d["id"] for d in defects["inverted"]["first"]],
                  "zero": [d["id"] for d in defects["zero_volume"]["first"]],
                  "not_simple": [d["id"] for d in defects["not_simple"]["first"]]}))
"""


def hbc_values(path):
    env = dict(os.environ, PYTHONPATH=os.environ["HBC_PYTHON_DIR"])
    run = subprocess.run([os.environ["HBC_PYTHON"], "-c", HBC_VALUES, str(path)], check=True, capture_output=True,
                         text=True, env=env)
    return {k: np.array(v, dtype=int if k in ("types", "inverted", "zero", "not_simple") else float)
            for k, v in json.loads(run.stdout).items()}


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def vtk_measures(grid):
    """Per cell: VTK type, vtkMeshQuality's scaled Jacobian, vtkCellSizeFilter's volume."""
    quality = vtk.vtkMeshQuality()
    quality.SetInputData(grid)
    quality.SetHexQualityMeasureToScaledJacobian()
    quality.SetTetQualityMeasureToScaledJacobian()
    quality.SetWedgeQualityMeasureToScaledJacobian()
    quality.SetPyramidQualityMeasureToScaledJacobian()
    quality.Update()
    size = vtk.vtkCellSizeFilter()
    size.SetInputData(grid)
    size.Update()
    types = np.array([grid.GetCellType(c) for c in range(grid.GetNumberOfCells())])
    return (types, vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Quality")),
            vtk_to_numpy(size.GetOutput().GetCellData().GetArray("Volume")))


def write_medit(path, points, cells):
    """`cells`: (VTK type, 0-based corners) in VTK's corner order, which is MEDIT's for these types."""
    section = {HEX: "Hexahedra", TET: "Tetrahedra", WEDGE: "Prisms", PYRAMID: "Pyramids"}
    lines = ["MeshVersionFormatted 2", "Dimension 3", "Vertices", str(len(points))]
    lines += [f"{float(x)!r} {float(y)!r} {float(z)!r} 0" for x, y, z in points]
    for t in (HEX, TET, WEDGE, PYRAMID):  # hbc numbers MEDIT's cells section by section, in this order
        rows = [c for ct, c in cells if ct == t]
        if rows:
            lines += [section[t], str(len(rows))] + [" ".join(str(v + 1) for v in c) + " 0" for c in rows]
    pathlib.Path(path).write_text("\n".join(lines + ["End"]) + "\n")


def tangled_mesh(path):
    """Two unit cubes side by side, a pyramid on the first whose apex is pushed down into it and a
    wedge lying on the second whose ridge is pushed down into it: both inverted once the cubes
    fix the orientation (hbc: negative scaled Jacobian and volume). Plus an upright pyramid."""
    p = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1),
         (2, 0, 0), (2, 1, 0), (2, 0, 1), (2, 1, 1), (0.5, 0.5, 0.7), (1.5, 0, 0.6), (1.5, 1, 0.6),
         (0.5, 0.5, -0.8)]
    cells = [(HEX, [0, 1, 2, 3, 4, 5, 6, 7]), (HEX, [1, 8, 9, 2, 5, 10, 11, 6]),
             (PYRAMID, [4, 5, 6, 7, 12]), (WEDGE, [5, 13, 10, 6, 14, 11]), (PYRAMID, [0, 3, 2, 1, 15])]
    write_medit(path, p, cells)
    return path


def mesh_named(name, tmp_path):
    if name == "tangled":
        return tangled_mesh(tmp_path / "tangled.mesh")
    if name.startswith("split-"):  # random cells of a grid split into pyramids, prisms or tets
        path = tmp_path / f"{name}.ovm"
        subprocess.run([HBC_CLI, "generate", "split", "--size", "4", "3", "2", "--split", name[6:], "--random", "6",
                        "-o", path], check=True, capture_output=True)
        return path
    return DATA / name


# Hexahedra and prisms (test_2), every type with general polyhedra (twistcube_s: 1157 hexahedra,
# 66 prisms, 2 tets, 1 pyramid, 75 polyhedra), a prism among polyhedra (cube_twist), a pyramid on a
# hexahedron (NonManifold), hexahedra of which 47 are inverted (teapot), generated splits, and an
# inverted wedge and pyramid.
MESHES = ["hybrid-base-complex/test_2.HYBRID", "hybrid-base-complex/twistcube_s.mesh",
          "hybrid-base-complex/cube_twist-comp.obj.HYBRID", "openvolumemesh/NonManifold.ovm",
          "hybrid-base-complex/teapot.hedra", "split-prisms", "split-pyramids", "split-tets", "tangled"]


@pytest.mark.parametrize("name", MESHES)
def test_vtk_measures_every_exported_cell_as_hbc_does(tmp_path, name):
    source = mesh_named(name, tmp_path)
    out = tmp_path / "out.vtu"
    subprocess.run([HBC_CLI, "export-vtu", source, "-o", out], check=True, capture_output=True)
    types, sj, vol = vtk_measures(read_vtu(out))
    hbc = hbc_values(source)
    assert np.array_equal(types, VTK_TYPE[hbc["types"]])
    # Verdict's scaled Jacobian, as hbc computes it, for every type Verdict defines; Verdict
    # returns 0 for a pyramid whose value is <= 0, where hbc keeps the negative value
    # (docs/metrics.md). Verdict has no measure of a general polyhedron.
    expected = np.where((types == PYRAMID) & (hbc["sj"] <= 0), 0.0, hbc["sj"])
    standard = types != POLYHEDRON
    np.testing.assert_allclose(sj[standard], expected[standard], rtol=1e-12, atol=1e-12)
    # Volumes: VTK's sign is hbc's, polyhedra included (hbc check: inverted = negative volume),
    # but for cells that are no simple polyhedron, which enclose no well-defined inside
    # (cube_twist's cell 352: hbc -0.00025 over its triangles, VTK positive; twistcube's 44
    # (3,3,4,4) cells), and nearly flat cells, whose sign depends on how their non-planar faces are
    # split into triangles (teapot's tangled hexahedron 28: VTK -0.0034, 0.1% of the median volume,
    # hbc positive): cells of zero volume or under 1% of the median volume are left out.
    negative = np.zeros(len(types), bool)
    negative[hbc["inverted"]] = True
    clear = np.abs(vol) > 0.01 * np.median(np.abs(vol))
    clear[np.concatenate([hbc["zero"], hbc["not_simple"]])] = False
    assert ((types[~clear] == POLYHEDRON) | (np.abs(vol[~clear]) < 0.01 * np.median(np.abs(vol)))).all()
    assert clear.sum() >= 0.95 * len(types)
    assert np.array_equal(vol[clear] < 0, negative[clear])
    assert (vol[clear & ~negative] > 0).all()
    if name == "tangled":  # the inverted wedge and pyramid are there, and so is the clamp
        assert list(types[negative]) == [WEDGE, PYRAMID]
        assert (sj[negative] < 0).tolist() == [True, False] and (hbc["sj"][negative] < 0).all()


def vtk_source(cell_type, blocks, shift):
    """A block of VTK's own cells of one type (vtkCellTypeSource: VTK's corner order), moved."""
    source = vtk.vtkCellTypeSource()
    source.SetCellType(cell_type)
    source.SetBlocksDimensions(*blocks)
    move = vtk.vtkTransform()
    move.Translate(*shift)
    moved = vtk.vtkTransformFilter()
    moved.SetTransform(move)
    moved.SetInputConnection(source.GetOutputPort())
    moved.Update()
    return moved.GetOutput()


def strip(x):
    """JSON without what names the file or its places in it, or measures time."""
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items()
                if k not in ("file", "timings", "line", "byte") and not k.startswith("seconds")}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x


def test_a_file_vtk_writes_reads_as_the_same_cells_in_medit(tmp_path):
    # Hexahedra beside wedges (their shared faces are quadrangles) and, apart, tetrahedra, all as
    # VTK makes them, corners moved at random so that quadrangles are not planar (a wedge read in
    # the mirror-image order would start its quadrangles at other corners: other volumes).
    append = vtk.vtkAppendFilter()
    append.MergePointsOn()
    for cell_type, shift in ((vtk.VTK_HEXAHEDRON, (0, 0, 0)), (vtk.VTK_TETRA, (0, 0, 3)), (vtk.VTK_WEDGE, (3, 0, 0))):
        append.AddInputData(vtk_source(cell_type, (3, 3, 2), shift))
    append.Update()
    grid = append.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
    points += np.random.default_rng(7).uniform(-0.12, 0.12, points.shape)
    grid.GetPoints().SetData(numpy_to_vtk(points, deep=True))
    vtu = tmp_path / "vtk.vtu"
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetFileName(str(vtu))
    writer.SetInputData(grid)
    assert writer.Write() == 1
    types, _, vol = vtk_measures(grid)
    assert set(types) == {HEX, WEDGE, TET} and (vol > 0).all()
    cells = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        cells.append((int(types[c]), [ids.GetId(i) for i in range(ids.GetNumberOfIds())]))
    medit = tmp_path / "medit.mesh"
    write_medit(medit, points, cells)
    # MEDIT numbers the cells by section (hexahedra, tetrahedra, prisms): VTK's order is the same.
    assert list(types) == sorted(types, key=lambda t: [HEX, TET, WEDGE].index(t))
    for command in ("analyze", "metrics", "quality", "check", "sheets", "wireframe"):
        got = [strip(json.loads(subprocess.run([HBC_CLI, command, p, "--json"], capture_output=True, text=True).stdout))
               for p in (vtu, medit)]
        assert got[0] == got[1], command
    # And what VTK measures on its own file is what hbc measures on it.
    hbc = hbc_values(vtu)
    _, sj, _ = vtk_measures(grid)
    np.testing.assert_allclose(sj, hbc["sj"], rtol=1e-12, atol=1e-12)


def vtk_hex_edge_ratio(corners):
    grid = vtk.vtkUnstructuredGrid()
    points = vtk.vtkPoints()
    for p in corners:
        points.InsertNextPoint(p)
    grid.SetPoints(points)
    grid.InsertNextCell(HEX, 8, list(range(8)))
    quality = vtk.vtkMeshQuality()
    quality.SetInputData(grid)
    quality.SetHexQualityMeasureToEdgeRatio()
    quality.Update()
    return vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Quality"))[0]


def test_verdict_hex_edge_ratio_looks_at_the_first_six_edges_only(tmp_path):
    # docs/metrics.md's example: a 1 x 1 x 2 box, corners 0-3 at z = 0 and 4-7 at z = 2. Its four
    # edges of length 2 (0-4, 1-5, 2-6, 3-7) are the last of Verdict's twelve; its hex_edge_ratio
    # takes the longest of the first six (0-1, 1-2, 2-3, 3-0, 4-5, 5-6) over the shortest of all
    # twelve, so ParaView shows 1 where hbc (longest / shortest of all twelve) gives 2.
    base = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    tall = base + [(x, y, 2) for x, y, _ in base]
    path = tmp_path / "box.mesh"
    write_medit(path, tall, [(HEX, list(range(8)))])
    assert vtk_hex_edge_ratio(tall) == 1.0
    assert hbc_values(path)["edge_ratio"][0] == 2.0
    # The same box lying along x (the long edges 0-1, 2-3, 4-5, 6-7): both give 2.
    long = [(2 * x, y, z / 2) for x, y, z in tall]
    write_medit(path, long, [(HEX, list(range(8)))])
    assert vtk_hex_edge_ratio(long) == 2.0
    assert hbc_values(path)["edge_ratio"][0] == 2.0
