"""Looking inside a mesh (issue 17): HexaLab's slicing plane, peeling, cell-type and quality filters,
applied to every cell-based layer (the direct view's cells, the blocks, the sheets), live in the
viewport, and the quality colour map of the direct view.

How it works:
- Per-face attributes. Every soup face knows the mesh cell it was taken from (`hbc_cell`, from
  hbc.block_soup's face_cell, written by scene.py). `equip_layer` copies per-cell arrays computed
  in C++ (hbc.cell_quality, hbc.cell_depth, hbc.cell_centroids, the analysis' cell_component and
  the picked sheet's cells) onto the faces, as FACE attributes: `hbc_cell_type` (int, CellType),
  `hbc_quality` (float, scaled Jacobian), `hbc_depth` (int), `hbc_block` (int, component id, -1
  without an analysis), `hbc_in_sheet` (int 0/1: the cell is in the picked sheet; rewritten when
  another sheet is picked), `hbc_centroid` (float vector, the cell's vertex centroid, in the object's coordinates).
- Filters. One shared geometry-nodes group (`HBC Inspect`) on every equipped object deletes the
  faces whose cell is hidden: centroid on the far side of the plane (the +Z side of the plane
  Empty, read with Object Info relative to the object; `Flip` swaps the sides), depth < `Peel`, cell
  type not in the `Types` bit mask (bit t for CellType t: 1 hex, 2 tet, 4 prism, 8 pyramid, 16
  polyhedron), scaled Jacobian outside [`Quality Min`, `Quality Max`] when `Filter Quality` is on,
  cell outside the picked sheet when `Sheet Only` is on.
  Moving or turning the Empty re-evaluates the modifier (a depsgraph relation), so the cut follows
  the drag; the panel's settings (Scene.hbc_inspect) set the modifier inputs of every equipped
  object of the active mesh through their update callbacks.
- Large meshes. Above `surface_above` cells (Scene.hbc_inspect, 100 000) the direct view's cells
  object is a live surface instead: only the surface of the kept cells, made by C++
  (hbc.kept_surface_soup) from a mask computed here with the same rules, and rebuilt by the
  update callbacks and, when the plane moves, by a depsgraph handler. The node group over every
  cell costs seconds per move at 10^6 cells; the live surface well under 0.2 s
  (blender_scripts/bench_addon.py --inspect).
- The cut. A cell is kept or hidden whole, by its centroid: the cells the plane crosses whose
  centroid is on the near side keep all their faces, so the cut surface is made of whole cells
  standing out of the plane by up to half a cell (HexaLab's look), never of sliced polygons. On the
  blocks and sheets layers a face is judged by the cell it was taken from, so a block is opened
  along the same cells and shows its inside.
- Quality colours. The direct view's cells can be coloured by the scaled Jacobian with viridis
  (perceptually uniform and readable with the common colour-vision deficiencies), sampled from
  matplotlib's table (CC0) at 9 points and interpolated linearly: 0 (and inverted cells, < 0) dark
  purple, 1 (ideal) yellow.
"""

import bpy
import numpy as np
from bpy.props import BoolProperty, FloatProperty, FloatVectorProperty, IntProperty, PointerProperty

from . import compat
from . import planning as P
from . import scene as S
from . import session

GROUP = "HBC Inspect"
GROUP_VERSION = 2
MODIFIER = "HBC Inspect"
CELL_ATTR = S.CELL_ATTR
INSPECT_LAYERS = ("direct", "blocks", "sheets", "sheet", "subsheets")
TYPE_NAMES = P.CELL_TYPE_NAMES
ALL_TYPES = (1 << len(TYPE_NAMES)) - 1

#: viridis (matplotlib's _viridis_data, CC0) at entries 0, 32, ..., 224, 255: sRGB.
VIRIDIS_SRGB = np.array([
    (0.267004, 0.004874, 0.329415),
    (0.278826, 0.175490, 0.483397),
    (0.229739, 0.322361, 0.545706),
    (0.172719, 0.448791, 0.557885),
    (0.127568, 0.566949, 0.550556),
    (0.157851, 0.683765, 0.501686),
    (0.369214, 0.788888, 0.382914),
    (0.678489, 0.863742, 0.189503),
    (0.993248, 0.906157, 0.143936),
])
HIST_BINS = 10  # over [0, 1], plus one bin for inverted cells (< 0)
LEGEND_VALUES = (0.0, 0.25, 0.5, 0.75, 1.0)


