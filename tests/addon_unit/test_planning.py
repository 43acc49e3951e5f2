"""Plain-pytest tests of the add-on's bpy-free planning (palette, opacity, block soups, lines)."""

import numpy as np
import pytest

from fakes import FakeMesh
from hybrid_base_complex import planning as P
from hybrid_base_complex.structure import Structure, concat_soups


def test_package_imports_without_bpy():
    import hybrid_base_complex as addon

    assert addon.bl_info["blender"] == (3, 4, 0)
    assert addon.bpy is None


def test_palette_is_distinct_and_deterministic():
    assert len({tuple(np.round(c, 3)) for c in P.PALETTE}) == P.PALETTE_SIZE
    np.testing.assert_array_equal(P.palette_color([0, 1, P.PALETTE_SIZE]), P.PALETTE[[0, 1, 0]])
    assert tuple(P.palette_color([-1])[0]) == pytest.approx(P.NON_HEX_COLOR)


def test_component_colors_neighbours_differ_rings_darker_non_hex_grey():
    kinds = np.array([0, 0, 1, 3, 0], np.uint8)
    c = P.component_colors(kinds)
    assert c.shape == (5, 4)
    assert not np.allclose(c[0], c[1])
    assert tuple(c[3]) == pytest.approx(P.NON_HEX_COLOR)
    base = P.PALETTE[P.spread_ids([2])[0]]
    np.testing.assert_allclose(c[2, :3], base[:3] * P.RING_DARKEN)


def test_opacity_mapping():
    o = np.array([0.15, 0.5, 1.0], np.float32)
    a = P.opacity_alpha(o, 0.3)
    assert a[0] == pytest.approx(0.3) and a[-1] == pytest.approx(1.0)
    assert np.all(np.diff(a) > 0)
    np.testing.assert_array_equal(P.opacity_alpha(np.ones(3), 0.2), np.ones(3))
    assert P.opacity_alpha(np.zeros(0), 0.2).size == 0


def test_csr_helpers():
    off = np.array([0, 2, 2, 5])
    items = np.array([7, 8, 1, 2, 3])
    np.testing.assert_array_equal(P.csr_rows(off, items, [2, 0]), [1, 2, 3, 7, 8])
    np.testing.assert_array_equal(P.csr_rows(off, items, []), [])
    inv_off, rows = P.csr_invert(np.array([0, 2, 3]), np.array([0, 1, 1]), 3)
    np.testing.assert_array_equal(inv_off, [0, 1, 3, 3])
    np.testing.assert_array_equal(rows, [0, 0, 1])
    cells_off, cells = np.array([0, 2, 3, 5]), np.array([0, 1, 5, 2, 3])
    assert P.label_cells(6, cells_off, cells).tolist() == [0, 0, 2, 2, -1, 1]
    assert P.label_cells(6, cells_off, cells, rows=[2, 1]).tolist() == [-1, -1, 0, 0, -1, 1]


def _soup(mesh, label, shrink=0.0):
    return P.block_soup(mesh.points, mesh.face_offsets, mesh.face_vertices, mesh.face_cells, mesh.cell_offsets,
                        mesh.cell_faces, mesh.cell_face_flip, label, shrink)


def test_block_soup_one_block_is_its_outer_surface():
    m = FakeMesh(3, 2, 2)
    soup = _soup(m, np.zeros(m.num_cells, np.int32))
    # Outer surface of a 3x2x2 box: 2*(3*2 + 3*2 + 2*2) quads, vertices on the box surface only.
    assert soup.num_faces == 2 * (6 + 6 + 4)
    assert len(soup.positions) == 4 * 3 * 3 - 2 * 1  # (4*3*3 grid points) minus the 2 interior ones
    assert set(soup.face_owner) == {0}


def test_block_soup_faces_point_outward():
    m = FakeMesh(2, 2, 1)
    soup = _soup(m, np.arange(m.num_cells, dtype=np.int32), shrink=0.0)
    starts = soup.loop_starts()
    centre_of_block = {o: m.points[m.face_vertices[m.face_offsets[m.cell_faces[m.cell_offsets[o]:m.cell_offsets[o + 1]]]]].mean(0)
                       for o in range(m.num_cells)}
    for f in range(soup.num_faces):
        loop = soup.positions[soup.face_vertices[starts[f]:starts[f] + soup.face_sizes[f]]]
        normal = np.cross(loop[1] - loop[0], loop[2] - loop[0])
        outward = loop.mean(0) - centre_of_block[soup.face_owner[f]]
        assert np.dot(normal, outward) > 0


def test_block_soup_partition_and_shrink():
    m = FakeMesh(4, 1, 1)
    label = np.array([0, 0, 1, -1], np.int32)
    soup = _soup(m, label, shrink=0.5)
    # Block 0: 2x1x1 box (10 quads), block 1: a cube (6 quads); cell 3 hidden.
    assert np.bincount(soup.face_owner).tolist() == [10, 6]
    # Shrunk block 1 (the unit cube at x in [2,3]) lies within [2.25, 2.75].
    pos1 = soup.positions[np.unique(soup.face_vertices[np.repeat(soup.face_owner == 1, soup.face_sizes)])]
    assert pos1[:, 0].min() == pytest.approx(2.25) and pos1[:, 0].max() == pytest.approx(2.75)
    # Vertex copies per block are contiguous (split_soup_objects relies on it).
    first = np.repeat(soup.face_owner, soup.face_sizes)
    verts_by_owner = [soup.face_vertices[first == o] for o in (0, 1)]
    assert verts_by_owner[0].max() < verts_by_owner[1].min()


