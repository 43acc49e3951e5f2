"""Scene settings of the add-on (bpy.types.Scene.hbc) and the sheet list items."""

import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty, FloatVectorProperty,
                       IntProperty, PointerProperty, StringProperty)


from . import planning as P


class HBCSheetItem(bpy.types.PropertyGroup):
    index: IntProperty()
    type: IntProperty(description="0 perfect, 1 non-hex (type 1), 2 self-parallel, 3 self-intersecting")
    cells: IntProperty()
    components: IntProperty()


def _legend_color(color):
    return FloatVectorProperty(subtype="COLOR", size=4, min=0.0, max=1.0, get=lambda self: tuple(color),
                               description="Legend colour (read-only)")


class HBCSettings(bpy.types.PropertyGroup):
    active_mesh: StringProperty(name="Mesh", description="Root collection of the mesh the panel acts on")

    # direct view
    direct_boundary: BoolProperty(name="Boundary", default=True, description="Show the boundary surface")
    direct_transparent: BoolProperty(name="See-through", default=True,
                                     description="Draw the boundary transparent so the inside shows")
    boundary_alpha: FloatProperty(name="Alpha", default=0.15, min=0.0, max=1.0,
                                  description="Opacity of the see-through boundary")
    direct_hex_cells: BoolProperty(name="Hex region", default=False,
                                   description="Also show the surface of the hex region as an opaque solid")
    direct_shrink: FloatProperty(name="Shrink", default=0.0, min=0.0, max=0.9,
                                 description="Pull every non-hex cell towards its centre")

    # blocks, sheets
    shrink: FloatProperty(name="Shrink", default=0.1, min=0.0, max=0.9,
                          description="Pull every block towards its centre to separate blocks")
    split_max: IntProperty(name="Max objects", default=1000, min=0,
                           description="Up to this many blocks, one object per block (clickable); "
                                       "more: one merged mesh with a face attribute 'owner'")
    sheets: CollectionProperty(type=HBCSheetItem)
    sheet_index: IntProperty(name="Sheet", default=0, min=0, update=lambda self, context: _sheet_picked(self, context))
    auto_show: BoolProperty(name="Show on pick", default=True,
                            description="Rebuild the picked-sheet layer when another sheet is picked in the list")
    sheets_all: BoolProperty(name="All sheets", default=False,
                             update=lambda self, context: _sheets_visibility(self),
                             description="Show every sheet of the sheets layer at once (they overlap); "
                                         "off: only the picked sheet")
    sheet_sort: EnumProperty(name="Sort", default="INDEX",
                             items=[("INDEX", "Index", "Sheets in analysis order"),
                                    ("TYPE", "Type", "By type, then size (largest first)"),
                                    ("SIZE", "Size", "By number of cells, largest first")],
                             description="Order of the sheet list")

    # lines
    line_radius: FloatProperty(name="Tube", default=0.0035, min=0.0, max=0.1, precision=4,
                               description="Tube radius of the lines, as a fraction of the model's diagonal")
    dot_radius: FloatProperty(name="Dot", default=0.006, min=0.0, max=0.1, precision=4,
                              description="Radius of the highlight dots, as a fraction of the model's diagonal")

    # wireframe
    rho: FloatProperty(name="ρ", default=0.8, min=0.0, max=1.0,
                       description="Partial-parallel threshold of the wireframe colours (re-analyzes)")
    opacity_floor: FloatProperty(name="Floor", default=0.15, min=0.0, max=1.0,
                                 description="Opacity of the faintest (farthest) wireframe lines")
    simplified: BoolProperty(name="Simplified", default=True,
                             description="Only the important polylines (and those keeping it connected)")
    wireframe_scope: EnumProperty(name="Scope", description="Wireframe of the whole mesh or of the picked sheet", items=[("MESH", "Mesh", "The whole mesh's wireframe"),
                                                       ("SHEET", "Sheet", "The picked sheet's wireframe")])
    spread: BoolProperty(name="Side by side", default=True,
                         description="Lay subsheets out side by side with their wireframe beneath")



def _sheets_visibility(settings):
    from . import layers, scene

    root = layers.find_root(settings.active_mesh) if settings.active_mesh else None
    coll = scene.find_layer(root, "sheets") if root is not None else None
    if coll is not None:
        layers.show_sheets([ob for ob in scene.objects_in(coll) if "hbc_sheet" in ob], settings)


def _sheet_picked(settings, context):
    """Picking a sheet in the list: the sheets layer shows it, the subsheets layer (of another
    sheet) is marked stale and hidden, and the picked-sheet layer is rebuilt (with auto_show)."""
    if not settings.active_mesh:
        return
    from . import layers, scene, session

    root = layers.find_root(settings.active_mesh)
    if root is None:
        return
    _sheets_visibility(settings)
    sub = scene.find_layer(root, "subsheets")
    if sub is not None:
        stale = any(ob.get("hbc_sheet") != settings.sheet_index for ob in scene.objects_in(sub))
        if stale != bool(sub.get("hbc_stale")):  # hidden while stale, shown again when current
            sub.hide_viewport = stale
        sub["hbc_stale"] = stale
    s = session.get(settings.active_mesh)
    if not settings.auto_show or s is None or s.analysis is None or scene.find_layer(root, "sheet") is None:
        return
    if 0 <= settings.sheet_index < s.num_sheets:
        try:
            layers.build_layer(root, "sheet", s, settings)
        except Exception as e:  # noqa: BLE001 - an update callback cannot report; the layer stays as it was
            print(f"hbc: could not show sheet {settings.sheet_index}: {P.describe_error(e)}")


# Legend swatches: one read-only colour property per planning.LEGEND_COLORS key.
HBCSettings.__annotations__.update({f"legend_{k}": _legend_color(c) for k, c in P.LEGEND_COLORS.items()})

classes = (HBCSheetItem, HBCSettings)


def _get_source(root):
    return root.get("hbc_source", "")


def _set_source(root, value):
    from . import session

    root["hbc_source"] = value
    session.drop(root.name)  # read again from the new path on the next build


def register_props():
    bpy.types.Scene.hbc = PointerProperty(type=HBCSettings)
    # The source path lives in the ID property "hbc_source" (it marks a collection as an imported
    # mesh); this file-path view of it gives the panel a file browser to point the mesh at its file
    # again. A get/set property stores nothing itself, so both stay one value in every Blender
    # (5.0 keeps bpy.props values apart from dictionary-style ID properties).
    bpy.types.Collection.hbc_path = StringProperty(
        name="Source", subtype="FILE_PATH", get=_get_source, set=_set_source,
        description="The mesh file the layers are built from (relative to the .blend when saved)")


def unregister_props():
    del bpy.types.Collection.hbc_path
    del bpy.types.Scene.hbc
