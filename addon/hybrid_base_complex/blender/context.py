"""What the scene holds, as the operators, panels, settings and the inspection all ask it: the
imported meshes' collections, the one the Hex Structure panel acts on, its Structure (read again
from its source when not in memory), the sheet list, which layers can be built now, and the owner
(component or sheet) picked in a merged mesh."""

from __future__ import annotations

import os

import bmesh
import bpy

from ..plan import planning as P
from ..plan import session
from . import scene as S
from . import sources


def find_root(name):
    """The collection of the imported mesh called `name`, None when there is none."""
    c = bpy.data.collections.get(name)
    return c if c is not None and c.get("hbc_source") is not None else None


def active_root(context):
    """The collection of the mesh the panel acts on: Scene.hbc.active_mesh, else the mesh of the
    active object."""
    st = context.scene.hbc
    root = find_root(st.active_mesh) if st.active_mesh else None
    if root is None:
        ob = context.active_object
        if ob is not None and ob.get("hbc_mesh"):
            root = find_root(ob["hbc_mesh"])
    return root


def structure_of(root, analyzed, log, rho=0.8):
    """The mesh's Structure, read again from its source (sources.resolve) when not in memory; a
    source found beside a moved .blend is stored as found."""
    path = sources.resolve(root)
    if os.path.normpath(bpy.path.abspath(root["hbc_source"])) != path:
        root["hbc_source"] = sources.stored(path)
    return session.ensure(root.name, path, float(root.get("hbc_scale", 1.0)),
                          float(root.get("hbc_rho", rho)), analyzed, log, tuple(root.get("hbc_offset", (0, 0, 0))),
                          bool(root.get("hbc_skip_invalid", False)))


def fill_sheet_list(settings, structure):
    """Scene.hbc's sheet list (index, type, cells, components per sheet) from an analyzed Structure."""
    settings.sheets.clear()
    if structure.analysis is None:
        return
    n = structure.num_sheets
    if n == 0:
        return
    types = structure.sheet_types()
    cells, comps = structure.sheet_sizes()
    for i in range(n):
        it = settings.sheets.add()
        it.index, it.type, it.cells, it.components = i, int(types[i]), int(cells[i]), int(comps[i])
    settings.sheet_index = min(settings.sheet_index, n - 1)


def picked_sheet() -> int:
    """The sheet picked in the list (Scene.hbc.sheet_index), -1 without the add-on's settings."""
    return int(getattr(getattr(bpy.context.scene, "hbc", None), "sheet_index", -1))


def picked_sheet_type(st):
    """Type of the sheet picked in the list, None when none is."""
    return st.sheets[st.sheet_index].type if 0 <= st.sheet_index < len(st.sheets) else None


def unavailable(context, layer):
    """Why `layer` cannot be built now (a sentence), or None."""
    if layer == "subsheets":
        return P.subsheets_unavailable(picked_sheet_type(context.scene.hbc))
    if layer == "sheet" and picked_sheet_type(context.scene.hbc) is None:
        return "Pick a sheet in the list first"
    return None


def merged_owner_faces(ob):
    """(bmesh, its `owner` face layer or None, the active face's owner or None) of a merged
    mesh in edit mode."""
    bm = bmesh.from_edit_mesh(ob.data)
    layer = bm.faces.layers.int.get(S.OWNER_ATTR)
    if layer is None:
        return bm, None, None
    face = bm.faces.active
    return bm, layer, (int(face[layer]) if face is not None else None)
