"""What a new user meets first, in every Blender of the matrix: a second mesh lands beside the first
with every object of it (the cells of the direct view too), the see-through boundary shows what is
inside in the add-on's Solid settings, the legend names every colour shown, and the panel,
menus and Preferences are found and read at the default sidebar width."""

import bpy
import numpy as np
import pytest
from types import SimpleNamespace

from conftest import render_from_above

TWISTCUBE = ("hybrid-base-complex", "twistcube_s.mesh")  # 1301 cells: hex, prisms, pyramids, tets
CYLINDER = ("openvolumemesh", "Cylinder.ovm")


def roots():
    return [c for c in bpy.data.collections if c.get("hbc_source") is not None]


def import_mesh(data_dir, parts=TWISTCUBE, **kwargs):
    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*parts)), **kwargs) == {"FINISHED"}
    return next(r for r in roots() if r.name == bpy.context.scene.hbc.active_mesh)


def world_box(objects):
    """(lo, hi) of the objects' points in world coordinates (their meshes, not bound_box: a live
    surface's bound_box lags until the depsgraph evaluates)."""
    pts = np.array([ob.matrix_world @ v.co for ob in objects for v in ob.data.vertices])
    return pts.min(axis=0), pts.max(axis=0)


def part(root, name):
    from hybrid_base_complex.blender import scene as S

    (ob,) = [ob for ob in S.objects_in(S.find_layer(root, "direct")) if ob.get("hbc_part") == name]
    return ob


@pytest.mark.parametrize("live_surface", [False, True], ids=["every-cell", "live-surface"])
def test_second_import_cells_sit_with_its_boundary(clean_scene, data_dir, live_surface):
    """With "Cells in direct view" on, the second mesh's cells object has the box of its own
    boundary (placed beside the first mesh), not the file's coordinates inside the first mesh; the
    cells' centroids the filters cut by are in the same place. Both ways of showing the cells: every
    cell (geometry-nodes filter) and the live surface of large meshes (surface_above 0)."""
    ins = bpy.context.scene.hbc_inspect
    ins.surface_above = 0 if live_surface else 10 ** 9
    first = import_mesh(data_dir)
    ins.direct_cells = True
    second = import_mesh(data_dir, CYLINDER, analyze=False)
    lo1, hi1 = world_box([part(first, "boundary")])
    lo2, hi2 = world_box([part(second, "boundary")])
    assert lo2[0] > hi1[0]  # the boundary is beside the first mesh
    cells = part(second, "cells")
    assert bool(cells.get("hbc_surface")) == live_surface
    lo, hi = world_box([cells])
    assert np.allclose(lo, lo2, atol=1e-3) and np.allclose(hi, hi2, atol=1e-3), (lo, hi, lo2, hi2)
    from hybrid_base_complex.blender import inspect as I

    I.equip_mesh(second)  # a build leaves the filters' attributes out until a filter is on
    centroids = np.zeros(3 * len(cells.data.polygons), np.float32)
    cells.data.attributes["hbc_centroid"].data.foreach_get("vector", centroids)
    centroids = centroids.reshape(-1, 3)
    assert np.all(centroids >= lo2 - 1e-3) and np.all(centroids <= hi2 + 1e-3)
    # The first mesh's cells stay where they were.
    lo, hi = world_box([part(first, "cells")])
    lo1b, hi1b = world_box([part(first, "boundary")])
    assert np.allclose(lo, lo1b, atol=1e-3) and np.allclose(hi, hi1b, atol=1e-3)


