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


def subsheet_rule(scene=None) -> str:
    """The rule every analysis splits self-intersecting sheets by: the panel's Subsheets setting
    (Scene.hbc.subsheet_rule). The one place that decides it: import, Analyze, the layers, Export
    VTU, the Metrics box and Figures all ask here."""
    st = getattr(scene if scene is not None else bpy.context.scene, "hbc", None)
    return str(getattr(st, "subsheet_rule", "layers"))


def structure_of(root, analyzed, log, rho=0.8):
    """The mesh's Structure, read again from its source (sources.resolve) when not in memory, and
    with `analyzed` analyzed by the panel's subsheet rule (again when it was by the other); a source
    found beside a moved .blend is stored as found."""
    path, ensure = structure_request(root, analyzed, log, rho)
    s = ensure()
    structure_found(root, path, analyzed)
    return s


def structure_request(root, analyzed, log, rho=0.8):
    """(the source's path, a function giving the mesh's Structure as structure_of does): the
    function touches no Blender data (a build runs it in a worker thread); `structure_found`
    stores what it found on the mesh afterwards."""
    path = sources.resolve(root)
    args = (root.name, path, float(root.get("hbc_scale", 1.0)), float(root.get("hbc_rho", rho)), analyzed, log,
            tuple(root.get("hbc_offset", (0, 0, 0))), bool(root.get("hbc_skip_invalid", False)), subsheet_rule())
    return path, lambda: session.ensure(*args)


def structure_ready(root, analyzed) -> bool:
    """Whether structure_of would find the mesh in memory as wanted (no reading, no analysis)."""
    s = session.get(root.name)
    return s is not None and (not analyzed or (s.analysis is not None and s.subsheet_rule == subsheet_rule()))


def structure_found(root, path, analyzed, tx=None):
    """After structure_request's function: the source stored as found, stale subsheets marked
    (through the transaction `tx` when given: a cancelled build puts them back)."""
    if os.path.normpath(bpy.path.abspath(root["hbc_source"])) != path:
        if tx is not None:
            tx.set_prop(root, "hbc_source", sources.stored(path))
        else:
            root["hbc_source"] = sources.stored(path)
    if analyzed:
        refresh_subsheets_stale(root, picked_sheet(), tx)


def drawn_sheet(root):
    """The sheet the picked-sheet layer of the mesh draws (its sheet object's `hbc_sheet`: with *Show
    on pick* off it can differ from the list's pick), None while that layer is not built."""
    coll = S.find_layer(root, "sheet") if root is not None else None
    for ob in S.objects_in(coll) if coll is not None else ():
        if ob.get("hbc_sheet") is not None and ob.get("hbc_highlight") is None:
            return int(ob["hbc_sheet"])
    return None


def rule_of(root):
    """The subsheet rule of the mesh's analysis in memory, None when there is none."""
    s = session.get(root.name)
    return s.subsheet_rule if s is not None and s.analysis is not None else None


def refresh_subsheets_stale(root, sheet_index, tx=None):
    """Marks the subsheets layer stale (the panel says: rebuild) and hides it while it shows
    another sheet than the picked one, or subsheets by another rule than the analysis in memory;
    shows it again when it is current (through the transaction `tx` when given)."""
    coll = S.find_layer(root, "subsheets")
    if coll is None:
        return
    rule = rule_of(root)
    stale = (any(ob.get("hbc_sheet") != sheet_index for ob in S.objects_in(coll))
             or (rule is not None and coll.get(SUBSHEET_RULE_PROP, rule) != rule))
    if tx is not None:
        if stale != bool(coll.get("hbc_stale")):
            tx.set_attr(coll, "hide_viewport", stale)
        if coll.get("hbc_stale") is not stale:
            tx.set_prop(coll, "hbc_stale", stale)
        return
    if stale != bool(coll.get("hbc_stale")):  # hidden while stale, shown again when current
        coll.hide_viewport = stale
    coll["hbc_stale"] = stale


#: The subsheet rule a subsheets layer was built by (on its collection).
SUBSHEET_RULE_PROP = "hbc_subsheet_rule"


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


def select_owner(ob, owner) -> int:
    """Selects every face of `owner` (a component or sheet id) in a merged mesh in edit mode, one of
    them the active face; returns how many faces that is."""
    bm, layer, _ = merged_owner_faces(ob)
    if layer is None:
        return 0
    n = 0
    for f in bm.faces:
        mine = f[layer] == owner
        f.select_set(mine)
        if mine:
            if n == 0:
                bm.faces.active = f
            n += 1
    bm.select_flush_mode()
    bmesh.update_edit_mesh(ob.data)
    return n
