"""Analysis.to_vtu() and `hbc export-vtu`: the files open in an independent reader (Debian's
python3-meshio) with one cell per mesh cell, the component ids of the analysis and the sheet arrays;
the singularity graph file holds one line per structural edge. Also: the new readers from Python."""

import base64
import json
import pathlib
import subprocess
import xml.etree.ElementTree as ET
import zlib

import numpy as np
import pytest

import hbc

import meshio  # Debian python3-meshio: the independent reader

FORMATS_DIR = pathlib.Path(__file__).resolve().parents[1] / "data" / "formats"
# An all-hex mesh of 288 cells in 5 components, a hex-dominant one with prisms, pyramids, tets and
# degenerate cells, and a polyhedral one (VTK_POLYHEDRON cells).
MESHES = ["openvolumemesh/Cylinder.ovm", "hybrid-base-complex/twistcube_s.mesh", "cinolib/eight_voronoi.hedra"]
DTYPES = {"Int32": np.int32, "Int64": np.int64, "UInt8": np.uint8, "Float64": np.float64}


def vtu_arrays(path):
    """A second, minimal VTU reader (xml.etree, base64, zlib): meshio 1.x misplaces the cell data
    of polyhedra with different vertex counts, so the polyhedral mesh is checked with this."""
    root = ET.parse(path).getroot()
    header = np.uint64 if root.get("header_type") == "UInt64" else np.uint32
    width = np.dtype(header).itemsize
    out = {}
    for da in root.iter("DataArray"):
        dtype = DTYPES[da.get("type")]
        if da.get("format") == "ascii":
            out[da.get("Name")] = np.array(da.text.split(), dtype=dtype)
            continue
        text = "".join(da.text.split())
        head3 = np.frombuffer(base64.b64decode(text[: 4 * -(-3 * width // 3)])[: 3 * width], header)
        head_chars = 4 * -(-(3 + int(head3[0])) * width // 3)
        sizes = np.frombuffer(base64.b64decode(text[:head_chars])[: (3 + int(head3[0])) * width], header)[3:]
        body = base64.b64decode(text[head_chars:])
        starts = np.concatenate([[0], np.cumsum(sizes)]).astype(int)
        raw = b"".join(zlib.decompress(body[a:b]) for a, b in zip(starts[:-1], starts[1:]))
        out[da.get("Name")] = np.frombuffer(raw, dtype)
    return out


def cells_of(m):
    """meshio splits cells into one block per cell type: back to one array per cell-data name."""
    return sum(len(b.data) for b in m.cells), {k: np.concatenate(v) for k, v in m.cell_data.items()}


@pytest.mark.parametrize("name", MESHES)
@pytest.mark.parametrize("ascii", [False, True])
def test_to_vtu_arrays_match_the_analysis(shared_data_dir, tmp_path, name, ascii):
    mesh = hbc.load(shared_data_dir / name)
    a = mesh.analyze(wireframe=False)
    a.to_vtu(str(tmp_path / "out.vtu"), sheet=0, ascii=ascii)
    d = vtu_arrays(tmp_path / "out.vtu")
    assert np.array_equal(d["component"], a.complex.cell_component)
    assert np.array_equal(d["cell_type"], mesh.cell_types)
    assert len(d["offsets"]) == mesh.num_cells
    assert np.array_equal(d["Points"].reshape(-1, 3), mesh.points64)
    # Each cell as its own VTK type (hbc's CellType order: hex, tet, prism, pyramid, polyhedron).
    assert np.array_equal(d["types"], np.array([12, 10, 13, 14, 42])[mesh.cell_types])


# meshio 5 reads no file mixing VTK_POLYHEDRON with other types: twistcube's 44 polyhedra leave
# the all-hex cylinder here; test_export_keeps_cell_types_and_orientation reads mixed elements.
@pytest.mark.parametrize("name", MESHES[:1])
@pytest.mark.parametrize("ascii", [False, True])
def test_to_vtu_opens_in_meshio_with_the_block_ids(shared_data_dir, tmp_path, name, ascii):
    mesh = hbc.load(shared_data_dir / name)
    a = mesh.analyze(wireframe=False)
    out = tmp_path / "out.vtu"
    graph_path = a.to_vtu(str(out), sheet=0, ascii=ascii)
    assert graph_path == str(tmp_path / "out_graph.vtu")
    m = meshio.read(out)
    n, data = cells_of(m)
    assert n == mesh.num_cells
    assert len(m.points) == mesh.num_vertices
    assert len(np.unique(data["component"])) == a.stats["components"]
    if name == MESHES[0]:
        assert a.stats["components"] == 5  # components, not cells: the ids are shared
    assert int(data["is_hex"].sum()) == int((mesh.cell_types == 0).sum())
    # meshio regroups the cells by VTK type: compare the counts of hbc's cell types.
    assert np.array_equal(np.bincount(data["cell_type"], minlength=5), np.bincount(mesh.cell_types, minlength=5))
    # Sheet 0's membership array holds exactly its cells.
    sheet0 = a.sheet_cells_items[a.sheet_cells_offsets[0]:a.sheet_cells_offsets[1]]
    assert int(data["in_sheet"].sum()) == len(sheet0)
    assert int((data["sheet_count"] > 0).sum()) == len(np.unique(a.sheet_cells_items))
    g = meshio.read(graph_path)
    lines, gdata = cells_of(g)
    st = a.stats
    assert lines == st["singular_edges"] + st["pseudo_singular_edges"] + st["non_manifold_edges"]
    assert int((gdata["edge_class"] == 1).sum()) == st["singular_edges"]
    assert int(m.point_data["singular"].sum()) == st["singular_vertices"]


def test_export_vtu_command_writes_what_meshio_reads(shared_data_dir, tmp_path, hbc_cli):
    src = shared_data_dir / MESHES[0]
    out = tmp_path / "cli.vtu"
    subprocess.run([hbc_cli, "export-vtu", str(src), "-o", str(out)], check=True, capture_output=True)
    m = meshio.read(out)
    n, data = cells_of(m)
    mesh = hbc.load(src)
    assert n == mesh.num_cells
    assert len(np.unique(data["component"])) == mesh.analyze(wireframe=False).stats["components"]
    assert (tmp_path / "cli_graph.vtu").exists()


@pytest.mark.parametrize("name", MESHES)
def test_export_vtu_reads_back_with_the_same_analysis(shared_data_dir, tmp_path, name):
    mesh = hbc.load(shared_data_dir / name)
    a = mesh.analyze(wireframe=False)
    a.to_vtu(str(tmp_path / "poly.vtu"))
    b = hbc.load(tmp_path / "poly.vtu").analyze(wireframe=False)
    for key in ("cells", "hex_ratio", "components", "singular_edges", "pseudo_singular_edges", "sheets"):
        assert a.stats[key] == b.stats[key], key


def test_to_vtu_rejects_a_sheet_out_of_range(shared_data_dir, tmp_path):
    a = hbc.load(shared_data_dir / MESHES[0]).analyze(wireframe=False)
    with pytest.raises(ValueError):
        a.to_vtu(str(tmp_path / "x.vtu"), sheet=a.num_sheets)
    with pytest.raises(ValueError):
        a.to_vtu(str(tmp_path / "x.vtu"), sheet=-2)


@pytest.mark.parametrize("name", ["slab_41_bin.msh", "slab_51_bin.vtk", "slab_zlib.vtu"])
def test_new_formats_load_from_python(name):
    ref = hbc.load(FORMATS_DIR / "real" / "slab.mesh").analyze(wireframe=False).stats
    got = hbc.load(FORMATS_DIR / "real" / name).analyze(wireframe=False).stats
    for key in ("cells", "hex_ratio", "components", "sheets", "singular_edges"):
        assert got[key] == ref[key], key


def test_malformed_new_formats_raise_mesh_format_error(tmp_path):
    bad = tmp_path / "bad.msh"
    bad.write_text("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n")
    with pytest.raises(hbc.MeshFormatError, match=r"bad\.msh:2: expected a \.msh version 2\.2 or 4\.1"):
        hbc.load(bad)


# Grids with random cells split into pyramids, prisms or tets (hbc generate split: no general
# polyhedron, so meshio reads them back); twistcube and teapot mix hexahedra with general polyhedra
# (meshio 5 refuses files mixing VTK_POLYHEDRON with other types: they are read back by the minimal
# reader above and by hbc).
VTK_TYPE = {0: 12, 1: 10, 2: 13, 3: 14, 4: 42}
MESHIO_NAME = {12: "hexahedron", 10: "tetra", 13: "wedge", 14: "pyramid"}


# The outward faces of VTK's cells in VTK's corner order (vtkTetra, vtkHexahedron, vtkWedge,
# vtkPyramid of VTK 9.7; older VTK documented the wedge mirrored): a cell of positive orientation
# in VTK's convention has a positive volume over them. tests/vtk compares with VTK itself.
VTK_FACES = {10: [(0, 1, 3), (1, 2, 3), (2, 0, 3), (0, 2, 1)],
             12: [(0, 4, 7, 3), (1, 2, 6, 5), (0, 1, 5, 4), (3, 7, 6, 2), (0, 3, 2, 1), (4, 5, 6, 7)],
             13: [(0, 2, 1), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)],
             14: [(0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]}


def vtk_volumes(points, conn, offsets, types):
    """Per cell, its volume over VTK's faces of its type (NaN for a polyhedron)."""
    out = np.full(len(types), np.nan)
    starts = np.concatenate([[0], offsets[:-1]])
    for c, (s, t) in enumerate(zip(starts, types)):
        if t == 42:
            continue
        p = points[conn[s:offsets[c]]]
        o = p.mean(axis=0)
        out[c] = sum(np.dot(p[f[0]] - o, np.cross(p[f[k]] - o, p[f[k + 1]] - o))
                     for f in VTK_FACES[t] for k in range(1, len(f) - 1)) / 6
    return out


def mesh_named(name, shared_data_dir, tmp_path, hbc_cli):
    if not name.startswith("split-"):
        return shared_data_dir / name
    path = tmp_path / f"{name}.ovm"  # a split hex's tets leave a polyhedron MEDIT cannot store
    subprocess.run([hbc_cli, "generate", "split", "--size", "4", "3", "2", "--split", name[6:], "--random", "5",
                    "-o", path], check=True, capture_output=True)
    return path


SPLIT = ["split-pyramids", "split-prisms", "split-tets"]


@pytest.mark.parametrize("name", SPLIT + ["hybrid-base-complex/twistcube_s.mesh", "hybrid-base-complex/teapot.hedra"])
def test_export_keeps_cell_types_and_orientation(shared_data_dir, tmp_path, name, hbc_cli):
    source = mesh_named(name, shared_data_dir, tmp_path, hbc_cli)
    mesh = hbc.load(source)
    out = tmp_path / "out.vtu"
    mesh.analyze(wireframe=False).to_vtu(str(out))
    d = vtu_arrays(out)
    types = d["types"]
    assert np.array_equal(types, np.vectorize(VTK_TYPE.get)(mesh.cell_types))
    assert (types == 12).sum() == (mesh.cell_types == 0).sum()
    # Positive in VTK's convention, except the cells hbc check finds inverted (tangled). Non-planar
    # quadrangles make a nearly flat cell's sign depend on how its faces are split into triangles
    # (teapot: 3 cells under 1% of the median volume): those under 2% are left out.
    vol = vtk_volumes(d["Points"].reshape(-1, 3), d["connectivity"], d["offsets"], types)
    inverted = {i["id"] for i in hbc.check(source, first=1 << 30)["defects"]["inverted"]["first"]}
    clear = np.flatnonzero((types != 42) & (np.abs(vol) > 0.02 * np.nanmedian(np.abs(vol))))
    assert {c for c in clear if vol[c] < 0} == {c for c in clear if c in inverted}
    assert len(clear) > 0.95 * (types != 42).sum()
    if (types == 42).any():
        with pytest.raises(ValueError, match="polyhedra"):
            meshio.read(out)
        return
    m = meshio.read(out)
    counts = {}
    for b in m.cells:  # one block per run of one type
        counts[b.type] = counts.get(b.type, 0) + len(b.data)
    assert counts == {MESHIO_NAME[t]: int((types == t).sum()) for t in np.unique(types)}
    assert counts["hexahedron"] == (mesh.cell_types == 0).sum() and len(counts) >= 2
    # meshio groups cells by type; within a type they keep their order, and so does their data.
    cell_type = np.concatenate(m.cell_data["cell_type"])
    assert sorted(cell_type) == sorted(mesh.cell_types)


@pytest.mark.parametrize("name", SPLIT + ["hybrid-base-complex/twistcube_s.mesh", "hybrid-base-complex/teapot.hedra",
                                          "cinolib/eight_voronoi.hedra"])
def test_export_vtu_round_trip_gives_the_same_analysis(shared_data_dir, tmp_path, name, hbc_cli):
    """hbc reads VTU: the export read back is the same mesh, so `hbc analyze --json` gives the same
    statistics (the file name and timings aside)."""
    source = mesh_named(name, shared_data_dir, tmp_path, hbc_cli)
    out = tmp_path / "out.vtu"
    subprocess.run([hbc_cli, "export-vtu", source, "-o", out], check=True, capture_output=True)
    stats = []
    for path in (source, out):
        run = subprocess.run([hbc_cli, "analyze", path, "--json"], check=True, capture_output=True, text=True)
        j = json.loads(run.stdout)
        stats.append({k: v for k, v in j.items() if k not in ("file", "timings")})
    assert stats[0] == stats[1]

