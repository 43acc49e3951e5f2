"""Operators: import, analyze, build / clear layers, copy the Table 1 row, select a merged owner
(component or sheet), add a cut plane. All undoable; a failure reports what went wrong (the message, not a Python
class), cancels (so Blender records no undo step) and leaves the scene as it was; a success
reports what was built and how long it took.

The builds that can take long (import, Build Layer, Build All) are jobs (plan/steps.py): run from a
script or in background mode at once, and started from the window's buttons or file browser as
modal operators in steps, the C++ work in a worker thread and the scene written between redraws,
with progress in the status bar; Esc cancels, leaving the scene and the undo history as they were."""

from __future__ import annotations

import os
import pathlib
import time

import bpy
import mathutils
import numpy as np
from bpy.props import BoolProperty, EnumProperty, FloatProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

from ..blender import compat
from ..blender import inspect
from ..blender import layers as L
from ..blender import scene as S
from ..blender import sources
from ..blender import stepping
from ..blender.context import (active_root, fill_sheet_list, find_root, merged_owner_faces,
                               refresh_subsheets_stale, select_owner, structure_found, structure_of,
                               structure_ready, structure_request, subsheet_rule, unavailable)
from ..plan import metrics_box as MB
from ..plan import planning as P
from ..plan import session
from ..plan import steps
from ..plan.steps import Phase, Work

# The file browser's filter: every extension the readers take, as files spell it and in lower case,
# and OpenFOAM's owner file.
FILTER = ";".join(sorted({f"*{e}" for x in P.mesh_extensions() for e in (x, x.lower())}) + list(P.MESH_FILE_NAMES)) or "*"


def LAYER_ITEMS(_self, _context):  # noqa: N802 - an enum's items, as a callback
    """The layer choices: the library's layers (planning.layer_items), asked when a choice is made
    so that the add-on registers without the compiled module."""
    return P.layer_items()


def make_log(context):
    """Progress messages: printed on the terminal always (the user guide asks for those `hbc:` lines
    in a report, from the window as from background mode), and in a window shown in the status bar
    too."""
    def log(msg):
        print(msg, flush=True)
        if not bpy.app.background:
            try:
                context.workspace.status_text_set(msg)
            except (AttributeError, RuntimeError):
                pass  # no workspace to show it in (a script's context): the terminal has it
    return log


def active_job(context):
    """What an operator on the active mesh starts from: the mesh's root collection, the scene's
    settings, the log and the clock (for the time its report gives)."""
    return active_root(context), context.scene.hbc, make_log(context), time.perf_counter()


def progress_line(fraction, message):
    """A step of a build as printed on the terminal (the user guide's `hbc:` lines)."""
    return f"hbc: [{int(100 * fraction):3d}%] {message}"


def model_boxes():
    """(lo, hi) world boxes of every imported mesh's objects (where new imports must not land)."""
    boxes = []
    for root in (c for c in bpy.data.collections if c.get("hbc_source") is not None):
        pts = [ob.matrix_world @ mathutils.Vector(corner) for ob in S.objects_in(root) if ob.type == "MESH"
               for corner in ob.bound_box]  # not the cut plane's Empty
        if pts:
            boxes.append((tuple(min(p[i] for p in pts) for i in range(3)), tuple(max(p[i] for p in pts) for i in range(3))))
    return boxes


def push_undo_step(message):
    """One undo step named `message` for what an operator without the "UNDO" option did (none
    where Blender has no undo stack: background mode without one)."""
    if bpy.ops.ed.undo_push.poll():
        bpy.ops.ed.undo_push(message=message)


class _Reporting:
    """How the operators end: one report, also written to the log when given."""

    def cancel_with(self, context, error, wrap=False):
        """Reports a failure and cancels; the scene was not touched (builds are all or nothing).
        wrap: the report in lines (planning.wrap_message) in a window: run from the file browser,
        Blender shows an operator's reports in a popup, one line per line of the report, each cut
        at the popup's width."""
        text = P.describe_error(error)
        print(f"hbc: failed: {text}", flush=True)  # on the terminal with the steps before it
        self.report({"ERROR"}, "\n".join(P.wrap_message(text)) if wrap and not bpy.app.background else text)
        return {"CANCELLED"}

    def finish_with(self, done, log=None):
        """Reports what was done and finishes."""
        if log is not None:
            log("hbc: " + done)
        self.report({"INFO"}, done)
        return {"FINISHED"}


