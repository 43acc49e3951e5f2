"""Scene building (bpy): planning Soups and Lines into Blender data, in bulk.

- Meshes: vertices.foreach_set("co"), polygons via loop_start (+ loop_total before 4.0) and the
  corners' vertices, as unsigned or signed arrays by version (compat.set_corner_verts); colours as a float colour attribute `hbc_color` (shown by
  Workbench with colour type Attribute, read by an Attribute node in Cycles/EEVEE): on the POINT
  domain when the colour is one per owner (hbc.block_soup never shares a point between owners) or
  one for all, a quarter of the memory of one per corner (16 B x 16 M corners at 10^6 cells);
  on the CORNER domain when faces of one point differ (the direct view's cells);
  the owner (cell, component, sheet, ...) a face belongs to as a FACE int attribute `owner`.
- Lines (singularity graph, wireframes, highlighted edges): a mesh of edges with a POINT colour
  attribute (alpha = opacity) and a shared geometry-nodes modifier (Mesh to Curve, Curve to Mesh)
  that makes tubes; the attribute is carried onto the tubes so the shared line material renders
  the per-point opacity.
- Every datablock made while building goes through a `Transaction`; on an exception it removes
  them all and puts back what it changed, so a failed build leaves the file as it was. A first
  build goes into an unlinked collection swapped in at the end; a rebuild refills the layer's
  objects in place (same names, links and view-layer entries; see Transaction).
"""

from __future__ import annotations

from collections import Counter
from contextlib import contextmanager

import bpy
import numpy as np
from mathutils import Matrix

from ..plan import planning as P
from ..plan.native import import_hbc
from . import compat

COLOR_ATTR = "hbc_color"
OWNER_ATTR = "owner"
CELL_ATTR = "hbc_cell"
MATERIAL_PROP = "hbc_material"  # a layer mesh's material as built (handlers put it back if lost)
TUBE_GROUP = "HBC Tube"
TUBE_GROUP_VERSION = 3  # files made with an older group get this one on their next build


# ---------------------------------------------------------------------------------------------
# Transactions

#: How foreach_get/foreach_set read each attribute type: (property, components, numpy dtype).
_ATTR_IO = {
    "FLOAT": ("value", 1, np.float32), "INT": ("value", 1, np.int32), "INT8": ("value", 1, np.int32),
    "BOOLEAN": ("value", 1, bool), "FLOAT_VECTOR": ("vector", 3, np.float32), "FLOAT2": ("vector", 2, np.float32),
    "FLOAT_COLOR": ("color", 4, np.float32), "BYTE_COLOR": ("color", 4, np.float32),
}


def _plain(value):
    """An ID property value as plain Python (arrays and groups are views into the datablock)."""
    if isinstance(value, (int, float, str)):
        return value
    if hasattr(value, "to_dict"):
        return value.to_dict()
    if hasattr(value, "to_list"):
        return value.to_list()
    return value


