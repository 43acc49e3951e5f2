"""Mesh.from_arrays on a hand-built mesh of two hexahedra sharing a face, compared with the same
mesh read from a MEDIT file, and its validation errors."""

import numpy as np
import pytest

import hbc


def two_hexes():
    """Two unit cubes side by side along x; vertex (x, y, z) has id x + 3*y + 6*z."""
    points = np.array([(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1, 2)], np.float64)

    def hex_faces(x0):
        return [[x0, x0 + 3, x0 + 4, x0 + 1], [x0 + 6, x0 + 7, x0 + 10, x0 + 9],
                [x0, x0 + 1, x0 + 7, x0 + 6], [x0 + 3, x0 + 9, x0 + 10, x0 + 4],
                [x0, x0 + 6, x0 + 9, x0 + 3], [x0 + 1, x0 + 4, x0 + 10, x0 + 7]]

    a, b = hex_faces(0), hex_faces(1)
    faces = a + b[:4] + b[5:]  # b[4] (x = 1) is a[5] reversed: listed once
    cells = [[0, 1, 2, 3, 4, 5], [6, 7, 8, 9, 5, 10]]
    return dict(points=points,
                face_vertices_offsets=np.arange(0, 4 * len(faces) + 1, 4),
                face_vertices_items=np.array(faces).ravel(),
                cell_faces_offsets=np.array([0, 6, 12]),
                cell_faces_items=np.array(cells).ravel())


SHARED_FACE = 5


def test_two_hexes():
    m = hbc.Mesh.from_arrays(**two_hexes())
    info = m.info()
    assert info == {"vertices": 12, "edges": 20, "faces": 11, "cells": 2, "hex_cells": 2,
                    "hex_ratio": 1.0,
                    "cell_types": {"hex": 2, "tet": 0, "prism": 0, "pyramid": 0, "polyhedron": 0},
                    "boundary_faces": 10, "non_manifold_vertices": 0, "dropped_faces": 0,
                    "dropped_edges": 0}
    assert m.source == "<arrays>"
    assert np.array_equal(m.points64, two_hexes()["points"])
    assert np.array_equal(m.cell_types, [0, 0])
    assert np.array_equal(m.face_cells[SHARED_FACE], [0, 1])
    assert np.array_equal(np.flatnonzero(~m.face_boundary), [SHARED_FACE])
    assert m.vertex_boundary.all() and m.edge_boundary.all()
    assert not m.vertex_non_manifold.any()
    # The four edges of the shared face are in both cells, every other edge in one.
    shared = m.face_edges_items[m.face_vertices_offsets[SHARED_FACE]:m.face_vertices_offsets[SHARED_FACE + 1]]
    expected = np.ones(20, np.int32)
    expected[shared] = 2
    assert np.array_equal(m.edge_valence, expected)
    assert sorted(map(tuple, m.edges[shared])) == [(1, 4), (1, 7), (4, 10), (7, 10)]


def test_same_as_medit_file(tmp_path):
    # MEDIT hexahedra list the bottom quad then the top quad (1-based ids).
    text = ["MeshVersionFormatted 1", "Dimension 3", "Vertices", "12"]
    text += [f"{x:g} {y:g} {z:g} 0" for x, y, z in two_hexes()["points"]]
    text += ["Hexahedra", "2"]
    for x0 in (0, 1):
        ids = [x0, x0 + 1, x0 + 4, x0 + 3, x0 + 6, x0 + 7, x0 + 10, x0 + 9]
        text.append(" ".join(str(i + 1) for i in ids) + " 0")
    path = tmp_path / "two_hexes.mesh"
    path.write_text("\n".join(text + ["End"]) + "\n")
    a = hbc.load(path)
    b = hbc.Mesh.from_arrays(**two_hexes())
    assert a.info() == b.info()
    assert np.array_equal(a.points64, b.points64)

    def face_sets(m):
        loops = np.split(m.face_vertices_items, m.face_vertices_offsets[1:-1])
        return sorted(tuple(sorted(loop)) for loop in loops)

    assert face_sets(a) == face_sets(b)
    assert sorted(map(tuple, a.edges)) == sorted(map(tuple, b.edges))