class _OnActiveMesh(_Reporting):
    """Operators that act on the mesh the Hex Structure panel shows."""

    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return active_root(context) is not None


class _Stepped(_Reporting):
    """A build that can take long, as a job (plan/steps.py): `job(context, log)` gives (the job, its
    phases, what to do with its result on success). At once (execute) from a script or in
    background mode; started from the window (invoke, or the file browser's execute), a modal
    operator: a timer steps the job between redraws, the window shows the progress, Esc cancels
    (the job's transactions roll back; Blender records no undo step for a cancelled operator)."""

    _stepper = None
    _window = None

    def job(self, context, log):
        raise NotImplementedError

    def run_now(self, context):
        """The whole job at once, its C++ work inline; the window manager's counter and the status
        text still follow it (drawn when there is a window: compat.redraw_status)."""
        wm, log = context.window_manager, make_log(context)

        def report(fraction, message):
            wm.progress_update(int(100 * fraction))
            log(progress_line(fraction, message))
            compat.redraw_status(context)

        t0 = time.perf_counter()
        wm.progress_begin(0, 100)
        try:
            job, plan, finish = self.job(context, log)
            stepper = steps.Stepper(job, plan, threads=False, report=report)
            result = stepper.run()
        except Exception as e:  # noqa: BLE001 - any failure must cancel cleanly
            return self.cancel_with(context, e, wrap=True)
        finally:
            wm.progress_end()
            if not bpy.app.background:
                try:
                    context.workspace.status_text_set(None)
                except (AttributeError, RuntimeError):
                    pass
        return finish(context, result, stepper.times, time.perf_counter() - t0, log)

    def start_steps(self, context):
        """Starts the job as a modal operator in the window."""
        try:
            job, plan, finish = self.job(context, print)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e, wrap=True)
        self._window = stepping.WindowProgress(context, self.bl_label)
        self._stepper = steps.Stepper(job, plan, threads=True, report=self._report)
        self._finish, self._t0 = finish, time.perf_counter()
        self._since = self._t0  # the end of the last step: what the window took since then
        context.window_manager.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _report(self, fraction, message):
        print(progress_line(fraction, message), flush=True)
        self._window.show(fraction, message)

    def step(self, context):
        """One timer event's share of the job; the operator's result once it has ended."""
        try:
            done = self._stepper.advance(stepping.budget(self._since))
            self._since = time.perf_counter()
        except Exception as e:  # noqa: BLE001
            self._window.end()
            return self.cancel_with(context, e, wrap=True)
        if not done:
            self._window.show(self._stepper.fraction, self._stepper.message)
            return {"RUNNING_MODAL"}
        self._window.end()
        return self._finish(context, self._stepper.result, self._stepper.times, time.perf_counter() - self._t0,
                            make_log(context))

    def cancel_steps(self, context):
        """Esc: the job ends where it stands and rolls back."""
        self._stepper.cancel()
        self._window.end()
        text = f"{self.bl_label} cancelled: the scene is as it was"
        print(f"hbc: {text}", flush=True)
        self.report({"WARNING"}, text)
        return {"CANCELLED"}

    def modal(self, context, event):
        if event.type == "ESC" and event.value == "PRESS":
            return self.cancel_steps(context)
        if event.type == "TIMER":  # ours (the event does not say which timer): one more step
            return self.step(context)
        return {"RUNNING_MODAL"}  # nothing else while the scene is half written

    def cancel(self, context):
        """Blender ends the operator (the window closes, the file is reloaded)."""
        if self._stepper is not None and not self._stepper.done:
            try:
                self._stepper.cancel()
                self._window.end()
            except (ReferenceError, RuntimeError) as e:  # the file already went: nothing to put back
                print(f"hbc: {self.bl_label} ended: {e}", flush=True)


