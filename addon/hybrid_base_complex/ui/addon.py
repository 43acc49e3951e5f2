"""The one place that registers the add-on with Blender: every class, property, menu entry and
app handler is listed here, registered in list order and unregistered in reverse."""

import sys

import bpy
from bpy.props import PointerProperty

from ..plan import session
from ..plan.native import module_problem
from . import export_ops, handlers, operators, panels, properties

def _bl_info() -> dict:
    """The package's bl_info (Blender 3.4's Preferences read it from the loaded module); an
    empty dict in an extension, whose packing leaves bl_info out (the manifest stands for it)."""
    return getattr(sys.modules[__package__.rpartition(".")[0]], "bl_info", {})


#: Every class, in registration order: a property group after the groups it points to, a panel
#: after its parent (sub-panels of equal bl_order show in this order).
CLASSES = (
    properties.HBCSheetItem,
    properties.HBCSettings,
    properties.HBCInspectSettings,
    operators.HBC_OT_import,
    operators.HBC_OT_analyze,
    operators.HBC_OT_build_layer,
    operators.HBC_OT_build_all,
    operators.HBC_OT_clear_layer,
    operators.HBC_OT_frame_layer,
    operators.HBC_OT_toggle_layer,
    operators.HBC_OT_set_active,
    operators.HBC_OT_copy_table1,
    operators.HBC_OT_explain,
    operators.HBC_OT_help,
    operators.HBC_OT_select_component,
    operators.HBC_OT_select_block,
    operators.HBC_OT_show_worst,
    operators.HBC_OT_add_cut_plane,
    export_ops.HBC_OT_export_vtu,
    export_ops.HBC_OT_export_layer,
    export_ops.HBC_OT_render_figures,
    panels.HBC_UL_sheets,
    panels.HBC_PT_main,
    panels.HBC_PT_table1,
    panels.HBC_PT_metrics,
    panels.HBC_PT_layers,
    *panels.layer_panels,
    panels.HBC_PT_legend,
    panels.HBC_PT_selection,
    panels.HBC_PT_inspect,
)

#: (Blender type, attribute, property) added to Blender's types once the classes are registered.
PROPERTIES = (
    (bpy.types.Scene, "hbc", PointerProperty(type=properties.HBCSettings)),
    (bpy.types.Scene, "hbc_inspect", PointerProperty(type=properties.HBCInspectSettings)),
    (bpy.types.Collection, "hbc_path", properties.source_path_property()),
)

#: (menu, draw function appended to it).
MENUS = (
    (bpy.types.TOPBAR_MT_file_import, operators.menu_import),
)

#: (bpy.app.handlers list, handler).
HANDLERS = (
    ("depsgraph_update_post", handlers.on_depsgraph),
    ("undo_post", handlers.on_undo),
    ("redo_post", handlers.on_undo),
    ("load_post", handlers.on_load),
    ("save_pre", handlers.on_save_pre),
    ("save_post", handlers.on_save_post),
)


def register():
    guide = operators.help_url()
    for key, url in (("doc_url", guide), ("tracker_url", guide + "#reporting-a-problem")):
        _bl_info()[key] = url
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    for owner, name, prop in PROPERTIES:
        setattr(owner, name, prop)
    for menu, draw in MENUS:
        menu.append(draw)
    for event, fn in HANDLERS:
        getattr(bpy.app.handlers, event).append(fn)
    # Registered either way (menus and panel stay usable); the panel and every operator say why
    # nothing can be analyzed, and so does the console.
    problem = module_problem()
    if problem:
        print(f"Hybrid Base Complex: {problem}", flush=True)


def unregister():
    for event, fn in reversed(HANDLERS):
        fns = getattr(bpy.app.handlers, event)
        if fn in fns:
            fns.remove(fn)
    for menu, draw in reversed(MENUS):
        menu.remove(draw)
    for owner, name, _ in reversed(PROPERTIES):
        delattr(owner, name)
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
    session.clear()
