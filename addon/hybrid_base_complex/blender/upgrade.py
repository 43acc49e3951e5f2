"""A .blend saved by an older add-on, brought to this one's names when it is opened (ui/handlers.py
runs `upgrade_file` at load_post; `stamp_file` at save_pre records the layout a file is saved with).

Every scene holding the add-on's data carries `hbc_file_version`. A scene without it that holds
the add-on's data (an imported mesh, a layer, a cut plane) was saved by add-on 0.1
(version 1). Version 2 (add-on 0.2) renamed, to docs/concepts.md's words:
- the Blocks layer, which draws components: the layer key `blocks` is `components` (`hbc_layer` of
  its collections and objects), its collection `<mesh> / Blocks` is `<mesh> / Components`, its
  objects `<mesh> blocks` and `<mesh> block N` are `<mesh> components` and `<mesh> component N`;
- the face attribute `hbc_block` (a face's component) is `hbc_component`;
- the setting `Scene.hbc.boundary_alpha` is `boundary_opacity`.
And the slicing plane: up to the inspection node group's version 2 the cut's normal was the plane
Empty's local Z; since version 3 it is its local +Y (blender/inspect.CUT_AXIS, the normal of the
circle Blender draws). An old plane is turned by +90° about its local X, so that its +Y points where
its Z did and the cut stays where the user left it; the node group is rebuilt at version 3 when
the next filter asks for it. A file saved after version 3 of the group but before these stamps (its
group says 3) is not turned.
"""

from __future__ import annotations

import math

import bpy
from mathutils import Matrix, Quaternion

from ..plan import planning as P
from . import inspect
from . import scene as S

FILE_VERSION = 2
VERSION_PROP = "hbc_file_version"
#: Version 1's layer key, collection title and object name words of the components layer.
OLD_LAYER, OLD_TITLE = "blocks", "Blocks"
OLD_ATTR, NEW_ATTR = "hbc_block", "hbc_component"
OLD_SETTINGS = {"boundary_alpha": "boundary_opacity"}  # Scene.hbc fields
#: The inspection group's first version whose cut is along CUT_AXIS (+Y) rather than local Z.
Y_CUT_GROUP = 3


def _holds_addon_data(scene) -> bool:
    """An imported mesh, a layer or a cut plane (settings alone are no data: every scene has them)."""
    ins = getattr(scene, "hbc_inspect", None)
    return (any(c.get("hbc_source") is not None or c.get("hbc_layer") for c in scene.collection.children_recursive)
            or ins is not None and ins.plane is not None)


def file_version(scene) -> int:
    """The layout `scene` was saved with: its stamp, else 1 with the add-on's data, else this one."""
    v = scene.get(VERSION_PROP)
    if v is not None:
        return int(v)
    return 1 if _holds_addon_data(scene) else FILE_VERSION


def _rename_layer(coll) -> int:
    n = 0
    if coll.get("hbc_layer") == OLD_LAYER:
        coll["hbc_layer"] = "components"
        mesh = coll.get("hbc_mesh")
        if mesh is not None and coll.name == f"{mesh} / {OLD_TITLE}":
            coll.name = P.layer_collection_name(mesh, "components")
        n += 1
    for ob in coll.objects:
        if ob.get("hbc_layer") != OLD_LAYER:
            continue
        ob["hbc_layer"] = "components"
        mesh = ob.get("hbc_mesh", "")
        for old, new in ((f"{mesh} blocks", f"{mesh} components"), (f"{mesh} block ", f"{mesh} component ")):
            if ob.name == old or old.endswith(" ") and ob.name.startswith(old):
                ob.name = new + ob.name[len(old):]
                break
        n += 1
    return n


def _rename_attributes() -> int:
    n = 0
    for me in bpy.data.meshes:
        attr = me.attributes.get(OLD_ATTR)
        if attr is not None and NEW_ATTR not in me.attributes:
            attr.name = NEW_ATTR
            n += 1
    return n