class HBC_OT_import(_Stepped, bpy.types.Operator, ImportHelper):
    """Import a hex-dominant volume mesh and show it (optionally analyzed)"""

    @classmethod
    def description(cls, context, properties):
        exts = ", ".join(sorted(P.mesh_extensions(), key=str.lower))
        return f"Import a hex-dominant volume mesh ({exts}) and show it (optionally analyzed)"

    bl_idname = "import_mesh.hbc"
    bl_label = "Import Hex-dominant Mesh"
    # No "UNDO": run from the file browser, Blender 3.x pushes an undo step for an UNDO operator
    # even when it cancels; the import pushes its own step when it succeeds (push_undo_step).
    bl_options = {"REGISTER", "PRESET"}

    filename_ext = ".mesh"
    filter_glob: StringProperty(default=FILTER, options={"HIDDEN"})
    scale: FloatProperty(name="Scale", default=1.0, min=1e-6, soft_max=100.0)
    analyze: BoolProperty(name="Analyze", default=True,
                          description="Analyze on import: singularity graph, base complex, sheets and wireframe")
    build_layers: BoolProperty(name="Build layers", default=False,
                               description="Also build the singularity graph, components and wireframe layers")
    beside: BoolProperty(name="Place beside", default=True,
                         description="Place the mesh to the right of the meshes already imported")
    frame: BoolProperty(name="Frame", default=True, description="Frame the imported mesh in the 3D views")
    skip_invalid: BoolProperty(name="Skip invalid cells", default=False,
                               description="Drop the cells that cannot be volumes (one face, open, a face in three "
                                           "cells; docs/check.md) instead of refusing the file; the report says which")

    stepped: BoolProperty(name="In steps", default=False, options={"HIDDEN", "SKIP_SAVE"},
                          description="Import in steps between the window's redraws (set when started from the window)")

    def invoke(self, context, event):
        self.stepped = stepping.in_window(context)  # the file browser then calls execute
        return ImportHelper.invoke(self, context, event)

    def execute(self, context):
        if self.stepped and stepping.in_window(context):
            return self.start_steps(context)
        return self.run_now(context)

    def job(self, context, log):
        path = os.path.abspath(self.filepath)
        if not os.path.isfile(path):
            raise FileNotFoundError(f"No such file: {path}")
        layers = ["direct"] + (["graph", "components", "wireframe"] if self.build_layers and self.analyze else [])
        options = dict(scale=self.scale, analyze=self.analyze, beside=self.beside, skip_invalid=self.skip_invalid)
        return (import_steps(context.scene, path, layers, log, **options), steps.import_phases(self.analyze, layers),
                self._finish_import)

    def _finish_import(self, context, result, times, seconds, log):
        root, s = result
        st = context.scene.hbc
        session.put(root.name, s)
        st.active_mesh = root.name
        fill_sheet_list(st, s)
        if self.frame:
            with S.selectable(S.objects_in(root)):
                compat.frame_objects(context, S.objects_in(root))
        push_undo_step(self.bl_label)
        report_times = {k: v for k, v in times.items() if k in ("load", "analysis")}
        report_times["scene"] = sum(v for k, v in times.items() if k not in ("load", "analysis"))
        return self.finish_with(P.import_report(root.name, s.num_cells, s.num_components if s.has_analysis else None,
                                                s.num_sheets if s.has_analysis else None,
                                                len(S.objects_in(root)), report_times, seconds,
                                                session.dropped_text(s.mesh.dropped)), log)


def import_steps(scene, path, layers, log, scale=1.0, analyze=True, beside=True, skip_invalid=False):
    """The import as a job: the file read and analysed (worker thread), placed beside the meshes
    already there, then its collection with `layers` built and linked at the end: all or nothing
    (the transaction removes what was made when a step fails or the job is cancelled). Returns
    (root collection, Structure)."""
    yield Phase("load", f"loading {os.path.basename(path)}")
    s = yield Work(session.load, path, scale, log, (0.0, 0.0, 0.0), skip_invalid)
    if beside:
        s.set_offset(P.beside(model_boxes(), *s.bbox()))
    yield f"loaded {s.num_cells} cells"
    if analyze:
        yield Phase("analysis", f"analyzing {s.num_cells} cells")
        yield Work(session.analyze, s, scene.hbc.rho, log, subsheet_rule(scene))
        yield f"analyzed: {s.num_components} components, {s.num_sheets} sheets"
    st = scene.hbc
    with S.Transaction() as tx:
        root = tx.collection(P.mesh_name_from_path(path))
        root["hbc_source"] = sources.stored(path)
        root["hbc_scale"] = float(scale)
        root["hbc_offset"] = [float(x) for x in s.offset]
        root["hbc_rho"] = float(st.rho)
        root["hbc_cells"] = int(s.num_cells)
        if skip_invalid:
            root["hbc_skip_invalid"] = True  # read again the same way (blender/context.py)
        for layer in layers:
            yield Phase(layer, f"building {P.LAYER_TITLES[layer]}")
            coll = yield from L.build_into_steps(tx, root, layer, s, st)
            S.swap_layer(root, layer, coll, tx)
            yield f"built {P.LAYER_TITLES[layer]}"
        scene.collection.children.link(root)
    return root, s


