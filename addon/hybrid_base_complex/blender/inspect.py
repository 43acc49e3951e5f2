"""Looking inside a mesh in Blender: HexaLab's slicing plane, peeling, cell-type and quality
filters, applied to every cell-based layer (the direct view's cells, the components, the sheets), live
in the viewport, and the quality colour map of the direct view. What is decided without Blender
(colour map, histogram, per-cell arrays, kept-cells mask) is in plan/inspection.py; the settings,
the operator and the panel are in ui/.

How it works:
- Per-face attributes. Every soup face knows the mesh cell it was taken from (`hbc_cell`, from
  hbc.block_soup's face_cell, written by scene.py). `ensure_equipped` copies per-cell arrays computed
  in C++ (hbc.cell_quality, hbc.cell_depth, hbc.cell_centroids, the analysis' cell_component and
  the picked sheet's cells) onto the faces, as FACE attributes: `hbc_cell_type` (int, CellType),
  `hbc_quality` (float, scaled Jacobian), `hbc_depth` (int), `hbc_component` (int, component id, -1
  without an analysis), `hbc_in_sheet` (int 0/1: the cell is in the picked sheet; rewritten when
  another sheet is picked), `hbc_centroid` (float vector, the cell's vertex centroid, in the object's coordinates).
  A build only marks its cell-based objects (`hbc_inspect`); the attributes and the modifier come
  when a filter that can hide a face is first switched on (`apply_to_object`), or at the build when
  one already is: written at every build they cost 0.24 s and a quarter of the 10^6-cell Components
  mesh (copied again by the depsgraph in 3.4) that most builds never use. A rebuilt layer is
  refilled in place: its meshes lose the attributes and its objects the modifier, so it is
  equipped again by the same rule.
- Filters. One shared geometry-nodes group (`HBC Inspect`) on every equipped object deletes the
  faces whose cell is hidden: centroid on the far side of the plane (the side of the plane Empty's
  local +Y axis, CUT_AXIS: the normal of the circle Blender draws for it; read with Object Info
  relative to the object; `Flip` swaps the sides), depth < `Peel`, cell
  type not in the `Types` bit mask (bit t for CellType t: 1 hex, 2 tet, 4 prism, 8 pyramid, 16
  polyhedron), scaled Jacobian outside [`Quality Min`, `Quality Max`] when `Filter Quality` is on,
  cell outside the picked sheet when `Sheet Only` is on. While no setting can hide a face the
  modifier is switched off (`filters_hide_anything`), so an unfiltered layer costs no evaluation.
  Moving or turning the Empty re-evaluates the modifier (a depsgraph relation), so the cut follows
  the drag; the panel's settings (Scene.hbc_inspect) set the modifier inputs of every equipped
  object of the active mesh through their update callbacks (ui/properties.py).
- Large meshes. Above `surface_above` cells (Scene.hbc_inspect, 100 000) the direct view's cells
  object is a live surface instead: only the surface of the kept cells, made by C++
  (hbc.kept_surface_soup) from a mask computed with the same rules (plan/inspection.kept_cells),
  and rebuilt by the update callbacks and, when the plane moves, by a depsgraph handler
  (ui/handlers.py). The node group over every cell costs seconds per move at 10^6 cells; the live
  surface well under 0.2 s (blender_scripts/bench_addon.py --inspect).
- The cut. A cell is kept or hidden whole, by its centroid: the cells the plane crosses whose
  centroid is on the near side keep all their faces, so the cut surface is made of whole cells
  standing out of the plane by up to half a cell (HexaLab's look), never of sliced polygons. On the
  components and sheets layers a face is judged by the cell it was taken from, so a component is
  opened along the same cells and shows its inside.
"""

import bpy
import numpy as np
from mathutils import Vector

from ..plan import inspection as IP
from ..plan import planning as P
from ..plan import session
from ..plan.native import import_hbc
from . import compat
from . import scene as S
from .context import active_root, picked_sheet

