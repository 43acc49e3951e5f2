"""Export operators of the panel: the active mesh's analysis as VTU (the library's writer) and a
built layer as OBJ or PLY (Blender's exporters, blender/export.py says why). Both write files
only: no undo step, and a failure reports what went wrong and cancels."""

from __future__ import annotations

import os
import time

import bpy
from bpy.props import BoolProperty, EnumProperty, StringProperty
from bpy_extras.io_utils import ExportHelper

from ..blender import export as E
from ..blender.context import active_root, structure_of
from ..plan import planning as P
from .operators import LAYER_ITEMS, _Reporting, make_log


class _ExportOnActiveMesh(_Reporting, ExportHelper):
    bl_options = {"REGISTER"}  # writes a file, changes nothing in the scene to undo

    @classmethod
    def poll(cls, context):
        return active_root(context) is not None

    def invoke(self, context, event):
        if not self.filepath:
            # The file browser opens on the mesh's own name beside the .blend (or the mesh file).
            root = active_root(context)
            folder = os.path.dirname(bpy.data.filepath or bpy.path.abspath(root.get("hbc_source", "")))
            self.filepath = os.path.join(folder, bpy.path.clean_name(root.name) + self.suffix())
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}

    def check(self, context):
        path = bpy.path.ensure_ext(self.filepath, self.suffix())
        changed, self.filepath = path != self.filepath, path
        return changed

    def suffix(self) -> str:
        return self.filename_ext


class HBC_OT_export_vtu(_ExportOnActiveMesh, bpy.types.Operator):
    """Write the active mesh's cells with their block (component) and sheet ids to a VTU file for ParaView, and its singularity graph beside it (_graph.vtu)"""

    bl_idname = "hbc.export_vtu"
    bl_label = "Export Analysis (VTU)"

    filename_ext = ".vtu"
    filter_glob: StringProperty(default="*.vtu", options={"HIDDEN"})
    picked_sheet: BoolProperty(name="Picked sheet", default=False,
                               description="Also mark the cells and subsheets of the sheet picked in the sheet list "
                                           "(in_sheet, subsheet arrays)")

    def execute(self, context):
        root = active_root(context)
        st = context.scene.hbc
        log = make_log(context)
        t0 = time.perf_counter()
        try:
            s = structure_of(root, True, log, st.rho)
            sheet = st.sheet_index if self.picked_sheet and s.num_sheets else None
            paths = E.export_vtu(s, bpy.path.abspath(self.filepath), sheet)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e)
        return self.finish_with(f"Wrote {' and '.join(paths)} in {time.perf_counter() - t0:.2f} s", log)


class HBC_OT_export_layer(_ExportOnActiveMesh, bpy.types.Operator):
    """Write a built layer of the active mesh as it is shown (its visible objects) to an OBJ or PLY file"""

    bl_idname = "hbc.export_layer"
    bl_label = "Export Layer"

    filename_ext = ".obj"
    filter_glob: StringProperty(default="*.obj;*.ply", options={"HIDDEN"})
    layer: EnumProperty(name="Layer", items=LAYER_ITEMS)
    format: EnumProperty(name="Format", items=[("OBJ", "OBJ", "Wavefront OBJ"), ("PLY", "PLY", "Stanford PLY")])

    def suffix(self) -> str:
        return "." + self.format.lower()

    def execute(self, context):
        root = active_root(context)
        log = make_log(context)
        path = bpy.path.ensure_ext(bpy.path.abspath(self.filepath), self.suffix())
        try:
            n = E.export_layer(context, root, self.layer, path, self.format)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e)
        return self.finish_with(f"Wrote {P.LAYER_TITLES[self.layer]} ({n} objects) to {path}", log)
