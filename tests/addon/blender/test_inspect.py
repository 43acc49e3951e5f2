"""The inspection filters in Blender background mode, counted on the evaluated meshes: a
plane through a generated grid hides exactly the cells on one side, peeling one layer of a
10x10x10 grid leaves the inner 8x8x8 cells, the type filter on a split grid leaves exactly its
non-hex cells, the quality range and the blocks/sheets layers."""

import os
import pathlib
import subprocess

import bpy
import numpy as np
import pytest


def hbc_cli():
    """The `hbc` command of the build holding the add-on (<build>/addon/hybrid_base_complex)."""
    value = os.environ.get("HBC_CLI")
    if value:
        return value
    build = pathlib.Path(os.environ["HBC_ADDON_DIR"]).resolve().parents[1]
    return str(build / "bin" / "hbc")


def generate(tmp_path, *args):
    out = tmp_path / "generated.ovm"
    subprocess.run([hbc_cli(), "generate", *args, "-o", str(out)], check=True, capture_output=True)
    return out


def import_mesh(path, analyze=False):
    from hybrid_base_complex.blender.context import find_root

    ins = bpy.context.scene.hbc_inspect
    ins.direct_cells = True
    assert bpy.ops.import_mesh.hbc(filepath=str(path), analyze=analyze) == {"FINISHED"}
    return find_root(bpy.context.scene.hbc.active_mesh)


def cells_object(root):
    from hybrid_base_complex.blender import scene as S

    return next(o for o in S.find_layer(root, "direct").all_objects if o.get("hbc_part") == "cells")


def evaluated_cells(ob):
    """(number of faces, distinct cells) of the object after its modifiers."""
    me = ob.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    cells = np.zeros(len(me.polygons), np.int32)
    if len(me.polygons):
        me.attributes["hbc_cell"].data.foreach_get("value", cells)
    return len(me.polygons), np.unique(cells)


def cell_arrays(ob):
    """(face cells, face centroids) of a layer object, equipped first (a build leaves the filters'
    attributes out until a filter is switched on)."""
    from hybrid_base_complex.blender import inspect as I
    from hybrid_base_complex.plan import session

    I.ensure_equipped(ob, session.get(ob["hbc_mesh"]))
    me = ob.data
    n = len(me.polygons)
    cells, cen = np.zeros(n, np.int32), np.zeros(3 * n, np.float32)
    me.attributes["hbc_cell"].data.foreach_get("value", cells)
    me.attributes["hbc_centroid"].data.foreach_get("vector", cen)
    return cells, cen.reshape(-1, 3)


@pytest.fixture
def reset(clean_scene):
    ins = bpy.context.scene.hbc_inspect
    for key in ("slice", "flip", "filter_quality", "direct_cells", "color_by_quality", "sheet_only"):
        setattr(ins, key, False)
    ins.peel = 0
    ins.plane = None
    ins.enabled = True
    for n in ("hex", "tet", "prism", "pyramid", "polyhedron"):
        setattr(ins, f"show_{n}", True)
    yield ins


def test_unfiltered_cells_object_has_every_cell(reset, tmp_path):
    root = import_mesh(generate(tmp_path, "grid", "--size", "4", "3", "2"))
    nf, cells = evaluated_cells(cells_object(root))
    assert nf == 6 * 24 and len(cells) == 24


@pytest.mark.parametrize("normal,flip", [((1, 0, 0), False), ((1, 0, 0), True), ((0.3, -1, 0.2), False)])
def test_plane_hides_the_cells_on_one_side(reset, tmp_path, normal, flip):
    """A 6x5x4 grid cut by a plane through a point off the cell centres: the kept cells are exactly
    those whose centroid is on the plane's -normal side (+normal with flip), all 6 faces each."""
    from hybrid_base_complex.blender import inspect as I

    root = import_mesh(generate(tmp_path, "grid", "--size", "6", "5", "4"))
    ob = cells_object(root)
    cells, cen = cell_arrays(ob)
    lo, hi = cen.min(axis=0), cen.max(axis=0)
    point = lo + (hi - lo) * np.array([0.43, 0.51, 0.37])
    I.add_plane(bpy.context, tuple(point), normal)
    reset.flip = flip
    side = (cen - point) @ (np.asarray(normal, np.float64) / np.linalg.norm(normal))
    keep = np.unique(cells[(side > 0) if flip else (side < 0)])
    assert 0 < len(keep) < 120
    nf, shown = evaluated_cells(ob)
    assert np.array_equal(shown, keep)
    assert nf == 6 * len(keep)
    # Moving the Empty moves the cut: past the mesh, nothing (or everything) is hidden.
    reset.plane.location = tuple(hi + 1.0) if not flip else tuple(lo - 1.0)
    if np.dot(normal, (1, 1, 1)) > 0:
        assert evaluated_cells(ob)[0] == 6 * 120


