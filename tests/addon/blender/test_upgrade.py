"""A .blend saved by add-on 0.1 opens with add-on 0.2's names and its cut where it was
(blender/upgrade.py, run by the load_post handler).

The test makes the old file itself: it imports and analyses a split grid, builds the Components
layer, adds a cut plane and switches on the filters, then writes every renamed thing back under
its 0.1 name — the layer key `blocks`, the collection `<mesh> / Blocks`, the objects
`<mesh> block N`, the face attribute `hbc_block`, the setting `boundary_alpha`, the inspection node
group's version 2 (whose cut was along the plane Empty's local Z), no layout stamp — and saves it
without the add-on's save handler (which would stamp it). Opened again, the file must have the new
names, the panel must find the layer, the picked object must name its component, and the plane
must hide exactly the cells on the side of the old cut (its old local Z), with the Empty turned so
that its +Y is that Z."""

import bpy
import numpy as np
import pytest
from mathutils import Euler, Vector

# reset: the inspection settings as a fresh scene has them (a fixture, used by name).
from test_inspect import cell_arrays, evaluated_cells, generate, import_mesh, reset  # noqa: F401


def components_objects(root):
    from hybrid_base_complex.blender import scene as S

    coll = S.find_layer(root, "components")
    return [] if coll is None else [o for o in S.objects_in(coll) if o.type == "MESH"]


def make_old_file(path, root, plane):
    """Every name 0.2 changed written back as 0.1 wrote it; saved without the stamp."""
    from hybrid_base_complex.blender import upgrade
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.blender import inspect as I
    from hybrid_base_complex.ui import handlers

    coll = S.find_layer(root, "components")
    coll["hbc_layer"] = "blocks"
    coll.name = f"{root.name} / Blocks"
    for ob in S.objects_in(coll):
        ob["hbc_layer"] = "blocks"
        ob.name = ob.name.replace(f"{root.name} component", f"{root.name} block")
        attr = ob.data.attributes.get("hbc_component")
        if attr is not None:
            attr.name = "hbc_block"
    st = bpy.context.scene.hbc
    st["boundary_alpha"] = 0.4
    if "boundary_opacity" in st:
        del st["boundary_opacity"]
    bpy.data.node_groups[I.GROUP]["hbc_group"] = 2
    scene = bpy.context.scene
    if upgrade.VERSION_PROP in scene:
        del scene[upgrade.VERSION_PROP]
    saved = list(bpy.app.handlers.save_pre)
    bpy.app.handlers.save_pre.remove(handlers.on_save_pre)
    try:
        assert bpy.ops.wm.save_as_mainfile(filepath=str(path)) == {"FINISHED"}
    finally:
        bpy.app.handlers.save_pre.clear()
        bpy.app.handlers.save_pre.extend(saved)