def structure_steps(tx, root, analyzed, log, rho):
    """The mesh's Structure as structure_of gives it, read and analysed in a worker thread when not
    in memory (the phase "analysis"), what it found stored through `tx`."""
    path, ensure = structure_request(root, analyzed, log, rho)
    if structure_ready(root, analyzed):
        s = ensure()
    else:
        yield Phase("analysis", f"reading and analyzing {root.name}" if session.get(root.name) is None
                    else f"analyzing {root.name}")
        s = yield Work(ensure)
        yield "analysis ready"
    structure_found(root, path, analyzed, tx)
    return s


class HBC_OT_analyze(_OnActiveMesh, bpy.types.Operator):
    """Analyze the active hex-dominant mesh (again)"""

    bl_idname = "hbc.analyze"
    bl_label = "Analyze"

    def execute(self, context):
        root, st, log, t0 = active_job(context)
        try:
            s = structure_of(root, False, log)
            session.analyze(s, st.rho, log, subsheet_rule(context.scene))
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e)
        root["hbc_rho"] = float(st.rho)
        st.active_mesh = root.name
        fill_sheet_list(st, s)
        refresh_subsheets_stale(root, st.sheet_index)
        return self.finish_with(f"Analyzed {root.name}: {s.num_components} components, {s.num_sheets} sheets "
                                f"in {time.perf_counter() - t0:.2f} s")


class HBC_OT_build_layer(_Stepped, _OnActiveMesh, bpy.types.Operator):
    """Build (or rebuild) one structure layer of the active mesh"""

    bl_idname = "hbc.build_layer"
    bl_label = "Build Layer"

    layer: EnumProperty(name="Layer", items=LAYER_ITEMS)

    @classmethod
    def description(cls, context, properties):
        why = unavailable(context, properties.layer)
        title = P.LAYER_TITLES[properties.layer].lower()
        return f"Cannot build the {title} layer: {why}" if why else f"Build (or rebuild) the {title} layer"

    def invoke(self, context, event):
        return self.start_steps(context) if stepping.in_window(context) else self.execute(context)

    def execute(self, context):
        return self.run_now(context)

    def job(self, context, log):
        why = unavailable(context, self.layer)
        if why:
            raise ValueError(why)
        root = active_root(context)
        analysis = not structure_ready(root, self.layer in L.NEEDS_ANALYSIS)
        return (build_layer_steps(context.scene, root, self.layer, log), steps.build_phases([self.layer], analysis),
                self._finish_layer)

    def _finish_layer(self, context, result, times, seconds, log):
        s, coll, done = result
        st = context.scene.hbc
        if not len(st.sheets) and s.analysis is not None:
            fill_sheet_list(st, s)
        st.active_mesh = coll["hbc_mesh"]
        if self.layer == "subsheets" and st.spread:  # laid out beside the mesh, out of view
            compat.frame_objects(context, S.objects_in(coll))
        return self.finish_with(done)


def build_layer_steps(scene, root, layer, log):
    """Build Layer as a job: the structure (read and analysed in a worker thread when not in memory),
    then the layer (blender/layers.build_layer_steps). Returns (Structure, the layer's collection,
    the sentence saying what was built)."""
    st = scene.hbc
    with S.Transaction() as tx:
        s = yield from structure_steps(tx, root, layer in L.NEEDS_ANALYSIS, log, st.rho)
        yield Phase(layer, f"building {P.LAYER_TITLES[layer]}")
        coll, done = yield from L.build_layer_steps(root, layer, s, st, log)
        yield f"built {P.LAYER_TITLES[layer]}"
    return s, coll, done


