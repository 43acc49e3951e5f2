"""The panel says what the viewport shows, and its buttons act on what the user sees (in Blender
background mode, through the operators and the data the GUI's clicks go through): the legend's
picked-sheet swatch is the colour the sheet is drawn in; the see-through boundary does not take a
click meant for a block inside it; *Show block* leaves an interior block in sight; the layers' eyes
and the legend follow the outliner's eyes."""

import bpy
import numpy as np
import pytest
from mathutils import Vector

TWISTCUBE = ("hybrid-base-complex", "twistcube_s.mesh")
#: A mesh whose worst block (lowest scaled Jacobian) lies inside: no cell of it has a boundary
#: vertex (the test checks it), so other blocks surround it.
ROCKERARM = ("cinolib", "rockerarm.mesh")


def import_mesh(data_dir, parts=TWISTCUBE, **kwargs):
    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*parts)), **kwargs) == {"FINISHED"}
    from hybrid_base_complex.blender.context import find_root

    return find_root(bpy.context.scene.hbc.active_mesh)


def objects(root, layer):
    from hybrid_base_complex.blender import scene as S

    return [ob for ob in S.objects_in(S.find_layer(root, layer)) if ob.type == "MESH"]


def boundary_of(root):
    (ob,) = [ob for ob in objects(root, "direct") if ob.get("hbc_part") == "boundary"]
    return ob


def see_through(ob) -> bool:
    """Drawn see-through in Solid mode: an object without colour attribute is drawn in its object
    colour, whose alpha is the boundary's (blender/layers.py)."""
    return ob.type == "MESH" and "hbc_color" not in ob.data.color_attributes and ob.color[3] < 1.0


def drawn_colors(ob) -> np.ndarray:
    """(n, 4) linear RGBA of the colour attribute a layer object is drawn with (Solid > Attribute)."""
    attr = ob.data.color_attributes["hbc_color"]
    out = np.zeros(4 * len(attr.data), np.float32)
    attr.data.foreach_get("color", out)
    return out.reshape(-1, 4)


def test_picked_sheet_swatch_is_the_sheets_colour(clean_scene, data_dir):
    """The legend's *Picked sheet* swatch has the colour the picked-sheet layer draws its sheet in
    (its blocks are shades of it, the lightest the colour itself): for sheet 1, for another sheet
    picked with *Show on pick*, and, with *Show on pick* off, the sheet still drawn rather than the
    one picked in the list."""
    from hybrid_base_complex.ui import panels

    root = import_mesh(data_dir)
    st = bpy.context.scene.hbc
    st.sheet_index = 1
    assert bpy.ops.hbc.build_layer(layer="sheet") == {"FINISHED"}

    def swatch():
        shown, entries = panels.panel_legend(bpy.context)
        assert "sheet" in shown
        (key,) = [k for k, words in entries if words == "Picked sheet"]
        return np.asarray(getattr(st, f"legend_{key}"), np.float32)

    def drawn(sheet):
        (ob,) = [o for o in objects(root, "sheet") if o.get("hbc_highlight") is None]
        assert ob["hbc_sheet"] == sheet
        colors = drawn_colors(ob)
        return colors[np.argmax(colors[:, :3].sum(axis=1))]

    first = drawn(1)
    assert np.allclose(swatch(), first, atol=1e-5), (swatch(), first)
    st.sheet_index = 2  # Show on pick (the default) rebuilds the layer for sheet 2
    assert np.allclose(swatch(), drawn(2), atol=1e-5)
    assert not np.allclose(first[:3], drawn(2)[:3])  # the sheets differ in colour: the check means something
    st.auto_show = False
    st.sheet_index = 1  # the layer still draws sheet 2
    assert np.allclose(swatch(), drawn(2), atol=1e-5)