#: The plane Blender draws an Empty of display type CIRCLE in: its local XZ plane, so the circle's
#: normal is the Empty's local Y axis (Blender's draw code puts the circle's points at x = sin,
#: y = 0, z = cos: DRW_cache_circle_get in draw_cache.c up to 4.1, the overlay's shape cache in
#: overlay_shape.cc from 4.2 on).
CIRCLE_NORMAL = (0.0, 1.0, 0.0)
CIRCLE_IN_PLANE = ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0))


@pytest.mark.parametrize("rotation", [(0.0, 0.0, 0.0), (0.4, -0.7, 1.1)])
@pytest.mark.parametrize("live", [False, True])
def test_cut_lies_in_the_drawn_circle(reset, tmp_path, rotation, live):
    """The Empty *Add cut plane* makes (the panel's button) cuts where its circle is drawn: the
    cells it hides are exactly those whose centroid is on the +normal side of the circle's plane,
    at rotation 0 and turned; moving the Empty within the circle's plane (G X, G Z at rotation 0)
    changes nothing, moving it along the circle's normal (G Y) moves the cut. Both with the
    geometry-nodes filter and with the live surface of a large mesh (a 6x5x4 grid: 120 cells)."""
    from mathutils import Vector

    reset.surface_above = 100 if live else 100000
    try:
        root = import_mesh(generate(tmp_path, "grid", "--size", "6", "5", "4"))
        ob = cells_object(root)
        assert bool(ob.get("hbc_surface")) == live
        cells, cen = cell_arrays(ob)
        if live:  # the live surface holds only the boundary's cells: every cell's centroid instead
            from hybrid_base_complex.plan import inspection as IP
            from hybrid_base_complex.plan import session

            cen = IP.cell_data(session.get(root.name))["centroid"]
            cells = np.arange(len(cen))
        lo, hi = cen.min(axis=0), cen.max(axis=0)
        assert bpy.ops.hbc.add_cut_plane() == {"FINISHED"}
        plane = reset.plane
        assert plane.empty_display_type == "CIRCLE" and reset.slice
        plane.location = tuple(float(x) for x in lo + (hi - lo) * np.array([0.43, 0.51, 0.37]))
        plane.rotation_euler = rotation

        def shown():
            bpy.context.view_layer.update()
            return evaluated_cells(cells_object(root))[1]

        def expected():
            """The cells on the -normal side of the circle as Blender draws it (world coordinates:
            the cells object sits at the origin)."""
            bpy.context.view_layer.update()
            m = plane.matrix_world
            n = np.array((m.to_3x3() @ Vector(CIRCLE_NORMAL)).normalized())
            return np.unique(cells[(cen - np.array(m.translation)) @ n < 0])

        def check():
            want, got = expected(), shown()
            assert 0 < len(want) < len(cen)
            if live:  # the surface of the kept cells: those of them that touch its boundary
                assert len(got) and np.all(np.isin(got, want)), "cells beyond the circle's plane are drawn"
            else:
                assert np.array_equal(got, want)
            return got

        before = check()
        step = float(np.min(hi - lo)) * 0.37
        m = plane.matrix_world.to_3x3()
        for axis in CIRCLE_IN_PLANE:  # within the circle's plane: the cut stays
            plane.location = Vector(plane.location) + (m @ Vector(axis)).normalized() * step
            assert np.array_equal(shown(), before), axis
        plane.location = Vector(plane.location) + (m @ Vector(CIRCLE_NORMAL)).normalized() * step
        assert not np.array_equal(check(), before)
    finally:
        reset.surface_above = 100000


