"""hbc.polygon_edges, which the add-on hands Blender instead of letting it search the edges of a
layer's mesh (blender/scene.fill_soup): distinct undirected edges, lower point first, grouped by
lower point in order of first use, and each corner's edge to the next corner of its polygon."""

import numpy as np
import pytest

hbc = pytest.importorskip("hbc")


def test_quad_and_triangle_sharing_an_edge():
    """Quad 0 1 2 3 and triangle 1 4 2 share edge 1-2. By lower point: 0: (0,1) then (0,3) [from
    corner 3 -> 0]; 1: (1,2), (1,4); 2: (2,3), (2,4) -> edges 0..5 in that order. Quad corners:
    0-1 e0, 1-2 e2, 2-3 e4, 3-0 e1; triangle corners: 1-4 e3, 4-2 e5, 2-1 e2."""
    d = hbc.polygon_edges(np.array([0, 4, 7], np.int32), np.array([0, 1, 2, 3, 1, 4, 2], np.int32), 5)
    assert d["edges"].tolist() == [[0, 1], [0, 3], [1, 2], [1, 4], [2, 3], [2, 4]]
    assert d["corner_edge"].tolist() == [0, 2, 4, 1, 3, 5, 2]


def test_closed_cube_surface_has_twelve_edges():
    """The 6 quads of a cube (points 0..7): 12 edges, each used by exactly two corners."""
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    d = hbc.polygon_edges(np.arange(0, 25, 4, dtype=np.int32), np.array(faces, np.int32).ravel(), 8)
    assert d["edges"].shape == (12, 2)
    assert np.all(d["edges"][:, 0] < d["edges"][:, 1])
    assert np.bincount(d["corner_edge"], minlength=12).tolist() == [2] * 12


def test_empty_and_bad_input():
    d = hbc.polygon_edges(np.array([0], np.int32), np.zeros(0, np.int32), 0)
    assert d["edges"].shape == (0, 2) and d["corner_edge"].shape == (0,)
    with pytest.raises(ValueError):
        hbc.polygon_edges(np.array([0, 3], np.int32), np.array([0, 1, 5], np.int32), 3)  # point 5 of 3
    with pytest.raises(ValueError):
        hbc.polygon_edges(np.array([0, 4], np.int32), np.array([0, 1, 2], np.int32), 3)  # ends past items