GROUP = "HBC Inspect"
GROUP_VERSION = 3  # 3: the cut's normal is CUT_AXIS (2 cut across the drawn circle, along local Z)
MODIFIER = "HBC Inspect"
CELL_ATTR = S.CELL_ATTR
#: The plane Empty's local axis normal to its cut, pointing to the hidden side. Blender draws an
#: Empty of display type CIRCLE in its local XZ plane (the circle's points at x = sin, y = 0,
#: z = cos in its draw code, 3.4 to 5.2 alike), so the cut is the plane of the circle the user
#: sees and moves: G Y moves the cut, G X and G Z slide the circle within it.
CUT_AXIS = (0.0, 1.0, 0.0)


# ---------------------------------------------------------------------------------------------
# The geometry-nodes group

def _feed(ng, sock, value):
    if isinstance(value, bpy.types.NodeSocket):
        ng.links.new(value, sock)
    else:
        sock.default_value = value


def _math(ng, op, a, b=None):
    """Math node; its inputs all share the name "Value", so they are taken by position."""
    n = ng.nodes.new("ShaderNodeMath")
    n.operation = op
    _feed(ng, n.inputs[0], a)
    if b is not None:
        _feed(ng, n.inputs[1], b)
    return n.outputs[0]


def _vmath(ng, op, a, b, out):
    n = ng.nodes.new("ShaderNodeVectorMath")
    n.operation = op
    _feed(ng, n.inputs[0], a)
    _feed(ng, n.inputs[1], b)
    return n.outputs[out]


def _named(ng, name, data_type):
    """Named Attribute output (3.x has one output per data type, all called "Attribute")."""
    n = ng.nodes.new("GeometryNodeInputNamedAttribute")
    n.data_type = data_type
    n.inputs["Name"].default_value = name
    return next(o for o in n.outputs if o.name == "Attribute" and o.enabled)


def _any(ng, *flags):
    out = flags[0]
    for f in flags[1:]:
        out = _math(ng, "MAXIMUM", out, f)
    return out


def inspect_group(tx):
    ng = bpy.data.node_groups.get(GROUP)
    if ng is not None and ng.get("hbc_group") == GROUP_VERSION:
        return ng
    ng = tx.add("node_groups", bpy.data.node_groups.new(GROUP, "GeometryNodeTree"))
    ng["hbc_group"] = GROUP_VERSION
    sock = lambda t, name, default=None: _default(compat.group_socket(ng, "INPUT", t, name), default)  # noqa: E731
    sock("NodeSocketGeometry", "Geometry")
    sock("NodeSocketObject", "Plane")
    sock("NodeSocketBool", "Slice", False)
    sock("NodeSocketBool", "Flip", False)
    sock("NodeSocketInt", "Peel", 0)
    sock("NodeSocketInt", "Types", IP.ALL_TYPES)
    sock("NodeSocketBool", "Filter Quality", False)
    sock("NodeSocketFloat", "Quality Min", -1.0)
    sock("NodeSocketFloat", "Quality Max", 1.0)
    sock("NodeSocketBool", "Sheet Only", False)
    compat.group_socket(ng, "OUTPUT", "NodeSocketGeometry", "Geometry")
    compat.mark_modifier_group(ng)
    gi, go = ng.nodes.new("NodeGroupInput"), ng.nodes.new("NodeGroupOutput")
    g = gi.outputs
    # Slice: the far side is where the plane's CUT_AXIS points.
    info = ng.nodes.new("GeometryNodeObjectInfo")
    info.transform_space = "RELATIVE"
    ng.links.new(g["Plane"], info.inputs["Object"])
    normal = compat.rotate_by_object_rotation(ng, CUT_AXIS, info.outputs["Rotation"])
    rel = _vmath(ng, "SUBTRACT", _named(ng, "hbc_centroid", "FLOAT_VECTOR"), info.outputs["Location"], "Vector")
    far = _math(ng, "GREATER_THAN", _vmath(ng, "DOT_PRODUCT", rel, normal, "Value"), 0.0)
    cut = _math(ng, "MULTIPLY", g["Slice"], _math(ng, "ABSOLUTE", _math(ng, "SUBTRACT", far, g["Flip"])))
    peeled = _math(ng, "LESS_THAN", _named(ng, "hbc_depth", "INT"), g["Peel"])
    # Bit t of Types for cell type t: floor(Types / 2^t) mod 2.
    bit = _math(ng, "MODULO", _math(ng, "FLOOR", _math(ng, "DIVIDE", g["Types"],
                                                        _math(ng, "POWER", 2.0, _named(ng, "hbc_cell_type", "INT")))), 2.0)
    typed = _math(ng, "LESS_THAN", bit, 0.5)
    q = _named(ng, "hbc_quality", "FLOAT")
    bad = _math(ng, "MULTIPLY", g["Filter Quality"],
                _any(ng, _math(ng, "LESS_THAN", q, g["Quality Min"]), _math(ng, "GREATER_THAN", q, g["Quality Max"])))
    delete = ng.nodes.new("GeometryNodeDeleteGeometry")
    delete.domain = "FACE"
    delete.mode = "ALL"
    ng.links.new(g["Geometry"], delete.inputs["Geometry"])
    outside = _math(ng, "MULTIPLY", g["Sheet Only"], _math(ng, "LESS_THAN", _named(ng, "hbc_in_sheet", "INT"), 0.5))
    ng.links.new(_any(ng, cut, peeled, typed, bad, outside), delete.inputs["Selection"])
    ng.links.new(delete.outputs["Geometry"], go.inputs["Geometry"])
    return ng


