"""hbc.load and the Mesh arrays on every shared real mesh: shapes, dtypes, invariants, and the
same summary the `hbc info --json` command prints."""

import gc
import json
import pathlib
import subprocess

import numpy as np
import pytest

import hbc

INFO_KEYS = {"vertices", "edges", "faces", "cells", "hex_cells", "hex_ratio", "cell_types",
             "boundary_faces", "dropped_faces", "dropped_edges"}  # hbc info --json (docs/concepts.md)
CELL_TYPE_KEYS = {"hex", "tet", "prism", "pyramid", "polyhedron"}


def test_version():
    assert isinstance(hbc.__version__, str)
    assert hbc.__version__.count(".") == 2


def test_shared_data_present(shared_data_dir):
    from conftest import shared_meshes

    files = shared_meshes()
    # SOURCES.md lists 19 mesh files covering all five formats.
    assert len(files) >= 19
    assert {p.suffix.lower() for p in files} == {".ovm", ".ovmb", ".mesh", ".hybrid", ".hedra"}


def cli_info(cli, path):
    out = subprocess.run([cli, "info", str(path), "--json"], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def test_info_matches_cli(shared_mesh, hbc_cli):
    expected = cli_info(hbc_cli, shared_mesh)
    got = hbc.load(shared_mesh).info()
    assert INFO_KEYS <= got.keys()
    assert set(got["cell_types"]) == CELL_TYPE_KEYS
    # The CLI's object without "file": the same keys in the same order, every value exact.
    del expected["file"]
    assert json.dumps(got) == json.dumps(expected)


def check_csr(offsets, items, rows):
    assert offsets.shape == (rows + 1,)
    assert offsets[0] == 0 and offsets[-1] == len(items)
    assert np.all(np.diff(offsets) > 0)


def test_arrays(shared_mesh):
    m = hbc.load(shared_mesh)
    nv, ne, nf, nc = m.num_vertices, m.num_edges, m.num_faces, m.num_cells
    info = m.info()
    assert (nv, ne, nf, nc) == (info["vertices"], info["edges"], info["faces"], info["cells"])

    expected = {
        "points": (np.float32, (nv, 3)), "points64": (np.float64, (nv, 3)),
        "edges": (np.int32, (ne, 2)), "face_vertices_offsets": (np.int32, (nf + 1,)),
        "face_edges_offsets": (np.int32, (nf + 1,)),
        "face_cells": (np.int32, (nf, 2)), "cell_faces_offsets": (np.int32, (nc + 1,)),
        "cell_types": (np.uint8, (nc,)), "face_boundary": (np.bool_, (nf,)),
        "edge_boundary": (np.bool_, (ne,)), "vertex_boundary": (np.bool_, (nv,)),
        "vertex_non_manifold": (np.bool_, (nv,)), "edge_valence": (np.int32, (ne,)),
    }
    for name, (dtype, shape) in expected.items():
        a = getattr(m, name)
        assert a.dtype == dtype, name
        assert a.shape == shape, name
    for name in ("face_vertices_items", "face_edges_items", "cell_faces_items", "cell_face_flip"):
        assert getattr(m, name).ndim == 1, name

    check_csr(m.face_vertices_offsets, m.face_vertices_items, nf)
    check_csr(m.cell_faces_offsets, m.cell_faces_items, nc)
    assert np.array_equal(m.face_edges_offsets, m.face_vertices_offsets)  # aligned item for item
    assert m.face_edges_items.shape == m.face_vertices_items.shape
    assert m.cell_face_flip.shape == m.cell_faces_items.shape
    assert np.array_equal(m.points, m.points64.astype(np.float32))
    assert np.all(m.edges[:, 0] < m.edges[:, 1])
    assert m.face_vertices_items.max() < nv and m.cell_faces_items.max() < nf and m.face_edges_items.max() < ne
    assert np.all(m.cell_types <= 4)
    assert np.count_nonzero(m.cell_types == 0) == info["hex_cells"]

    # Face sides: the first cell always exists; the boundary is where the second is missing.
    fc = m.face_cells
    assert np.all(fc[:, 0] >= 0) and fc.max() < nc
    assert np.array_equal(m.face_boundary, fc[:, 1] == -1)
    assert np.count_nonzero(m.face_boundary) == info["boundary_faces"]
    # Each face appears in the cell lists exactly as often as it has cells.
    assert np.array_equal(np.bincount(m.cell_faces_items, minlength=nf), (fc >= 0).sum(axis=1))

    # Boundary vertices/edges are exactly those of boundary faces.
    corner_face = np.repeat(np.arange(nf), np.diff(m.face_vertices_offsets))
    on_boundary = m.face_boundary[corner_face]
    vb = np.zeros(nv, bool)
    vb[m.face_vertices_items[on_boundary]] = True
    eb = np.zeros(ne, bool)
    eb[m.face_edges_items[on_boundary]] = True
    assert np.array_equal(m.vertex_boundary, vb)
    assert np.array_equal(m.edge_boundary, eb)

    # Face edge i joins loop vertices i and i+1.
    nxt = np.arange(len(m.face_vertices_items)) + 1
    ends = m.face_vertices_offsets[1:][corner_face]
    nxt[nxt == ends] = m.face_vertices_offsets[:-1][corner_face][nxt == ends]
    pairs = np.sort(np.stack([m.face_vertices_items, m.face_vertices_items[nxt]], axis=1), axis=1)
    assert np.array_equal(m.edges[m.face_edges_items], pairs)

    # Closed cells: at an edge every cell has two faces, every face two cell sides of which the
    # boundary ones lack a cell, so valence = faces at the edge - boundary faces at it / 2.
    faces_at = np.bincount(m.face_edges_items, minlength=ne)
    boundary_at = np.bincount(m.face_edges_items[on_boundary], minlength=ne)
    assert np.array_equal(2 * m.edge_valence, 2 * faces_at - boundary_at)


def test_arrays_are_readonly_views_that_keep_the_mesh_alive(shared_data_dir):
    m = hbc.load(shared_data_dir / "hybrid-base-complex" / "test_2.HYBRID")
    views = {name: getattr(m, name) for name in (
        "points", "points64", "edges", "face_vertices_offsets", "face_vertices_items", "face_edges_offsets",
        "face_edges_items", "face_cells", "cell_faces_offsets", "cell_faces_items", "cell_face_flip", "cell_types",
        "face_boundary",
        "edge_boundary", "vertex_boundary", "vertex_non_manifold")}
    for name, a in views.items():
        assert a.base is m, name
        assert not a.flags.writeable, name
        with pytest.raises(ValueError):
            a[0] = a[0]
    # No copy: two reads share memory (points: the cached float32 copy is made once).
    for name in views:
        assert np.shares_memory(getattr(m, name), getattr(m, name)), name
    snapshot = {name: a.copy() for name, a in views.items()}
    del m
    gc.collect()
    for name, a in views.items():
        assert np.array_equal(a, snapshot[name]), name


def test_repr_source_warnings(shared_data_dir):
    path = shared_data_dir / "hybrid-base-complex" / "test_2.HYBRID"
    m = hbc.load(path)
    assert m.source == str(path)
    assert m.warnings == []
    assert repr(m) == f"<hbc.Mesh '{path}': 64 vertices, 24 cells (21 hex)>"


def test_dropped_elements_are_reported(shared_data_dir):
    # NonManifold.ovm(b) carry a face in no cell and edges in no face (SOURCES.md).
    for name in ("NonManifold.ovm", "NonManifold.ovmb"):
        m = hbc.load(shared_data_dir / "openvolumemesh" / name)
        assert m.info()["dropped_faces"] == 1 and m.info()["dropped_edges"] == 4
        assert m.warnings == ["1 face(s) used by no cell dropped", "4 edge(s) used by no face dropped"]


def test_load_accepts_path_and_format(shared_data_dir):
    path = shared_data_dir / "hybrid-base-complex" / "twistcube_s.mesh"
    a = hbc.load(path)
    b = hbc.load(str(path), format="mesh")
    c = hbc.load(pathlib.PurePath(path), "MESH")
    assert a.info() == b.info() == c.info()
    assert np.array_equal(a.cell_faces_items, b.cell_faces_items)


def test_load_rejects_unknown_format_and_non_paths(shared_data_dir):
    path = shared_data_dir / "hybrid-base-complex" / "twistcube_s.mesh"
    with pytest.raises(ValueError, match="unknown format 'stl'"):
        hbc.load(path, format="stl")
    with pytest.raises(TypeError):
        hbc.load(42)


def test_threads_keyword_changes_nothing(shared_data_dir):
    # The load splits its work over threads; every array must come out the same.
    path = shared_data_dir / "hexalab-edge-cone-rectification" / "armadillo_out.mesh"
    one, two = hbc.load(path, threads=1), hbc.load(path, threads=2)
    names = [n for n in dir(one) if not n.startswith("_") and isinstance(getattr(one, n), np.ndarray)]
    assert len(names) >= 5, names
    for n in names:
        np.testing.assert_array_equal(getattr(one, n), getattr(two, n), err_msg=n)
    with pytest.raises(ValueError):
        hbc.load(path, threads=0)