def test_soup_select_and_concat():
    m = FakeMesh(2, 1, 1)
    soup = _soup(m, np.array([0, 1], np.int32))
    part = soup.select(soup.face_owner == 1)
    assert part.num_faces == 6 and len(part.positions) == 8
    both = concat_soups([part, part], owners=[5, 6])
    assert both.num_faces == 12 and set(both.face_owner) == {5, 6}
    assert both.face_vertices.max() == 15
    assert P.Soup.empty().num_faces == 0


def test_polylines_colors_alpha_keep():
    pts = np.arange(30, dtype=np.float32).reshape(10, 3)
    off = np.array([0, 3, 5, 8])
    verts = np.array([0, 1, 2, 3, 4, 5, 6, 7])
    cols = P.palette_color([0, 1, 2])
    lines = P.polylines(pts, off, verts, cols, alpha=np.linspace(0, 1, 8), keep=[True, False, True])
    assert len(lines.positions) == 6
    assert lines.edges.tolist() == [[0, 1], [1, 2], [3, 4], [4, 5]]
    assert lines.polyline.tolist() == [0, 0, 0, 1, 1, 1]
    np.testing.assert_allclose(lines.colors[3, :3], cols[2, :3])
    assert lines.colors[-1, 3] == pytest.approx(1.0)
    ring = P.polylines(pts, off, verts, closed=[True, False, False])
    assert ring.edges.tolist() == [[0, 1], [1, 2], [3, 4], [5, 6], [6, 7], [2, 0]]
    both = P.Lines.concat([lines, P.edge_lines(pts, [[0, 9]], (1, 0, 0, 1))])
    assert both.num_polylines == 3 and both.edges[-1].tolist() == [6, 7]


def test_dots():
    d = P.dots(np.zeros((3, 3)), 0.5, owner=[4, 5, 6])
    assert d.num_faces == 24 and len(d.positions) == 18
    assert set(d.face_owner) == {4, 5, 6}
    assert np.abs(d.positions).max() == pytest.approx(0.5)


def test_names_and_table_row():
    assert P.mesh_name_from_path("/x/cube_twist-comp.obj.HYBRID") == "cube_twist-comp.obj"
    assert P.mesh_name_from_path("teapot.hedra") == "teapot"
    assert P.layer_collection_name("teapot", "blocks") == "teapot / Blocks"
    row = dict(P.table1_row({"cells": 10, "hex_ratio": 0.5, "components": 4, "hex_components": 3,
                             "sheets": -1, "timings": {"base_complex": 0.0123}}))
    assert row["|C|"] == "10" and row["|H|/|C|"] == "50.0%" and row["|H_B|/|C_B|"] == "75.0%"
    assert row["#Sheets"] == "-" and row["T_GB"] == "12 ms" and row["T_GS"] == "-"


def test_progress_reports_fractions():
    seen = []
    p = P.Progress(2, lambda f, m: seen.append((f, m)))
    p.step("a")
    p.step("b")
    p.step("c")
    assert seen == [(0.5, "a"), (1.0, "b"), (1.0, "c")]


def test_structure_layers_on_fake_analysis():
    m = FakeMesh(4, 2, 1, non_hex_last=True)
    s = Structure(m, m.analyze(), scale=2.0)
    assert s.points.max() == pytest.approx(8.0)
    assert s.num_components == 4 + 1 - 0  # 8 cells in pairs, the last (non-hex) cell on its own
    blocks = s.blocks(0.1)
    assert set(blocks.face_owner) == set(range(s.num_components))
    assert s.num_sheets == 3
    cells, comps = s.sheet_sizes()
    assert comps.tolist() == [2, s.num_components, 1]
    np.testing.assert_array_equal(s.component_sheets(0), [0, 1])
    sheets = s.all_sheets(0.0)
    assert set(sheets.face_owner) == {0, 1, 2}
    unmatched, shared, edges, si_cells = s.sheet_highlights(1, 0.1)
    assert unmatched.num_faces == 16 and shared.num_faces == 0 and si_cells.num_faces > 0
    _, shared2, edges2, _ = s.sheet_highlights(2, 0.1)
    assert shared2.num_faces == 8 and edges2.num_polylines == 2
    groups = s.singularity_lines()
    assert [g[0] for g in groups] == ["Valence 3", "Valence 5", "Pseudo-singular", "Non-manifold"]
    assert groups[0][2].num_polylines == 2
    w = s.wireframe(floor=0.3)
    assert w.num_polylines == 3  # the 4th is not shown in the simplified wireframe
    assert w.colors[:, 3].min() == pytest.approx(0.3)
    assert s.wireframe(simplified=False).num_polylines == 4
    sub = s.subsheets(1)
    assert sub.count == 2
    subs = s.subsheet_soup(1, sub, 0.0)
    assert set(subs.face_owner) == {0, 1}
    assert s.subsheet_unmatched(sub, 0).size == 0
    direct = s.direct_boundary()
    assert direct.num_faces == int(m.face_boundary.sum())
    assert s.non_hex_cells().num_faces == 6
    assert s.direct_cells(hex_cells=True).num_faces > 0