#: Build All's layers, and the one left visible (the others are a click away: their eye icons).
BUILD_ALL = ("direct", "graph", "components", "sheets", "wireframe")
BUILD_ALL_SHOWN = "components"


def build_all_steps(scene, root, log):
    """Build All as a job, one overall progress: the analysis when not in memory, then every layer
    of BUILD_ALL built first and swapped in at the end (all or nothing). Returns the Structure."""
    st = scene.hbc
    with S.Transaction() as tx:
        s = yield from structure_steps(tx, root, True, log, st.rho)
        built = []
        for layer in BUILD_ALL:
            yield Phase(layer, f"building {P.LAYER_TITLES[layer]}")
            built.append((layer, (yield from L.build_into_steps(tx, root, layer, s, st))))
            yield f"built {P.LAYER_TITLES[layer]}"
        for layer, coll in built:
            S.swap_layer(root, layer, coll, tx).hide_viewport = layer != BUILD_ALL_SHOWN
    return s


class HBC_OT_build_all(_Stepped, _OnActiveMesh, bpy.types.Operator):
    """Build the overview layers (direct view, singularity graph, components, sheets, wireframe); only the components stay visible"""

    bl_idname = "hbc.build_all"
    bl_label = "Build All"

    def invoke(self, context, event):
        return self.start_steps(context) if stepping.in_window(context) else self.execute(context)

    def execute(self, context):
        return self.run_now(context)

    def job(self, context, log):
        root = active_root(context)
        analysis = not structure_ready(root, True)
        return build_all_steps(context.scene, root, log), steps.build_phases(BUILD_ALL, analysis), self._finish_all

    def _finish_all(self, context, s, times, seconds, log):
        root = active_root(context)
        st = context.scene.hbc
        if not len(st.sheets):
            fill_sheet_list(st, s)
        n = sum(len(S.objects_in(S.find_layer(root, layer))) for layer in BUILD_ALL)
        return self.finish_with(f"{root.name}: built {len(BUILD_ALL)} layers ({n} objects) in "
                                f"{seconds:.2f} s; showing {P.LAYER_TITLES[BUILD_ALL_SHOWN]}", log)


class HBC_OT_clear_layer(_OnActiveMesh, bpy.types.Operator):
    """Remove this layer of the active mesh"""

    bl_idname = "hbc.clear_layer"
    bl_label = "Clear Layer"

    layer: EnumProperty(name="Layer", items=LAYER_ITEMS)

    def execute(self, context):
        S.remove_layer(active_root(context), self.layer)
        return {"FINISHED"}


class HBC_OT_frame_layer(_OnActiveMesh, bpy.types.Operator):
    """Select this layer's visible objects and frame them in the 3D views"""

    bl_idname = "hbc.frame_layer"
    bl_label = "Frame Layer"

    layer: EnumProperty(name="Layer", items=LAYER_ITEMS)

    def execute(self, context):
        coll = S.show_layer(active_root(context), self.layer, context.view_layer)
        if coll is None:
            self.report({"ERROR"}, f"The {P.LAYER_TITLES[self.layer].lower()} layer is not built")
            return {"CANCELLED"}
        objects = [ob for ob in S.objects_in(coll) if not ob.hide_viewport]
        with S.selectable(objects):
            compat.frame_objects(context, objects)
        return {"FINISHED"}


class HBC_OT_toggle_layer(_OnActiveMesh, bpy.types.Operator):
    """Show or hide this layer in the 3D views (shown again whatever hid it: this eye, or the outliner's eyes of the mesh, the layer or its objects)"""

    bl_idname = "hbc.toggle_layer"
    bl_label = "Show/Hide Layer"

    layer: EnumProperty(name="Layer", items=LAYER_ITEMS)

    def execute(self, context):
        root = active_root(context)
        coll = S.find_layer(root, self.layer)
        if coll is None:
            return {"CANCELLED"}
        if S.layer_shown(coll, context.view_layer):
            coll.hide_viewport = True
        else:
            S.show_layer(root, self.layer, context.view_layer)
        return {"FINISHED"}