def quality_colors(sj) -> np.ndarray:
    """Linear RGBA (n, 4) float32 of scaled Jacobians: viridis over [0, 1], clamped."""
    t = np.clip(np.nan_to_num(np.asarray(sj, np.float64), nan=0.0), 0.0, 1.0)
    x = np.linspace(0.0, 1.0, len(VIRIDIS_SRGB))
    rgb = np.stack([np.interp(t, x, VIRIDIS_SRGB[:, k]) for k in range(3)], axis=-1)
    out = np.ones(t.shape + (4,), np.float32)
    out[..., :3] = P.srgb_to_linear(rgb)
    return out


def quality_histogram(sj):
    """(labels, counts): inverted cells, then HIST_BINS equal bins over [0, 1]."""
    sj = np.asarray(sj, np.float64)
    counts = [int(np.sum(sj < 0))] + np.histogram(np.clip(sj[sj >= 0], 0, 1), HIST_BINS, (0.0, 1.0))[0].tolist()
    edges = np.linspace(0, 1, HIST_BINS + 1)
    labels = ["< 0"] + [f"{edges[i]:.1f}-{edges[i + 1]:.1f}" for i in range(HIST_BINS)]
    return labels, counts


# ---------------------------------------------------------------------------------------------
# Per-cell data (C++), cached on the Structure for as long as its analysis is the same

def _hbc():
    from .structure import import_hbc

    return import_hbc()


def cell_data(s) -> dict:
    cache = getattr(s, "_hbc_inspect", None)
    if cache is not None and cache["analysis"] is s.analysis:
        return cache
    hbc = _hbc()
    nc = s.num_cells
    block = (np.asarray(s.analysis.complex.cell_component, np.int32) if s.analysis is not None
             else np.full(nc, -1, np.int32))
    cache = {
        "analysis": s.analysis,
        "type": np.asarray(s.mesh.cell_types, np.int32),
        "quality": np.asarray(hbc.cell_quality(s.mesh)["scaled_jacobian"], np.float32),
        "depth": np.asarray(hbc.cell_depth(s.mesh), np.int32),
        "centroid": (np.asarray(hbc.cell_centroids(s.mesh), np.float64) * s.scale).astype(np.float32),
        "block": block,
    }
    cache["histogram"] = quality_histogram(cache["quality"])
    s._hbc_inspect = cache
    return cache


def sheet_mask(s, sheet: int) -> np.ndarray:
    """(nc,) int32: 1 for the cells of `sheet` (none when there is no such sheet)."""
    mask = np.zeros(s.num_cells, np.int32)
    if s.analysis is not None and 0 <= sheet < s.num_sheets:
        mask[np.asarray(s.sheet_cells(sheet), np.int64)] = 1
    return mask


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
    sock("NodeSocketInt", "Types", ALL_TYPES)
    sock("NodeSocketBool", "Filter Quality", False)
    sock("NodeSocketFloat", "Quality Min", -1.0)
    sock("NodeSocketFloat", "Quality Max", 1.0)
    sock("NodeSocketBool", "Sheet Only", False)
    compat.group_socket(ng, "OUTPUT", "NodeSocketGeometry", "Geometry")
    compat.mark_modifier_group(ng)
    gi, go = ng.nodes.new("NodeGroupInput"), ng.nodes.new("NodeGroupOutput")
    g = gi.outputs
    # Slice: the far side is where the plane's +Z points.
    info = ng.nodes.new("GeometryNodeObjectInfo")
    info.transform_space = "RELATIVE"
    ng.links.new(g["Plane"], info.inputs["Object"])
    normal = compat.rotate_by_object_rotation(ng, (0.0, 0.0, 1.0), info.outputs["Rotation"])
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


def _face_cells(me) -> np.ndarray:
    cells = np.zeros(len(me.polygons), np.int32)
    me.attributes[CELL_ATTR].data.foreach_get("value", cells)
    return cells