def test_lists_flips_and_source():
    arrays = {k: v.tolist() for k, v in two_hexes().items()}
    flip = [0] * 12
    flip[10] = 1  # the second cell sees the shared face reversed
    m = hbc.Mesh.from_arrays(**arrays, cell_face_flip=flip, source="two hexes")
    assert m.source == "two hexes"
    assert np.array_equal(m.cell_face_flip, flip)
    # Without flips both cells would see the shared face (index 5 of each cell's list) the same
    # way; the builder turns one so that neighbours agree, and each cell stays outward.
    unflipped = hbc.Mesh.from_arrays(**two_hexes()).cell_face_flip
    assert unflipped[5] != unflipped[10]
    assert np.array_equal(unflipped, flip)
    bool_flip = np.array(flip, bool)
    assert np.array_equal(hbc.Mesh.from_arrays(**two_hexes(), cell_face_flip=bool_flip).cell_face_flip, flip)


def with_change(**changes):
    arrays = two_hexes()
    arrays.update(changes)
    return arrays


def test_content_errors_are_mesh_format_errors():
    base = two_hexes()
    bad_vertex = base["face_vertices_items"].copy()
    bad_vertex[7] = 99
    with pytest.raises(hbc.MeshFormatError, match=r"^<arrays>: .*found 99"):
        hbc.Mesh.from_arrays(**with_change(face_vertices_items=bad_vertex))

    open_cell = dict(cell_faces_offsets=np.array([0, 6, 11]), cell_faces_items=base["cell_faces_items"][:11])
    with pytest.raises(hbc.MeshFormatError, match="closed cell"):
        hbc.Mesh.from_arrays(**with_change(**open_cell))

    bad_face = base["cell_faces_items"].copy()
    bad_face[3] = 11
    with pytest.raises(hbc.MeshFormatError, match=r"cell_faces_items values in \[0, 11\), found 11 at index 3"):
        hbc.Mesh.from_arrays(**with_change(cell_faces_items=bad_face))

    with pytest.raises(hbc.MeshFormatError, match="face_vertices_offsets starting with 0"):
        hbc.Mesh.from_arrays(**with_change(face_vertices_offsets=base["face_vertices_offsets"] + 1))
    with pytest.raises(hbc.MeshFormatError, match=r"face_vertices_offsets\[-1\] == len\(face_vertices_items\)"):
        hbc.Mesh.from_arrays(**with_change(face_vertices_offsets=base["face_vertices_offsets"][:-1]))
    with pytest.raises(hbc.MeshFormatError, match="non-decreasing"):
        hbc.Mesh.from_arrays(**with_change(cell_faces_offsets=np.array([0, 13, 12])))

    nan_points = base["points"].copy()
    nan_points[4, 1] = np.nan
    with pytest.raises(hbc.MeshFormatError, match="finite coordinate for vertex 4"):
        hbc.Mesh.from_arrays(**with_change(points=nan_points))


def test_shape_and_dtype_errors():
    base = two_hexes()
    with pytest.raises(TypeError, match="integer array"):
        hbc.Mesh.from_arrays(**with_change(face_vertices_items=base["face_vertices_items"].astype(float)))
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        hbc.Mesh.from_arrays(**with_change(points=base["points"][:, :2]))
    with pytest.raises(ValueError, match="1-D"):
        hbc.Mesh.from_arrays(**with_change(cell_faces_items=base["cell_faces_items"].reshape(2, 6)))
    with pytest.raises(ValueError, match="len\\(cell_faces_items\\) = 12"):
        hbc.Mesh.from_arrays(**base, cell_face_flip=np.zeros(11, np.uint8))
    with pytest.raises(ValueError, match="0 or 1, found 2"):
        hbc.Mesh.from_arrays(**base, cell_face_flip=np.full(12, 2))


def test_round_trip_of_every_shared_mesh(shared_mesh):
    # A loaded mesh fed back through from_arrays (with a foreign memory layout) is the same mesh:
    # the builder numbers faces by first use and edges by first appearance, which the arrays keep.
    m = hbc.load(shared_mesh)
    points = np.asfortranarray(m.points64).astype(">f8")  # non-native byte order, column-major
    again = hbc.Mesh.from_arrays(points, m.face_vertices_offsets.astype(np.int64), m.face_vertices_items,
                                 m.cell_faces_offsets, m.cell_faces_items, m.cell_face_flip)
    for name in ("points64", "edges", "face_vertices_offsets", "face_vertices_items", "face_edges_offsets",
                 "face_edges_items", "face_cells", "cell_faces_offsets", "cell_faces_items", "cell_face_flip",
                 "cell_types", "face_boundary",
                 "edge_boundary", "vertex_boundary", "vertex_non_manifold", "edge_valence"):
        assert np.array_equal(getattr(again, name), getattr(m, name)), name
    assert again.warnings == []