def test_cut_plane_of_second_mesh_cuts_its_blocks(clean_scene, data_dir):
    """The Blocks layer of a mesh placed beside another is cut where the plane is: the centroids
    the filter compares with the plane are in the blocks' own (placed) coordinates."""
    from hybrid_base_complex.blender import scene as S

    import_mesh(data_dir, CYLINDER)
    second = import_mesh(data_dir)
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    from hybrid_base_complex.blender import inspect as I

    I.equip_mesh(second)  # what switching a filter on does first
    obs = [ob for ob in S.objects_in(S.find_layer(second, "components")) if ob.type == "MESH"]
    lo, hi = world_box(obs)
    for ob in obs:
        c = np.zeros(3 * len(ob.data.polygons), np.float32)
        ob.data.attributes["hbc_centroid"].data.foreach_get("vector", c)
        c = c.reshape(-1, 3)
        assert np.all(c >= lo - 1e-3) and np.all(c <= hi + 1e-3), ob.name


def render_solid(tmp_path, tag, size=64):
    """The scene rendered by Workbench with the add-on's Solid settings (colour type Attribute,
    the enum's "VERTEX"), from above, orthographic, framed on every mesh object shown:
    (size, size, 4) pixels."""
    scene = bpy.context.scene
    shown = [ob for ob in scene.objects if ob.type == "MESH" and not ob.hide_render
             and all(not c.hide_render for c in ob.users_collection)]
    lo, hi = world_box(shown)
    px = render_from_above(tmp_path, tag, lo, hi, size, size)
    bpy.data.objects.remove(bpy.data.objects["HBC test camera"])
    return px


def coloured(px):
    """Pixels showing a saturated colour (the graph's valence colours, the non-hex cells), not the
    boundary's grey."""
    rgb = px[..., :3]
    return (px[..., 3] > 0.5) & (rgb.max(axis=-1) - rgb.min(axis=-1) > 0.2)


def test_see_through_boundary_in_solid_view(clean_scene, data_dir, tmp_path):
    """The add-on's Solid settings (Attribute colours) draw the see-through boundary transparent:
    the singularity graph and the non-hex cells inside show through it in a Workbench render, about
    as many coloured pixels as without the boundary (an opaque boundary hides nearly all)."""
    from hybrid_base_complex.blender import scene as S

    root = import_mesh(data_dir)
    assert bpy.ops.hbc.build_layer(layer="graph") == {"FINISHED"}
    boundary = part(root, "boundary")
    with_boundary = coloured(render_solid(tmp_path, "with")).sum()
    boundary.hide_render = True
    without = coloured(render_solid(tmp_path, "without")).sum()
    assert without > 100, "the graph and the non-hex cells render nothing"
    assert with_boundary > 0.6 * without, (with_boundary, without)
    # See-through off: the boundary is opaque and hides the inside.
    boundary.hide_render = False
    bpy.context.scene.hbc.direct_transparent = False
    assert bpy.ops.hbc.build_layer(layer="direct") == {"FINISHED"}
    opaque = coloured(render_solid(tmp_path, "opaque")).sum()
    assert opaque < 0.3 * without, (opaque, without)
    assert S.find_layer(root, "direct") is not None


def test_failed_import_leaves_no_undo_step_and_says_everything(clean_scene, data_dir, tmp_path):
    """A failed import adds no undo step: the import operator has no "UNDO" option (from the file
    browser Blender 3.x pushes a step for an UNDO operator even when it cancels) and pushes its own
    step only on success, so undoing a successful import removes it. The error names the
    undecodable bytes as U+FFFD and its popup lines hold the whole message."""
    from hybrid_base_complex.plan import planning as P
    from hybrid_base_complex.ui.operators import HBC_OT_import

    assert "UNDO" not in HBC_OT_import.bl_options
    bad = tmp_path / ("a-folder-with-a-rather-long-name-" * 3) / "latin1.mesh"
    bad.parent.mkdir()
    bad.write_bytes(b"MeshVersionFormatted 1\nDimension 3\nVertices\n1\n0 z\xff\xfe 0 0\nEnd\n")
    with pytest.raises(RuntimeError) as info:
        bpy.ops.import_mesh.hbc(filepath=str(bad))
    text = str(info.value)[len("Error: "):].rstrip("\n")
    assert text.startswith(f"{bad}:5: ") and "z\ufffd\ufffd" in text, text
    lines = P.wrap_message(text)
    assert len(lines) > 1 and all(len(line) <= 60 for line in lines)
    assert "".join(lines).replace(" ", "") == text.replace(" ", "")
    if not bpy.ops.ed.undo_push.poll():
        pytest.skip(f"Blender {bpy.app.version_string}: no undo stack without a window here")
    bpy.ops.ed.undo_push(message="before")
    import_mesh(data_dir, CYLINDER, analyze=False)
    assert roots()
    try:
        assert bpy.ops.ed.undo() == {"FINISHED"}
    except RuntimeError as e:
        pytest.skip(f"Blender {bpy.app.version_string}: undo refused in background mode: {e}")
    assert not roots(), "undo did not take the import back: it pushed no step of its own"