def _set_attr(me, name, kind, values):
    attr = me.attributes.get(name) or me.attributes.new(name, kind, "FACE")
    key = "vector" if kind == "FLOAT_VECTOR" else "value"
    attr.data.foreach_set(key, np.ascontiguousarray(values).ravel())


def write_attributes(me, data, in_sheet):
    """The per-face attributes of a mesh with `hbc_cell`, copied from the per-cell arrays."""
    cells = _face_cells(me)
    _set_attr(me, "hbc_cell_type", "INT", data["type"][cells])
    _set_attr(me, "hbc_quality", "FLOAT", data["quality"][cells])
    _set_attr(me, "hbc_depth", "INT", data["depth"][cells])
    _set_attr(me, "hbc_block", "INT", data["block"][cells])
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


def equip_layer(tx, coll, layer, s, st):
    """Hook after a layer is built: equips every cell-based object of the layer (not highlights)."""
    # The per-cell arrays come from the hbc module: stand-in meshes (tests' fakes) get no filters.
    if layer not in INSPECT_LAYERS or not isinstance(s.mesh, _hbc().Mesh):
        return 0
    obs = [ob for ob in S.objects_in(coll) if ob.type == "MESH" and CELL_ATTR in ob.data.attributes
           and ob.get("hbc_highlight") is None]
    if not obs:
        return 0
    data = cell_data(s)
    sheet = int(getattr(st, "sheet_index", -1))
    in_sheet = sheet_mask(s, sheet)
    for ob in obs:
        equip_object(tx, ob, data, in_sheet)
        ob["hbc_in_sheet_of"] = sheet
    return len(obs)


def cell_soup(s, shrink=0.0) -> P.Soup:
    """Every cell with all its faces (hbc.block_soup 'cells', C++), positions scaled like s.points."""
    soup = P.Soup.from_dict(_hbc().block_soup(s.mesh, s.analysis, "cells", shrink=float(shrink)))
    if s.scale != 1.0:
        soup.positions = soup.positions * np.float32(s.scale)
    return soup


def cell_colors(s, soup, by_quality: bool) -> np.ndarray:
    """Per-face colours of a cell soup: quality colour map, or the cell-type colours."""
    if by_quality:
        return quality_colors(cell_data(s)["quality"][soup.face_cell])
    return s.cell_type_colors(soup.face_cell)


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
        soup = surface_soup(s, kept_cells(s, ins, None), shrink)
    else:
        soup = cell_soup(s, shrink)
    S.soup_object(tx, coll, f"{name} cells", soup, cell_colors(s, soup, ins.color_by_quality), None, props)
    return 1


# ---------------------------------------------------------------------------------------------
# Live surface: for large meshes the direct view's cells are not all in Blender; the filters are
# applied to the cells here (numpy masks over the per-cell arrays) and C++ rebuilds the surface of
# the kept cells (hbc.kept_surface_soup), which replaces the object's mesh. Same rules as the node
# group: a cell is hidden whole, by its centroid, depth, type and scaled Jacobian.

def _placement(ob):
    """ob's matrix now: matrix_world lags behind a moved object until the depsgraph evaluates, its
    own location/rotation/scale (matrix_basis) do not."""
    return ob.matrix_basis if ob.parent is None else ob.matrix_world


def _relative(ob, plane):
    return _placement(ob).inverted() @ _placement(plane) if ob is not None else _placement(plane)


def plane_in(ob, plane):
    """(point, unit normal) of the plane Empty in ob's coordinates (Object Info's Relative)."""
    from mathutils import Vector

    rel = _relative(ob, plane)
    n = rel.to_quaternion() @ Vector((0.0, 0.0, 1.0))
    return np.array(rel.translation, np.float64), np.array(n, np.float64)


def kept_cells(s, ins, ob) -> np.ndarray:
    """(nc,) bool: the cells the settings keep, as the node group decides for faces."""
    data = cell_data(s)
    keep = np.ones(s.num_cells, bool)
    if not ins.enabled:
        return keep
    if ins.slice and ins.plane is not None:
        p, n = plane_in(ob, ins.plane)
        far = (data["centroid"] - p.astype(np.float32)) @ n.astype(np.float32) > 0
        keep &= far == bool(ins.flip)
    if ins.peel > 0:
        keep &= data["depth"] >= ins.peel
    if type_mask(ins) != ALL_TYPES:
        keep &= ((type_mask(ins) >> data["type"]) & 1).astype(bool)
    if ins.sheet_only:
        keep &= sheet_mask(s, _picked_sheet()).astype(bool)
    if ins.filter_quality:
        keep &= (data["quality"] >= ins.quality_min) & (data["quality"] <= ins.quality_max)
    return keep


