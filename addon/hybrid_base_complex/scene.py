"""Scene building (bpy): planning Soups and Lines into Blender data, in bulk.

- Meshes: vertices.foreach_set("co"), polygons via loop_start (+ loop_total before 4.0) and
  loops.foreach_set("vertex_index"); colours as a CORNER float colour attribute `hbc_color`
  (shown by Workbench with colour type Attribute, read by an Attribute node in Cycles/EEVEE);
  the block a face belongs to as a FACE int attribute `owner`.
- Lines (singularity graph, wireframes, highlighted edges): a mesh of edges with a POINT colour
  attribute (alpha = opacity) and a shared geometry-nodes modifier (Mesh to Curve, Curve to Mesh)
  that makes tubes; the attribute is carried onto the tubes so the shared line material renders
  the per-point opacity.
- Every datablock made while building goes through a `Transaction`; on an exception it removes
  them all, so a failed build leaves the file exactly as it was. Layers are built into an unlinked
  collection and only swapped in (replacing the old one) at the end.
"""

from __future__ import annotations

from collections import Counter

import bpy
import numpy as np

from . import compat
from . import planning as P

COLOR_ATTR = "hbc_color"
OWNER_ATTR = "owner"
CELL_ATTR = "hbc_cell"
TUBE_GROUP = "HBC Tube"


# ---------------------------------------------------------------------------------------------
# Transactions

class Transaction:
    """Records the datablocks it creates; `with Transaction() as tx:` removes them on error."""

    def __init__(self):
        self.created = []  # (collection name in bpy.data, datablock)
        self.renamed = []  # (datablock, its name before)
        self.retired = {}  # (root name, layer) -> the old layer collection, unlinked from its root
        self.removed = []  # (collection, name, data, ID properties, colour, hidden) of objects removed early

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, tb):
        if exc_type is not None:
            self.rollback()
        return False

    def add(self, kind, block):
        self.created.append((kind, block))
        return block

    def rename(self, block, name):
        """Renames an existing datablock; a rollback gives it its old name back."""
        self.renamed.append((block, block.name))
        block.name = name

    def rollback(self):
        ids = []
        for _, block in reversed(self.created):
            try:
                ids.append(block)
                block.name  # noqa: B018 - raises ReferenceError for a block already gone
            except ReferenceError:
                ids.pop()
        if ids:
            bpy.data.batch_remove(ids)
        for block, name in reversed(self.renamed):
            try:
                block.name = name
            except ReferenceError:
                pass
        for coll, name, data, props, color, hidden in self.removed:
            ob = bpy.data.objects.new(name, data)
            for k, v in props.items():
                ob[k] = v
            ob.color, ob.hide_viewport = color, hidden
            coll.objects.link(ob)
        self.removed.clear()
        for (root_name, _), old in self.retired.items():
            root = bpy.data.collections.get(root_name)
            if root is not None and old.name not in root.children:
                root.children.link(old)
        self.created.clear()
        self.renamed.clear()
        self.retired.clear()

    # factories
    def collection(self, name):
        return self.add("collections", bpy.data.collections.new(name))

    def mesh(self, name):
        return self.add("meshes", bpy.data.meshes.new(name))

    def object(self, name, data, coll):
        ob = self.add("objects", bpy.data.objects.new(name, data))
        coll.objects.link(ob)
        return ob


# ---------------------------------------------------------------------------------------------
# Materials and node groups (shared by every layer and every imported mesh)

