"""What a new user meets first, in every Blender of the matrix: a second mesh lands beside the first
with every object of it (the cells of the direct view too), the see-through boundary shows what is
inside in the add-on's Solid settings, the legend names every colour shown, and the panel,
menus and Preferences are found and read at the default sidebar width."""

import bpy
import numpy as np
import pytest

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
    assert bpy.ops.hbc.build_layer(layer="blocks") == {"FINISHED"}
    obs = [ob for ob in S.objects_in(S.find_layer(second, "blocks")) if ob.type == "MESH"]
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
    cam = bpy.data.objects.new("HBC test camera", bpy.data.cameras.new("HBC test camera"))
    scene.collection.objects.link(cam)
    cam.data.type = "ORTHO"
    cam.data.ortho_scale = float(max(hi[:2] - lo[:2])) * 1.05
    cam.location = (float(lo[0] + hi[0]) / 2, float(lo[1] + hi[1]) / 2, float(hi[2]) + 10.0)
    scene.camera = cam
    scene.render.engine = "BLENDER_WORKBENCH"
    from hybrid_base_complex.blender import compat

    compat.solid_shading(scene.display.shading)
    scene.display.shading.light = "FLAT"
    scene.view_settings.view_transform = "Standard"
    scene.render.film_transparent = True
    scene.render.resolution_x = scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "PNG"
    scene.render.filepath = str(tmp_path / f"{tag}.png")
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(scene.render.filepath)
    try:
        px = np.empty(len(img.pixels), np.float32)
        img.pixels.foreach_get(px)
    finally:
        bpy.data.images.remove(img)
    bpy.data.objects.remove(cam)
    return px.reshape(size, size, 4)


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
