"""Operators: import, analyze, build / clear layers. All undoable; a failure reports an error,
cancels, and leaves the scene as it was."""

from __future__ import annotations

import os
import time

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

from . import layers as L
from . import planning as P
from . import scene as S
from . import session

FILTER = "*.ovm;*.ovmb;*.mesh;*.HYBRID;*.hybrid;*.hedra"
LAYER_ITEMS = [(k, title, f"Build the {title.lower()} layer") for k, title in P.LAYERS]


def make_log(context):
    """Progress messages: printed in background mode, shown in the header otherwise."""
    def log(msg):
        if bpy.app.background:
            print(msg, flush=True)
        else:
            try:
                context.workspace.status_text_set(msg)
            except (AttributeError, RuntimeError):
                print(msg)
    return log


class _Progress:
    def __init__(self, context, total):
        self.wm = context.window_manager
        self.log = make_log(context)
        self.p = P.Progress(total, self._report)
        self.wm.progress_begin(0, 100)

    def _report(self, fraction, message):
        self.wm.progress_update(int(100 * fraction))
        self.log(f"hbc: [{int(100 * fraction):3d}%] {message}")

    def step(self, message):
        self.p.step(message)

    def end(self, context):
        self.wm.progress_end()
        if not bpy.app.background:
            try:
                context.workspace.status_text_set(None)
            except (AttributeError, RuntimeError):
                pass


def fill_sheet_list(settings, structure):
    settings.sheets.clear()
    if structure.analysis is None:
        return
    n = structure.num_sheets
    if n == 0:
        return
    types = structure.sheet_types()
    cells, comps = structure.sheet_sizes()
    for i in range(n):
        it = settings.sheets.add()
        it.index, it.type, it.cells, it.components = i, int(types[i]), int(cells[i]), int(comps[i])
    settings.sheet_index = min(settings.sheet_index, n - 1)


def active_root(context):
    st = context.scene.hbc
    root = L.find_root(st.active_mesh) if st.active_mesh else None
    if root is None:
        ob = context.active_object
        if ob is not None and ob.get("hbc_mesh"):
            root = L.find_root(ob["hbc_mesh"])
    return root


def structure_of(root, analyzed, log, rho=0.8):
    return session.ensure(root.name, root["hbc_source"], float(root.get("hbc_scale", 1.0)),
                          float(root.get("hbc_rho", rho)), analyzed, log)


class _OnActiveMesh:
    """Operators that act on the mesh the Hex Structure panel shows."""

    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return active_root(context) is not None

    def cancel_with(self, context, error, prog=None):
        """Reports a failure and cancels; the scene was not touched (builds are all or nothing)."""
        if prog is not None:
            prog.end(context)
        self.report({"ERROR"}, f"{type(error).__name__}: {error}")
        return {"CANCELLED"}


class HBC_OT_import(bpy.types.Operator, ImportHelper):
    """Import a hex-dominant volume mesh and show it (optionally analyzed)"""

    bl_idname = "import_mesh.hbc"
    bl_label = "Import Hex-dominant Mesh"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    filename_ext = ".mesh"
    filter_glob: StringProperty(default=FILTER, options={"HIDDEN"})
    scale: FloatProperty(name="Scale", default=1.0, min=1e-6, soft_max=100.0)
    analyze: BoolProperty(name="Analyze on import", default=True,
                          description="Compute the singularity graph, base complex, sheets and wireframe")
    build_layers: BoolProperty(name="Build structure layers", default=False,
                               description="Also build the singularity graph, blocks and wireframe layers")

    def execute(self, context):
        path = self.filepath
        log = make_log(context)
        if not os.path.isfile(path):
            self.report({"ERROR"}, f"No such file: {path}")
            return {"CANCELLED"}
        prog = _Progress(context, 2 + (1 if self.analyze else 0) + (3 if self.build_layers and self.analyze else 0))
        st = context.scene.hbc
        tx = S.Transaction()
        try:
            t0 = time.perf_counter()
            s = session.load(path, self.scale, log)
            prog.step("loaded")
            if self.analyze:
                session.analyze(s, st.rho, log)
                prog.step("analyzed")
            name = P.mesh_name_from_path(path)
            with tx:
                root = tx.collection(name)
                root["hbc_source"] = os.path.abspath(path)
                root["hbc_scale"] = float(self.scale)
                root["hbc_rho"] = float(st.rho)
                root["hbc_cells"] = int(s.num_cells)
                layers = ["direct"] + (["graph", "blocks", "wireframe"] if self.build_layers and self.analyze else [])
                for layer in layers:
                    coll = L.build_into(tx, root.name, layer, s, st)
                    S.swap_layer(root, layer, coll)
                    prog.step(f"built {P.LAYER_TITLES[layer]}")
                context.scene.collection.children.link(root)
        except Exception as e:  # noqa: BLE001 - any failure must cancel cleanly
            prog.end(context)
            self.report({"ERROR"}, f"{type(e).__name__}: {e}")
            return {"CANCELLED"}
        prog.end(context)
        session.put(root.name, s)
        st.active_mesh = root.name
        fill_sheet_list(st, s)
        log(f"hbc: imported {root.name} in {time.perf_counter() - t0:.2f} s")
        return {"FINISHED"}