class HBC_OT_set_active(bpy.types.Operator):
    """Make this mesh the one the Hex Structure panel acts on"""

    bl_idname = "hbc.set_active"
    bl_label = "Set Active Mesh"
    bl_options = {"REGISTER", "UNDO"}

    name: StringProperty()

    def execute(self, context):
        root = find_root(self.name)
        if root is None:
            self.report({"ERROR"}, f"No imported mesh named {self.name!r}")
            return {"CANCELLED"}
        st = context.scene.hbc
        st.active_mesh = root.name
        s = session.get(root.name)
        st.sheets.clear()
        if s is not None:
            fill_sheet_list(st, s)
        return {"FINISHED"}


class HBC_OT_copy_table1(_OnActiveMesh, bpy.types.Operator):
    """Copy the active mesh's Table 1 row to the clipboard"""

    bl_idname = "hbc.copy_table1"
    bl_label = "Copy Row"
    bl_options = {"REGISTER"}

    format: EnumProperty(name="Format", items=[("MARKDOWN", "Markdown", "A Markdown table: header, rule, row"),
                                               ("CSV", "CSV", "Comma-separated: header line, row line")])

    def execute(self, context):
        root = active_root(context)
        s = session.get(root.name)
        if s is None:
            self.report({"ERROR"}, "The mesh is not in memory: Analyze it first")
            return {"CANCELLED"}
        context.window_manager.clipboard = P.table1_text(root.name, s.stats(), self.format)
        self.report({"INFO"}, f"Copied the Table 1 row of {root.name} ({self.format.title()})")
        return {"FINISHED"}


class HBC_OT_explain(bpy.types.Operator):
    """What a value means (shown as the tooltip)"""

    bl_idname = "hbc.explain"
    bl_label = "Explain"
    bl_options = {"INTERNAL"}

    text: StringProperty()

    @classmethod
    def description(cls, context, properties):
        return properties.text

    def execute(self, context):
        self.report({"INFO"}, self.text)
        return {"CANCELLED"}  # nothing changed: no undo step


def help_url() -> str:
    """The add-on's user guide (README.md beside its __init__.py) as a file URL."""
    return (pathlib.Path(__file__).resolve().parents[1] / "README.md").as_uri()


class HBC_OT_help(bpy.types.Operator):
    """Open the add-on's user guide: where things are, how to report a problem"""

    bl_idname = "hbc.help"
    bl_label = "Hex Structure Help"
    bl_options = {"INTERNAL"}

    def execute(self, context):
        bpy.ops.wm.url_open(url=help_url())
        return {"FINISHED"}


class _SelectOwner:
    """Select every face of the picked component or sheet (the active face's owner) in a merged mesh"""

    @classmethod
    def poll(cls, context):
        ob = context.active_object
        return ob is not None and ob.mode == "EDIT" and ob.type == "MESH" and bool(ob.get("hbc_owner"))

    def execute(self, context):
        ob = context.active_object
        _, layer, owner = merged_owner_faces(ob)
        if owner is None:
            self.report({"ERROR"}, "Pick a face of the component or sheet first")
            return {"CANCELLED"}
        n = select_owner(ob, owner)
        if self.frame:
            compat.frame_edit_selection(context)
        self.report({"INFO"}, f"Selected {ob['hbc_owner']} {owner}: {n} faces")
        return {"FINISHED"}


class HBC_OT_select_component(_SelectOwner, bpy.types.Operator):
    """Select every face of the picked component or sheet (the active face's owner) in a merged mesh"""

    bl_idname = "hbc.select_component"
    bl_label = "Select Component"
    bl_options = {"REGISTER", "UNDO"}

    frame: BoolProperty(name="Frame", default=False, description="Also frame it in the 3D views")


class HBC_OT_select_block(_SelectOwner, bpy.types.Operator):
    """Deprecated name of Select Component (add-on 0.1), kept for scripts"""

    # Not a subclass of HBC_OT_select_component: Blender then ran both ids with the selection
    # of neither (every face selected).
    bl_idname = "hbc.select_block"
    bl_label = "Select Component"
    bl_options = {"REGISTER", "UNDO", "INTERNAL"}

    frame: BoolProperty(name="Frame", default=False, description="Also frame it in the 3D views")