def _default(sock, value):
    if value is not None:
        sock.default_value = value
    return sock


# ---------------------------------------------------------------------------------------------
# Layers

def settings(scene=None):
    return getattr(scene or bpy.context.scene, "hbc_inspect", None)


def face_cells(me) -> np.ndarray:
    """The mesh cell (`hbc_cell`) of every face of a layer mesh."""
    cells = np.zeros(len(me.polygons), np.int32)
    me.attributes[CELL_ATTR].data.foreach_get("value", cells)
    return cells


def _set_attr(me, name, kind, values):
    attr = me.attributes.get(name) or me.attributes.new(name, kind, "FACE")
    key = "vector" if kind == "FLOAT_VECTOR" else "value"
    attr.data.foreach_set(key, np.ascontiguousarray(values).ravel())


def write_attributes(me, data, in_sheet):
    """The per-face attributes of a mesh with `hbc_cell`, copied from the per-cell arrays."""
    cells = face_cells(me)
    _set_attr(me, "hbc_cell_type", "INT", data["type"][cells])
    _set_attr(me, "hbc_quality", "FLOAT", data["quality"][cells])
    _set_attr(me, "hbc_depth", "INT", data["depth"][cells])
    _set_attr(me, "hbc_component", "INT", data["component"][cells])
    _set_attr(me, "hbc_in_sheet", "INT", in_sheet[cells])
    _set_attr(me, "hbc_centroid", "FLOAT_VECTOR", data["centroid"][cells])


def equip_object(tx, ob, data, in_sheet):
    """Writes the per-face attributes of ob's faces and adds the shared filter modifier (a live
    surface object gets no modifier: its filters are applied when its surface is rebuilt)."""
    write_attributes(ob.data, data, in_sheet)
    ob["hbc_inspect"] = True
    if ob.get("hbc_surface"):
        return
    mod = tx.modifier(ob, MODIFIER)
    ng = inspect_group(tx)
    if mod.node_group != ng:  # assigning even the same group rebuilds the scene's relations
        mod.node_group = ng
    apply_to_object(ob, settings())


FILTER_ATTRS = ("hbc_cell_type", "hbc_quality", "hbc_depth", "hbc_component", "hbc_in_sheet", "hbc_centroid")


def is_equipped(ob) -> bool:
    """Whether ob has the per-face filter attributes and (unless a live surface) the modifier."""
    attrs = ob.data.attributes
    return all(a in attrs for a in FILTER_ATTRS) and bool(ob.get("hbc_surface") or ob.modifiers.get(MODIFIER))