#: Characters across the sidebar at its default width (a panel's row; sub-panels alike).
SIDEBAR = 30
#: Characters a list row has (the list's margins and scroll bar take the rest).
LIST_ROW = 26


class _Layout:
    """A stand-in UILayout that knows how wide each of its items is: a row shares its width
    equally among what it holds, a split gives its first item `factor` of it, a grid `1/columns`,
    a column or box the whole width. Records (text, characters needed, characters given) for
    every item showing words: a label, a button, a property's name (a checkbox or an icon takes 3
    characters more, a number field's value 8)."""

    def __init__(self, items, kind="column", factor=0.5, columns=1):
        self.items, self.kind, self.factor, self.columns = items, kind, factor, columns
        self.children = []  # _Layout or (text, needed)

    def _child(self, kind, **kw):
        child = _Layout(self.items, kind, **kw)
        self.children.append(child)
        return child

    def row(self, **_):
        return self._child("row")

    def column(self, **_):
        return self._child("column")

    def box(self):
        return self._child("box")

    def column_flow(self, columns=1, **_):
        return self._child("grid", columns=columns)

    def grid_flow(self, columns=1, **_):
        return self._child("grid", columns=max(columns, 1))

    def split(self, factor=0.5, **_):
        return self._child("split", factor=factor)

    def _word(self, text, extra):
        self.children.append((str(text), len(str(text)) + extra if text else 0))

    def label(self, text="", icon="NONE", **_):
        self._word(text, 3 if icon not in ("NONE", "BLANK1") else 0)

    def operator(self, idname, text=None, icon="NONE", **_):
        self._word(text if text is not None else idname, 3 if icon != "NONE" else 0)
        return SimpleNamespace()

    def prop(self, data, name, text=None, toggle=False, expand=False, icon="NONE", **_):
        rna = data.bl_rna.properties[name]
        label = rna.name if text is None else text
        if rna.type == "ENUM" and expand:
            row = self._child("row")
            for item in rna.enum_items:
                row._word(item.name, 0)
            return
        if rna.type == "BOOLEAN":
            extra = 1 if toggle else 3
        elif rna.type in ("INT", "FLOAT") and getattr(rna, "array_length", 0) == 0:
            extra = 8
        else:
            extra = 0
        self._word(label, extra)

    def template_list(self, *_, **__):
        pass

    def separator(self, **_):
        pass

    def __setattr__(self, name, value):
        object.__setattr__(self, name, value)

    def measure(self, width):
        """(text, needed, given) of every word under this layout of `width` characters."""
        if self.kind == "box":
            width -= 2
        n = len(self.children)
        out = []
        for i, child in enumerate(self.children):
            if self.kind == "row":
                w = width / n
            elif self.kind == "split":
                w = width * self.factor if i == 0 else width * (1 - self.factor) / max(n - 1, 1)
            elif self.kind == "grid":
                w = width / self.columns
            else:
                w = width
            if isinstance(child, _Layout):
                out += child.measure(w)
            elif child[0]:
                out.append((child[0], child[1], w))
        return out


