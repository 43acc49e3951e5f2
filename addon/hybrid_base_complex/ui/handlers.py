"""The add-on's app handlers (ui/addon.py registers them): after undo, redo or loading a file the
layers look as they did (a file saved by an older add-on first gets this one's names and plane,
blender/upgrade.py; their colour attribute is the active and rendered one, their material the
one they were built with) and Blender's object caches of the imported meshes are fresh; the source
paths are stored the Blender way on save (blender/sources.py) with the file's layout version; and after a depsgraph update the
inspection follows the dragged cut plane and the picked sheet (blender/inspect.py). Every handler
is persistent: it stays when a file is opened."""

from __future__ import annotations

import bpy
from bpy.app.handlers import persistent

from ..blender import compat
from ..blender import inspect
from ..blender import scene as S
from ..blender import sources
from ..blender import upgrade


def _is_current(me, attr) -> bool:
    ca = me.color_attributes
    active = ca.active_color
    i = ca.render_color_index
    return active is not None and active.name == attr.name and 0 <= i < len(ca) and ca[i].name == attr.name


def relink_colors() -> int:
    """Makes `hbc_color` the active and rendered colour attribute of every layer mesh again, and its
    material the one the build gave it (`hbc_material`), where either was lost: Solid > Attribute
    draws the active colour attribute, Material Preview and renders read `hbc_color` through the
    material. Only what differs is set (setting a mesh's colour attribute makes Blender evaluate it
    again). Returns how many meshes changed."""
    changed = 0
    for me in bpy.data.meshes:
        attr = me.color_attributes.get(S.COLOR_ATTR)
        if attr is None:
            continue
        fixed = False
        if not _is_current(me, attr):
            compat.make_active_color(me, attr)
            fixed = True
        want = me.get(S.MATERIAL_PROP)
        if isinstance(want, bpy.types.Material) and list(me.materials) != [want]:
            S.set_materials(me, [want])
            fixed = True
        changed += fixed
    return changed


def refresh_caches() -> int:
    """Blender (3.4 to 4.5 seen) keeps the object cache behind `Collection.all_objects` of a
    collection an undo did not change, so it still lists objects the undo freed: reading them
    crashes or gives another object. The add-on reads no `all_objects` (scene.objects_in), and
    this refreshes the caches of every imported mesh's collection and those above it for any other
    script: a child linked and unlinked again frees them up the hierarchy."""
    roots = [c for c in bpy.data.collections if c.get("hbc_source") is not None]
    if not roots:
        return 0
    tmp = bpy.data.collections.new("HBC cache refresh")
    try:
        for coll in roots:
            coll.children.link(tmp)
            coll.children.unlink(tmp)
    finally:
        bpy.data.collections.remove(tmp)
    return len(roots)


@persistent
def on_load(*_args):
    # A file of an older add-on first gets this one's names (blender/upgrade.py), then its colours.
    try:
        done = upgrade.upgrade_file()
    except Exception as e:  # noqa: BLE001 - a handler cannot report; the file stays as it was read
        print(f"hbc: could not upgrade the file of an older add-on: {e}")
    else:
        if any(done.values()):
            print("hbc: file of an older add-on upgraded: " + ", ".join(f"{v} {k}" for k, v in done.items() if v))
    relink_colors()


@persistent
def on_undo(*_args):
    refresh_caches()
    relink_colors()


@persistent
def on_save_pre(*args):
    # Blender versions that pass the target path give it as a string argument; 3.4 passes none.
    sources.store_for_save(next((a for a in args if isinstance(a, str) and a), None))
    upgrade.stamp_file()


@persistent
def on_save_post(*_args):
    sources.store_relative()


@persistent
def on_depsgraph(scene, depsgraph=None):
    """Dragging the plane: rebuild the live surfaces when it moved; a newly picked sheet: its
    membership attribute."""
    ins = getattr(scene, "hbc_inspect", None)
    if ins is None:
        return
    try:
        inspect.follow_picked_sheet(bpy.context)
        if ins.plane is not None and ins.direct_cells:
            inspect.refresh_all(bpy.context, only_moved=True)
    except Exception as e:  # noqa: BLE001 - a handler cannot report; the surface stays as it was
        print(f"hbc: live surface: {e}")
