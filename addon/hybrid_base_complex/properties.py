"""Scene settings of the add-on (bpy.types.Scene.hbc) and the sheet list items."""

import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty, IntProperty,
                       PointerProperty, StringProperty)


class HBCSheetItem(bpy.types.PropertyGroup):
    index: IntProperty()
    type: IntProperty(description="0 perfect, 1, 2 self-parallel, 3 self-intersecting")
    cells: IntProperty()
    components: IntProperty()


class HBCSettings(bpy.types.PropertyGroup):
    active_mesh: StringProperty(name="Mesh", description="Root collection of the mesh the panel acts on")

    # direct view
    direct_boundary: BoolProperty(name="Boundary", default=True, description="Show the boundary surface")
    direct_transparent: BoolProperty(name="Transparent", default=True)
    boundary_alpha: FloatProperty(name="Alpha", default=0.15, min=0.0, max=1.0)
    direct_hex_cells: BoolProperty(name="Hex region", default=False,
                                   description="Also show the surface of the hex region as an opaque solid")
    direct_shrink: FloatProperty(name="Cell shrink", default=0.0, min=0.0, max=0.9)

    # blocks, sheets
    shrink: FloatProperty(name="Shrink", default=0.1, min=0.0, max=0.9,
                          description="Pull every block towards its centre to separate blocks")
    split_max: IntProperty(name="Objects up to", default=1000, min=0,
                           description="Up to this many blocks, one object per block (clickable); "
                                       "more: one merged mesh with a face attribute 'owner'")
    sheets: CollectionProperty(type=HBCSheetItem)
    sheet_index: IntProperty(name="Sheet", default=0, min=0, update=lambda self, context: _sheet_picked(self, context))
    auto_show: BoolProperty(name="Show on pick", default=True,
                            description="Rebuild the picked-sheet layer when another sheet is picked in the list")

    # lines
    line_radius: FloatProperty(name="Curve radius", default=0.0035, min=0.0, max=0.1, precision=4,
                               description="Tube radius as a fraction of the model's diagonal")
    dot_radius: FloatProperty(name="Dot radius", default=0.006, min=0.0, max=0.1, precision=4)

    # wireframe
    rho: FloatProperty(name="ρ", default=0.8, min=0.0, max=1.0,
                       description="Partial-parallel threshold of the wireframe colours (re-analyzes)")
    opacity_floor: FloatProperty(name="Opacity floor", default=0.15, min=0.0, max=1.0)
    simplified: BoolProperty(name="Simplified", default=True)
    wireframe_scope: EnumProperty(name="Scope", items=[("MESH", "Whole mesh", ""), ("SHEET", "Picked sheet", "")])
    spread: BoolProperty(name="Side by side", default=True,
                         description="Lay subsheets out side by side with their wireframe beneath")


def _sheet_picked(settings, context):
    """Picking a sheet in the list shows it (when the picked-sheet layer is on and auto_show)."""
    if not settings.auto_show or not settings.active_mesh:
        return
    from . import layers, scene, session

    root = layers.find_root(settings.active_mesh)
    s = session.get(settings.active_mesh)
    if root is None or s is None or s.analysis is None or scene.find_layer(root, "sheet") is None:
        return
    if 0 <= settings.sheet_index < s.num_sheets:
        try:
            layers.build_layer(root, "sheet", s, settings)
        except Exception as e:  # noqa: BLE001 - an update callback cannot report; the layer stays as it was
            print(f"hbc: could not show sheet {settings.sheet_index}: {e}")


classes = (HBCSheetItem, HBCSettings)


def register_props():
    bpy.types.Scene.hbc = PointerProperty(type=HBCSettings)


def unregister_props():
    del bpy.types.Scene.hbc