def test_old_file_opens_with_new_names_and_the_same_cut(reset, tmp_path):
    from hybrid_base_complex.blender import inspect as I
    from hybrid_base_complex.blender import upgrade
    from hybrid_base_complex.blender.context import find_root
    from hybrid_base_complex.ui import panels

    root = import_mesh(generate(tmp_path, "split", "--size", "4", "3", "3", "--split", "pyramids", "--cells", "1,1,1"), analyze=True)
    st = bpy.context.scene.hbc
    st.split_max = 1000
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    obs = components_objects(root)
    assert len(obs) > 1  # one object per component: a split grid has several
    assert bpy.ops.hbc.add_cut_plane() == {"FINISHED"}
    plane = reset.plane
    cells, cen = np.concatenate([cell_arrays(o)[0] for o in obs]), np.concatenate([cell_arrays(o)[1] for o in obs])
    lo, hi = cen.min(axis=0), cen.max(axis=0)
    plane.location = tuple(float(x) for x in lo + (hi - lo) * np.array([0.43, 0.51, 0.37]))
    plane.rotation_euler = Euler((0.3, -0.5, 0.2))
    bpy.context.view_layer.update()
    # The old add-on's cut: the cells whose centroid is on the -Z side of the Empty stay.
    m = plane.matrix_world.copy()
    old_normal = (m.to_3x3() @ Vector((0.0, 0.0, 1.0))).normalized()
    kept = np.unique(cells[(cen - np.array(m.translation)) @ np.array(old_normal) < 0])
    assert 0 < len(kept) < len(np.unique(cells))
    name = root.name
    path = tmp_path / "old.blend"
    make_old_file(path, root, plane)

    assert bpy.ops.wm.open_mainfile(filepath=str(path)) == {"FINISHED"}
    scene = bpy.context.scene
    assert scene[upgrade.VERSION_PROP] == upgrade.FILE_VERSION
    root = find_root(name)
    obs = components_objects(root)  # the panel's lookup: by the layer key
    assert obs and bpy.data.collections.get(f"{name} / Components") is not None
    assert bpy.data.collections.get(f"{name} / Blocks") is None
    assert all(o["hbc_layer"] == "components" and o.name.startswith(f"{name} component") for o in obs)
    assert all("hbc_component" in o.data.attributes and "hbc_block" not in o.data.attributes for o in obs)
    assert scene.hbc.boundary_opacity == pytest.approx(0.4) and "boundary_alpha" not in scene.hbc
    # The plane: where it was, its +Y along the old Z; the group renewed on every modifier.
    plane = scene.hbc_inspect.plane
    bpy.context.view_layer.update()
    assert (plane.matrix_world.translation - m.translation).length < 1e-6
    assert (plane.matrix_world.to_3x3() @ Vector(I.CUT_AXIS)).normalized().dot(old_normal) > 1 - 1e-6
    assert bpy.data.node_groups[I.GROUP]["hbc_group"] == I.GROUP_VERSION
    assert all(o.modifiers[I.MODIFIER].node_group == bpy.data.node_groups[I.GROUP] for o in obs)
    # Filters: the same cells as the old cut kept.
    shown = np.unique(np.concatenate([evaluated_cells(o)[1] for o in obs]))
    assert np.array_equal(shown, kept)
    # Picking: the active object of the layer names its component, as the Selection panel reads it.
    ob = obs[0]
    bpy.context.view_layer.objects.active = ob
    component, kind, _ = panels.picked_component(bpy.context)
    assert kind == "component" and component == ob["hbc_component"]

    # Saved by this add-on and opened again: stamped, nothing turned a second time.
    before = plane.matrix_world.copy()
    assert bpy.ops.wm.save_as_mainfile(filepath=str(path)) == {"FINISHED"}
    assert bpy.ops.wm.open_mainfile(filepath=str(path)) == {"FINISHED"}
    plane = bpy.context.scene.hbc_inspect.plane
    assert all(abs(a - b) < 1e-6 for ra, rb in zip(plane.matrix_world, before) for a, b in zip(ra, rb))


def test_file_of_this_version_is_left_alone(reset, tmp_path):
    """A file of 0.2 with a plane is stamped at save and not turned when opened; a file without the
    add-on's data gets no stamp."""
    from hybrid_base_complex.blender import upgrade

    assert upgrade.file_version(bpy.context.scene) == upgrade.FILE_VERSION  # nothing of ours yet
    path = tmp_path / "empty.blend"
    assert bpy.ops.wm.save_as_mainfile(filepath=str(path)) == {"FINISHED"}
    assert bpy.ops.wm.open_mainfile(filepath=str(path)) == {"FINISHED"}
    assert upgrade.VERSION_PROP not in bpy.context.scene
    import_mesh(generate(tmp_path, "grid", "--size", "3", "3", "3"))
    assert bpy.ops.hbc.add_cut_plane() == {"FINISHED"}
    plane = bpy.context.scene.hbc_inspect.plane
    plane.rotation_euler = Euler((0.3, -0.5, 0.2))
    bpy.context.view_layer.update()
    before = plane.matrix_world.copy()
    path = tmp_path / "new.blend"
    assert bpy.ops.wm.save_as_mainfile(filepath=str(path)) == {"FINISHED"}
    assert bpy.ops.wm.open_mainfile(filepath=str(path)) == {"FINISHED"}
    scene = bpy.context.scene
    assert scene[upgrade.VERSION_PROP] == upgrade.FILE_VERSION
    plane = scene.hbc_inspect.plane
    assert all(abs(a - b) < 1e-6 for ra, rb in zip(plane.matrix_world, before) for a, b in zip(ra, rb))
