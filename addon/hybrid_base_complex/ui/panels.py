"""The "Hex Structure" sidebar (3D view > N): the mesh, its Table 1 row, its key metrics, one sub-panel per layer,
a legend, and the selection. Laid out for the sidebar's default width: one short-labelled
property per row, icons for actions, longer words in tooltips. Panel order is fixed (bl_order) and
no panel appears or disappears with the selection, so buttons never move under the cursor."""

from __future__ import annotations

import textwrap

import bpy

from ..blender import inspect
from ..blender import layers
from ..blender import scene as S
from ..blender import sources
from ..blender.context import active_root, merged_owner_faces, unavailable
from ..plan import inspection as IP
from ..plan import metrics_box as MB
from ..plan import planning as P
from ..plan import session
from ..plan.native import import_hbc, module_problem

#: Longest label a row may carry at the default sidebar width (about 30 characters across, a
#: property's value taking the rest); tests/addon/blender checks every drawn label against it.
MAX_LABEL = 14
#: Characters of the longest histogram bar (its share of a sidebar row, beside the bin and count).
HISTOGRAM_BAR = 8


#: The sheet list's columns (sheet, type, cells) as split factors: a number, "type 3", a count.
SHEET_COLUMNS = (0.25, 0.5)


def sheet_columns(layout, index, kind, cells):
    """One row of the sheet list (or its header): the index, the type, the cell count at the right."""
    split = layout.split(factor=SHEET_COLUMNS[0], align=True)
    split.label(text=index)
    split = split.split(factor=SHEET_COLUMNS[1], align=True)
    split.label(text=kind)
    right = split.row()
    right.alignment = "RIGHT"
    right.label(text=cells)


class HBC_UL_sheets(bpy.types.UIList):
    """Sheets: index, type, cells. Filter by type word, sort by index, type or size."""

    bl_idname = "HBC_UL_sheets"

    def draw_item(self, context, layout, data, item, icon, active_data, active_propname, index=0):
        t = item.type
        sheet_columns(layout, str(item.index), P.SHEET_TYPE_SHORT[t] if 0 <= t < len(P.SHEET_TYPE_SHORT) else str(t),
                      str(item.cells))

    def draw_filter(self, context, layout):
        row = layout.row(align=True)
        row.prop(self, "filter_name", text="", icon="VIEWZOOM")
        row.prop(context.scene.hbc, "sheet_sort", text="")

    def filter_items(self, context, data, propname):
        items = getattr(data, propname)
        words = self.filter_name.strip().lower()
        flags = [self.bitflag_filter_item if not words or words in P.SHEET_TYPES[it.type].lower()
                 or words == str(it.index) else 0 for it in items]
        order = P.sheet_order([it.type for it in items], [it.cells for it in items], context.scene.hbc.sheet_sort)
        new_order = [0] * len(order)
        for position, i in enumerate(order):
            new_order[i] = position
        return flags, new_order


class _Base:
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Hex Structure"


class HBC_PT_main(_Base, bpy.types.Panel):
    bl_idname = "HBC_PT_main"
    bl_label = "Hex Structure"
    bl_order = 0

    def draw(self, context):
        layout = self.layout
        st = context.scene.hbc
        problem = module_problem()
        if problem:
            # The add-on is registered, but it can analyze nothing until the module matches.
            box = layout.box()
            box.label(text="hbc module unavailable", icon="ERROR")
            for line in textwrap.wrap(problem, 34):
                box.label(text=line)
            return
        root = active_root(context)
        row = layout.row(align=True)
        row.operator("import_mesh.hbc", text="Import", icon="IMPORT")
        row.operator("hbc.help", text="", icon="HELP")
        roots = [c for c in bpy.data.collections if c.get("hbc_source") is not None]
        if len(roots) > 1:
            col = layout.column(align=True)
            for c in roots:
                col.operator("hbc.set_active", text=c.name, icon="MESH_CUBE",
                             depress=(root is not None and c == root)).name = c.name
        if root is None:
            layout.label(text="No mesh yet", icon="INFO")
            return
        s = session.get(root.name)
        layout.label(text=f"{root.get('hbc_cells', '?')} cells", icon="MESH_CUBE")
        layout.prop(root, "hbc_path", text="")
        try:
            sources.resolve(root)
        except sources.SourceMissing:
            layout.label(text="Source missing", icon="ERROR")
        layout.prop(st, "rho")
        layout.prop(st, "subsheet_rule")
        row = layout.row(align=True)
        row.operator("hbc.analyze", text="Analyze" if s is None or s.analysis is None else "Re-analyze",
                     icon="VIEWZOOM")
        row.operator("hbc.build_all", text="Build All", icon="SCENE_DATA")
        row = layout.row(align=True)
        row.operator("hbc.export_vtu", text="Export VTU", icon="EXPORT")
        row.operator("hbc.render_figures", text="Figures", icon="RENDER_STILL")