def _rename_settings(scene) -> int:
    """Old fields of Scene.hbc are ID properties no RNA property reads any more: their values go to
    the new fields, and they go."""
    st = getattr(scene, "hbc", None)
    if st is None:
        return 0
    n = 0
    for old, new in OLD_SETTINGS.items():
        if old in st:
            setattr(st, new, st[old])
            del st[old]
            n += 1
    return n


def _group_cuts_along_z() -> bool:
    ng = bpy.data.node_groups.get(inspect.GROUP)
    return ng is None or int(ng.get("hbc_group", 0)) < Y_CUT_GROUP


def _renew_group() -> int:
    """A group of an older version replaced by this one's on every modifier using it (its inputs
    set again from each scene's settings); how many modifiers changed."""
    old = bpy.data.node_groups.get(inspect.GROUP)
    if old is None or int(old.get("hbc_group", 0)) >= inspect.GROUP_VERSION:
        return 0
    old.name = f"{inspect.GROUP} (version {int(old.get('hbc_group', 0))})"
    with S.Transaction() as tx:
        ng = inspect.inspect_group(tx)
    n = 0
    for scene in bpy.data.scenes:
        ins = getattr(scene, "hbc_inspect", None)
        for ob in scene.objects:
            mod = ob.modifiers.get(inspect.MODIFIER) if ob.type == "MESH" else None
            if mod is None or mod.node_group != old:
                continue
            mod.node_group = ng
            if ins is not None:
                values = inspect.filter_values(ins)
                inspect.set_filters(ob, values, bool(ins.enabled) and inspect.filters_hide_anything(values))
            n += 1
    bpy.data.node_groups.remove(old)
    return n


def turn_plane(ob) -> None:
    """Turn the Empty about its local X by +90°: its local +Y then points where its local Z did
    (R·Rx(90°)·y = R·z), its location and scale unchanged (so the +Y group cuts where the Z group did,
    with a parent too: the turn is in the Empty's own frame)."""
    loc, rot, scale = ob.matrix_basis.decompose()
    rot = rot @ Quaternion((1.0, 0.0, 0.0), math.radians(90.0))
    ob.matrix_basis = Matrix.LocRotScale(loc, rot, scale)


def upgrade_scene(scene, turned=None) -> dict:
    """Brings one scene to FILE_VERSION; returns what it changed (counts by kind). A scene of this
    version, or without the add-on's data, is left as it is (no stamp on other people's files).
    `turned`: names of plane Empties already turned (two scenes may share one)."""
    done = {"layers": 0, "attributes": 0, "settings": 0, "planes": 0}
    if file_version(scene) >= FILE_VERSION:
        return done
    turned = set() if turned is None else turned
    for coll in [scene.collection, *scene.collection.children_recursive]:
        done["layers"] += _rename_layer(coll)
    done["attributes"] += _rename_attributes()
    done["settings"] += _rename_settings(scene)
    ins = getattr(scene, "hbc_inspect", None)
    plane = ins.plane if ins is not None else None
    if plane is not None and plane.name not in turned and _group_cuts_along_z():
        turn_plane(plane)
        turned.add(plane.name)
        done["planes"] += 1
    scene[VERSION_PROP] = FILE_VERSION
    return done


def upgrade_file() -> dict:
    """Every scene of the open file brought to FILE_VERSION, then the inspection group; the totals
    of what changed."""
    total, turned = {}, set()
    for scene in bpy.data.scenes:
        for k, v in upgrade_scene(scene, turned).items():
            total[k] = total.get(k, 0) + v
    total["modifiers"] = _renew_group()
    return total


def stamp_file() -> None:
    """At save: the layout this add-on writes, on every scene that holds its data."""
    for scene in bpy.data.scenes:
        if _holds_addon_data(scene):
            scene[VERSION_PROP] = FILE_VERSION