def _panel(cls, layout):
    """An instance-like stand-in of a panel class whose draw() draws into `layout`."""
    import inspect as pyinspect

    class Proxy:
        def __getattr__(self, name):
            attr = pyinspect.getattr_static(cls, name)
            if isinstance(attr, staticmethod):
                return attr.__func__
            if callable(attr):
                return attr.__get__(self)
            return getattr(cls, name)

    proxy = Proxy()
    proxy.layout = layout
    return proxy


def cut_words(context, names):
    """Every word the Hex Structure panels (all of them, the Look inside panel too) and the sheet
    list's rows draw that does not fit the default sidebar width: [(text, needed, given)]."""
    from hybrid_base_complex.ui import addon, panels

    out = []
    for cls in addon.CLASSES:
        if not issubclass(cls, bpy.types.Panel) or (hasattr(cls, "poll") and not cls.poll(context)):
            continue
        root = _Layout([])
        cls.draw(_panel(cls, root), context)
        out += root.measure(SIDEBAR)
    st = context.scene.hbc
    for item in list(st.sheets)[:3] + [SimpleNamespace(index=12345, type=3, cells=1234567)]:
        row = _Layout([])
        panels.HBC_UL_sheets.draw_item(None, context, row, None, item, 0, None, "")
        out += row.measure(LIST_ROW)
    return [(t, need, round(given, 1)) for t, need, given in out if need > given and t not in names]


def test_panels_fit_the_default_sidebar(clean_scene, data_dir):
    """Nothing the panels draw is cut off at the default sidebar width (about 30 characters
    across): the sheet list's index, type and size, the Look inside panel's options, cell types
    and histogram counts, the layer buttons, the legend, the selection. Object and mesh names
    are the user's and may be long."""
    root = import_mesh(data_dir)
    assert bpy.ops.hbc.build_all() == {"FINISHED"}
    from hybrid_base_complex.plan import inspection as IP
    from hybrid_base_complex.plan import session

    IP.cell_data(session.get(root.name))  # the histogram is drawn once computed
    ob = next(o for o in bpy.context.scene.objects if o.get("hbc_sheet") is not None)
    bpy.context.view_layer.objects.active = ob
    names = {o.name for o in bpy.data.objects} | {c.name for c in bpy.data.collections}
    assert not cut_words(bpy.context, names)


def test_panel_order_layers_first(addon):
    """After an import the layers come first: the Look inside panel (filters, cut plane, an
    11-row histogram) is below them and closed at first."""
    from hybrid_base_complex.ui import addon as A, panels

    under_main = sorted((c.bl_order, c.bl_label) for c in A.CLASSES
                        if issubclass(c, bpy.types.Panel) and getattr(c, "bl_parent_id", "") == "HBC_PT_main")
    labels = [label for _, label in under_main]
    assert labels.index("Layers") < labels.index("Look inside") and labels[-1] == "Look inside", labels
    assert "DEFAULT_CLOSED" in panels.HBC_PT_inspect.bl_options


def test_cut_plane_goes_with_the_mesh_selected_and_visible(clean_scene, data_dir):
    """The cut plane is an Empty in the mesh's own collection (not the scene's top level), drawn
    as a circle in the plane, selected and active (ready to move and turn), and visible."""
    from hybrid_base_complex.blender import scene as S

    root = import_mesh(data_dir)
    assert bpy.ops.hbc.add_cut_plane() == {"FINISHED"}
    plane = bpy.context.scene.hbc_inspect.plane
    assert plane is not None and plane.name in root.objects
    assert plane.name not in bpy.context.scene.collection.objects
    assert plane.empty_display_type == "CIRCLE"
    assert plane.select_get() and bpy.context.view_layer.objects.active == plane
    assert plane.visible_get()
    assert [ob for ob in bpy.context.selected_objects] == [plane]
    assert plane in S.objects_in(root)