class _Sub(_Base):
    bl_parent_id = "HBC_PT_main"

    @classmethod
    def poll(cls, context):
        return active_root(context) is not None


class HBC_PT_table1(_Sub, bpy.types.Panel):
    """The paper's Table 1 row: label and value on one line, the meaning as the label's tooltip."""

    bl_idname = "HBC_PT_table1"
    bl_label = "Table 1"
    bl_order = 1

    def draw(self, context):
        layout = self.layout
        root = active_root(context)
        s = session.get(root.name)
        if s is None:
            layout.label(text="Not in memory", icon="INFO")
            return
        col = layout.column(align=True)
        for label, text in P.table1_row(s.stats()):
            split = col.split(factor=0.5, align=True)
            split.operator("hbc.explain", text=label, emboss=False).text = P.table1_meaning(label)
            right = split.row()
            right.alignment = "RIGHT"
            right.label(text=text)
        row = layout.row(align=True)
        row.operator("hbc.copy_table1", text="Markdown", icon="COPYDOWN").format = "MARKDOWN"
        row.operator("hbc.copy_table1", text="CSV", icon="COPYDOWN").format = "CSV"


def _value_row(col, label, tip, text):
    """A label (a button whose tooltip says what it means) and its value at the right."""
    split = col.split(factor=0.5, align=True)
    split.operator("hbc.explain", text=label, emboss=False).text = tip
    right = split.row()
    right.alignment = "RIGHT"
    right.label(text=text)


class HBC_PT_metrics(_Sub, bpy.types.Panel):
    """The key structural metrics of the active mesh (plan/metrics_box.py, docs/metrics.md), and
    buttons that show its worst component and worst sheet. Closed at first: the metrics are
    computed when the box is first drawn open (a pass over the cells for the scaled Jacobians)."""

    bl_idname = "HBC_PT_metrics"
    bl_label = "Metrics"
    bl_order = 2
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        layout = self.layout
        root = active_root(context)
        s = session.get(root.name)
        if s is None or s.analysis is None:
            layout.label(text="Analyze first" if s is not None else "Not in memory", icon="INFO")
            return
        try:
            metrics = s.metrics()
        except Exception as e:  # noqa: BLE001 - a panel cannot report; say it where the values would be
            layout.label(text="No metrics", icon="ERROR")
            for line in textwrap.wrap(P.describe_error(e), 30):
                layout.label(text=line)
            return
        col = layout.column(align=True)
        for label, text, tip, indented, _ in MB.rows(metrics, import_hbc().METRIC_FIELDS):
            _value_row(col, ("  " if indented else "") + label, tip, text)
        col = layout.column(align=True)
        worst = MB.worst(metrics)
        col.label(text="Worst")
        for kind, _, text, label in worst:
            _value_row(col, "  " + label, f"The {kind} holding the lowest scaled Jacobian (its value in brackets)", text)
        row = layout.row(align=True)
        for kind, i, _, _ in worst:
            sub = row.row(align=True)
            sub.enabled = i is not None
            sub.operator("hbc.show_worst", text=kind.capitalize(), icon="RESTRICT_SELECT_OFF").kind = kind