def test_see_through_boundary_does_not_take_the_click(clean_scene, data_dir, tmp_path):
    """A click in the viewport (view3d.select) picks among the objects the view layer marks
    selectable, the flag Object.select_set obeys too: while the boundary is see-through it is not
    selectable, so a click on a block inside goes to the block. Framing and exporting the direct
    view still take the boundary with them; with *See-through* off (an opaque boundary hides the
    blocks) the boundary is selectable again."""
    root = import_mesh(data_dir, build_layers=True)
    st = bpy.context.scene.hbc
    assert st.direct_transparent
    boundary, block = boundary_of(root), objects(root, "components")[0]
    assert see_through(boundary) and boundary.visible_get() and block.visible_get()
    boundary.select_set(True)
    assert not boundary.select_get()
    block.select_set(True)
    assert block.select_get()
    # The layer's export writes the boundary (every visible object of the layer).
    out = tmp_path / "direct.obj"
    assert bpy.ops.hbc.export_layer(filepath=str(out), layer="direct", format="OBJ") == {"FINISHED"}
    written = [line[2:] for line in out.read_text().splitlines() if line.startswith("o ")]
    assert boundary.name.replace(" ", "_") in written, written  # the OBJ exporter's object names
    assert not boundary.select_get() and block.select_get()  # the selection is put back
    st.direct_transparent = False
    assert bpy.ops.hbc.build_layer(layer="direct") == {"FINISHED"}
    boundary = boundary_of(root)
    assert not see_through(boundary)
    boundary.select_set(True)
    assert boundary.select_get()


def first_opaque_hit(origin, direction, limit):
    """The first object a ray meets that is not see-through (the rays go on through see-through
    objects), or None."""
    scene = bpy.context.scene
    origin, direction = Vector(origin), Vector(direction).normalized()
    travelled = 0.0
    while travelled < limit:
        hit, loc, _, _, ob, _ = scene.ray_cast(bpy.context.evaluated_depsgraph_get(), origin, direction,
                                               distance=limit - travelled)
        if not hit:
            return None
        if not see_through(ob):
            return ob
        step = (loc - origin).length + 1e-4 * limit
        origin, travelled = origin + direction * step, travelled + step
    return None


@pytest.mark.parametrize("split_max", [1000, 0], ids=["one-object-a-block", "merged-blocks"])
def test_show_block_leaves_an_interior_block_in_sight(clean_scene, data_dir, split_max):
    """rockerarm's worst block lies inside the mesh. *Show block* (Metrics) leaves it in sight:
    every other object of the mesh still drawn is see-through, and rays from outside along +-x,
    +-y, +-z to the cell nearest the block's centre meet the block first; in a merged Blocks mesh
    (more blocks than *Max objects*) the faces left shown in Edit Mode are the block's."""
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.plan import inspection as IP
    from hybrid_base_complex.plan import metrics_box as MB
    from hybrid_base_complex.plan import session

    st = bpy.context.scene.hbc
    st.split_max = split_max
    try:
        root = import_mesh(data_dir, ROCKERARM, build_layers=True)
        s = session.get(root.name)
        block = {kind: i for kind, i, _, _ in MB.worst(s.metrics())}["component"]
        comp = np.asarray(s.analysis.complex.cell_component)
        data = IP.cell_data(s)
        cells = np.flatnonzero(comp == block)
        assert data["depth"][cells].min() >= 1  # inside: no cell of it touches the boundary
        assert bpy.ops.hbc.show_worst(kind="component") == {"FINISHED"}
        bpy.context.view_layer.update()
        mine = [ob for ob in objects(root, "components") if ob.get("hbc_component") == block]
        merged = None if mine else next(ob for ob in objects(root, "components") if ob.get("hbc_owner") == "component")
        shown = mine or [merged]
        others = [ob for ob in S.objects_in(root) if ob.type == "MESH" and ob not in shown and ob.visible_get()]
        assert all(see_through(ob) for ob in others), [ob.name for ob in others if not see_through(ob)]
        if merged is not None:
            import bmesh

            assert merged.mode == "EDIT"
            bm = bmesh.from_edit_mesh(merged.data)
            layer = bm.faces.layers.int["owner"]
            assert {f[layer] for f in bm.faces if not f.hide} == {block}
            bpy.ops.object.mode_set(mode="OBJECT")
            return
        centre = data["centroid"][cells].mean(axis=0)
        target = data["centroid"][cells[np.argmin(np.linalg.norm(data["centroid"][cells] - centre, axis=1))]]
        size = float(np.linalg.norm(np.ptp(s.points, axis=0)))
        for d in np.vstack([np.eye(3), -np.eye(3)]):
            ob = first_opaque_hit(target - d * 2 * size, d, 3 * size)
            assert ob is not None and ob in mine, (d, ob and ob.name)
    finally:
        st.split_max = 1000


