"""The wireframe coloured by non-hex kind, without Blender: the per-chain colours and the legend's
entries (planning.chain_kind_colors, planning.legend with wire_by_kind), on a generated grid whose
non-hex cells are placed by hand and on hand-made kind rows."""

import numpy as np

from hybrid_base_complex.plan import planning as P
from hybrid_base_complex.plan.structure import Structure


def code(t, faces):
    return (t << 16) | faces


def test_one_type_takes_its_colour_several_black_none_grey():
    # Rows: none; a prism; two polyhedra (7 and 8 faces, one type); a tet and a polyhedron.
    offsets = [0, 0, 1, 3, 5]
    items = [code(2, 5), code(4, 7), code(4, 8), code(1, 4), code(4, 7)]
    assert P.chain_kind_types(offsets, items).tolist() == [0, 2, 4, -1]
    c = P.chain_kind_colors(offsets, items)
    assert c.shape == (4, 4)
    np.testing.assert_allclose(c[0], P.WIRE_HEX_COLOR)
    np.testing.assert_allclose(c[1], P.CELL_TYPE_COLORS[2])
    np.testing.assert_allclose(c[2], P.CELL_TYPE_COLORS[4])
    np.testing.assert_allclose(c[3], P.WIRE_SEVERAL_COLOR)
    assert P.kind_faces(items).tolist() == [5, 7, 8, 4, 7]
    assert P.chain_kind_types([0], []).shape == (0,)


def test_legend_names_the_kinds_only_when_coloured_by_them():
    entries = P.legend(["wireframe"], non_hex_types=[1, 2, 3, 4], wire_by_kind=True)
    assert [k for k, _ in entries] == ["tet", "prism", "pyramid", "polyhedron", "wire_several", "wire_hex"]
    assert all(k in P.LEGEND_COLORS and len(w) <= P.LEGEND_MAX for k, w in entries)
    assert P.legend(["wireframe"], non_hex_types=[1, 2], wire_by_kind=False) == []
    # The subsheets' wireframes are coloured the same way.
    assert ("wire_hex", "Wire at hexes only") in P.legend(["subsheets"], wire_by_kind=True)


def test_pyramid_grid_colours_the_chains_through_the_split_cell(generate):
    # 3×3×3 grid, the centre hex split into 6 pyramids: the chains through the split cell's 9
    # vertices carry {pyramid, 5 faces} and nothing else (tests/cpp/test_wireframe_kinds.cpp
    # derives it); every other chain has hex cells only around it.
    mesh, a = generate("split", "--size", "3", "3", "3", "--split", "pyramids", "--cells", "1,1,1")
    w = a.wireframe()
    types = P.chain_kind_types(w.non_hex_offsets, w.non_hex_items)
    assert set(types.tolist()) == {0, 3}
    assert set(P.kind_faces(w.non_hex_items).tolist()) == {5}
    lines = Structure(mesh, a).wireframe(simplified=False, by_kind=True)
    sizes = np.diff(np.asarray(w.polylines_offsets))
    expected = np.repeat(P.chain_kind_colors(w.non_hex_offsets, w.non_hex_items), sizes, axis=0)
    np.testing.assert_allclose(lines.colors[:, :3], expected[:, :3])
