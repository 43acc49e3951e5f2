"""Export operators of the panel: the active mesh's analysis as VTU (the library's writer), a
built layer as OBJ or PLY (Blender's exporters, blender/export.py says why), and its figures
(the add-on's own figures/render_figures.py in a separate Blender process, polled by a modal
operator). All write files only: no undo step, and a failure reports what went wrong and cancels."""

from __future__ import annotations

import os
import sys
import time

import bpy
from bpy.props import BoolProperty, EnumProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ExportHelper

from ..blender import export as E
from ..blender import sources
from ..blender.context import active_root, structure_of, subsheet_rule
from ..plan import figures_job
from ..plan import native
from ..plan import planning as P
from .operators import LAYER_ITEMS, _Reporting, active_job, make_log


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

    #: The extensions of the operator's other formats, replaced when the format changes.
    other_suffixes = ()  # no annotation: Blender would take it for a property

    def check(self, context):
        path = P.with_extension(self.filepath, self.suffix(), self.other_suffixes)
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
        root, st, log, t0 = active_job(context)
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
    other_suffixes = tuple("." + fmt.lower() for fmt in E.LAYER_FORMATS)

    def suffix(self) -> str:
        return "." + self.format.lower()

    def execute(self, context):
        root = active_root(context)
        log = make_log(context)
        path = P.with_extension(bpy.path.abspath(self.filepath), self.suffix(), self.other_suffixes)
        try:
            n = E.export_layer(context, root, self.layer, path, self.format)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e)
        return self.finish_with(f"Wrote {P.LAYER_TITLES[self.layer]} ({n} objects) to {path}", log)


#: The add-on package's folder: the figures it ships (figures/render_figures.py) are found there.
ADDON_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _figures_problem():
    """Why the figures cannot run in this Blender (plan/figures_job.py), or None."""
    return figures_job.problem(ADDON_DIR, bpy.app.binary_path, sys.executable, native.module_problem())


class HBC_OT_render_figures(_Reporting, bpy.types.Operator):
    """Render the paper-style figures of the active mesh (pipeline panels and a contact sheet) into a folder, in a separate Blender process; Esc cancels"""

    bl_idname = "hbc.render_figures"
    bl_label = "Render Figures"
    bl_options = {"REGISTER"}  # writes files only

    directory: StringProperty(name="Folder", subtype="DIR_PATH")
    filter_folder: BoolProperty(default=True, options={"HIDDEN"})
    engine: EnumProperty(name="Engine", items=[("cycles", "Cycles", "Path traced, denoised where Blender can"),
                                               ("eevee", "EEVEE", "Rasterized"),
                                               ("workbench", "Workbench", "Fastest")])
    width: IntProperty(name="Width", default=640, min=16, max=8192)
    height: IntProperty(name="Height", default=480, min=16, max=8192)
    samples: IntProperty(name="Samples", default=16, min=1, max=4096)
    wait: BoolProperty(name="Wait", default=False, options={"HIDDEN", "SKIP_SAVE"},
                       description="Run to the end before returning (scripts; always in background mode)")

    @classmethod
    def poll(cls, context):
        return active_root(context) is not None

    @classmethod
    def description(cls, context, properties):
        return _figures_problem() or cls.__doc__

    def invoke(self, context, event):
        # Checked before the file browser opens: nobody picks a folder and an engine for nothing.
        why = _figures_problem()
        if why:
            self.report({"ERROR"}, why)
            return {"CANCELLED"}
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}

    def execute(self, context):
        root = active_root(context)
        why = _figures_problem()
        if why:
            self.report({"ERROR"}, why)
            return {"CANCELLED"}
        try:
            mesh = sources.resolve(root)
            out = bpy.path.abspath(self.directory) or os.path.dirname(mesh)
            cmd = figures_job.command(bpy.app.binary_path, sys.executable, figures_job.find_script(ADDON_DIR), mesh,
                                      out, self.engine, (self.width, self.height), self.samples,
                                      subsheet_rule=subsheet_rule(context.scene))
            env = figures_job.child_env(os.environ, sys.executable, native.import_hbc().__file__, ADDON_DIR)
            self._job = figures_job.Job(cmd, env=env)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e)
        self._log = make_log(context)
        self._log(f"hbc: rendering the figures of {root.name} into {out}")
        self._t0 = time.perf_counter()
        if self.wait or bpy.app.background:
            while (status := self._job.poll()) is None:
                time.sleep(0.1)
            return self._end(context, status)
        wm = context.window_manager
        wm.progress_begin(0, 100)
        self._timer = wm.event_timer_add(0.25, window=context.window)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type == "ESC":
            self._job.cancel()
            return self._end(context, self._job.poll())
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        status = self._job.poll()
        context.window_manager.progress_update(int(100 * self._job.fraction))
        context.workspace.status_text_set(f"Rendering figures ({len(self._job.written)} files, Esc cancels): "
                                          f"{self._job.last[:80]}")
        return {"PASS_THROUGH"} if status is None else self._end(context, status)

    def _end(self, context, status):
        if getattr(self, "_timer", None) is not None:
            context.window_manager.event_timer_remove(self._timer)
            context.window_manager.progress_end()
            context.workspace.status_text_set(None)
        job, seconds = self._job, time.perf_counter() - self._t0
        if job.cancelled:
            self.report({"WARNING"}, f"Figures cancelled after {seconds:.0f} s ({len(job.written)} files written)")
            return {"CANCELLED"}
        if status != 0:
            for line in job.tail:
                self._log(line)
            self.report({"ERROR"}, f"Rendering the figures failed (exit {status}): {job.tail[-1] if job.tail else ''}")
            return {"CANCELLED"}
        contact = [p for p in job.written if p.endswith("_contact.png")]
        return self.finish_with(f"Wrote {len(job.written)} figure files in {seconds:.0f} s"
                                + (f": {contact[0]}" if contact else ""), self._log)