def test_found_in_preferences_with_a_guide(addon):
    """Searching "hex" in Preferences > Add-ons finds the add-on (Blender searches name, author and
    category); its Documentation and Report a Bug buttons open the add-on's own user guide, which
    says how to report a problem; the extension's manifest names it the same way."""
    import os
    import pathlib
    import urllib.parse
    import urllib.request

    info = addon.bl_info
    assert "hex" in info["name"].casefold()
    for key in ("doc_url", "tracker_url"):
        url = info[key]
        assert url.startswith("file:"), (key, url)
        path = pathlib.Path(urllib.request.url2pathname(urllib.parse.urlparse(url).path))
        assert path.is_file() and path.parent == pathlib.Path(os.environ["HBC_ADDON_DIR"]).resolve(), url
    guide = path.read_text(encoding="utf-8")
    assert "## Reporting a problem" in guide and info["tracker_url"].endswith("#reporting-a-problem")
    manifest = (pathlib.Path(os.environ["HBC_ADDON_DIR"]) / "blender_manifest.toml").read_text()
    name = next(line for line in manifest.splitlines() if line.startswith("name = "))
    tagline = next(line for line in manifest.splitlines() if line.startswith("tagline = "))
    assert "hex" in name.casefold() and "hex" in tagline.casefold() and len(tagline) - 12 <= 64
    assert hasattr(bpy.ops.hbc, "help") and bpy.ops.hbc.help.poll()


def test_import_menu_entry_is_short_and_the_filter_lists_every_format(addon):
    """File > Import's entry lists no extensions (eight would make it the menu's widest); the file
    browser's filter and the tooltip list every one, .ovmb among them."""
    from hybrid_base_complex.plan import planning as P
    from hybrid_base_complex.ui import operators as O

    menu = _Layout([])
    O.menu_import(SimpleNamespace(layout=menu), bpy.context)
    (text, _), = menu.children
    assert text == "Hex-dominant Mesh" and "." not in text
    exts = P.mesh_extensions()
    assert ".ovmb" in exts
    filters = bpy.ops.import_mesh.hbc.get_rna_type().properties["filter_glob"].default.split(";")
    tip = O.HBC_OT_import.description(bpy.context, None)
    for e in exts:
        assert f"*{e.lower()}" in filters and e in tip, e


def test_layer_eye_shows_open_or_closed(clean_scene, data_dir):
    """A layer's header shows an open eye when the layer is shown and a closed one when hidden
    (shapes that differ, not only by fill); clicking it toggles the layer."""
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.ui import panels

    root = import_mesh(data_dir)
    assert bpy.ops.hbc.build_layer(layer="graph") == {"FINISHED"}
    cls = next(c for c in panels.layer_panels if c.layer == "graph")
    icons = []

    class Header:
        def operator(self, idname, icon="NONE", **_):
            icons.append((idname, icon))
            return SimpleNamespace()

        def prop(self, *_, **__):
            icons.append(("prop", "collection's own toggle"))

        def label(self, *_, **__):
            pass

    def header_icon():
        icons.clear()
        cls.draw_header(SimpleNamespace(layout=Header(), layer="graph"), bpy.context)
        (entry,) = icons
        return entry

    assert header_icon() == ("hbc.toggle_layer", "HIDE_OFF")
    assert bpy.ops.hbc.toggle_layer(layer="graph") == {"FINISHED"}
    assert S.find_layer(root, "graph").hide_viewport
    assert header_icon() == ("hbc.toggle_layer", "HIDE_ON")


def test_frame_layer_selects_what_it_frames(clean_scene, data_dir):
    """Frame (per layer) selects the layer's shown objects and frames them (a hidden layer is
    shown first); the subsheets, laid out beside the mesh, are framed when built."""
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.plan import session

    root = import_mesh(data_dir)
    assert bpy.ops.hbc.build_all() == {"FINISHED"}
    graph = S.find_layer(root, "graph")
    assert graph.hide_viewport
    assert bpy.ops.hbc.frame_layer(layer="graph") == {"FINISHED"}
    assert not graph.hide_viewport
    assert {ob.name for ob in bpy.context.selected_objects} == {ob.name for ob in S.objects_in(graph)}
    st = bpy.context.scene.hbc
    st.sheet_index = int(np.flatnonzero(session.get(root.name).sheet_types() == 3)[0])
    assert bpy.ops.hbc.build_layer(layer="subsheets") == {"FINISHED"}
    sub = S.find_layer(root, "subsheets")
    assert {ob.name for ob in bpy.context.selected_objects} == {ob.name for ob in S.objects_in(sub)}
    with pytest.raises(RuntimeError, match="not built"):
        bpy.ops.hbc.frame_layer(layer="sheet")