class _Header:
    """A stand-in layout for a layer panel's header: records the icon of the eye it draws."""

    def __init__(self):
        self.icons = []

    def operator(self, idname, text="", emboss=True, icon="NONE"):
        self.icons.append(icon)
        return type("Props", (), {})()

    def label(self, text="", icon="NONE"):
        self.icons.append(icon)


def eye(layer):
    """The icon of the eye the panel draws in a layer's header."""
    from hybrid_base_complex.ui import panels

    cls = next(c for c in panels.layer_panels if c.layer == layer)
    header = _Header()
    cls.draw_header(type("Panel", (), {"layout": header, "layer": layer})(), bpy.context)
    (icon,) = header.icons
    return icon


def layer_collection(coll, lc=None):
    """The view layer's LayerCollection of a collection (what the outliner's eye of it sets)."""
    lc = lc or bpy.context.view_layer.layer_collection
    if lc.collection == coll:
        return lc
    for child in lc.children:
        found = layer_collection(coll, child)
        if found is not None:
            return found
    return None


def test_panel_follows_the_outliner(clean_scene, data_dir):
    """The outliner's eye hides a mesh (its collection), a layer (the layer's collection) or
    objects in the view layer. The panel follows what is drawn: the layer's eye closes and the
    legend drops it; the panel's eye then shows that layer again, and only it."""
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.ui import panels

    root = import_mesh(data_dir)
    assert bpy.ops.hbc.build_all() == {"FINISHED"}  # only the blocks stay shown

    def drawn(layer):
        bpy.context.view_layer.update()
        return any(ob.visible_get() for ob in objects(root, layer))

    def legend_layers():
        return panels.panel_legend(bpy.context)[0]

    assert drawn("components") and eye("components") == "HIDE_OFF" and legend_layers() == ["components"]
    assert not drawn("direct") and eye("direct") == "HIDE_ON"
    mesh_eye = layer_collection(root)
    mesh_eye.hide_viewport = True  # the outliner's eye of the mesh
    assert not drawn("components")
    assert eye("components") == "HIDE_ON" and legend_layers() == []
    assert bpy.ops.hbc.toggle_layer(layer="components") == {"FINISHED"}  # the panel's eye
    assert drawn("components") and eye("components") == "HIDE_OFF" and legend_layers() == ["components"]
    assert not any(drawn(layer) for layer in ("direct", "graph", "sheets", "wireframe"))
    layer_eye = layer_collection(S.find_layer(root, "components"))
    layer_eye.hide_viewport = True  # the outliner's eye of the Blocks layer
    assert not drawn("components") and eye("components") == "HIDE_ON" and legend_layers() == []
    layer_eye.hide_viewport = False
    assert drawn("components") and eye("components") == "HIDE_OFF"
    for ob in objects(root, "components"):
        ob.hide_set(True)  # the outliner's eyes of the layer's objects
    assert not drawn("components") and eye("components") == "HIDE_ON" and legend_layers() == []
    assert bpy.ops.hbc.toggle_layer(layer="components") == {"FINISHED"}
    assert drawn("components") and eye("components") == "HIDE_OFF" and legend_layers() == ["components"]
    assert bpy.ops.hbc.toggle_layer(layer="components") == {"FINISHED"}
    assert not drawn("components") and eye("components") == "HIDE_ON" and legend_layers() == []