def _real(s) -> bool:
    # The per-cell arrays come from the hbc module: stand-in meshes (tests' fakes) get no filters.
    return s is not None and isinstance(s.mesh, import_hbc().Mesh)


def ensure_equipped(ob, s, tx=None, sheet=None) -> bool:
    """Equips a cell-based object (marked `hbc_inspect` by its build) of the mesh session `s` for
    the filters, once: True when it had to. `sheet`: the sheet whose cells `hbc_in_sheet` marks
    (default the picked one)."""
    if not ob.get("hbc_inspect") or is_equipped(ob) or not _real(s):
        return False
    sheet = picked_sheet() if sheet is None else int(sheet)
    if tx is None:
        with S.Transaction() as own:
            equip_object(own, ob, IP.cell_data(s), IP.sheet_mask(s, sheet))
    else:
        equip_object(tx, ob, IP.cell_data(s), IP.sheet_mask(s, sheet))
    ob["hbc_in_sheet_of"] = sheet
    return True


def filters_on(ins) -> bool:
    """Whether the settings can hide a face (then the layers' objects need their attributes)."""
    return ins is not None and bool(ins.enabled) and filters_hide_anything(filter_values(ins))


def equip_layer(tx, coll, layer, s, st):
    """Hook after a layer is built: marks every cell-based object of the layer (not highlights) as
    one the filters apply to, and equips them at once when a filter is already on."""
    if layer not in IP.INSPECT_LAYERS or not _real(s):
        return 0
    obs = [ob for ob in S.objects_in(coll) if ob.type == "MESH" and CELL_ATTR in ob.data.attributes
           and ob.get("hbc_highlight") is None]
    for ob in obs:
        ob["hbc_inspect"] = True
    if obs and filters_on(settings()):
        sheet = int(getattr(st, "sheet_index", -1))
        for ob in obs:
            ensure_equipped(ob, s, tx, sheet)
    return len(obs)


def equip_mesh(root) -> int:
    """Equips every cell-based object of a mesh's collection (the filters' readers call this through
    `ensure_equipped`; tests and scripts that read the attributes call it directly)."""
    s = session.get(root.name) if root is not None else None
    return sum(ensure_equipped(ob, s) for ob in inspected_objects(root))


def build_direct_cells(tx, coll, s, st, name):
    """The direct view's every cell (for looking inside), when Scene.hbc_inspect.direct_cells.
    Above `surface_above` cells, a live surface object instead (see `refresh_surface`)."""
    ins = settings()
    if ins is None or not ins.direct_cells or s.num_cells == 0:
        return 0
    shrink = float(getattr(st, "direct_shrink", 0.0))
    props = {"hbc_mesh": name, "hbc_layer": "direct", "hbc_part": "cells", "hbc_shrink": shrink}
    if s.num_cells > ins.surface_above:
        props["hbc_surface"] = True
        soup = IP.surface_soup(s, kept_cells(s, ins, None), shrink)
    else:
        soup = IP.cell_soup(s, shrink)
    S.soup_object(tx, coll, f"{name} cells", soup, IP.cell_colors(s, soup, ins.color_by_quality), None, props)
    return 1


# ---------------------------------------------------------------------------------------------
# Live surface: for large meshes the direct view's cells are not all in Blender; the filters are
# applied to the cells (plan/inspection.kept_cells: numpy masks over the per-cell arrays) and C++
# rebuilds the surface of the kept cells (hbc.kept_surface_soup), which replaces the object's
# mesh. Same rules as the node group: a cell is hidden whole, by its centroid, depth, type and
# scaled Jacobian.

def _placement(ob):
    """ob's matrix now: matrix_world lags behind a moved object until the depsgraph evaluates, its
    own location/rotation/scale (matrix_basis) do not."""
    return ob.matrix_basis if ob.parent is None else ob.matrix_world


def _relative(ob, plane):
    return _placement(ob).inverted() @ _placement(plane) if ob is not None else _placement(plane)


def plane_in(ob, plane):
    """(point, unit normal) of the plane Empty in ob's coordinates (Object Info's Relative)."""
    rel = _relative(ob, plane)
    n = rel.to_quaternion() @ Vector(CUT_AXIS)
    return np.array(rel.translation, np.float64), np.array(n, np.float64)