class _MeshState:
    """A mesh's geometry, attributes and materials, read in bulk, to put back on a rollback. Internal
    attributes (names starting with '.': selection, corner and edge maps) are Blender's own and
    follow from the geometry; the edges and each corner's edge are kept as they were (a layer's
    edges come from hbc.polygon_edges, in another order than Blender's own search)."""

    def __init__(self, me):
        nv, nl, nf, ne = len(me.vertices), len(me.loops), len(me.polygons), len(me.edges)
        self.co = np.empty(3 * nv, np.float32)
        me.vertices.foreach_get("co", self.co)
        self.edges = np.empty(2 * ne, np.int32)
        if ne:
            me.edges.foreach_get("vertices", self.edges)
        self.loops = np.empty(nl, np.int32)
        me.loops.foreach_get("vertex_index", self.loops)
        self.corner_edges = np.empty(nl if ne else 0, np.int32)
        if len(self.corner_edges):
            me.loops.foreach_get("edge_index", self.corner_edges)
        self.starts = np.empty(nf, np.int32)
        me.polygons.foreach_get("loop_start", self.starts)
        size = {"POINT": nv, "CORNER": nl, "FACE": nf}
        self.attrs = []
        for a in me.attributes:
            name = a.name
            if name[:1] == "." or name == "position":
                continue
            data_type, domain = a.data_type, a.domain
            io = _ATTR_IO.get(data_type)
            if io is None or domain not in size:
                continue
            key, width, dtype = io
            values = np.empty(size[domain] * width, dtype)
            a.data.foreach_get(key, values)
            self.attrs.append((name, data_type, domain, key, values))
        active = me.color_attributes.active_color
        self.active = active.name if active is not None else None
        self.materials = list(me.materials)

    def restore(self, me):
        me.clear_geometry()
        me.vertices.add(len(self.co) // 3)
        me.vertices.foreach_set("co", self.co)
        if len(self.edges):
            me.edges.add(len(self.edges) // 2)
            compat.set_edge_verts(me, self.edges)
        me.loops.add(len(self.loops))
        compat.set_corner_verts(me, self.loops)
        if len(self.corner_edges):
            compat.set_corner_edges(me, self.corner_edges)
        me.polygons.add(len(self.starts))
        compat.set_polygons(me, self.starts, np.diff(np.append(self.starts, len(self.loops))).astype(np.int32))
        for name, data_type, domain, key, values in self.attrs:
            attr = me.attributes.get(name) or me.attributes.new(name, data_type, domain)
            attr.data.foreach_set(key, values)
        if self.active is not None and self.active in me.color_attributes:
            compat.make_active_color(me, me.color_attributes[self.active])
        me.update(calc_edges=len(self.starts) > 0 and not len(self.edges))
        me.materials.clear()
        for mat in self.materials:
            me.materials.append(mat)


class _ObjectState:
    """What refilling an object in place changes on it (its data, its add-on properties, colour,
    visibility, placement, modifiers), to put back on a rollback."""

    def __init__(self, ob, refill_mesh: bool):
        self.ob, self.data = ob, ob.data
        self.mesh = _MeshState(ob.data) if refill_mesh else None
        self.props = {k: _plain(v) for k, v in ob.items() if k.startswith("hbc_")}
        self.color = tuple(ob.color)
        self.hidden = (ob.hide_viewport, ob.hide_render, ob.hide_select)
        self.matrix = ob.matrix_basis.copy()
        self.modifiers = [m.name for m in ob.modifiers]

    def restore(self):
        ob = self.ob
        if ob.data != self.data:
            ob.data = self.data
        if self.mesh is not None:
            self.mesh.restore(ob.data)
        for k in [k for k in ob.keys() if k.startswith("hbc_")]:
            del ob[k]
        for k, v in self.props.items():
            ob[k] = v
        ob.color = self.color
        ob.hide_viewport, ob.hide_render, ob.hide_select = self.hidden
        ob.matrix_basis = self.matrix
        for mod in [m for m in ob.modifiers if m.name not in self.modifiers]:
            ob.modifiers.remove(mod)


_MISSING = object()


class Transaction:
    """Records what a build creates and changes; `with Transaction() as tx:` undoes it on error.

    A layer that is built again is rebuilt in place (`reuse`): the objects the new build asks for
    by name (`mesh_object`) are the old ones, their meshes cleared and filled again, so a rebuild
    keeps names, collection links and view-layer entries and costs no more than a first build
    (removing and making objects again is what made rebuilds slow: Blender's removal of objects and
    meshes and the view layer's resync dominate). Objects the new build does not ask for go when
    the layer is swapped in (`swap_layer`); what is refilled is saved first, so a failed build
    still leaves the file as it was."""

    def __init__(self):
        self.created = []  # (collection name in bpy.data, datablock)
        self.pools = {}  # layer collection -> {object name: object} not yet asked for by the rebuild
        self.kept = {}  # object -> its _ObjectState, for every object refilled in place
        self.used_modifiers = set()  # (object, modifier name) the build asked for
        self.inputs = []  # (modifier, input name, value before) set on kept objects
        self.layers = []  # (layer collection, name, hide_viewport, hide_render, stale) rebuilt in place
        self.props = []  # (is an attribute, datablock, key, value before or _MISSING): set_prop, set_attr

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, tb):
        if exc_type is not None:
            self.rollback()
        return False

    def add(self, kind, block):
        self.created.append((kind, block))
        return block

    def set_prop(self, block, key, value):
        """Sets an ID property of a datablock the build did not make; a rollback puts it back."""
        self.props.append((False, block, key, _plain(block[key]) if key in block else _MISSING))
        block[key] = value

    def set_attr(self, block, attr, value):
        """Sets an attribute (hide_viewport, ...) of a datablock the build did not make; a rollback
        puts it back."""
        self.props.append((True, block, attr, getattr(block, attr)))
        setattr(block, attr, value)

    def rollback(self):
        for is_attr, block, key, value in reversed(self.props):
            if is_attr:
                setattr(block, key, value)
            elif value is _MISSING:
                block.pop(key, None)
            else:
                block[key] = value
        for mod, name, value in reversed(self.inputs):
            compat.set_modifier_input(mod, name, value)
        for state in reversed(list(self.kept.values())):
            try:
                state.restore()
            except Exception as e:  # noqa: BLE001 - keep undoing the rest; say what stays changed
                print(f"hbc: rollback could not restore {state.ob.name}: {e}")
        ids = []
        for _, block in reversed(self.created):
            try:
                block.name  # noqa: B018 - raises ReferenceError for a block already gone
                ids.append(block)
            except ReferenceError:
                pass
        if ids:
            bpy.data.batch_remove(ids)
        for coll, name, hide_viewport, hide_render, stale in self.layers:
            coll.name, coll.hide_viewport, coll.hide_render = name, hide_viewport, hide_render
            if stale is not None:
                coll["hbc_stale"] = stale
        self.__init__()

    # factories
    def collection(self, name):
        return self.add("collections", bpy.data.collections.new(name))

    def mesh(self, name):
        return self.add("meshes", bpy.data.meshes.new(name))

    def object(self, name, data, coll):
        ob = self.add("objects", bpy.data.objects.new(name, data))
        coll.objects.link(ob)
        return ob

    # rebuilding in place
    def reuse(self, coll):
        """Rebuilds the layer collection `coll` in place: its objects become the pool `mesh_object`
        takes from."""
        self.pools[coll] = {ob.name: ob for ob in coll.objects}
        self.layers.append((coll, coll.name, coll.hide_viewport, coll.hide_render, coll.get("hbc_stale")))

    def mesh_object(self, name, coll):
        """(object, empty mesh) called `name` in `coll`: the old object of that name when `coll` is
        rebuilt in place (its mesh cleared; a mesh other objects share is left to them and replaced),
        else new ones. A refilled object is reset to what a new object has (no add-on properties,
        white, shown, at the origin) before the builder sets what it wants."""
        ob = self.pools.get(coll, {}).pop(name, None)
        if ob is None or ob.type != "MESH":
            me = self.mesh(name)
            return self.object(name, me, coll), me
        own = ob.data.users == 1 and ob.data.library is None
        state = self.kept[ob] = _ObjectState(ob, refill_mesh=own)
        if own:
            me = ob.data
            me.clear_geometry()  # keeps the materials: set_materials changes them only if they differ
        else:
            me = self.mesh(name)
            ob.data = me
        for k in state.props:
            del ob[k]
        if tuple(ob.color) != (1.0, 1.0, 1.0, 1.0):
            ob.color = (1.0, 1.0, 1.0, 1.0)
        if ob.hide_viewport or ob.hide_render or ob.hide_select:
            ob.hide_viewport = ob.hide_render = ob.hide_select = False
        if not _is_identity(ob.matrix_basis):
            ob.matrix_basis.identity()
        return ob, me

    def modifier(self, ob, name, kind="NODES"):
        """The object's modifier `name`: the one it has (a refilled object keeps it, with its inputs),
        else a new one. Modifiers of refilled objects the build does not ask for go at the swap."""
        self.used_modifiers.add((ob, name))
        return ob.modifiers.get(name) or ob.modifiers.new(name, kind)

    def set_input(self, mod, name, value):
        """Sets a geometry-nodes modifier input; a rollback puts a refilled object's old value back."""
        old = compat.get_modifier_input(mod, name)
        if old == value:
            return
        state = self.kept.get(mod.id_data)
        if state is not None and mod.name in state.modifiers:
            self.inputs.append((mod, name, old))
        compat.set_modifier_input(mod, name, value)

    def finish(self, coll):
        """The rebuild of `coll` succeeded: the objects it did not ask for go with their own data,
        and so do child collections; refilled objects lose the modifiers the build did not ask for."""
        pool = self.pools.pop(coll, {})
        surplus = set(pool.values())
        children = []
        if coll.children:
            colls, objects, _ = _tree(coll)
            children = [c for c in colls if c != coll]
            surplus |= objects - set(coll.objects)
        for ob in coll.objects:
            if ob in self.kept and ob not in surplus:
                for mod in [m for m in ob.modifiers if (ob, m.name) not in self.used_modifiers]:
                    ob.modifiers.remove(mod)
        uses = Counter(ob.data for ob in surplus if ob.data is not None)
        own = [d for d, n in uses.items() if d.users <= n]
        # Objects first, then their data (see remove_collection_tree).
        for ids in (list(surplus), own, children):
            if ids:
                bpy.data.batch_remove(ids)


_IDENTITY = Matrix.Identity(4)


def _is_identity(m) -> bool:
    return m == _IDENTITY


# ---------------------------------------------------------------------------------------------
# Materials and node groups (shared by every layer and every imported mesh)

def material(tx: Transaction, kind: str, color=(0.8, 0.8, 0.8, 1.0), alpha: float = 1.0):
    """Shared material by kind:
    - "attr": base colour and alpha from the `hbc_color` attribute (soups, lines, dots);
    - "object": base colour from Object Info > Color (one object per owner);
    - "flat": one colour with `alpha` (the transparent boundary); named by colour and alpha.
    """
    if kind == "flat":
        name = "HBC Flat %02x%02x%02x a%03d" % (int(color[0] * 255), int(color[1] * 255), int(color[2] * 255),
                                                 int(alpha * 100))
    else:
        name = {"attr": "HBC Attribute Color", "object": "HBC Object Color"}[kind]
    mat = bpy.data.materials.get(name)
    if mat is not None and mat.get("hbc_material") == kind:
        return mat
    mat, nt, bsdf = compat.new_node_material(name)
    tx.add("materials", mat)
    mat["hbc_material"] = kind
    if kind == "attr":
        attr = nt.nodes.new("ShaderNodeAttribute")
        attr.attribute_name = COLOR_ATTR
        nt.links.new(attr.outputs["Color"], bsdf.inputs["Base Color"])
        nt.links.new(attr.outputs["Alpha"], bsdf.inputs["Alpha"])
        compat.set_blend(mat, True)
    elif kind == "object":
        info = nt.nodes.new("ShaderNodeObjectInfo")
        nt.links.new(info.outputs["Color"], bsdf.inputs["Base Color"])
        compat.set_blend(mat, False)
    else:
        bsdf.inputs["Base Color"].default_value = tuple(color[:3]) + (1.0,)
        bsdf.inputs["Alpha"].default_value = alpha
        compat.set_viewport_color(mat, tuple(color[:3]) + (alpha,))
        compat.set_blend(mat, alpha < 1.0)
    return mat


def tube_group(tx: Transaction):
    """Geometry nodes: edges -> curves -> tubes of radius `Radius`, attributes carried along."""
    ng = bpy.data.node_groups.get(TUBE_GROUP)
    if ng is not None and ng.get("hbc_group") == TUBE_GROUP_VERSION:
        return ng
    ng = tx.add("node_groups", bpy.data.node_groups.new(TUBE_GROUP, "GeometryNodeTree"))
    ng["hbc_group"] = TUBE_GROUP_VERSION
    compat.group_socket(ng, "INPUT", "NodeSocketGeometry", "Geometry")
    r = compat.group_socket(ng, "INPUT", "NodeSocketFloat", "Radius")
    r.default_value = 0.01
    compat.group_socket(ng, "INPUT", "NodeSocketInt", "Resolution").default_value = 6
    compat.group_socket(ng, "OUTPUT", "NodeSocketGeometry", "Geometry")
    compat.mark_modifier_group(ng)
    n = ng.nodes
    gi, go = n.new("NodeGroupInput"), n.new("NodeGroupOutput")
    m2c = n.new("GeometryNodeMeshToCurve")
    c2m = n.new("GeometryNodeCurveToMesh")
    circ = n.new("GeometryNodeCurvePrimitiveCircle")
    # Mesh to Curve drops the mesh's materials: put the shared attribute material back.
    setmat = n.new("GeometryNodeSetMaterial")
    setmat.inputs["Material"].default_value = material(tx, "attr")
    L = ng.links.new
    L(gi.outputs["Geometry"], m2c.inputs["Mesh"])
    L(m2c.outputs["Curve"], c2m.inputs["Curve"])
    L(gi.outputs["Radius"], circ.inputs["Radius"])
    L(gi.outputs["Resolution"], circ.inputs["Resolution"])
    L(circ.outputs["Curve"], c2m.inputs["Profile Curve"])
    L(c2m.outputs["Mesh"], setmat.inputs["Geometry"])
    # Curve to Mesh makes a new mesh that (4.2 and later) has no active colour attribute: Solid >
    # Attribute drew every tube black. Joined after the input's own points (its edges deleted;
    # loose points draw nothing), the tubes get the input mesh's settings, `hbc_color` active
    # among them: Join takes them from its first mesh, and a multi-input socket lists the link
    # made last first.
    points = n.new("GeometryNodeDeleteGeometry")
    points.domain, points.mode = "EDGE", "EDGE_FACE"
    points.inputs["Selection"].default_value = True
    join = n.new("GeometryNodeJoinGeometry")
    L(gi.outputs["Geometry"], points.inputs["Geometry"])
    L(setmat.outputs["Geometry"], join.inputs["Geometry"])
    L(points.outputs["Geometry"], join.inputs["Geometry"])
    L(join.outputs["Geometry"], go.inputs["Geometry"])
    return ng


# ---------------------------------------------------------------------------------------------
# Geometry

def fill_soup(me, soup: P.Soup, face_colors=None, owner_colors=None, edges=None):
    """Writes a soup into an empty mesh: points, corners, faces, the `owner` (and `hbc_cell`) face
    attributes and the colour attribute: with face_colors one per face (CORNER domain) or one for
    all (POINT), or with owner_colors one per owner id (POINT: the soup's points must each belong
    to one owner, as hbc.block_soup's do). edges: the soup's `_soup_edges` when made already
    (`with_edges`, off the main thread)."""
    nv, nf = len(soup.positions), soup.num_faces
    me.vertices.add(nv)
    me.vertices.foreach_set("co", np.ascontiguousarray(soup.positions, np.float32).ravel())
    me.loops.add(len(soup.face_vertices))
    compat.set_corner_verts(me, soup.face_vertices)
    me.polygons.add(nf)
    compat.set_polygons(me, soup.loop_starts(), soup.face_sizes)
    if edges is None:
        edges = _soup_edges(soup, nv)
    if edges is not None:
        me.edges.add(len(edges["edges"]))
        compat.set_edge_verts(me, edges["edges"])
        compat.set_corner_edges(me, edges["corner_edge"])
    owner = me.attributes.new(OWNER_ATTR, "INT", "FACE")
    owner.data.foreach_set("value", np.ascontiguousarray(soup.face_owner, np.int32))
    if soup.face_cell is not None:  # the cell of each face, for the inspection filters (blender/inspect.py)
        me.attributes.new(CELL_ATTR, "INT", "FACE").data.foreach_set("value", np.ascontiguousarray(soup.face_cell, np.int32))
    colors, domain = None, "POINT"
    if owner_colors is not None:
        point_owner = np.zeros(nv, np.intp)
        point_owner[soup.face_vertices] = np.repeat(soup.face_owner, soup.face_sizes)
        colors = np.asarray(owner_colors, np.float32).reshape(-1, 4)[point_owner]
    elif face_colors is not None:
        fc = np.asarray(face_colors, np.float32).reshape(-1, 4)
        if len(fc) == nf:
            colors, domain = np.repeat(fc, soup.face_sizes, axis=0), "CORNER"
        else:
            colors = np.broadcast_to(fc[0], (nv, 4))
    if colors is not None:
        col = me.color_attributes.new(COLOR_ATTR, "FLOAT_COLOR", domain)
        col.data.foreach_set("color", np.ascontiguousarray(colors, np.float32).ravel())
        compat.make_active_color(me, col)
    me.update(calc_edges=edges is None)
    return me


def _soup_edges(soup: P.Soup, num_points: int):
    """hbc.polygon_edges of the soup (its edges made in C++, several times faster than Blender's
    own search: docs/performance.md), or None when the compiled module lacks it (Blender then
    finds the edges)."""
    try:
        polygon_edges = getattr(import_hbc(), "polygon_edges", None)
    except Exception:  # noqa: BLE001 - no compiled module: Blender's edge search
        polygon_edges = None
    if polygon_edges is None:
        return None
    offsets = np.zeros(soup.num_faces + 1, np.int32)
    np.cumsum(soup.face_sizes, out=offsets[1:])
    return polygon_edges(offsets, np.ascontiguousarray(soup.face_vertices, np.int32), num_points)


def with_edges(make, *args):
    """(soup, its edges) of the soup `make(*args)` gives: a build's `steps.Work`, so that the soup
    and its edges (C++ both) are made off the main thread; no Blender data is touched."""
    soup = make(*args)
    return soup, _soup_edges(soup, len(soup.positions))


def without_edges(make, *args):
    """(soup, None): `with_edges` for soups split into objects (each finds its own edges)."""
    return make(*args), None


def set_materials(me, materials):
    """Gives a mesh these material slots and records a single one as the mesh's `hbc_material`.
    A refilled mesh usually has them already: changing a mesh's materials rebuilds the whole
    scene's dependency graph, so equal ones are left alone."""
    materials = list(materials)
    if len(materials) == 1 and me.get(MATERIAL_PROP) != materials[0]:
        me[MATERIAL_PROP] = materials[0]
    if list(me.materials) == materials:
        return
    me.materials.clear()
    for mat in materials:
        me.materials.append(mat)


def mesh_from_soup(tx: Transaction, name: str, soup: P.Soup, face_colors=None, owner_colors=None):
    """A new mesh (registered in tx) filled with a soup, for an object to take (fill_soup)."""
    return fill_soup(tx.mesh(name), soup, face_colors, owner_colors)


def soup_object(tx, coll, name, soup: P.Soup, face_colors=None, mat=None, props=None, owner_colors=None, edges=None):
    ob, me = tx.mesh_object(name, coll)
    fill_soup(me, soup, face_colors, owner_colors, edges)
    if mat is None:
        mat = material(tx, "attr")
    set_materials(me, [mat])
    for k, v in (props or {}).items():
        ob[k] = v
    return ob


def split_soup_objects(tx, coll, prefix, soup: P.Soup, colors, props_of, name_of=None):
    """One object per owner (faces with equal owner), all sharing the Object Info material with
    ob.color set: for layers with few owners, so that clicking one selects it. Relies on
    hbc.block_soup giving each owner its own points (usually one contiguous range). A build step
    (plan/steps.py): yields the share written after each object, returns the objects."""
    mat = material(tx, "object")
    order = np.argsort(soup.face_owner, kind="stable")
    offsets = np.append(soup.loop_starts(), len(soup.face_vertices))  # once: a copy per owner cost 4 s for 352 sheets
    owners_sorted = soup.face_owner[order]
    uniq, first = np.unique(owners_sorted, return_index=True)
    bounds = np.append(first, len(order))
    objects = []
    for i, owner in enumerate(uniq):
        faces = order[bounds[i]: bounds[i + 1]]
        sizes = soup.face_sizes[faces]
        loops = P.csr_rows(offsets, soup.face_vertices, faces)
        lo, hi = int(loops.min()), int(loops.max()) + 1
        if hi - lo == len(np.unique(loops)):  # the owner's points are one contiguous range
            part = P.Soup(soup.positions[lo:hi], sizes, (loops - lo).astype(np.int32), soup.face_owner[faces])
        else:
            used, inverse = np.unique(loops, return_inverse=True)
            part = P.Soup(soup.positions[used], sizes, inverse.astype(np.int32), soup.face_owner[faces])
        if soup.face_cell is not None:
            part.face_cell = soup.face_cell[faces]
        name = name_of(int(owner)) if name_of else f"{prefix} {int(owner)}"
        rgba = tuple(float(c) for c in colors[int(owner)])
        # The colour also as the object's colour attribute, so Solid > Attribute shows it.
        ob = soup_object(tx, coll, name, part, [rgba], mat, props_of(int(owner)))
        ob.color = rgba
        objects.append(ob)
        yield (i + 1) / len(uniq)
    return objects


def lines_object(tx, coll, name, lines: P.Lines, radius: float, props=None):
    """Tubes along polylines; per-point colour with alpha = opacity."""
    ob, me = tx.mesh_object(name, coll)
    me.vertices.add(len(lines.positions))
    me.vertices.foreach_set("co", np.ascontiguousarray(lines.positions, np.float32).ravel())
    me.edges.add(len(lines.edges))
    compat.set_edge_verts(me, lines.edges)
    col = me.color_attributes.new(COLOR_ATTR, "FLOAT_COLOR", "POINT")
    col.data.foreach_set("color", np.ascontiguousarray(lines.colors, np.float32).ravel())
    compat.make_active_color(me, col)
    poly = me.attributes.new("polyline", "INT", "POINT")
    poly.data.foreach_set("value", np.ascontiguousarray(lines.polyline, np.int32))
    me.update()
    set_materials(me, [material(tx, "attr")])
    ng = tube_group(tx)
    mod = tx.modifier(ob, "Tubes")
    if mod.node_group != ng:  # assigning even the same group rebuilds the scene's relations
        mod.node_group = ng
    tx.set_input(mod, "Radius", float(radius))
    ob["hbc_polylines"] = lines.num_polylines
    for k, v in (props or {}).items():
        ob[k] = v
    return ob


# ---------------------------------------------------------------------------------------------
# Collections

@contextmanager
def selectable(objects):
    """Lets the add-on select, for what it does with a selection (frame, export), objects a click
    cannot select (hide_select: the see-through boundary); they are unselectable again after, which
    also deselects them."""
    locked = [ob for ob in objects if ob.hide_select]
    for ob in locked:
        ob.hide_select = False
    try:
        yield
    finally:
        for ob in locked:
            ob.hide_select = True


def iter_objects(coll):
    """Every object of a collection and of the collections below it, once each, walked lazily (so a
    caller looking for one can stop at it). `Collection.all_objects` reads a cache Blender does not
    refresh after an undo (3.4: it still lists objects the undo freed, and reading them crashes or
    yields another object), so the add-on walks the collections itself wherever it may run after an
    undo (handlers, update callbacks, panels, operators)."""
    seen, stack = set(), [coll]
    while stack:
        c = stack.pop()
        for ob in c.objects:
            if ob.name not in seen:
                seen.add(ob.name)
                yield ob
        stack.extend(c.children)


def objects_in(coll) -> list:
    """iter_objects as a list."""
    return list(iter_objects(coll))


def find_layer(root, layer: str):
    for c in root.children:
        if c.get("hbc_layer") == layer:
            return c
    return None


def see_through(ob) -> bool:
    """Whether ob is the direct view's boundary drawn see-through (its object colour's alpha, which
    Solid mode draws it with)."""
    return ob.get("hbc_part") == "boundary" and ob.color[3] < 1.0


def isolate(root, keep, view_layer) -> int:
    """Hides in the view layer (as H does; Alt+H shows them again) every object of the mesh the
    viewport draws but `keep` and the see-through boundary, so that nothing stands in front of
    what is kept. Returns how many it hid."""
    keep = set(keep)
    hid = 0
    for ob in objects_in(root):
        if (ob in keep or ob.type == "EMPTY" or see_through(ob) or ob.name not in view_layer.objects
                or not ob.visible_get(view_layer=view_layer)):
            continue
        ob.hide_set(True, view_layer=view_layer)
        hid += 1
    return hid


def layers_of(root) -> list:
    """The built layer collections of a mesh."""
    return [c for c in root.children if c.get("hbc_layer")]


def view_layer_path(view_layer, coll):
    """The view layer's LayerCollections from its top one (the scene collection's) down to coll's:
    what the outliner's checkboxes and eyes set. None when coll is not in the scene."""
    stack = [[view_layer.layer_collection]]
    while stack:
        path = stack.pop()
        if path[-1].collection == coll:
            return path
        stack.extend(path + [child] for child in path[-1].children)
    return None


def layer_shown(coll, view_layer) -> bool:
    """Whether the viewport draws a layer (what the panel's eye and legend show): the layer and every
    collection above it are enabled in viewports and neither excluded nor hidden in the view layer
    (the outliner's checkbox and eye), and, when it holds objects, one of them is shown (their own
    eyes, and the sheets layer's hidden sheets)."""
    path = view_layer_path(view_layer, coll)
    if path is None or any(lc.exclude or lc.hide_viewport or lc.collection.hide_viewport for lc in path[1:]):
        return False
    # Drawn by the panel at every redraw: stop at the first object shown (a Components layer may hold
    # one object per component, tens of thousands on a snappyHexMesh case).
    empty = True
    for ob in iter_objects(coll):
        if not ob.hide_viewport and not ob.hide_get(view_layer=view_layer):
            return True
        empty = False
    return empty


def show_layer(root, layer: str, view_layer):
    """Makes the viewport draw a built layer, whatever hid it: its collection enabled, its view-layer
    collection and those above it included and shown, its objects' own eyes open (not the sheets
    layer's per-sheet hiding). The mesh's other layers that an eye above them hid stay hidden: their
    collections are disabled instead. Returns the layer's collection (None when not built)."""
    coll = find_layer(root, layer)
    if coll is None:
        return None
    hidden = [c for c in layers_of(root) if c != coll and not layer_shown(c, view_layer)]
    coll.hide_viewport = False
    for lc in (view_layer_path(view_layer, coll) or [])[1:]:
        if lc.exclude:
            lc.exclude = False
        if lc.hide_viewport:
            lc.hide_viewport = False
        if lc.collection.hide_viewport:
            lc.collection.hide_viewport = False
    for ob in objects_in(coll):
        if ob.hide_get(view_layer=view_layer):
            ob.hide_set(False, view_layer=view_layer)
    for c in hidden:
        if layer_shown(c, view_layer):
            c.hide_viewport = True
    return coll


def _tree(coll):
    """The collection, its child collections, their objects and the objects' own data (data no
    object outside the tree uses)."""
    colls, stack = [], [coll]
    while stack:
        c = stack.pop()
        colls.append(c)
        stack.extend(c.children)
    objects = {ob for c in colls for ob in c.objects}
    uses = Counter(ob.data for ob in objects if ob.data is not None)
    data = {d for d, n in uses.items() if d.users <= n}
    return colls, objects, data


def remove_collection_tree(coll):
    """Removes a collection with everything `_tree` lists, in one batch (removing objects one
    by one costs time growing with the number of objects in the file for each)."""
    colls, objects, data = _tree(coll)
    # Objects first, then their data: one batch of both costs several times more (Blender
    # remaps the users of the data still held by the objects).
    for ids in (objects, data, colls):
        if ids:
            bpy.data.batch_remove(list(ids))


def swap_layer(root, layer: str, new_coll, tx: Transaction | None = None):
    """Puts a freshly built layer collection under root, replacing the old one (never both); a
    layer rebuilt in place (Transaction.reuse) stays where it is and drops what the rebuild left
    over."""
    old = find_layer(root, layer)
    final_name = P.layer_collection_name(root.name, layer)
    if old is not None and old == new_coll:
        if tx is not None:
            tx.finish(new_coll)
        if new_coll.get("hbc_stale"):  # hidden for being another sheet's: shown as a new layer is
            new_coll.hide_viewport = new_coll.hide_render = False
            del new_coll["hbc_stale"]
        if new_coll.name != final_name:
            new_coll.name = final_name
        compat.show_attribute_colors()
        return new_coll
    # The old layer's eye and camera icons carry over (not when it was hidden for being stale).
    keep_hidden = (old.hide_viewport, old.hide_render) if old is not None and not old.get("hbc_stale") else None
    if old is not None:
        root.children.unlink(old)
        remove_collection_tree(old)
    new_coll["hbc_layer"] = layer
    new_coll["hbc_mesh"] = root.name
    root.children.link(new_coll)
    new_coll.name = final_name
    if keep_hidden is not None:
        new_coll.hide_viewport, new_coll.hide_render = keep_hidden
    # Layers are coloured by attributes; Solid mode's default (one colour per material) shows grey.
    compat.show_attribute_colors()
    return new_coll


def remove_layer(root, layer: str) -> bool:
    old = find_layer(root, layer)
    if old is None:
        return False
    root.children.unlink(old)
    remove_collection_tree(old)
    return True


def datablock_names():
    """{kind: set of names} of the datablocks the add-on may create (tests compare before/after)."""
    kinds = ("objects", "meshes", "curves", "materials", "collections", "node_groups")
    return {k: {b.name for b in getattr(bpy.data, k)} for k in kinds}