def test_peeling_one_layer_leaves_the_inner_block(reset, tmp_path):
    root = import_mesh(generate(tmp_path, "grid", "--size", "10", "10", "10"))
    ob = cells_object(root)
    reset.peel = 1
    nf, cells = evaluated_cells(ob)
    assert len(cells) == 8 * 8 * 8 and nf == 6 * 8 * 8 * 8
    reset.peel = 3
    assert len(evaluated_cells(ob)[1]) == 4 * 4 * 4
    reset.peel = 0
    assert len(evaluated_cells(ob)[1]) == 1000


def test_type_filter_leaves_the_non_hex_cells(reset, tmp_path):
    from hybrid_base_complex.plan import session

    root = import_mesh(generate(tmp_path, "split", "--size", "4", "4", "4", "--split", "pyramids",
                                "--cells", "1,1,1;2,3,0"))
    types = np.asarray(session.get(root.name).mesh.cell_types)
    non_hex = np.flatnonzero(types != 0)
    assert len(non_hex) > 0
    ob = cells_object(root)
    reset.show_hex = False
    nf, cells = evaluated_cells(ob)
    assert np.array_equal(cells, non_hex)
    reset.show_pyramid = False
    assert evaluated_cells(ob)[0] == 0
    reset.show_hex = True
    assert np.array_equal(evaluated_cells(ob)[1], np.flatnonzero(types == 0))


def test_quality_range_and_colours(reset, tmp_path):
    """Pyramids of a split grid are not ideal (scaled Jacobian < 1): [0.99, 1] keeps the hexes."""
    from hybrid_base_complex.blender import inspect as I
    from hybrid_base_complex.plan import inspection as IP
    from hybrid_base_complex.plan import session
    from hybrid_base_complex.plan.native import import_hbc

    root = import_mesh(generate(tmp_path, "split", "--size", "3", "3", "3", "--split", "pyramids",
                                "--cells", "1,1,1"))
    s = session.get(root.name)
    sj = import_hbc().cell_quality(s.mesh)["scaled_jacobian"]
    ob = cells_object(root)
    reset.quality_min, reset.quality_max, reset.filter_quality = 0.99, 1.0, True
    assert np.array_equal(evaluated_cells(ob)[1], np.flatnonzero((sj >= 0.99) & (sj <= 1.0)))
    reset.color_by_quality = True
    col = np.zeros(4 * len(ob.data.loops), np.float32)
    ob.data.attributes["hbc_color"].data.foreach_get("color", col)
    assert np.allclose(col.reshape(-1, 4)[0], IP.quality_colors([sj[I.face_cells(ob.data)[0]]])[0], atol=1e-5)
    labels, counts = IP.cell_data(s)["histogram"]
    assert sum(counts) == s.num_cells and len(labels) == len(counts)