def kept_cells(s, ins, ob) -> np.ndarray:
    """(nc,) bool: the cells the settings keep for the object `ob` (None: the cells' own
    coordinates), with the plane Empty and the picked sheet of the scene."""
    plane = plane_in(ob, ins.plane) if ins.enabled and ins.slice and ins.plane is not None else None
    return IP.kept_cells(s, ins, plane, picked_sheet())


def _surface_key(ob, ins):
    """What the surface depends on beyond the settings' update callbacks: the plane's placement."""
    if ins.plane is None:
        return ()
    return tuple(round(x, 7) for row in _relative(ob, ins.plane) for x in row)


def refresh_surface(ob, s, ins):
    """Rebuilds a live surface object's mesh for the current settings."""
    soup = IP.surface_soup(s, kept_cells(s, ins, ob), ob.get("hbc_shrink", 0.0))
    old = ob.data
    with S.Transaction() as tx:
        me = S.mesh_from_soup(tx, old.name, soup, IP.cell_colors(s, soup, ins.color_by_quality))
    S.set_materials(me, list(old.materials))
    write_attributes(me, IP.cell_data(s), IP.sheet_mask(s, picked_sheet()))
    ob["hbc_in_sheet_of"] = picked_sheet()
    name = old.name
    ob.data = me
    bpy.data.meshes.remove(old)
    me.name = name
    ob["hbc_surface_key"] = _surface_key(ob, ins)


_REFRESHING = []


def refresh_all(context=None, only_moved=False):
    """Rebuilds the live surfaces of the active mesh (with only_moved, those whose plane moved)."""
    if _REFRESHING:
        return
    context = context or bpy.context
    ins = settings(context.scene)
    root = active_root(context)
    s = session.get(root.name) if root is not None else None
    if ins is None or s is None:
        return
    _REFRESHING.append(True)
    try:
        for ob in inspected_objects(root):
            if ob.get("hbc_surface") and not (only_moved and tuple(ob.get("hbc_surface_key", ())) == _surface_key(ob, ins)):
                refresh_surface(ob, s, ins)
    finally:
        _REFRESHING.clear()


def follow_picked_sheet(context=None):
    """Rewrites `hbc_in_sheet` of the objects built for another sheet than the picked one (the
    sheet list's pick changes Scene.hbc.sheet_index, which the depsgraph handler notices)."""
    if _REFRESHING:
        return
    context = context or bpy.context
    root = active_root(context)
    s = session.get(root.name) if root is not None else None
    if s is None:
        return
    sheet, mask = picked_sheet(), None
    for ob in inspected_objects(root):
        if ob.get("hbc_in_sheet_of", -1) == sheet:
            continue
        ob["hbc_in_sheet_of"] = sheet
        if "hbc_in_sheet" in ob.data.attributes:  # not equipped yet: equipping writes the picked sheet
            mask = IP.sheet_mask(s, sheet) if mask is None else mask
            _set_attr(ob.data, "hbc_in_sheet", "INT", mask[face_cells(ob.data)])
            ob.data.update()
        if ob.get("hbc_surface"):
            refresh_surface(ob, s, settings(context.scene))


# ---------------------------------------------------------------------------------------------
# Settings -> modifiers

def filter_values(ins) -> dict:
    """The modifier inputs for the settings Scene.hbc_inspect holds."""
    return {"Plane": ins.plane, "Slice": bool(ins.slice and ins.plane is not None), "Flip": bool(ins.flip),
            "Peel": int(ins.peel), "Types": IP.type_mask(ins), "Filter Quality": bool(ins.filter_quality),
            "Quality Min": float(ins.quality_min), "Quality Max": float(ins.quality_max),
            "Sheet Only": bool(ins.sheet_only)}