def layer_controls(context, layout, root, layer):
    """Build / Rebuild and Clear for one layer; greyed out (reason in the tooltip) when the layer
    cannot be built now."""
    coll = S.find_layer(root, layer)
    built = coll is not None
    # A row shares its width equally: beside three icon buttons "Rebuild" would get a quarter of
    # the default sidebar and be cut, so the icons share the split's narrower side.
    row = layout.split(factor=0.55, align=True) if built else layout.row(align=True)
    row.enabled = unavailable(context, layer) is None
    stale = built and bool(coll.get("hbc_stale"))
    row.operator("hbc.build_layer", text="Rebuild" if built else "Build",
                 icon="ERROR" if stale else "FILE_REFRESH").layer = layer
    if built:
        icons = row.row(align=True)
        icons.operator("hbc.frame_layer", text="", icon="ZOOM_SELECTED").layer = layer
        icons.operator("hbc.export_layer", text="", icon="EXPORT").layer = layer
        icons.operator("hbc.clear_layer", text="", icon="X").layer = layer
    if stale:
        layout.label(text="Stale: rebuild", icon="ERROR")
    return coll


class _Layer(_Sub):
    """A layer's sub-panel: eye toggle in the header, Build/Rebuild/Clear, then its options."""

    layer = ""
    bl_parent_id = "HBC_PT_layers"

    def draw_header(self, context):
        coll = S.find_layer(active_root(context), self.layer)
        if coll is not None:
            # An open or a closed eye (the collection's own toggle icons differ only by fill).
            self.layout.operator("hbc.toggle_layer", text="", emboss=False,
                                 icon=visibility_icon(coll, context.view_layer)).layer = self.layer
        else:
            self.layout.label(text="", icon="BLANK1")

    def draw(self, context):
        layer_controls(context, self.layout, active_root(context), self.layer)
        self.draw_options(self.layout.column(), context.scene.hbc)

    def draw_options(self, col, st):
        pass


def visibility_icon(coll, view_layer) -> str:
    """The eye of a layer: open while the viewport draws it, whatever hides it (the panel's own
    eye, the outliner's eyes of the mesh, the layer or its objects)."""
    return "HIDE_OFF" if S.layer_shown(coll, view_layer) else "HIDE_ON"


class HBC_PT_layers(_Sub, bpy.types.Panel):
    bl_idname = "HBC_PT_layers"
    bl_label = "Layers"
    bl_order = 3

    def draw(self, context):
        pass


def _props(*names):
    """A layer's draw_options drawing these settings, one a row."""

    def draw_options(self, col, st):
        for name in names:
            col.prop(st, name)

    return draw_options


def _sheets_options(self, col, st):
    col.prop(st, "sheets_all")
    sheet_columns(col.row(), "Sheet", "Type", "Cells")
    col.template_list("HBC_UL_sheets", "", st, "sheets", st, "sheet_index", rows=5)


def _subsheets_options(self, col, st):
    col.prop(st, "spread")
    if unavailable(bpy.context, "subsheets"):
        col.label(text="Needs type 3", icon="INFO")


def _wireframe_options(self, col, st):
    col.row().prop(st, "wireframe_scope", expand=True)
    col.row().prop(st, "wireframe_colors", expand=True)
    for name in ("opacity_floor", "simplified", "line_radius"):
        col.prop(st, name)


#: The layer sub-panels in their order: layer, title, draw_options.
LAYER_PANELS = (
    ("direct", "Direct view",
     _props("direct_boundary", "direct_transparent", "boundary_opacity", "direct_hex_cells", "direct_shrink")),
    ("graph", "Singularities", _props("line_radius")),
    ("components", "Components", _props("shrink", "split_max")),
    ("sheets", "Sheets", _sheets_options),
    ("sheet", "Picked sheet", _props("auto_show", "dot_radius")),
    ("subsheets", "Subsheets", _subsheets_options),
    ("wireframe", "Wireframe", _wireframe_options),
)


