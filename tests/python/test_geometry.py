"""hbc.block_soup() and hbc.polylines(): polygon soups of owners (cells, components, sheets,
subsheets, one sheet's components, non-hex cells, the boundary, the hex region) with outward loops,
one vertex copy per owner, shrinking toward each owner's centroid; and polyline point positions."""

import subprocess

import numpy as np
import pytest

import hbc

from conftest import MESHES, TABLE1


def rows(offsets, items):
    return [items[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def kinds(a):
    """(what, sheet, number of possible owners) for every soup kind the analysis allows."""
    out = [("cells", None, a.mesh.num_cells), ("components", None, len(a.complex.component_kind)),
           ("sheets", None, a.num_sheets), ("non_hex", None, a.mesh.num_cells), ("boundary", None, 5),
           ("hex", None, 1)]
    for s in range(min(a.num_sheets, 3)):
        out += [("sheet", s, len(a.complex.component_kind)), ("sheet_non_hex", s, a.mesh.num_cells)]
    for s in a.self_intersecting_sheets:
        out.append(("subsheets", int(s), a.subsheets(int(s)).count))
    return out


def check_soup(m, d, owners):
    """Shapes, ranges, and the point/owner structure every soup has."""
    pos, pv = d["positions"], d["point_vertex"]
    starts, fv, owner, src = d["face_vertices_offsets"], d["face_vertices_items"], d["face_owner"], d["face_source"]
    sizes = np.diff(starts)
    npnt, nf = len(pv), len(sizes)
    assert pos.dtype == np.float32 and pos.shape == (npnt, 3)
    for arr in (pv, starts, fv, owner, src):
        assert arr.dtype == np.int32 and arr.ndim == 1
    assert owner.shape == src.shape == (nf,)
    assert starts[0] == 0 and starts[-1] == len(fv)
    assert np.all(sizes >= 3)
    assert np.all((fv >= 0) & (fv < npnt))
    assert np.all((owner >= 0) & (owner < owners))
    assert np.all(np.diff(owner) >= 0), "faces grouped by increasing owner"
    assert np.all((pv >= 0) & (pv < m.num_vertices))
    assert np.all((src >= 0) & (src < m.num_faces))
    # Each face is the mesh face it comes from, as a loop (either direction, any rotation).
    for i in range(0, nf, max(1, nf // 200)):
        loop = pv[fv[starts[i]:starts[i + 1]]].tolist()
        f = src[i]
        mesh_loop = m.face_vertices_items[m.face_vertices_offsets[f]:m.face_vertices_offsets[f + 1]].tolist()
        assert sorted(loop) == sorted(mesh_loop)
    # Points are not shared between owners, and shared within one (one copy per mesh vertex).
    point_owner = np.full(npnt, -1)
    face_of = np.repeat(np.arange(nf), sizes)
    point_owner[fv] = owner[face_of]
    assert np.all(point_owner[fv] == owner[face_of]), "a point used by two owners"
    assert np.all(point_owner >= 0), "a point used by no face"
    pairs = point_owner.astype(np.int64) * m.num_vertices + pv
    assert len(np.unique(pairs)) == npnt, "two copies of one vertex in one owner"
    return point_owner


@pytest.mark.parametrize("name", MESHES)
def test_soups_valid_and_shrink(analyzed, name):
    m, a = analyzed[name]
    pts = m.points64
    for what, sheet, owners in kinds(a):
        d0 = hbc.block_soup(m, a, what, sheet=sheet)
        po = check_soup(m, d0, owners)
        assert np.array_equal(d0["positions"], m.points[d0["point_vertex"]]), what
        shrink = 0.3
        d = hbc.block_soup(m, a, what, sheet=sheet, shrink=shrink)
        for k in ("face_vertices_offsets", "face_vertices_items", "face_owner", "face_source", "point_vertex"):
            assert np.array_equal(d[k], d0[k]), (what, k)
        if len(po) == 0:
            continue
        n_own = po.max() + 1
        count = np.bincount(po, minlength=n_own)
        c = np.zeros((n_own, 3))
        np.add.at(c, po, pts[d0["point_vertex"]])
        c = c[po] / count[po, None]
        p = pts[d0["point_vertex"]]
        expected = c + (1 - shrink) * (p - c)
        assert np.allclose(d["positions"], expected, atol=1e-4 * np.ptp(pts)), what
        before = np.linalg.norm(p - c, axis=1)
        after = np.linalg.norm(d["positions"] - c, axis=1)
        assert np.all(after <= before * (1 - shrink) + 1e-4 * np.ptp(pts)), what
        assert np.all(after[before > 1e-3 * np.ptp(pts)] < before[before > 1e-3 * np.ptp(pts)]), what


@pytest.mark.parametrize("name", MESHES)
def test_soup_face_counts(analyzed, name):
    m, a = analyzed[name]
    nfaces = np.diff(m.cell_faces_offsets)
    hexes = m.cell_types == 0
    cells = hbc.block_soup(m, a, "cells")
    assert len(cells["face_owner"]) == len(m.cell_faces_items)
    assert np.array_equal(np.bincount(cells["face_owner"], minlength=m.num_cells), nfaces)
    non_hex = hbc.block_soup(m, a, "non_hex")
    assert len(non_hex["face_owner"]) == nfaces[~hexes].sum()
    assert set(np.unique(non_hex["face_owner"])) == set(np.flatnonzero(~hexes))
    boundary = hbc.block_soup(m, a, "boundary")
    bf = np.flatnonzero(m.face_boundary)
    assert np.array_equal(np.sort(boundary["face_source"]), bf)
    order = np.argsort(boundary["face_source"])
    assert np.array_equal(boundary["face_owner"][order], m.cell_types[m.face_cells[bf, 0]])
    # The hex region: one owner (0), the faces with a hex cell on exactly one side (a
    # boundary face of a hex cell counts: its other side is no cell), each seen from its hex cell.
    region = hbc.block_soup(m, a, "hex")
    hex_side = np.append(hexes, False)[m.face_cells]  # face_cells -1 picks the appended False
    expected = np.flatnonzero(hex_side[:, 0] != hex_side[:, 1])
    assert np.array_equal(np.sort(region["face_source"]), expected)
    assert np.all(region["face_owner"] == 0)
    if hexes.all():
        assert np.array_equal(expected, bf)  # an all-hex mesh: the region's surface is the boundary
    # Components: separation faces, once per side; interior ones twice.
    comps = hbc.block_soup(m, a, "components")
    sep = a.complex.face_separation
    assert len(comps["face_owner"]) == int(sep.sum() + (sep & ~m.face_boundary).sum())
    assert np.all(sep[comps["face_source"]])
    # Sheets: for each sheet, the faces of its cells with the other side outside the sheet.
    sheets = hbc.block_soup(m, a, "sheets")
    for s in range(min(a.num_sheets, 5)):
        inside = np.zeros(m.num_cells + 1, bool)
        inside[rows(a.sheet_cells_offsets, a.sheet_cells_items)[s]] = True
        fc = m.face_cells
        expected = np.flatnonzero(inside[fc[:, 0]] != inside[fc[:, 1]])
        assert np.array_equal(np.sort(sheets["face_source"][sheets["face_owner"] == s]), expected)
        one = hbc.block_soup(m, a, "sheet", sheet=s)
        owners = np.unique(one["face_owner"])
        assert np.array_equal(owners, rows(a.sheet_components_offsets, a.sheet_components_items)[s])
        nh = hbc.block_soup(m, a, "sheet_non_hex", sheet=s)
        assert np.array_equal(np.unique(nh["face_owner"]), rows(a.sheet_non_hex_cells_offsets, a.sheet_non_hex_cells_items)[s])
    for s in a.self_intersecting_sheets:
        sub = a.subsheets(int(s))
        d = hbc.block_soup(m, a, "subsheets", sheet=int(s))
        assert np.array_equal(np.unique(d["face_owner"]), np.flatnonzero(np.diff(sub.subsheet_cells_offsets) > 0))


def signed_volume(pos, sizes, fv):
    """Divergence theorem over fan triangles: positive for a closed surface with outward loops."""
    starts = np.concatenate(([0], np.cumsum(sizes)))
    vol = 0.0
    for i in range(len(sizes)):
        loop = pos[fv[starts[i]:starts[i + 1]]]
        for k in range(1, len(loop) - 1):
            vol += np.dot(loop[0], np.cross(loop[k], loop[k + 1])) / 6
    return vol


def disagreeing_cells(m):
    """Cells on an interior face that both its cells see with the same loop direction."""
    seen = np.zeros(m.num_faces, int)
    np.add.at(seen, m.cell_faces_items, m.cell_face_flip.astype(int))
    fc = m.face_cells
    bad = (fc[:, 1] >= 0) & (seen != 1)
    return np.unique(fc[bad].ravel())


def inverted_cells(m, a):
    """Cells whose own signed volume is negative once oriented consistently with their
    neighbours (tangled or inverted cells in the data)."""
    d = hbc.block_soup(m, a, "cells")
    pos = d["positions"].astype(np.float64)
    starts, fv, owner = d["face_vertices_offsets"], d["face_vertices_items"], d["face_owner"]
    sizes = np.diff(starts)
    out = []
    for c in range(m.num_cells):
        faces = np.flatnonzero(owner == c)
        loops = np.concatenate([fv[starts[f]:starts[f + 1]] for f in faces])
        if signed_volume(pos - pos[loops].mean(axis=0), sizes[faces], loops) < 0:
            out.append(c)
    return np.array(out, dtype=np.int64)


@pytest.mark.parametrize("name", MESHES)
def test_cube_component_blocks_closed_and_outward(analyzed, name):
    m, a = analyzed[name]
    d = hbc.block_soup(m, a, "components")
    pos = d["positions"].astype(np.float64) - m.points64.mean(axis=0)
    starts, fv, owner = d["face_vertices_offsets"], d["face_vertices_items"], d["face_owner"]
    sizes = np.diff(starts)
    cubes = np.flatnonzero(a.complex.component_kind == 0)
    # The mesh builder orients neighbouring cells consistently: no interior face is seen the same
    # way from both sides. Owners holding an inverted cell may enclose a negative volume.
    assert len(disagreeing_cells(m)) == 0
    tangled = set(a.complex.cell_component[inverted_cells(m, a)].tolist())
    assert len(cubes) > 0
    checked_orientation = 0
    for k in cubes[:: max(1, len(cubes) // 60)]:
        faces = np.flatnonzero(owner == k)
        directed = []
        for f in faces:
            loop = fv[starts[f]:starts[f + 1]].tolist()
            directed += list(zip(loop, loop[1:] + loop[:1]))
        # Closed: every undirected edge on exactly two faces.
        undirected = np.sort(np.array(directed), axis=1)
        _, counts = np.unique(undirected, axis=0, return_counts=True)
        assert np.all(counts == 2)
        if k in tangled:
            continue
        # Outward: every edge once in each direction and a positive enclosed volume.
        checked_orientation += 1
        assert len(set(directed)) == len(directed)
        assert set(directed) == {(b, a_) for a_, b in directed}
        assert signed_volume(pos, sizes[faces], np.concatenate([fv[starts[f]:starts[f + 1]] for f in faces])) > 0
    assert checked_orientation > 0


def test_hex_cells_outward(analyzed):
    m, a = analyzed[TABLE1 + "cube_twist-comp.obj.HYBRID"]
    d = hbc.block_soup(m, a, "cells")
    pos = d["positions"].astype(np.float64)
    starts, fv, owner = d["face_vertices_offsets"], d["face_vertices_items"], d["face_owner"]
    sizes = np.diff(starts)
    for c in np.flatnonzero(m.cell_types == 0)[::7]:
        faces = np.flatnonzero(owner == c)
        loops = np.concatenate([fv[starts[f]:starts[f + 1]] for f in faces])
        centre = pos[loops].mean(axis=0)
        assert signed_volume(pos - centre, sizes[faces], loops) > 0


def test_soup_errors(analyzed):
    m, a = analyzed[TABLE1 + "twistcube_s.mesh"]
    with pytest.raises(ValueError, match="expected one of"):
        hbc.block_soup(m, a, "patches")
    for bad in (-0.1, 1.0, float("nan")):
        with pytest.raises(ValueError, match="shrink"):
            hbc.block_soup(m, a, "cells", shrink=bad)
    with pytest.raises(ValueError, match="needs a sheet"):
        hbc.block_soup(m, a, "sheet")
    with pytest.raises(ValueError, match="non-negative"):
        hbc.block_soup(m, a, "sheet", sheet=-1)
    with pytest.raises(ValueError, match="out of range"):
        hbc.block_soup(m, a, "sheet", sheet=a.num_sheets)
    not_type3 = int(np.flatnonzero(a.sheet_type != 3)[0])
    with pytest.raises(ValueError, match="not self-intersecting"):
        hbc.block_soup(m, a, "subsheets", sheet=not_type3)
    other, _ = analyzed[TABLE1 + "test_2.HYBRID"]
    with pytest.raises(ValueError, match="another mesh"):
        hbc.block_soup(other, a, "cells")
    no_sheets = m.analyze(sheets=False, wireframe=False)
    with pytest.raises(ValueError, match="without sheets"):
        hbc.block_soup(m, no_sheets, "sheets")


def test_soup_arrays_are_owned(analyzed):
    m, a = analyzed[TABLE1 + "test_2.HYBRID"]
    d = hbc.block_soup(m, a, "cells", shrink=0.5)
    pos = d["positions"]
    assert not pos.flags.owndata and pos.base is not None  # the C++ vector, moved into a capsule
    del d, a
    assert np.isfinite(pos).all()


def test_polylines(analyzed):
    m, a = analyzed[TABLE1 + "teapot.hedra"]
    c = a.complex
    p = hbc.polylines(m, c.curve_vertices_offsets, c.curve_vertices_items)
    assert p.dtype == np.float32 and p.shape == (len(c.curve_vertices_items), 3)
    assert np.array_equal(p, m.points[c.curve_vertices_items])
    w = a.wireframe()
    assert np.array_equal(hbc.polylines(m, w.polylines_offsets, w.polylines_items), m.points[w.polylines_items])
    assert hbc.polylines(m, [0, 2, 3], [0, 1, 2]).shape == (3, 3)  # any integer sequence
    assert hbc.polylines(m, [0], []).shape == (0, 3)
    with pytest.raises(ValueError, match="offsets"):
        hbc.polylines(m, [0, 2], [0, 1, 2])
    with pytest.raises(ValueError, match="decrease"):
        hbc.polylines(m, [0, 3, 2, 3], [0, 1, 2])
    with pytest.raises(ValueError, match="out of range"):
        hbc.polylines(m, [0, 2], [0, m.num_vertices])


def test_mesh_only_soups_need_no_analysis(analyzed):
    # The boundary, the cells, the non-hex cells and the hex region are the mesh's own: with no
    # analysis they are the same soups; anything of the analysis is refused by name.
    m, a = analyzed[TABLE1 + "twistcube_s.mesh"]
    for what in ("boundary", "cells", "non_hex", "hex"):
        with_a, without = hbc.block_soup(m, a, what), hbc.block_soup(m, None, what)
        for key in with_a:
            assert np.array_equal(with_a[key], without[key]), (what, key)
    with pytest.raises(ValueError, match="'components' needs an analysis"):
        hbc.block_soup(m, None, "components")


@pytest.mark.parametrize("name", MESHES)
def test_soup_face_cell(analyzed, name):
    """face_cell is a cell the face bounds, on the owner's side: the face's owner is that cell (cell
    kinds), its component (components, one sheet's components), or a sheet holding it (sheets)."""
    m, a = analyzed[name]
    comp = a.complex.cell_component
    fc = m.face_cells
    sheet_cells = rows(a.sheet_cells_offsets, a.sheet_cells_items)
    for what, sheet, _ in kinds(a):
        d = hbc.block_soup(m, a, what, sheet=sheet)
        cell, src, owner = d["face_cell"], d["face_source"], d["face_owner"]
        assert cell.dtype == np.int32 and cell.shape == src.shape, what
        assert np.all((fc[src, 0] == cell) | (fc[src, 1] == cell)), what
        if what in ("cells", "non_hex", "sheet_non_hex"):
            assert np.array_equal(cell, owner), what
        elif what in ("components", "sheet"):
            assert np.array_equal(comp[cell], owner), what
        elif what == "boundary":
            assert np.array_equal(m.cell_types[cell], owner), what
        elif what == "sheets":
            for i in range(0, len(owner), max(1, len(owner) // 100)):
                assert cell[i] in sheet_cells[owner[i]], what


def test_cell_centroids_grid(hbc_cli, tmp_path):
    """A 2x1x1 grid of spacing 0.5 from the origin: centroids (0.25, .25, .25) and (0.75, .25, .25)."""
    out = tmp_path / "grid.ovm"
    subprocess.run([hbc_cli, "generate", "grid", "--size", "2", "1", "1", "--spacing", "0.5", "-o", str(out)],
                   check=True, capture_output=True)
    m = hbc.load(out)
    c = hbc.cell_centroids(m)
    assert c.dtype == np.float64 and c.shape == (2, 3)
    order = np.argsort(c[:, 0])
    assert np.allclose(c[order] - m.points64.min(axis=0), [[0.25, 0.25, 0.25], [0.75, 0.25, 0.25]])


@pytest.mark.parametrize("name", MESHES)
def test_cell_centroids_mean_of_distinct_vertices(analyzed, name):
    m, _ = analyzed[name]
    c = hbc.cell_centroids(m)
    assert c.shape == (m.num_cells, 3)
    pts = m.points64
    for cell in range(0, m.num_cells, max(1, m.num_cells // 50)):
        faces = m.cell_faces_items[m.cell_faces_offsets[cell]:m.cell_faces_offsets[cell + 1]]
        verts = np.unique(np.concatenate([m.face_vertices_items[m.face_vertices_offsets[f]:m.face_vertices_offsets[f + 1]] for f in faces]))
        assert np.allclose(c[cell], pts[verts].mean(axis=0))


def test_kept_surface_soup_of_a_grid(hbc_cli, tmp_path):
    """A 4x4x4 grid: all cells kept gives the 96 boundary faces; the inner 2x2x2 cells alone their 24
    outer faces; nothing kept, nothing. Faces point out of their (kept) cell."""
    out = tmp_path / "grid.ovm"
    subprocess.run([hbc_cli, "generate", "grid", "--size", "4", "4", "4", "-o", str(out)], check=True,
                   capture_output=True)
    m = hbc.load(out)
    every = hbc.kept_surface_soup(m, np.ones(64, bool))
    assert len(every["face_owner"]) == 96
    assert np.array_equal(np.sort(every["face_source"]), np.flatnonzero(m.face_boundary))
    inner = hbc.cell_depth(m) >= 1
    d = hbc.kept_surface_soup(m, inner)
    assert len(d["face_owner"]) == 24 and set(d["face_cell"]) == set(np.flatnonzero(inner))
    assert np.array_equal(d["face_owner"], d["face_cell"])
    # Outward: the loop's normal points from the cell's centroid to the face's centre.
    cen = hbc.cell_centroids(m)
    starts = d["face_vertices_offsets"]
    for i in range(len(d["face_owner"])):
        p = d["positions"][d["face_vertices_items"][starts[i]:starts[i + 1]]].astype(float)
        n = np.cross(p[1] - p[0], p[2] - p[0])
        assert np.dot(n, p.mean(axis=0) - cen[d["face_cell"][i]]) > 0
    assert len(hbc.kept_surface_soup(m, np.zeros(64, bool))["face_owner"]) == 0
    with pytest.raises(ValueError, match="entries for 64 cells"):
        hbc.kept_surface_soup(m, np.ones(3, bool))