def surface_soup(s, keep, shrink=0.0) -> P.Soup:
    soup = P.Soup.from_dict(_hbc().kept_surface_soup(s.mesh, np.asarray(keep, np.uint8), shrink=float(shrink)))
    if s.scale != 1.0:
        soup.positions = soup.positions * np.float32(s.scale)
    return soup


def _surface_key(ob, ins):
    """What the surface depends on beyond the settings' update callbacks: the plane's placement."""
    if ins.plane is None:
        return ()
    return tuple(round(x, 7) for row in _relative(ob, ins.plane) for x in row)


def refresh_surface(ob, s, ins):
    """Rebuilds a live surface object's mesh for the current settings."""
    soup = surface_soup(s, kept_cells(s, ins, ob), ob.get("hbc_shrink", 0.0))
    old = ob.data
    with S.Transaction() as tx:
        me = S._mesh_from_soup(tx, old.name, soup, cell_colors(s, soup, ins.color_by_quality))
    S.set_materials(me, list(old.materials))
    write_attributes(me, cell_data(s), sheet_mask(s, _picked_sheet()))
    ob["hbc_in_sheet_of"] = _picked_sheet()
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
    root = _active_root(context)
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


def _picked_sheet() -> int:
    return int(getattr(getattr(bpy.context.scene, "hbc", None), "sheet_index", -1))


def follow_picked_sheet(context=None):
    """Rewrites `hbc_in_sheet` of the objects built for another sheet than the picked one (the
    sheet list's pick changes Scene.hbc.sheet_index, which the depsgraph handler notices)."""
    if _REFRESHING:
        return
    context = context or bpy.context
    root = _active_root(context)
    s = session.get(root.name) if root is not None else None
    if s is None:
        return
    sheet, mask = _picked_sheet(), None
    for ob in inspected_objects(root):
        if ob.get("hbc_in_sheet_of", -1) == sheet:
            continue
        mask = sheet_mask(s, sheet) if mask is None else mask
        _set_attr(ob.data, "hbc_in_sheet", "INT", mask[_face_cells(ob.data)])
        ob["hbc_in_sheet_of"] = sheet
        ob.data.update()
        if ob.get("hbc_surface"):
            refresh_surface(ob, s, settings(context.scene))


@bpy.app.handlers.persistent  # kept when a file is opened
def _on_depsgraph(scene, depsgraph=None):
    """Dragging the plane: rebuild the live surfaces when it moved; a newly picked sheet: its
    membership attribute."""
    ins = getattr(scene, "hbc_inspect", None)
    if ins is None:
        return
    try:
        follow_picked_sheet(bpy.context)
        if ins.plane is not None and ins.direct_cells:
            refresh_all(bpy.context, only_moved=True)
    except Exception as e:  # noqa: BLE001 - a handler cannot report; the surface stays as it was
        print(f"hbc: live surface: {e}")


# ---------------------------------------------------------------------------------------------
# Settings -> modifiers

def type_mask(ins) -> int:
    return sum(1 << t for t, n in enumerate(TYPE_NAMES) if getattr(ins, f"show_{n}"))