def set_filters(ob, values, enabled=True):
    """Sets the filter modifier's inputs (socket name -> value) of an equipped object."""
    mod = ob.modifiers.get(MODIFIER)
    if mod is None:
        return
    for k, v in values.items():
        if compat.get_modifier_input(mod, k) != v:
            compat.set_modifier_input(mod, k, v)
    if mod.show_viewport != bool(enabled) or mod.show_render != bool(enabled):
        mod.show_viewport = mod.show_render = bool(enabled)
    ob.update_tag()


def filters_hide_anything(values) -> bool:
    """Whether these modifier inputs can hide a face. When none can, the modifier is switched off:
    evaluating it anyway copies the whole mesh to delete nothing (1.0 s and 0.85 GB for the 4 M
    faces of a 10^6-cell mesh's Components layer in Blender 3.4, at every build and every evaluation of
    the object)."""
    return bool(values["Slice"] or values["Peel"] > 0 or values["Types"] != IP.ALL_TYPES
                or values["Filter Quality"] or values["Sheet Only"])


def apply_to_object(ob, ins, s=None):
    """Sets ob's modifier from the settings; equips ob first (with the mesh session `s`) when a
    filter can hide a face."""
    if ins is not None and not ob.get("hbc_surface"):
        values = filter_values(ins)
        on = bool(ins.enabled) and filters_hide_anything(values)
        if on and ensure_equipped(ob, s):
            return  # equip_object applied the settings
        set_filters(ob, values, on)


def inspected_objects(root):
    return [ob for ob in S.objects_in(root) if ob.get("hbc_inspect")] if root is not None else []


def apply(context=None):
    """Pushes Scene.hbc_inspect into the modifier of every equipped object of the active mesh."""
    context = context or bpy.context
    ins = settings(context.scene)
    root = active_root(context)
    s = session.get(root.name) if root is not None else None
    for ob in inspected_objects(root):
        apply_to_object(ob, ins, s)
    refresh_all(context)


def recolor(context=None):
    """Direct-view cells: quality colours or cell-type colours, from their face attributes."""
    context = context or bpy.context
    ins = settings(context.scene)
    root = active_root(context)
    s = session.get(root.name) if root is not None else None
    for ob in inspected_objects(root):
        if ob.get("hbc_part") != "cells" or ob.get("hbc_surface"):
            continue
        ensure_equipped(ob, s)  # the colours are read from the filter attributes
        if "hbc_quality" not in ob.data.attributes:
            continue
        me = ob.data
        n = len(me.polygons)
        if ins.color_by_quality:
            q = np.zeros(n, np.float32)
            me.attributes["hbc_quality"].data.foreach_get("value", q)
            fc = IP.quality_colors(q)
        else:
            t = np.zeros(n, np.int32)
            me.attributes["hbc_cell_type"].data.foreach_get("value", t)
            fc = P.CELL_TYPE_COLORS[t]
        sizes = np.zeros(n, np.int32)
        me.polygons.foreach_get("loop_total", sizes)
        me.attributes[S.COLOR_ATTR].data.foreach_set("color", np.repeat(fc, sizes, axis=0).ravel())
        me.update()


def plane_rotation(normal):
    """Euler rotation turning the plane Empty's CUT_AXIS onto `normal` (its circle then lies in the
    plane normal to `normal`)."""
    return Vector(CUT_AXIS).rotation_difference(Vector(normal).normalized()).to_euler()


def add_plane(context, location, normal=(0.0, 0.0, 1.0), size=1.0, collection=None):
    """An Empty used as the slicing plane: a circle in the plane (the side `normal`, its local +Y
    axis, points to is hidden), in
    `collection` (the mesh's own; else the scene's), selected and active so it can be moved and
    turned at once."""
    ob = bpy.data.objects.new("HBC cut plane", None)
    ob.empty_display_type = "CIRCLE"
    ob.empty_display_size = size
    ob.location = location
    ob.rotation_euler = plane_rotation(normal)
    (collection or context.scene.collection).objects.link(ob)
    view_layer = context.view_layer
    for other in view_layer.objects:
        if other.select_get():
            other.select_set(False)
    ob.select_set(True)
    view_layer.objects.active = ob
    ins = settings(context.scene)
    ins.plane = ob
    ins.slice = True
    return ob