def _layer_panel(order, layer, title, draw_options):
    """The sub-panel class of one layer: Blender registers a class per panel, under its own
    bl_idname, so each layer gets a class of its own made from the table above."""
    name = f"HBC_PT_layer_{layer}"
    return type(name, (_Layer, bpy.types.Panel), {
        "bl_idname": name, "bl_label": title, "bl_order": order, "layer": layer, "draw_options": draw_options})


layer_panels = tuple(_layer_panel(order, *row) for order, row in enumerate(LAYER_PANELS))


def shown_layers(context, root) -> list:
    """The built layers of the mesh that the viewport draws, in panel order."""
    return [layer for layer, _ in P.LAYERS if root is not None and (c := S.find_layer(root, layer)) is not None
            and S.layer_shown(c, context.view_layer)]


def legend_entries(context):
    """planning.legend for the active mesh's built, visible layers and the highlights they hold."""
    root = active_root(context)
    shown = shown_layers(context, root)
    s = session.get(root.name) if root is not None else None
    if s is None:
        return P.legend(shown)
    highlights = {ob.get("hbc_highlight") for layer in ("sheet", "subsheets") if layer in shown
                  for ob in S.objects_in(S.find_layer(root, layer))}
    by_kind = context.scene.hbc.wireframe_colors == "KIND"
    return P.legend(shown, highlights=highlights, wire_by_kind=by_kind, **s.legend_facts())


def panel_legend(context):
    """(the layers shown, [(colour key, words)]): legend_entries and what the palette colours of the
    shown layers mean; in a reopened file (the mesh not in memory yet) from the facts stored on the
    mesh's collection, so the legend is as whole as before."""
    root = active_root(context)
    if root is None:
        return [], []
    shown = shown_layers(context, root)
    if session.get(root.name) is None:
        highlights = {ob.get("hbc_highlight") for layer in ("sheet", "subsheets") if layer in shown
                      for ob in S.objects_in(S.find_layer(root, layer))}
        entries = P.legend(shown, highlights=highlights, **layers.stored_legend_facts(root))
    else:
        entries = legend_entries(context)
    by_kind = getattr(context.scene.hbc, "wireframe_colors", "CLASS") == "KIND"
    return shown, entries + P.palette_legend(shown, wire_by_kind=by_kind)


class HBC_PT_legend(_Sub, bpy.types.Panel):
    """What the colours, dots and edges of the visible layers mean."""

    bl_idname = "HBC_PT_legend"
    bl_label = "Legend"
    bl_order = 4

    def draw(self, context):
        st = context.scene.hbc
        shown, entries = panel_legend(context)
        if not shown:
            self.layout.label(text="No layer shown", icon="INFO")
        col = self.layout.column(align=True)
        for key, words in entries:
            split = col.split(factor=0.15, align=True)
            split.prop(st, f"legend_{key}", text="")
            split.label(text=words)


def picked_component(context):
    """(component or None, owner kind, object) of the selection: a per-owner object, or the
    active face of a merged mesh in edit mode."""
    ob = context.active_object
    if ob is None or not ob.get("hbc_mesh"):
        return None, None, ob
    if "hbc_component" in ob:
        return int(ob["hbc_component"]), "component", ob
    owner_kind = ob.get("hbc_owner")
    if owner_kind and ob.mode == "EDIT" and ob.type == "MESH":
        _, _, owner = merged_owner_faces(ob)
        if owner is not None:
            return owner, owner_kind, ob
    return None, owner_kind, ob


