"""Calls whose form depends on the Blender version (3.4 and the 4.x/5.x bpy wheels), in one place."""

from __future__ import annotations

import bpy


def view3d_regions(context):
    """(window, area, region) of every 3D viewport's main region (none in background mode)."""
    wm = context.window_manager
    for window in getattr(wm, "windows", []):
        for area in window.screen.areas:
            if area.type != "VIEW_3D":
                continue
            for region in area.regions:
                if region.type == "WINDOW":
                    yield window, area, region


def frame_objects(context, objects) -> bool:
    """Frames `objects` in every 3D viewport (selects them, makes the first active). False when
    there is no viewport (background mode). context.temp_override exists from 3.2 on."""
    regions = list(view3d_regions(context))
    if not regions:
        return False
    context.view_layer.update()  # objects linked in this same operator join the view layer here
    objects = [ob for ob in objects if ob.name in context.view_layer.objects]
    if not objects:
        return False
    for ob in context.view_layer.objects:
        if ob.select_get():
            ob.select_set(False)
    for ob in objects:
        ob.select_set(True)
    context.view_layer.objects.active = objects[0]
    for window, area, region in regions:
        with context.temp_override(window=window, area=area, region=region):
            bpy.ops.view3d.view_selected()
    return True


def frame_edit_selection(context) -> bool:
    """Frames the selected elements of the mesh in edit mode in every 3D viewport."""
    regions = list(view3d_regions(context))
    for window, area, region in regions:
        with context.temp_override(window=window, area=area, region=region):
            bpy.ops.view3d.view_selected()
    return bool(regions)