def filter_values(ins) -> dict:
    """The modifier inputs for the settings Scene.hbc_inspect holds."""
    return {"Plane": ins.plane, "Slice": bool(ins.slice and ins.plane is not None), "Flip": bool(ins.flip),
            "Peel": int(ins.peel), "Types": type_mask(ins), "Filter Quality": bool(ins.filter_quality),
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


def apply_to_object(ob, ins):
    if ins is not None and not ob.get("hbc_surface"):
        set_filters(ob, filter_values(ins), ins.enabled)


def inspected_objects(root):
    return [ob for ob in S.objects_in(root) if ob.get("hbc_inspect")] if root is not None else []


def _active_root(context):
    from .operators import active_root

    return active_root(context)


def apply(context=None):
    """Pushes Scene.hbc_inspect into the modifier of every equipped object of the active mesh."""
    context = context or bpy.context
    ins = settings(context.scene)
    for ob in inspected_objects(_active_root(context)):
        apply_to_object(ob, ins)
    refresh_all(context)


def recolor(context=None):
    """Direct-view cells: quality colours or cell-type colours, from their face attributes."""
    context = context or bpy.context
    ins = settings(context.scene)
    for ob in inspected_objects(_active_root(context)):
        if ob.get("hbc_part") != "cells" or ob.get("hbc_surface"):
            continue
        me = ob.data
        n = len(me.polygons)
        if ins.color_by_quality:
            q = np.zeros(n, np.float32)
            me.attributes["hbc_quality"].data.foreach_get("value", q)
            fc = quality_colors(q)
        else:
            t = np.zeros(n, np.int32)
            me.attributes["hbc_cell_type"].data.foreach_get("value", t)
            fc = P.CELL_TYPE_COLORS[t]
        sizes = np.zeros(n, np.int32)
        me.polygons.foreach_get("loop_total", sizes)
        me.attributes[S.COLOR_ATTR].data.foreach_set("color", np.repeat(fc, sizes, axis=0).ravel())
        me.update()


def plane_rotation(normal):
    """Euler rotation turning +Z onto `normal`."""
    from mathutils import Vector

    return Vector((0.0, 0.0, 1.0)).rotation_difference(Vector(normal).normalized()).to_euler()


def add_plane(context, location, normal=(0.0, 0.0, 1.0), size=1.0):
    """An Empty (single arrow: the normal, pointing to the hidden side) used as the slicing plane."""
    ob = bpy.data.objects.new("HBC cut plane", None)
    ob.empty_display_type = "SINGLE_ARROW"
    ob.empty_display_size = size
    ob.location = location
    ob.rotation_euler = plane_rotation(normal)
    context.scene.collection.objects.link(ob)
    ins = settings(context.scene)
    ins.plane = ob
    ins.slice = True
    return ob


# ---------------------------------------------------------------------------------------------
# Operators, properties, panel

def _upd(self, context):
    apply(context)


def _upd_color(self, context):
    recolor(context)
    refresh_all(context)


def _upd_cells(self, context):
    """Showing the cells needs the direct view rebuilt (with its cells object)."""
    from . import layers

    root = _active_root(context)
    s = session.get(root.name) if root is not None else None
    if s is not None and S.find_layer(root, "direct") is not None:
        layers.build_layer(root, "direct", s, context.scene.hbc)


class HBCInspectSettings(bpy.types.PropertyGroup):
    enabled: BoolProperty(name="Filters", default=True, update=_upd,
                          description="Apply the inspection filters to the cell-based layers")
    direct_cells: BoolProperty(name="Cells in direct view", default=False, update=_upd_cells,
                               description="Show every cell in the direct view (to look inside)")
    color_by_quality: BoolProperty(name="Colour by quality", default=False, update=_upd_color,
                                   description="Colour the direct view's cells by scaled Jacobian (viridis)")
    plane: PointerProperty(name="Plane", type=bpy.types.Object, update=_upd,
                           description="Empty whose XY plane cuts; cells on its +Z side are hidden")
    slice: BoolProperty(name="Slice", default=False, update=_upd)
    flip: BoolProperty(name="Flip", default=False, update=_upd, description="Hide the other side")
    peel: IntProperty(name="Peel", default=0, min=0, soft_max=20, update=_upd,
                      description="Hide the cells fewer than this many layers from the boundary")
    show_hex: BoolProperty(name="Hex", default=True, update=_upd)
    show_tet: BoolProperty(name="Tet", default=True, update=_upd)
    show_prism: BoolProperty(name="Prism", default=True, update=_upd)
    show_pyramid: BoolProperty(name="Pyramid", default=True, update=_upd)
    show_polyhedron: BoolProperty(name="Polyhedron", default=True, update=_upd)
    filter_quality: BoolProperty(name="Quality range", default=False, update=_upd,
                                 description="Show only the cells whose scaled Jacobian is in [min, max]")
    quality_min: FloatProperty(name="Min", default=-1.0, min=-1.0, max=1.0, update=_upd)
    quality_max: FloatProperty(name="Max", default=1.0, min=-1.0, max=1.0, update=_upd)
    sheet_only: BoolProperty(name="Picked sheet only", default=False, update=_upd,
                             description="Show only the cells of the sheet picked in the sheet list")
    surface_above: IntProperty(name="Live surface above", default=100000, min=0,
                               description="Meshes with more cells show only the surface of the kept cells in "
                                           "the direct view, rebuilt in C++ when a filter or the plane changes "
                                           "(fast for 10^6 cells); smaller ones hold every cell, filtered by "
                                           "geometry nodes")
    # Legend swatches: the colour map at LEGEND_VALUES (display only).
    for _i, _c in enumerate(quality_colors(LEGEND_VALUES)):
        __annotations__[f"legend_{_i}"] = FloatVectorProperty(
            name=f"{LEGEND_VALUES[_i]:.2f}", subtype="COLOR", size=3, min=0.0, max=1.0,
            default=tuple(float(x) for x in _c[:3]))
    del _i, _c


class HBC_OT_add_cut_plane(bpy.types.Operator):
    bl_idname = "hbc.add_cut_plane"
    bl_label = "Add cut plane"
    bl_description = "Add an Empty through the mesh centre as the slicing plane (move and turn it)"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        root = _active_root(context)
        s = session.get(root.name) if root is not None else None
        if s is None:
            self.report({"ERROR"}, "No mesh in memory")
            return {"CANCELLED"}
        lo, hi = s.points.min(axis=0), s.points.max(axis=0)
        add_plane(context, tuple(float(x) for x in (lo + hi) / 2), size=float(np.max(hi - lo)) * 0.3)
        return {"FINISHED"}


class HBC_PT_inspect(bpy.types.Panel):
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Hex Structure"
    bl_idname = "HBC_PT_inspect"
    bl_label = "Look inside"
    bl_parent_id = "HBC_PT_main"

    @classmethod
    def poll(cls, context):
        return _active_root(context) is not None

    def draw(self, context):
        layout = self.layout
        ins = settings(context.scene)
        row = layout.row(align=True)
        row.prop(ins, "enabled")
        row.prop(ins, "direct_cells")
        box = layout.box()
        row = box.row(align=True)
        row.prop(ins, "slice")
        row.prop(ins, "flip")
        row = box.row(align=True)
        row.prop(ins, "plane", text="")
        row.operator("hbc.add_cut_plane", text="", icon="ADD")
        box.prop(ins, "peel")
        box.prop(ins, "surface_above")
        row = box.row(align=True)
        for n in TYPE_NAMES:
            row.prop(ins, f"show_{n}", toggle=True)
        row = box.row(align=True)
        row.prop(ins, "filter_quality")
        row.prop(ins, "quality_min")
        row.prop(ins, "quality_max")
        box.prop(ins, "sheet_only")
        self.draw_quality(layout, context, ins)

    @staticmethod
    def draw_quality(layout, context, ins):
        box = layout.box()
        box.prop(ins, "color_by_quality")
        box.label(text="Scaled Jacobian (viridis): " + "  ".join(f"{v:.2f}" for v in LEGEND_VALUES))
        row = box.row(align=True)
        for i in range(len(LEGEND_VALUES)):
            row.prop(ins, f"legend_{i}", text="")
        root = _active_root(context)
        s = session.get(root.name) if root is not None else None
        cache = getattr(s, "_hbc_inspect", None) if s is not None else None
        if cache is None:
            box.label(text="Histogram: build a layer first")
            return
        labels, counts = cache["histogram"]
        top = max(max(counts), 1)
        col = box.column(align=True)
        for label, c in zip(labels, counts):
            col.label(text=f"{label:>8}  {'█' * int(round(20 * c / top)):<20} {c}")


classes = (HBCInspectSettings, HBC_OT_add_cut_plane, HBC_PT_inspect)


def register_props():
    bpy.types.Scene.hbc_inspect = PointerProperty(type=HBCInspectSettings)
    bpy.app.handlers.depsgraph_update_post.append(_on_depsgraph)


def unregister_props():
    if _on_depsgraph in bpy.app.handlers.depsgraph_update_post:
        bpy.app.handlers.depsgraph_update_post.remove(_on_depsgraph)
    del bpy.types.Scene.hbc_inspect