class HBC_OT_analyze(_OnActiveMesh, bpy.types.Operator):
    """Analyze the active hex-dominant mesh (again, with the current ρ)"""

    bl_idname = "hbc.analyze"
    bl_label = "Analyze"

    def execute(self, context):
        root = active_root(context)
        st = context.scene.hbc
        log = make_log(context)
        try:
            s = structure_of(root, False, log)
            session.analyze(s, st.rho, log)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e)
        root["hbc_rho"] = float(st.rho)
        st.active_mesh = root.name
        fill_sheet_list(st, s)
        return {"FINISHED"}


class HBC_OT_build_layer(_OnActiveMesh, bpy.types.Operator):
    """Build (or rebuild) one structure layer of the active mesh"""

    bl_idname = "hbc.build_layer"
    bl_label = "Build Layer"

    layer: EnumProperty(name="Layer", items=LAYER_ITEMS)

    def execute(self, context):
        root = active_root(context)
        st = context.scene.hbc
        log = make_log(context)
        prog = _Progress(context, 2)
        try:
            s = structure_of(root, self.layer in L.NEEDS_ANALYSIS, log, st.rho)
            prog.step("analysis ready")
            if not len(st.sheets) and s.analysis is not None:
                fill_sheet_list(st, s)
            L.build_layer(root, self.layer, s, st, log)
            prog.step(f"built {P.LAYER_TITLES[self.layer]}")
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e, prog)
        prog.end(context)
        st.active_mesh = root.name
        return {"FINISHED"}


class HBC_OT_build_all(_OnActiveMesh, bpy.types.Operator):
    """Build every overview layer (direct view, singularity graph, blocks, sheets, wireframe)"""

    bl_idname = "hbc.build_all"
    bl_label = "Build All Layers"

    def execute(self, context):
        root = active_root(context)
        st = context.scene.hbc
        log = make_log(context)
        todo = ["direct", "graph", "blocks", "sheets", "wireframe"]
        prog = _Progress(context, len(todo) + 1)
        try:
            s = structure_of(root, True, log, st.rho)
            if not len(st.sheets):
                fill_sheet_list(st, s)
            prog.step("analysis ready")
            # All or nothing: build every layer first, swap them in at the end.
            with S.Transaction() as tx:
                built = []
                for layer in todo:
                    built.append((layer, L.build_into(tx, root.name, layer, s, st)))
                    prog.step(f"built {P.LAYER_TITLES[layer]}")
                for layer, coll in built:
                    S.swap_layer(root, layer, coll)
        except Exception as e:  # noqa: BLE001
            return self.cancel_with(context, e, prog)
        prog.end(context)
        return {"FINISHED"}


class HBC_OT_clear_layer(_OnActiveMesh, bpy.types.Operator):
    """Remove one layer of the active mesh"""

    bl_idname = "hbc.clear_layer"
    bl_label = "Clear Layer"

    layer: EnumProperty(name="Layer", items=LAYER_ITEMS)

    def execute(self, context):
        S.remove_layer(active_root(context), self.layer)
        return {"FINISHED"}


class HBC_OT_set_active(bpy.types.Operator):
    """Make this mesh the one the Hex Structure panel acts on"""

    bl_idname = "hbc.set_active"
    bl_label = "Set Active Mesh"
    bl_options = {"REGISTER", "UNDO"}

    name: StringProperty()

    def execute(self, context):
        root = L.find_root(self.name)
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


def menu_import(self, context):
    self.layout.operator(HBC_OT_import.bl_idname, text="Hex-dominant mesh (.ovm/.ovmb/.mesh/.HYBRID/.hedra)")


classes = (HBC_OT_import, HBC_OT_analyze, HBC_OT_build_layer, HBC_OT_build_all, HBC_OT_clear_layer,
           HBC_OT_set_active)


def register_menus():
    bpy.types.TOPBAR_MT_file_import.append(menu_import)


def unregister_menus():
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