class HBC_OT_show_worst(_OnActiveMesh, bpy.types.Operator):
    """Show, select and frame the component (of hex cells) or the sheet holding the active mesh's lowest scaled Jacobian"""

    bl_idname = "hbc.show_worst"
    bl_label = "Show Worst"

    kind: EnumProperty(name="What", items=[("component", "Component", "The worst component of hex cells"),
                                           ("sheet", "Sheet", "The worst sheet")])

    def execute(self, context):
        root = active_root(context)
        st = context.scene.hbc
        log = make_log(context)
        try:
            s = structure_of(root, True, log, st.rho)
            which = {kind: i for kind, i, _, _ in MB.worst(s.metrics())}[self.kind]
            if which is None:
                raise ValueError(f"The mesh has no worst {self.kind}: no {self.kind} of hexahedra")
            if self.kind == "sheet":
                n = self._show_sheet(context, root, s, which, log)
            else:
                n = self._show_component(context, root, s, which, log)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e)
        st.active_mesh = root.name
        if self.kind == "sheet":
            return self.finish_with(f"{root.name}: worst sheet {which} shown and selected ({n} objects)")
        return self.finish_with(f"{root.name}: worst component {which} shown and selected ({n} objects or faces), "
                                "the rest of the mesh hidden (Alt+H shows it)")

    @staticmethod
    def _show_sheet(context, root, s, sheet, log):
        """Picks the sheet in the list (the sheets layer shows it) and shows the picked-sheet layer
        (its highlights) with it, selected and framed."""
        st = context.scene.hbc
        if len(st.sheets) != s.num_sheets:
            fill_sheet_list(st, s)
        st.sheet_index = sheet  # its update shows the sheet in the sheets layer (and rebuilds "sheet")
        coll = S.find_layer(root, "sheet")
        if coll is None or any(ob.get("hbc_sheet") != sheet for ob in S.objects_in(coll)):
            L.build_layer(root, "sheet", s, st, log)
        coll = S.show_layer(root, "sheet", context.view_layer)
        objects = [ob for ob in S.objects_in(coll) if not ob.hide_viewport]
        compat.frame_objects(context, objects)
        return len(objects)

    @staticmethod
    def _show_component(context, root, s, component, log):
        """Selects the component's object in the Components layer (built when missing) and frames it,
        isolated: the worst component is often inside the mesh, behind the other components, so every other
        object of the mesh but the see-through boundary is hidden (scene.isolate). In a merged
        Components mesh, its faces in edit mode (as Select Component does) with the others hidden."""
        st = context.scene.hbc
        vl = context.view_layer
        if S.find_layer(root, "components") is None:
            L.build_layer(root, "components", s, st, log)
        coll = S.show_layer(root, "components", vl)
        objects = S.objects_in(coll)
        mine = [ob for ob in objects if ob.get("hbc_component") == component]
        if context.object is not None and context.object.mode != "OBJECT":
            bpy.ops.object.mode_set(mode="OBJECT")
        if mine:
            mine[0].hide_viewport = False
            S.isolate(root, mine, vl)
            compat.frame_objects(context, mine)
            return 1
        merged = next(ob for ob in objects if ob.get("hbc_owner") == "component")
        S.isolate(root, [merged], vl)
        compat.frame_objects(context, [merged])
        bpy.ops.object.mode_set(mode="EDIT")
        bpy.ops.mesh.select_mode(type="FACE")
        bpy.ops.mesh.reveal(select=False)  # the faces an earlier Show component hid
        n = select_owner(merged, component)
        bpy.ops.mesh.hide(unselected=True)
        compat.frame_edit_selection(context)
        return n


class HBC_OT_add_cut_plane(bpy.types.Operator):
    bl_idname = "hbc.add_cut_plane"
    bl_label = "Add cut plane"
    bl_description = "Add an Empty through the mesh centre as the slicing plane (move and turn it)"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        root = active_root(context)
        s = session.get(root.name) if root is not None else None
        if s is None:
            self.report({"ERROR"}, "No mesh in memory")
            return {"CANCELLED"}
        lo, hi = s.points.min(axis=0), s.points.max(axis=0)
        inspect.add_plane(context, tuple(float(x) for x in (lo + hi) / 2), size=float(np.max(hi - lo)) * 0.6,
                          collection=root)
        return {"FINISHED"}


#: File > Import's entry: the extensions (eight of them) would make it the menu's widest; the file
#: browser's filter and the operator's tooltip list them.
MENU_LABEL = "Hex-dominant Mesh"


def menu_import(self, context):
    self.layout.operator(HBC_OT_import.bl_idname, text=MENU_LABEL)
