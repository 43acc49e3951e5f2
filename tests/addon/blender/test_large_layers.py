"""What makes the layers of a 10^6-cell mesh cheaper keeps what they show (docs/performance.md,
"Blender add-on"): the mesh writers of compat.py (unsigned or signed index arrays by version)
write exactly the given indices, and the edges made in C++ (hbc.polygon_edges) give a mesh
Blender's validation finds nothing to repair in; the colours one per owner live on the POINT domain and give every
face its owner's colour; the filter modifier is switched off while no filter can hide a face and
on as soon as one can."""

import bpy
import numpy as np
import pytest


def test_mesh_writers_write_the_given_indices(clean_scene):
    """A quad (0 1 2 3) and a triangle (1 4 2) on five points: corners, polygon starts and sizes
    and edges read back as written; the mesh needs no repair (validate returns False)."""
    from hybrid_base_complex.blender import compat

    me = bpy.data.meshes.new("writers")
    me.vertices.add(5)
    me.vertices.foreach_set("co", np.array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0.5, 0], np.float32))
    corners = np.array([0, 1, 2, 3, 1, 4, 2], np.int32)
    me.loops.add(len(corners))
    compat.set_corner_verts(me, corners)
    me.polygons.add(2)
    compat.set_polygons(me, np.array([0, 4], np.int32), np.array([4, 3], np.int32))
    me.update(calc_edges=True)
    got = np.zeros(len(corners), np.int32)
    me.loops.foreach_get("vertex_index", got)
    assert got.tolist() == corners.tolist()
    starts, sizes = np.zeros(2, np.int32), np.zeros(2, np.int32)
    me.polygons.foreach_get("loop_start", starts)
    me.polygons.foreach_get("loop_total", sizes)
    assert starts.tolist() == [0, 4] and sizes.tolist() == [4, 3]
    assert len(me.edges) == 6  # 4 of the quad + 2 of the triangle (1-2 is shared)
    assert not me.validate()

    # The same polygons with the edges given (hbc.polygon_edges' answer for them, derived in
    # tests/addon/unit/test_polygon_edges.py) instead of searched by Blender.
    given = bpy.data.meshes.new("given edges")
    given.vertices.add(5)
    given.vertices.foreach_set("co", np.array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0.5, 0], np.float32))
    given.loops.add(len(corners))
    compat.set_corner_verts(given, corners)
    given.polygons.add(2)
    compat.set_polygons(given, np.array([0, 4], np.int32), np.array([4, 3], np.int32))
    given.edges.add(6)
    compat.set_edge_verts(given, np.array([[0, 1], [0, 3], [1, 2], [1, 4], [2, 3], [2, 4]], np.int32))
    compat.set_corner_edges(given, np.array([0, 2, 4, 1, 3, 5, 2], np.int32))
    given.update(calc_edges=False)
    got = np.zeros(len(corners), np.int32)
    given.loops.foreach_get("edge_index", got)
    assert got.tolist() == [0, 2, 4, 1, 3, 5, 2]
    assert not given.validate()

    lines = bpy.data.meshes.new("lines")
    lines.vertices.add(4)
    lines.edges.add(3)
    edges = np.array([[0, 1], [1, 2], [3, 0]], np.int32)
    compat.set_edge_verts(lines, edges)
    got = np.zeros(6, np.int32)
    lines.edges.foreach_get("vertices", got)
    assert got.tolist() == edges.ravel().tolist()


def _point_colors(ob):
    me = ob.data
    attr = me.color_attributes["hbc_color"]
    assert attr.domain == "POINT", ob.name
    col = np.zeros(4 * len(me.vertices), np.float32)
    attr.data.foreach_get("color", col)
    return col.reshape(-1, 4)


def _face_point_colors(ob):
    """(owner of each corner's face, colour of each corner's point)."""
    me = ob.data
    nf, nl = len(me.polygons), len(me.loops)
    owner, sizes, corners = np.zeros(nf, np.int32), np.zeros(nf, np.int32), np.zeros(nl, np.int32)
    me.attributes["owner"].data.foreach_get("value", owner)
    me.polygons.foreach_get("loop_total", sizes)
    me.loops.foreach_get("vertex_index", corners)
    return np.repeat(owner, sizes), _point_colors(ob)[corners]


@pytest.mark.parametrize("split_max", [0, 100000])
def test_layer_colours_are_one_per_owner_on_points(clean_scene, data_dir, split_max):
    """twistcube_s, merged (split_max 0) and one object per owner: every corner of a Blocks face has
    its component's colour, of a Sheets face its sheet's colour, of the picked sheet its block's
    shade of the sheet's colour (0.8, 0.9 or 1.0 by component id mod 3 after x7)."""
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.blender.context import find_root
    from hybrid_base_complex.plan import planning as P
    from hybrid_base_complex.plan import session

    st = bpy.context.scene.hbc
    st.split_max = split_max
    path = data_dir / "hybrid-base-complex" / "twistcube_s.mesh"
    assert bpy.ops.import_mesh.hbc(filepath=str(path), analyze=True) == {"FINISHED"}
    root = find_root(st.active_mesh)
    s = session.get(root.name)
    for layer in ("components", "sheets", "sheet"):
        assert bpy.ops.hbc.build_layer(layer=layer) == {"FINISHED"}, layer
    comp = s.component_colors()
    sheet = P.sheet_colors(s.num_sheets)
    for layer, colors in (("components", comp), ("sheets", sheet)):
        obs = [o for o in S.find_layer(root, layer).all_objects if o.type == "MESH"]
        assert len(obs) == (1 if split_max == 0 else len(colors)), layer
        for ob in obs:
            owner, col = _face_point_colors(ob)
            assert np.allclose(col, colors[owner], atol=1e-6), ob.name
        # The edges hbc.polygon_edges made need no repair.
        assert not obs[0].data.validate(), layer
    (picked,) = [o for o in S.find_layer(root, "sheet").all_objects if o.get("hbc_highlight") is None]
    owner, col = _face_point_colors(picked)
    shade = 0.8 + 0.2 * ((owner * 7) % 3) / 2.0
    want = np.tile(sheet[st.sheet_index], (len(owner), 1))
    want[:, :3] *= shade[:, None]
    assert np.allclose(col, want, atol=1e-6)


def test_filter_modifier_runs_only_when_it_can_hide(clean_scene, data_dir):
    """The Blocks layer has no filter modifier with every filter at rest (nothing to delete); it
    gets one, on, when peeling one layer, off again back at 0 or with the filters disabled."""
    from hybrid_base_complex.blender import inspect as I
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.blender.context import find_root

    ins = bpy.context.scene.hbc_inspect
    ins.peel, ins.slice, ins.sheet_only, ins.filter_quality, ins.enabled = 0, False, False, False, True
    st = bpy.context.scene.hbc
    st.split_max = 0
    path = data_dir / "hybrid-base-complex" / "twistcube_s.mesh"
    assert bpy.ops.import_mesh.hbc(filepath=str(path), analyze=True) == {"FINISHED"}
    root = find_root(st.active_mesh)
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    (ob,) = S.find_layer(root, "components").all_objects
    assert ob.modifiers.get(I.MODIFIER) is None
    ins.peel = 1
    mod = ob.modifiers[I.MODIFIER]
    assert mod.show_viewport and mod.show_render
    ins.enabled = False
    assert not mod.show_viewport
    ins.enabled = True
    assert mod.show_viewport
    ins.peel = 0
    assert not mod.show_viewport