def test_blocks_and_sheets_layers_are_filtered(reset, data_dir):
    """A built block or sheet object has neither the filter attributes nor the modifier while no
    filter is on; peeling far enough (past the deepest cell) equips every one (hidden ones too: the
    sheets layer shows only the picked sheet) with all six attributes, the block attribute being
    the face's cell's component, and empties every shown one. A layer rebuilt while the filter is
    on is equipped again; one rebuilt with the filters at rest is not."""
    from hybrid_base_complex.blender import inspect as I
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.plan import inspection as IP
    from hybrid_base_complex.plan import session

    root = import_mesh(data_dir / "hybrid-base-complex" / "twistcube_s.mesh", analyze=True)
    s = session.get(root.name)
    for layer in ("components", "sheets"):
        assert bpy.ops.hbc.build_layer(layer=layer) == {"FINISHED"}
    comp = np.asarray(s.analysis.complex.cell_component)
    deepest = int(IP.cell_data(s)["depth"].max())

    def objects(layer):
        return [o for o in S.find_layer(root, layer).all_objects if o.type == "MESH"]

    def bare(ob):
        return ob.modifiers.get(I.MODIFIER) is None and not any(a in ob.data.attributes for a in I.FILTER_ATTRS)

    for layer in ("components", "sheets"):
        obs = objects(layer)
        assert obs and all(o.get("hbc_inspect") and bare(o) for o in obs), layer
    before = sum(evaluated_cells(o)[0] for o in objects("components"))
    assert before > 0
    reset.peel = deepest + 1
    for layer in ("components", "sheets"):
        obs = objects(layer)
        assert all(I.is_equipped(o) and o.modifiers[I.MODIFIER].show_viewport for o in obs), layer
        ob = obs[0]
        block = np.zeros(len(ob.data.polygons), np.int32)
        ob.data.attributes["hbc_component"].data.foreach_get("value", block)
        assert np.array_equal(block, comp[I.face_cells(ob.data)])
        shown = [o for o in obs if not o.hide_viewport]
        assert shown, layer
        assert sum(evaluated_cells(o)[0] for o in shown) == 0, layer
    assert I.ensure_equipped(objects("components")[0], s) is False  # idempotent
    reset.enabled = False
    assert sum(evaluated_cells(o)[0] for o in objects("components")) == before
    reset.enabled = True
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    assert all(I.is_equipped(o) for o in objects("components"))
    assert sum(evaluated_cells(o)[0] for o in objects("components")) == 0
    reset.peel = 0
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    assert all(bare(o) for o in objects("components"))
    assert sum(evaluated_cells(o)[0] for o in objects("components")) == before


def test_live_surface_of_a_large_mesh(reset, tmp_path):
    """Above `surface_above` cells the direct view holds only the surface of the kept cells, rebuilt
    by C++ when a filter changes or the plane moves: counts on a 10x10x10 grid (cell centroids at
    integer + 1/2 along each axis, in grid units)."""
    from hybrid_base_complex.blender import inspect as I

    reset.surface_above = 100
    try:
        root = import_mesh(generate(tmp_path, "grid", "--size", "10", "10", "10"))
        ob = cells_object(root)
        assert ob.get("hbc_surface") and ob.modifiers.get(I.MODIFIER) is None
        assert evaluated_cells(ob)[0] == 600  # the boundary of the whole grid
        reset.peel = 1
        nf, cells = evaluated_cells(cells_object(root))
        assert nf == 6 * 64 and len(cells) == 8 ** 3 - 6 ** 3
        reset.peel = 0
        _, cen = cell_arrays(cells_object(root))
        lo, hi = cen.min(axis=0), cen.max(axis=0)
        # Halfway: the 5 layers with centroid x below the plane, a 5x10x10 box: 2 (50 + 50 + 100) faces.
        I.add_plane(bpy.context, tuple(lo + (hi - lo) * 0.5), (1, 0, 0))
        assert evaluated_cells(cells_object(root))[0] == 400
        reset.flip = True
        assert evaluated_cells(cells_object(root))[0] == 400
        reset.flip = False
        # Dragging the plane (the depsgraph handler rebuilds): 3 layers left, 2 (30 + 30 + 100) faces.
        reset.plane.location.x = float(lo[0] + (hi[0] - lo[0]) * 0.25)
        bpy.context.view_layer.update()
        assert evaluated_cells(cells_object(root))[0] == 320
        reset.show_hex = False
        assert evaluated_cells(cells_object(root))[0] == 0
    finally:
        reset.surface_above = 100000


def test_picked_sheet_only_follows_the_pick(reset, data_dir):
    """'Picked sheet only' keeps exactly the picked sheet's cells in the direct view; picking
    another sheet in the list (Scene.hbc.sheet_index) moves the attribute and the view with it."""
    from hybrid_base_complex.plan import session

    root = import_mesh(data_dir / "hybrid-base-complex" / "twistcube_s.mesh", analyze=True)
    s = session.get(root.name)
    st = bpy.context.scene.hbc
    st.auto_show = False
    st.sheet_index = 0
    assert bpy.ops.hbc.build_layer(layer="direct") == {"FINISHED"}
    reset.sheet_only = True
    for sheet in (0, 1, 2):
        st.sheet_index = sheet
        bpy.context.view_layer.update()
        shown = evaluated_cells(cells_object(root))[1]
        assert np.array_equal(shown, np.sort(s.sheet_cells(sheet))), sheet
