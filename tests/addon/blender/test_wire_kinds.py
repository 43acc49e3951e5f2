"""The wireframe coloured by non-hex kind inside Blender: the Colour setting switches the wireframe
layer (and the subsheets' wireframes) from colour classes to the colours of planning.chain_kind_colors,
and the Legend panel then names each colour (docs/concepts.md, "Non-hex kinds")."""

import numpy as np
import pytest

bpy = pytest.importorskip("bpy")

TWISTCUBE = ("hybrid-base-complex", "twistcube_s.mesh")  # prisms, tets, a pyramid, polyhedra


def wire_colors(root):
    from hybrid_base_complex.blender import scene as S

    coll = S.find_layer(root, "wireframe")
    (ob,) = [o for o in S.objects_in(coll)]
    col = np.zeros(4 * len(ob.data.vertices), np.float32)
    ob.data.color_attributes["hbc_color"].data.foreach_get("color", col)
    return col.reshape(-1, 4)[:, :3]


def test_wireframe_coloured_by_non_hex_kind_with_its_legend(clean_scene, data_dir):
    from hybrid_base_complex.plan import planning as P
    from hybrid_base_complex.plan import session
    from hybrid_base_complex.ui import panels

    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*TWISTCUBE))) == {"FINISHED"}
    root = next(c for c in bpy.data.collections if c.name == bpy.context.scene.hbc.active_mesh)
    s = session.get(root.name)
    st = bpy.context.scene.hbc
    assert st.wireframe_colors == "CLASS"  # today's colouring stays the default
    assert bpy.ops.hbc.build_layer(layer="wireframe") == {"FINISHED"}
    by_class = wire_colors(root)
    st.wireframe_colors = "KIND"
    assert bpy.ops.hbc.build_layer(layer="wireframe") == {"FINISHED"}
    by_kind = wire_colors(root)
    # The points of the kept chains, in the colours the plan gives each chain.
    w = s.analysis.wireframe()
    colors = P.chain_kind_colors(w.non_hex_offsets, w.non_hex_items)
    shown = np.asarray(w.shown, bool)
    sizes = np.diff(np.asarray(w.polylines_offsets))
    expected = np.repeat(colors[shown], sizes[shown], axis=0)[:, :3]
    assert by_kind.shape == by_class.shape == expected.shape
    np.testing.assert_allclose(by_kind, expected, atol=1e-6)
    assert not np.allclose(by_kind, by_class)
    # twistcube_s's simplified wireframe has chains at one type and at several types.
    types = P.chain_kind_types(w.non_hex_offsets, w.non_hex_items)[shown]
    assert np.any(types > 0) and np.any(types < 0)
    # The legend names every colour the layer uses (it lists the visible layers).
    from hybrid_base_complex.blender import scene as S

    S.find_layer(root, "wireframe").hide_viewport = False
    entries = panels.legend_entries(bpy.context)
    keys = {k for k, _ in entries}
    assert {"wire_several", "wire_hex"} <= keys
    for t in set(types[types > 0].tolist()):
        assert P.CELL_TYPE_NAMES[t] in keys
    legend_colors = {tuple(np.round(np.asarray(P.LEGEND_COLORS[k][:3], np.float32), 5)) for k in keys}
    for c in np.unique(np.round(colors[shown][:, :3], 5), axis=0):
        assert tuple(c) in legend_colors
    for _, words in entries:
        assert len(words) <= P.LEGEND_MAX
    # Back to the colour classes: the legend no longer names the kinds.
    st.wireframe_colors = "CLASS"
    assert "wire_several" not in {k for k, _ in panels.legend_entries(bpy.context)}