class HBC_PT_selection(_Base, bpy.types.Panel):
    """Always present (and last), so the panels above never move when the selection changes."""

    bl_idname = "HBC_PT_selection"
    bl_label = "Selection"
    bl_parent_id = "HBC_PT_main"
    bl_order = 5

    def draw(self, context):
        layout = self.layout
        ob = context.active_object
        if ob is None or ob.get("hbc_mesh") is None:
            layout.label(text="Nothing picked", icon="RESTRICT_SELECT_OFF")
            return
        layout.label(text=ob.name, icon="OBJECT_DATA")
        col = layout.column(align=True)
        for key in ("hbc_layer", "hbc_sheet", "hbc_sheet_type", "hbc_subsheet", "hbc_highlight", "hbc_count",
                    "hbc_group", "hbc_polylines"):
            if key in ob:
                name, text = key[4:].replace("_", " "), str(ob[key])
                if len(text) > 15:  # a long value (a sheet type's words) on a row of its own
                    col.label(text=name)
                    col.label(text="  " + text)
                    continue
                split = col.split(factor=0.45, align=True)
                split.label(text=name)
                split.label(text=text)
        owner, kind, _ = picked_component(context)
        if owner is None:
            if kind:
                layout.label(text="Edit Mode: pick", icon="INFO")
            return
        layout.label(text=f"{kind}: {owner}")
        if kind != "component" or ob.get("hbc_component") is None:
            row = layout.row(align=True)
            row.operator("hbc.select_component", text="Select", icon="RESTRICT_SELECT_OFF").frame = False
            row.operator("hbc.select_component", text="Frame", icon="ZOOM_SELECTED").frame = True
        s = session.get(ob["hbc_mesh"])
        if kind == "component" and s is not None and s.analysis is not None and owner < s.num_components:
            layout.label(text=f"kind: {P.COMPONENT_KINDS[int(s.component_kinds()[owner])]}")
            types = s.component_cell_types(owner)
            layout.label(text=f"cells: {sum(n for _, n in types)}")
            col = layout.column(align=True)
            for name, n in types:
                split = col.split(factor=0.45, align=True)
                split.label(text=f"  {name}")
                split.label(text=str(n))
            sheets = s.component_sheets(owner)
            layout.label(text="sheets: " + (", ".join(str(int(x)) for x in sheets) or "none"))


class HBC_PT_inspect(_Sub, bpy.types.Panel):
    """Looking inside (blender/inspect.py): filters, the cut plane, the quality colour map."""

    bl_idname = "HBC_PT_inspect"
    bl_label = "Look inside"
    # Below the layers and closed at first: an import shows the layers without scrolling.
    bl_order = 6
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        layout = self.layout
        ins = inspect.settings(context.scene)
        layout.prop(ins, "direct_cells")
        layout.prop(ins, "enabled")
        box = layout.box()
        row = box.row(align=True)
        row.prop(ins, "slice")
        row.prop(ins, "flip")
        row = box.row(align=True)
        row.prop(ins, "plane", text="")
        row.operator("hbc.add_cut_plane", text="", icon="ADD")
        box.prop(ins, "peel")
        box.prop(ins, "surface_above")
        grid = box.grid_flow(columns=2, even_columns=True, align=True)
        for n in IP.TYPE_NAMES:
            grid.prop(ins, f"show_{n}", toggle=True)
        box.prop(ins, "filter_quality")
        row = box.row(align=True)
        row.prop(ins, "quality_min")
        row.prop(ins, "quality_max")
        box.prop(ins, "sheet_only")
        self.draw_quality(layout, context, ins)

    @staticmethod
    def draw_quality(layout, context, ins):
        box = layout.box()
        box.prop(ins, "color_by_quality")
        box.label(text="Scaled Jacobian (viridis)")
        row = box.row(align=True)
        for i in range(len(IP.LEGEND_VALUES)):
            row.prop(ins, f"legend_{i}", text="")
        row = box.row(align=True)
        for v in IP.LEGEND_VALUES:
            row.label(text=f"{v:g}")
        root = active_root(context)
        s = session.get(root.name) if root is not None else None
        histogram = IP.computed_histogram(s) if s is not None else None
        if histogram is None:
            box.label(text="Histogram: build a layer first")
            return
        labels, counts = histogram
        top = max(max(counts), 1)
        col = box.column(align=True)
        for label, c in zip(labels, counts):
            split = col.split(factor=0.3, align=True)
            split.label(text=label)
            split = split.split(factor=0.6, align=True)
            split.label(text="█" * int(round(HISTOGRAM_BAR * c / top)))
            right = split.row()
            right.alignment = "RIGHT"
            right.label(text=str(c))