def material(tx: Transaction, kind: str, color=(0.8, 0.8, 0.8, 1.0), alpha: float = 1.0):
    """Shared material by kind:
    - "attr": base colour and alpha from the `hbc_color` attribute (blocks, lines, dots);
    - "object": base colour from Object Info > Color (per-block objects);
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
    if ng is not None and ng.get("hbc_group") == 2:
        return ng
    ng = tx.add("node_groups", bpy.data.node_groups.new(TUBE_GROUP, "GeometryNodeTree"))
    ng["hbc_group"] = 2
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
    L(setmat.outputs["Geometry"], go.inputs["Geometry"])
    return ng


# ---------------------------------------------------------------------------------------------
# Geometry

def _mesh_from_soup(tx: Transaction, name: str, soup: P.Soup, face_colors=None):
    me = tx.mesh(name)
    nv, nf = len(soup.positions), soup.num_faces
    me.vertices.add(nv)
    me.vertices.foreach_set("co", np.ascontiguousarray(soup.positions, np.float32).ravel())
    me.loops.add(len(soup.face_vertices))
    me.loops.foreach_set("vertex_index", np.ascontiguousarray(soup.face_vertices, np.int32))
    me.polygons.add(nf)
    compat.set_polygons(me, soup.loop_starts(), np.ascontiguousarray(soup.face_sizes, np.int32))
    owner = me.attributes.new(OWNER_ATTR, "INT", "FACE")
    owner.data.foreach_set("value", np.ascontiguousarray(soup.face_owner, np.int32))
    if soup.face_cell is not None:  # the cell of each face, for the inspection filters (inspect.py)
        me.attributes.new(CELL_ATTR, "INT", "FACE").data.foreach_set("value", np.ascontiguousarray(soup.face_cell, np.int32))
    if face_colors is not None:
        fc = np.asarray(face_colors, np.float32).reshape(-1, 4)
        corner = np.repeat(fc, soup.face_sizes, axis=0) if len(fc) == nf else np.broadcast_to(fc[0], (len(soup.face_vertices), 4))
        col = me.color_attributes.new(COLOR_ATTR, "FLOAT_COLOR", "CORNER")
        col.data.foreach_set("color", np.ascontiguousarray(corner, np.float32).ravel())
        compat.make_active_color(me, col)
    me.update(calc_edges=True)
    return me


def soup_object(tx, coll, name, soup: P.Soup, face_colors=None, mat=None, props=None):
    me = _mesh_from_soup(tx, name, soup, face_colors)
    if mat is None:
        mat = material(tx, "attr")
    me.materials.append(mat)
    ob = tx.object(name, me, coll)
    for k, v in (props or {}).items():
        ob[k] = v
    return ob


def split_soup_objects(tx, coll, prefix, soup: P.Soup, colors, props_of, name_of=None):
    """One object per owner (faces with equal owner), all sharing the Object Info material with
    ob.color set: for layers with few blocks, so that clicking a block selects it. Relies on
    hbc.block_soup giving each owner its own points (usually one contiguous range)."""
    mat = material(tx, "object")
    order = np.argsort(soup.face_owner, kind="stable")
    starts = soup.loop_starts()
    owners_sorted = soup.face_owner[order]
    uniq, first = np.unique(owners_sorted, return_index=True)
    bounds = np.append(first, len(order))
    objects = []
    for i, owner in enumerate(uniq):
        faces = order[bounds[i]: bounds[i + 1]]
        sizes = soup.face_sizes[faces]
        loops = P.csr_rows(np.append(starts, len(soup.face_vertices)), soup.face_vertices, faces)
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
    return objects


def lines_object(tx, coll, name, lines: P.Lines, radius: float, props=None):
    """Tubes along polylines; per-point colour with alpha = opacity."""
    me = tx.mesh(name)
    me.vertices.add(len(lines.positions))
    me.vertices.foreach_set("co", np.ascontiguousarray(lines.positions, np.float32).ravel())
    me.edges.add(len(lines.edges))
    me.edges.foreach_set("vertices", np.ascontiguousarray(lines.edges, np.int32).ravel())
    col = me.color_attributes.new(COLOR_ATTR, "FLOAT_COLOR", "POINT")
    col.data.foreach_set("color", np.ascontiguousarray(lines.colors, np.float32).ravel())
    compat.make_active_color(me, col)
    poly = me.attributes.new("polyline", "INT", "POINT")
    poly.data.foreach_set("value", np.ascontiguousarray(lines.polyline, np.int32))
    me.update()
    me.materials.append(material(tx, "attr"))
    ob = tx.object(name, me, coll)
    ng = tube_group(tx)
    mod = ob.modifiers.new("Tubes", "NODES")
    mod.node_group = ng
    compat.set_modifier_input(mod, "Radius", float(radius))
    ob["hbc_polylines"] = lines.num_polylines
    for k, v in (props or {}).items():
        ob[k] = v
    return ob


# ---------------------------------------------------------------------------------------------
# Collections

def find_layer(root, layer: str):
    for c in root.children:
        if c.get("hbc_layer") == layer:
            return c
    return None


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


def retire_layer(tx: Transaction, root, layer: str):
    """Takes the layer about to be replaced out of the scene (its objects leave the view layer, so
    renaming and removing them costs no view-layer update each), removes its plain objects and
    renames what stays (meshes, tube objects), so the new ones get the plain names of a first build
    (no `.001`, no search for a free number). A rollback makes the removed objects again and links
    the layer back under its old names; swap_layer removes the rest."""
    old = find_layer(root, layer)
    if old is None:
        return None
    root.children.unlink(old)
    tx.retired[(root.name, layer)] = old
    colls, objects, data = _tree(old)
    for block in data:
        tx.rename(block, "~" + block.name[:60])
    # Plain mesh objects go now, while the file does not hold the new ones yet (Blender removes
    # objects in time growing with the objects in the file); a rollback makes them again from
    # what is kept here (their data stays until the swap). Objects with modifiers (tubes) stay.
    home = {ob: c for c in colls for ob in c.objects}
    plain = [ob for ob in objects if ob.type == "MESH" and not ob.modifiers]
    tx.removed += [(home[ob], ob.name, ob.data, {k: ob[k] for k in ob.keys()}, tuple(ob.color), ob.hide_viewport)
                   for ob in plain]
    if plain:
        bpy.data.batch_remove(plain)
    for ob in objects:
        if ob not in plain:
            tx.rename(ob, "~" + ob.name[:60])
    return old


def swap_layer(root, layer: str, new_coll, tx: Transaction | None = None):
    """Puts a freshly built layer collection under root, replacing the old one (never both): the
    one retired into `tx`, else the one under root."""
    old = tx.retired.pop((root.name, layer), None) if tx is not None else None
    if old is None:
        old = find_layer(root, layer)
        if old is not None:
            root.children.unlink(old)
    # The old layer's eye and camera icons carry over (not when it was hidden for being stale).
    keep_hidden = (old.hide_viewport, old.hide_render) if old is not None and not old.get("hbc_stale") else None
    final_name = P.layer_collection_name(root.name, layer)
    if old is not None:
        old_colls = set(_tree(old)[0])
        early = [d for coll, _, d, *_ in (tx.removed if tx is not None else []) if coll in old_colls]
        remove_collection_tree(old)
        if tx is not None:
            tx.removed = [r for r in tx.removed if r[2] not in early]
        early = [d for d in early if d.users == 0]
        if early:
            bpy.data.batch_remove(early)
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