def test_picked_component_shows_its_cells(clean_scene, data_dir):
    """The Selection panel names a picked block's cell count and its cells' types, as the analysis
    has them."""
    from hybrid_base_complex.plan import planning as P
    from hybrid_base_complex.plan import session
    from hybrid_base_complex.ui import panels

    root = import_mesh(data_dir, CYLINDER)
    s = session.get(root.name)
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    ob = next(o for o in bpy.context.scene.objects if o.get("hbc_component") is not None)
    c = int(ob["hbc_component"])
    bpy.context.view_layer.objects.active = ob
    layout = _Layout([])
    panels.HBC_PT_selection.draw(_panel(panels.HBC_PT_selection, layout), bpy.context)
    words = [t for t, _, _ in layout.measure(SIDEBAR)]
    cells = np.flatnonzero(np.asarray(s.analysis.complex.cell_component) == c)
    assert f"cells: {len(cells)}" in words, words
    types = np.asarray(s.mesh.cell_types)[cells]
    for t in np.unique(types):
        i = words.index(f"  {P.CELL_TYPE_NAMES[t]}")
        assert words[i + 1] == str(int((types == t).sum()))


def test_legend_names_every_layers_colours(clean_scene, data_dir, tmp_path):
    """Each layer shown alone gets legend entries (the wireframe's class colours and faint lines,
    the subsheets' and sheets' own colours among them) and the legend never says "No layer shown"
    while a layer is visible; after the file is saved and reopened in a new session (the meshes
    not in memory) the legend is as whole as before."""
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.plan import planning as P
    from hybrid_base_complex.plan import session
    from hybrid_base_complex.ui import panels

    root = import_mesh(data_dir)
    st = bpy.context.scene.hbc
    assert bpy.ops.hbc.build_all() == {"FINISHED"}
    st.sheet_index = int(np.flatnonzero(session.get(root.name).sheet_types() == 3)[0])
    for layer in ("sheet", "subsheets"):
        assert bpy.ops.hbc.build_layer(layer=layer) == {"FINISHED"}
    expected = {"wireframe": ("palette", "Wire: chain class"), "subsheets": ("palette", "A colour a subsheet"),
                "sheets": ("palette", "A colour a sheet"), "components": ("palette", "Hex-cell component")}

    def legend_alone(layer):
        for key, _ in P.LAYERS:
            coll = S.find_layer(root, key)
            if coll is not None:
                coll.hide_viewport = key != layer
        shown, entries = panels.panel_legend(bpy.context)
        layout = _Layout([])
        panels.HBC_PT_legend.draw(_panel(panels.HBC_PT_legend, layout), bpy.context)
        words = [t for t, _, _ in layout.measure(SIDEBAR)]
        return shown, entries, words

    before = {}
    for layer, _ in P.LAYERS:
        shown, entries, words = legend_alone(layer)
        assert shown == [layer] and entries, layer
        assert "No layer shown" not in words, layer
        if layer in expected:
            assert expected[layer] in entries, (layer, entries)
        before[layer] = entries
    path, name = tmp_path / "legend.blend", root.name
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    session.clear()  # what a new Blender session has
    bpy.ops.wm.open_mainfile(filepath=str(path))
    root = bpy.data.collections[name]
    for layer, _ in P.LAYERS:
        assert legend_alone(layer)[1] == before[layer], layer
    for key, _ in P.LAYERS:
        S.find_layer(root, key).hide_viewport = True
    shown, entries, words = legend_alone(None)
    assert shown == [] and "No layer shown" in words
