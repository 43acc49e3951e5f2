"""The "Hex Structure" sidebar panel (3D view > N) and the sheet list."""

from __future__ import annotations

import bpy

from . import planning as P
from . import scene as S
from . import session
from .operators import active_root


class HBC_UL_sheets(bpy.types.UIList):
    bl_idname = "HBC_UL_sheets"

    def draw_item(self, context, layout, data, item, icon, active_data, active_propname, index=0):
        row = layout.row(align=True)
        row.label(text=f"Sheet {item.index}")
        row.label(text=P.SHEET_TYPES[item.type] if 0 <= item.type < len(P.SHEET_TYPES) else str(item.type))
        row.label(text=f"{item.cells} cells / {item.components} blocks")


def _layer_header(layout, root, layer, title):
    box = layout.box()
    row = box.row(align=True)
    coll = S.find_layer(root, layer) if root is not None else None
    if coll is not None:
        row.prop(coll, "hide_viewport", text="", emboss=False)
        row.prop(coll, "hide_render", text="", emboss=False)
    row.label(text=title)
    op = row.operator("hbc.build_layer", text="Rebuild" if coll is not None else "Build", icon="FILE_REFRESH")
    op.layer = layer
    if coll is not None:
        row.operator("hbc.clear_layer", text="", icon="X").layer = layer
    return box


class _Base:
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Hex Structure"


class HBC_PT_main(_Base, bpy.types.Panel):
    bl_idname = "HBC_PT_main"
    bl_label = "Hex Structure"

    def draw(self, context):
        layout = self.layout
        st = context.scene.hbc
        root = active_root(context)
        layout.operator("import_mesh.hbc", icon="IMPORT")
        roots = [c for c in bpy.data.collections if c.get("hbc_source") is not None]
        if len(roots) > 1:
            col = layout.column(align=True)
            for c in roots:
                col.operator("hbc.set_active", text=c.name, depress=(root is not None and c == root)).name = c.name
        if root is None:
            layout.label(text="No mesh imported")
            return
        s = session.get(root.name)
        layout.label(text=f"{root.name}: {root.get('hbc_cells', '?')} cells", icon="MESH_CUBE")
        row = layout.row(align=True)
        row.prop(st, "rho")
        row.operator("hbc.analyze", text="Analyze" if s is None or s.analysis is None else "Re-analyze")
        layout.operator("hbc.build_all", icon="SCENE_DATA")
        if s is not None:
            grid = layout.grid_flow(columns=2, even_columns=True, align=True)
            for label, text in P.table1_row(s.stats()):
                grid.label(text=label)
                grid.label(text=text)
        elif root is not None:
            layout.label(text="Not in memory: Analyze to read the file again")


class HBC_PT_layers(_Base, bpy.types.Panel):
    bl_idname = "HBC_PT_layers"
    bl_label = "Layers"
    bl_parent_id = "HBC_PT_main"

    @classmethod
    def poll(cls, context):
        return active_root(context) is not None

    def draw(self, context):
        layout = self.layout
        st = context.scene.hbc
        root = active_root(context)

        box = _layer_header(layout, root, "direct", "Direct view")
        row = box.row(align=True)
        row.prop(st, "direct_boundary")
        row.prop(st, "direct_transparent")
        row.prop(st, "boundary_alpha")
        row = box.row(align=True)
        row.prop(st, "direct_hex_cells")
        row.prop(st, "direct_shrink")

        box = _layer_header(layout, root, "graph", "Singularity graph")
        box.prop(st, "line_radius")

        box = _layer_header(layout, root, "blocks", "Base complex blocks")
        row = box.row(align=True)
        row.prop(st, "shrink")
        row.prop(st, "split_max")

        box = _layer_header(layout, root, "sheets", "Sheets")
        box.template_list("HBC_UL_sheets", "", st, "sheets", st, "sheet_index", rows=5)
        picked = _layer_header(box, root, "sheet", "Picked sheet + highlights")
        row = picked.row(align=True)
        row.prop(st, "auto_show")
        row.prop(st, "dot_radius")
        sub = _layer_header(box, root, "subsheets", "Subsheets of picked sheet")
        sub.prop(st, "spread")
        if 0 <= st.sheet_index < len(st.sheets) and st.sheets[st.sheet_index].type != 3:
            sub.label(text="Pick a self-intersecting (type 3) sheet", icon="INFO")

        box = _layer_header(layout, root, "wireframe", "VSG wireframe")
        box.prop(st, "wireframe_scope", expand=True)
        row = box.row(align=True)
        row.prop(st, "opacity_floor")
        row.prop(st, "simplified")
        box.prop(st, "line_radius")


def picked_block(context):
    """(component or None, owner kind, object) of the selection: a per-block object, or the
    active face of a merged mesh in edit mode."""
    ob = context.active_object
    if ob is None or not ob.get("hbc_mesh"):
        return None, None, ob
    if "hbc_component" in ob:
        return int(ob["hbc_component"]), "component", ob
    owner_kind = ob.get("hbc_owner")
    if owner_kind and ob.mode == "EDIT" and ob.type == "MESH":
        import bmesh

        bm = bmesh.from_edit_mesh(ob.data)
        layer = bm.faces.layers.int.get("owner")
        face = bm.faces.active
        if layer is not None and face is not None:
            return int(face[layer]), owner_kind, ob
    return None, owner_kind, ob


class HBC_PT_selection(_Base, bpy.types.Panel):
    bl_idname = "HBC_PT_selection"
    bl_label = "Selection"
    bl_parent_id = "HBC_PT_main"

    @classmethod
    def poll(cls, context):
        ob = context.active_object
        return ob is not None and ob.get("hbc_mesh") is not None

    def draw(self, context):
        layout = self.layout
        ob = context.active_object
        layout.label(text=ob.name, icon="OBJECT_DATA")
        for key in ("hbc_layer", "hbc_sheet", "hbc_sheet_type", "hbc_subsheet", "hbc_highlight", "hbc_count",
                    "hbc_group", "hbc_polylines"):
            if key in ob:
                layout.label(text=f"{key[4:].replace('_', ' ')}: {ob[key]}")
        owner, kind, _ = picked_block(context)
        if owner is None:
            if kind:
                layout.label(text=f"Merged {kind}s: Edit Mode, pick a face", icon="INFO")
            return
        layout.label(text=f"{kind}: {owner}")
        s = session.get(ob["hbc_mesh"])
        if kind == "component" and s is not None and s.analysis is not None and owner < s.num_components:
            layout.label(text=f"kind: {P.COMPONENT_KINDS[int(s.component_kinds()[owner])]}")
            try:
                sheets = s.component_sheets(owner)
                layout.label(text="sheets: " + (", ".join(str(int(x)) for x in sheets) or "none"))
            except AttributeError:
                pass


classes = (HBC_UL_sheets, HBC_PT_main, HBC_PT_layers, HBC_PT_selection)
