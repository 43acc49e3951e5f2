"""The Blender side of the figures: studio scene (camera, soft lights, light background), panel
contents built with the add-on's layer and scene builders, outlines, rendering, text labels and
PNG input/output through bpy.data.images. Decisions live in `plan`, pixel work in `compose`.
"""

from __future__ import annotations

import math
import os
import time
import types

import bpy
import numpy as np

# Aliased: `scene` and `compat` are also the parameter names of the studio functions below.
from ..blender import compat as compat_module
from ..blender import inspect as inspect_module
from ..blender import layers as layers_module
from ..blender import scene as scene_module
from ..plan import inspection, planning, session, structure
from ..ui import properties
from . import compose as C
from . import plan

BOUNDARY_COLOR = (0.80, 0.80, 0.80, 1.0)


def log(msg):
    print(msg, flush=True)


def srgb_to_linear(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


# ---------------------------------------------------------------------------------------------
# The add-on

class Addon:
    """The add-on's modules the figures use (no registration needed: the layer builders take a
    plain settings object). The figures are part of the add-on package, so these are the very
    modules of the add-on they were shipped in."""

    def __init__(self):
        self.P = planning
        self.session = session
        self.structure = structure
        self.inspection = inspection
        self.compat = compat_module
        self.S = scene_module
        self.L = layers_module
        self.inspect = inspect_module
        self.properties = properties

    def settings(self, **overrides):
        """The panel's settings with the add-on's defaults (read from its property definitions)."""
        d = {}
        for key, prop in getattr(self.properties.HBCSettings, "__annotations__", {}).items():
            kw = getattr(prop, "keywords", None)
            if kw is not None and "default" in kw:
                d[key] = kw["default"]
        d.setdefault("wireframe_scope", "MESH")
        d.update(overrides)
        return types.SimpleNamespace(**d)


# ---------------------------------------------------------------------------------------------
# Studio scene

def reset_file():
    bpy.ops.wm.read_homefile(use_empty=True)
    return bpy.context.scene


def setup_render(scene, engine, samples, width, height, compat, denoise="auto", look=None):
    """`compat`: the add-on's Blender-version module; `denoise`: auto, on or off (Cycles); `look`:
    a plan.Look (default paper)."""
    look = look or plan.LOOKS["paper"]
    r = scene.render
    r.resolution_x, r.resolution_y, r.resolution_percentage = int(width), int(height), 100
    r.film_transparent = False
    r.image_settings.file_format = "PNG"
    r.image_settings.color_mode = "RGB"
    r.image_settings.color_depth = "8"
    r.use_freestyle = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    if engine == "cycles":
        r.engine = "CYCLES"
        c = scene.cycles
        c.device = "CPU"
        c.samples = int(samples)
        # Denoised where Cycles has OpenImageDenoise (the bpy wheels): grain-free at the same
        # sample count; Debian's 3.4 lacks it, so those renders stay raw.
        if denoise == "on" and not compat.has_denoiser():
            raise RuntimeError(f"--denoise on: Cycles in Blender {bpy.app.version_string} has no OpenImageDenoise")
        denoise = denoise != "off" and compat.has_denoiser()
        log(f"render_figures: Cycles {samples} samples, {'denoised (OpenImageDenoise)' if denoise else 'not denoised'}")
        c.use_denoising = denoise
        if denoise:
            c.denoiser = "OPENIMAGEDENOISE"
            if hasattr(c, "denoising_input_passes"):
                c.denoising_input_passes = "RGB_ALBEDO_NORMAL"
            if hasattr(c, "denoising_prefilter"):
                c.denoising_prefilter = "ACCURATE"
        if hasattr(c, "use_adaptive_sampling"):
            c.use_adaptive_sampling = False
        # Soft studio light needs little indirect light: few bounces (speed), clamped (no fireflies);
        # transparency (shell, faint wireframe ends) needs many transparent bounces.
        c.max_bounces = 3
        c.diffuse_bounces = 1
        c.glossy_bounces = 1
        c.transmission_bounces = 0
        c.volume_bounces = 0
        c.transparent_max_bounces = 24
        c.caustics_reflective = c.caustics_refractive = False
        c.sample_clamp_indirect = 1.0
        c.use_fast_gi = False
        c.pixel_filter_type = "BLACKMAN_HARRIS"
        c.filter_width = 1.5
        try:
            scene.view_layers[0].cycles.use_denoising = denoise
        except AttributeError:
            pass
    elif engine == "eevee":
        r.engine = compat.eevee_engine()
        e = scene.eevee
        e.taa_render_samples = int(samples)
        for attr, value in (("use_gtao", True), ("gtao_distance", 0.2), ("use_soft_shadows", True),
                            ("shadow_cube_size", "1024"), ("use_ssr", False)):
            if hasattr(e, attr):
                setattr(e, attr, value)
    else:
        r.engine = "BLENDER_WORKBENCH"
        sh = scene.display.shading
        sh.light = "STUDIO"
        sh.color_type = "VERTEX"
        sh.show_cavity = True
        sh.cavity_type = "BOTH"
        sh.show_object_outline = True
        sh.object_outline_color = look.outline[:3]
        sh.show_specular_highlight = False
        scene.display.render_aa = "8"
        if look.clay:
            sh.color_type = "SINGLE"
            sh.single_color = plan.CLAY_COLOR[:3]
    if look.clay and engine != "workbench":
        clay_override(scene, compat)


def clay_override(scene, compat):
    """The clay look in Cycles and EEVEE: one matte grey material over every object of the view layer
    (the see-through shell included), so only shading, ambient occlusion and the edges tell the blocks apart."""
    mat, _, bsdf = compat.new_node_material("Figures Clay")
    bsdf.inputs["Base Color"].default_value = plan.CLAY_COLOR
    bsdf.inputs["Roughness"].default_value = 0.9
    compat.principled_input(bsdf, "Specular IOR Level").default_value = 0.1
    scene.view_layers[0].material_override = mat


def setup_world(scene, engine, compat, look=None):
    """Soft ambient light from a uniform world; the camera sees a flat grey (the look's background)."""
    world = bpy.data.worlds.new("Figures World")
    scene.world = world
    bg_lin = srgb_to_linear((look or plan.LOOKS["paper"]).background)
    world.color = (bg_lin, bg_lin, bg_lin)
    nt = compat.world_use_nodes(world)
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputWorld")
    ambient = nt.nodes.new("ShaderNodeBackground")
    ambient.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    ambient.inputs["Strength"].default_value = 0.45
    seen = nt.nodes.new("ShaderNodeBackground")
    seen.inputs["Color"].default_value = (bg_lin, bg_lin, bg_lin, 1.0)
    seen.inputs["Strength"].default_value = 1.0
    path = nt.nodes.new("ShaderNodeLightPath")
    mix = nt.nodes.new("ShaderNodeMixShader")
    nt.links.new(path.outputs["Is Camera Ray"], mix.inputs["Fac"])
    nt.links.new(ambient.outputs["Background"], mix.inputs[1])
    nt.links.new(seen.outputs["Background"], mix.inputs[2])
    nt.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return world


def add_camera(scene, cam: plan.Camera, points):
    data = bpy.data.cameras.new("Figures Camera")
    data.lens = cam.lens
    data.sensor_fit = "AUTO"
    data.sensor_width = 36.0
    data.clip_start, data.clip_end = plan.clip_range(cam, plan.bbox_corners(points))
    ob = bpy.data.objects.new("Figures Camera", data)
    scene.collection.objects.link(ob)
    scene.camera = ob
    place_camera(ob, cam)
    return ob


def place_camera(ob, cam: plan.Camera):
    from mathutils import Matrix

    m = Matrix.Identity(4)
    for i in range(3):
        for j in range(3):
            m[i][j] = float(cam.matrix[i, j])
        m[i][3] = float(cam.location[i])
    ob.matrix_world = m
    ob.data.lens = cam.lens


def add_lights(scene, cam: plan.Camera, points):
    """Key and fill area lights placed from the camera's point of view, sized to the model;
    powers scaled with distance so the irradiance is the same at any model size."""
    from mathutils import Vector

    lo, hi = np.min(points, axis=0), np.max(points, axis=0)
    center = (lo + hi) / 2.0
    size = float(np.linalg.norm(hi - lo)) or 1.0
    right, up, back = cam.matrix[:, 0], cam.matrix[:, 1], cam.matrix[:, 2]
    made = []
    for name, (a, b, c), irradiance, spread in (("Key", (-0.7, 0.9, 0.8), 3.2, 1.2),
                                                 ("Fill", (0.9, 0.2, 0.6), 1.0, 2.0),
                                                 ("Rim", (0.2, 0.7, -1.0), 1.2, 1.0)):
        d = a * right + b * up + c * back
        d /= np.linalg.norm(d)
        dist = 2.5 * size
        data = bpy.data.lights.new(f"Figures {name}", "AREA")
        data.shape = "DISK"
        data.size = spread * size
        data.energy = irradiance * math.pi * dist * dist
        if hasattr(data, "use_shadow"):
            data.use_shadow = True
        ob = bpy.data.objects.new(f"Figures {name}", data)
        ob.location = Vector(center + d * dist)
        ob.rotation_euler = Vector(-d).to_track_quat("-Z", "Y").to_euler()
        scene.collection.objects.link(ob)
        made.append(ob)
    return made


def shell_material(tx, compat, alpha=0.10):
    """Faint matte grey (no specular: no sparkle at low sample counts) for the context shell."""
    name = "Figures Shell"
    mat = bpy.data.materials.get(name)
    if mat is not None:
        return mat
    mat, _, bsdf = compat.new_node_material(name)
    tx.add("materials", mat)
    bsdf.inputs["Base Color"].default_value = BOUNDARY_COLOR
    bsdf.inputs["Alpha"].default_value = alpha
    bsdf.inputs["Roughness"].default_value = 1.0
    compat.principled_input(bsdf, "Specular IOR Level").default_value = 0.0
    compat.set_viewport_color(mat, tuple(BOUNDARY_COLOR[:3]) + (alpha,))
    compat.set_blend(mat, True)
    return mat


# ---------------------------------------------------------------------------------------------
# Panels: collections of objects, shown one set at a time

class Subject:
    """One analysed mesh in the scene, its panels as collections (hidden from render unless
    shown) and its camera."""

    def __init__(self, addon: Addon, path, args, scene):
        self.addon, self.args, self.scene = addon, args, scene
        self.path = path
        self.look = plan.LOOKS[getattr(args, "look", "paper")]
        self.name = addon.P.mesh_name_from_path(path)
        t = time.perf_counter()
        s = addon.session.load(path, 1.0, log)
        addon.session.analyze(s, args.rho, log, getattr(args, "subsheet_rule", "layers"))
        self.s = s
        self.t_analysis = time.perf_counter() - t
        self.points = s.points
        self.length = s.length
        self.direction = plan.view_direction(args.azimuth, args.elevation, args.up)
        w, h = args.resolution
        self.camera = plan.frame(plan.framing_points(self.points), self.direction, args.up, w, h)
        # Size of one pixel at the model (at the distance of the bounding box centre).
        center = (self.points.min(axis=0) + self.points.max(axis=0)) / 2.0
        tx, _ = plan.half_tangents(self.camera.lens, w, h)
        dist = float(np.linalg.norm(self.camera.location - center))
        self.pixel = 2.0 * dist * tx / w
        self.root = bpy.data.collections.new(f"{self.name} figures")
        scene.collection.children.link(self.root)
        self.panels = {}  # key -> [collections]
        self.shared = {}  # name -> collection (shell) shown by several panels
        types_ = s.sheet_types() if s.num_sheets else np.zeros(0, np.uint8)
        cells = s.sheet_sizes()[0] if s.num_sheets else np.zeros(0, np.int64)
        self._wireframes = {}  # sheet id -> its VSG wireframe (asked for by the choice, drawn by e)
        self.sheet = plan.pick_sheet(types_, cells, args.sheet, self.shows_vsg)
        self.sheet_type = int(types_[self.sheet]) if self.sheet is not None else None

    # -- helpers --------------------------------------------------------------------------------
    def st(self, **kw):
        line = max(0.0035, 1.3 * self.pixel / self.length)
        dot = max(0.006, 3.0 * self.pixel / self.length)
        base = dict(line_radius=line, dot_radius=dot, shrink=0.08, split_max=1000, spread=False,
                    sheet_index=self.sheet if self.sheet is not None else 0,
                    wireframe_colors=getattr(self.args, "wire_colors", "class").upper())
        base.update(kw)
        return self.addon.settings(**base)

    def _new_coll(self, key):
        coll = bpy.data.collections.new(f"{self.name} / {key}")
        self.root.children.link(coll)
        coll.hide_render = True
        return coll

    def _adopt(self, built, key):
        """Links a collection made by the add-on's build_into under our root."""
        built.name = f"{self.name} / {key}"
        self.root.children.link(built)
        built.hide_render = True
        return built

    def outline(self, tx, coll, name, soup, angle=35.0, color=None, every_edge=False, scale=0.55):
        """Tubes along a soup's feature edges (or every edge), the look's outline colour unless
        given: components and sheets read clearly in any engine, and the line builder of the add-on
        makes them."""
        P, S = self.addon.P, self.addon.S
        color = self.look.outline if color is None else color
        if soup.num_faces == 0:
            return None
        if every_edge:
            edges = plan.all_edges(soup.face_sizes, soup.face_vertices)
        else:
            edges = plan.feature_edges(soup.positions, soup.face_sizes, soup.face_vertices, angle)
        if len(edges) == 0:
            return None
        used, inv = np.unique(edges.ravel(), return_inverse=True)
        lines = P.Lines(np.asarray(soup.positions, np.float32)[used], inv.reshape(-1, 2).astype(np.int32),
                        np.tile(np.asarray(color, np.float32), (len(used), 1)), np.zeros(len(used), np.int32))
        return S.lines_object(tx, coll, name, lines, scale * self.pixel, {"hbc_mesh": self.name, "hbc_outline": True})

    def shell(self):
        """[the mesh's boundary, faint]: context for line panels; [] in Workbench, which draws it
        opaque (it only honours attribute colours, not a material's alpha, with them)."""
        if self.args.engine == "workbench":
            return []
        if "shell" in self.shared:
            return [self.shared["shell"]]
        S, P = self.addon.S, self.addon.P
        coll = self._new_coll("shell")
        with S.Transaction() as tx:
            mat = shell_material(tx, self.addon.compat)
            S.soup_object(tx, coll, f"{self.name} shell", self.s.direct_boundary(), None, mat,
                          {"hbc_mesh": self.name, "hbc_part": "shell"})
        self.no_shadows(coll)
        self.shared["shell"] = coll
        return [coll]

    def build(self, key, layer, **kw):
        """An add-on layer with given settings, as the panel collection `key`."""
        with self.addon.S.Transaction() as tx:
            built = self.addon.L.build_into(tx, self.name, layer, self.s, self.st(**kw))
        return self._adopt(built, key)

    # -- panels ---------------------------------------------------------------------------------
    def panel_mesh(self):
        s, S = self.s, self.addon.S
        see_through = self.args.engine != "workbench"
        coll = self.build("mesh", "direct", direct_boundary=True, direct_transparent=see_through, boundary_opacity=0.22,
                          direct_hex_cells=False, direct_shrink=0.0)
        with S.Transaction() as tx:
            self.outline(tx, coll, f"{self.name} mesh edges", s.direct_boundary(), color=self.look.mesh_edge,
                         every_edge=True, scale=0.45)
            if np.any(np.asarray(s.mesh.cell_types) != 0):
                self.outline(tx, coll, f"{self.name} non-hex outlines", s.non_hex_cells(0.0), angle=20.0)
        self.no_shadows(coll)
        return [coll]

    def panel_graph(self):
        return [self.build("graph", "graph")] + self.shell()

    def panel_complex(self):
        coll = self.build("complex", "components")
        st = self.st()
        with self.addon.S.Transaction() as tx:
            self.outline(tx, coll, f"{self.name} component outlines", self.s.blocks(st.shrink))
        return [coll]

    def panel_sheet(self):
        if self.sheet is None:
            return None
        return [self.sheet_layer(self.sheet, "sheet")] + self.shell()

    def sheet_layer(self, sheet, key):
        """Sheet `sheet` with its highlights and outlines, as the collection `key`."""
        # Thinner highlight edges than the line panels': they sit on the blocks and would hide them.
        coll = self.build(key, "sheet", line_radius=0.6 * self.st().line_radius, sheet_index=sheet)
        S = self.addon.S
        with S.Transaction() as tx:
            self.outline(tx, coll, f"{self.name} sheet {sheet} outlines", self.s.sheet_blocks(sheet, self.st().shrink))
            # Self-intersecting cells: see-through, so the sheet inside stays visible.
            mat = S.material(tx, "flat", self.addon.P.SELF_INTERSECTING_COLOR, 0.35)
            for ob in coll.objects:
                if ob.get("hbc_highlight") == "self_intersecting":
                    S.set_materials(ob.data, [mat])
        return coll

    def sheet_wireframe(self, sheet):
        """The VSG wireframe of a sheet's region, computed once."""
        sheet = int(sheet)
        if sheet not in self._wireframes:
            self._wireframes[sheet] = self.s.analysis.wireframe(sheet=sheet)
        return self._wireframes[sheet]

    def shows_vsg(self, sheet):
        """Whether panels e and f of this sheet have something to draw: VSG chains (kind 0) and a
        simplified wireframe."""
        w = self.sheet_wireframe(sheet)
        return bool(np.any(np.asarray(w.kind) == 0)) and len(np.asarray(w.simplified_polylines_offsets)) > 1

    def _vsg_lines(self, sheet):
        """The VSG chains of a sheet's wireframe (kind 0), palette colours, opaque."""
        P = self.addon.P
        w = self.sheet_wireframe(sheet)
        off = np.asarray(w.polylines_offsets)
        verts = np.asarray(w.polylines_items)
        k = len(off) - 1
        if k == 0:
            return None
        keep = np.asarray(w.kind) == 0
        if not keep.any():
            return None
        colors = P.palette_color(np.asarray(w.color, np.int64))
        return self.s._lines(off, verts, colors, None, keep)

    def panel_vsg(self):
        if self.sheet is None:
            return None
        lines = self._vsg_lines(self.sheet)
        if lines is None or not lines.positions.size:
            return None
        coll = self._new_coll("vsg")
        st = self.st()
        with self.addon.S.Transaction() as tx:
            self.addon.S.lines_object(tx, coll, f"{self.name} sheet {self.sheet} VSG", lines,
                                      st.line_radius * self.length,
                                      {"hbc_mesh": self.name, "hbc_sheet": self.sheet, "hbc_vsg": True})
        return [coll] + self.shell()

    def panel_wireframe(self):
        if self.sheet is None:
            return None
        coll = self.build("wireframe", "wireframe", wireframe_scope="SHEET", simplified=True)
        if not len(coll.objects):
            return None
        return [coll] + self.shell()

    def panel_mesh_wireframe(self):
        coll = self.build("mesh_wireframe", "wireframe", wireframe_scope="MESH", simplified=True)
        if not len(coll.objects):
            return None
        return [coll] + self.shell()

    def subsheet_tiles(self):
        """Panel g's content: the built subsheets layer and the subsheets to show, or None when
        the sheet is not self-intersecting."""
        if self.sheet is None or self.sheet_type != 3:
            return None
        sub = self.s.subsheets(self.sheet)
        off = np.asarray(sub.subsheet_cells_offsets)
        picked = plan.pick_subsheets(np.diff(off), self.args.max_subsheets)
        coll = self.build("subsheets", "subsheets", spread=False)
        with self.addon.S.Transaction() as tx:
            soup = self.s.subsheet_soup(self.sheet, self.st().shrink)
            for k in picked:
                ob = self.outline(tx, coll, f"{self.name} subsheet {k} outlines", soup.select(soup.face_owner == k))
                if ob is not None:
                    ob["hbc_subsheet"] = k
        return coll, picked, int(sub.count)

    def cut_plane_object(self):
        """The Empty cutting the cut and quality panels (made once; empties do not render)."""
        if "plane" not in self.shared:
            p, n = plan.cut_plane(self.points, self.direction, self.args.cut_plane)
            ob = bpy.data.objects.new(f"{self.name} cut plane", None)
            ob.location = tuple(p)
            ob.rotation_euler = self.addon.inspect.plane_rotation(tuple(n))
            self.scene.collection.objects.link(ob)
            self.shared["plane"] = ob
        return self.shared["plane"]

    def cut(self, coll):
        """Turns on the slicing filter of every equipped object of coll."""
        plane = self.cut_plane_object()
        for ob in coll.all_objects:
            self.addon.inspect.ensure_equipped(ob, self.s)  # a build leaves the filters' attributes out
            self.addon.inspect.set_filters(ob, {"Plane": plane, "Slice": True})
        return plane

    def kept_by_cut(self, soup):
        """Faces of a soup (with face_cell) whose cell the cut keeps, for outlines."""
        p, n = plan.cut_plane(self.points, self.direction, self.args.cut_plane)
        cen = self.addon.inspection.cell_data(self.s)["centroid"][soup.face_cell]
        return soup.select((cen - p) @ n <= 0)

    def panel_cut(self):
        """The base complex's components sliced by the plane (whole cells kept by their centroid)."""
        coll = self.build("cut", "components")
        self.cut(coll)
        with self.addon.S.Transaction() as tx:
            self.outline(tx, coll, f"{self.name} cut component outlines", self.kept_by_cut(self.s.blocks(self.st().shrink)))
        return [coll]

    def panel_quality(self):
        """Every cell coloured by its scaled Jacobian (viridis), sliced by the plane."""
        I, IP, S = self.addon.inspect, self.addon.inspection, self.addon.S
        coll = self._new_coll("quality")
        with S.Transaction() as tx:
            soup = IP.cell_soup(self.s)
            ob = S.soup_object(tx, coll, f"{self.name} cells by quality", soup, IP.cell_colors(self.s, soup, True),
                               None, {"hbc_mesh": self.name, "hbc_layer": "direct", "hbc_part": "cells"})
            I.equip_object(tx, ob, IP.cell_data(self.s), IP.sheet_mask(self.s, -1))
            self.outline(tx, coll, f"{self.name} cut cell edges", self.kept_by_cut(soup), color=self.look.mesh_edge,
                         every_edge=True, scale=0.35)
        self.cut(coll)
        return [coll]

    def no_shadows(self, coll, parts=("boundary", "shell")):
        """See-through surfaces and thin edges cast no shadows (Cycles samples transparent
        shadows stochastically: speckles at low sample counts)."""
        for ob in coll.objects:
            if ob.get("hbc_part") in parts or ob.get("hbc_outline"):
                if hasattr(ob, "visible_shadow"):
                    ob.visible_shadow = False
                else:
                    ob.cycles_visibility.shadow = False

    def show(self, colls):
        """Only these collections render."""
        for c in self.root.children:
            c.hide_render = c not in colls


# ---------------------------------------------------------------------------------------------
# Rendering and images

class quiet_stdout:
    """Renders print a progress line per tile and sample to stdout: silence them (file
    descriptor 1) so the script's own output stays readable. Stderr is kept."""

    def __enter__(self):
        import sys

        sys.stdout.flush()
        self.saved = os.dup(1)
        self.null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(self.null, 1)
        return self

    def __exit__(self, *exc):
        os.dup2(self.saved, 1)
        os.close(self.saved)
        os.close(self.null)
        return False


def render_to(scene, path):
    scene.render.filepath = path
    t = time.perf_counter()
    with quiet_stdout():
        bpy.ops.render.render(write_still=True, scene=scene.name)
    if not os.path.isfile(path):
        raise RuntimeError(f"render did not write {path}")
    return time.perf_counter() - t


def load_png(path):
    img = bpy.data.images.load(path, check_existing=False)
    try:
        w, h = img.size
        buf = np.empty(w * h * 4, np.float32)
        img.pixels.foreach_get(buf)
        return C.from_blender(buf, w, h)
    finally:
        bpy.data.images.remove(img)


def save_png(arr, path):
    h, w = arr.shape[:2]
    img = bpy.data.images.new(os.path.basename(path), w, h, alpha=True)
    try:
        img.pixels.foreach_set(C.to_blender(np.clip(arr, 0.0, 1.0)))
        img.filepath_raw = path
        img.file_format = "PNG"
        img.save()
    finally:
        bpy.data.images.remove(img)
    if not os.path.isfile(path):
        raise RuntimeError(f"could not write {path}")
    return path


#: Fonts for labels and legend words, the first one present used (else Blender's own, whose "1"
#: reads like an "I" in 3.x): DejaVu Sans, clear digits, the same glyphs in every Blender.
LABEL_FONTS = ("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
               "/usr/share/fonts/TTF/DejaVuSans.ttf",
               "/usr/share/fonts/dejavu/DejaVuSans.ttf")


CAP_HEIGHT = 0.42  # capitals' height in a label, as a fraction of the label's height


def label_font():
    """The font datablock of the first LABEL_FONTS file present, or None (Blender's own)."""
    for path in LABEL_FONTS:
        if os.path.isfile(path):
            return bpy.data.fonts.load(path, check_existing=True)
    return None


def render_labels(texts, width, height, tmpdir, align="LEFT", bold=False):
    """Each text rendered (Workbench, flat, dark on white) into a (height, width, 4) image whose
    background is transparent: one scene, one text object, one render per label."""
    scene = bpy.data.scenes.new("Figures Labels")
    try:
        r = scene.render
        r.engine = "BLENDER_WORKBENCH"
        r.resolution_x, r.resolution_y, r.resolution_percentage = int(width), int(height), 100
        r.film_transparent = True
        r.image_settings.file_format = "PNG"
        r.image_settings.color_mode = "RGBA"
        scene.view_settings.view_transform = "Standard"
        sh = scene.display.shading
        sh.light = "FLAT"
        sh.color_type = "SINGLE"
        sh.single_color = (0.02, 0.02, 0.025)
        scene.display.render_aa = "16"
        cam_data = bpy.data.cameras.new("Label Camera")
        cam_data.type = "ORTHO"
        cam_data.ortho_scale = float(max(width, height))  # 1 world unit = 1 pixel
        cam = bpy.data.objects.new("Label Camera", cam_data)
        scene.collection.objects.link(cam)
        scene.camera = cam
        cam.location = (width / 2.0, height / 2.0, 10.0)
        curve = bpy.data.curves.new("Label", "FONT")
        font = label_font()
        if font is not None:
            curve.font = font
        curve.size = 0.62 * height
        curve.align_x = {"LEFT": "LEFT", "CENTER": "CENTER"}[align]
        curve.align_y = "CENTER"
        ob = bpy.data.objects.new("Label", curve)
        scene.collection.objects.link(ob)
        x = 0.25 * height if align == "LEFT" else width / 2.0
        ob.location = (x, height / 2.0 - 0.05 * height, 0.0)

        def render(text, i):
            curve.body = text
            path = os.path.join(tmpdir, f"label_{i}.png")
            render_to(scene, path)
            img = load_png(path)
            os.remove(path)
            return img

        if font is not None:
            # Fonts fill their size differently: scale so that capitals stand CAP_HEIGHT of the
            # label high, as Blender's own font does at 0.62 of it. Measured on a large "H" (a
            # small one's edges fall between pixels).
            big = 200
            r.resolution_x = r.resolution_y = big
            cam_data.ortho_scale = float(big)
            cam.location = (big / 2.0, big / 2.0, 10.0)
            ob.location = (big / 4.0, big / 2.0, 0.0)
            curve.size = 100.0
            ink = np.nonzero((render("H", "cap")[..., 3] > 0.5).any(axis=1))[0]
            r.resolution_x, r.resolution_y = int(width), int(height)
            cam_data.ortho_scale = float(max(width, height))
            cam.location = (width / 2.0, height / 2.0, 10.0)
            ob.location = (x, height / 2.0 - 0.05 * height, 0.0)
            curve.size = 0.62 * height
            if len(ink) > 10:
                curve.size = CAP_HEIGHT * height * 100.0 / (ink[-1] - ink[0] + 1)
        out = [render(text, i) for i, text in enumerate(texts)]
        bpy.data.objects.remove(ob)
        bpy.data.curves.remove(curve)
        bpy.data.objects.remove(cam)
        bpy.data.cameras.remove(cam_data)
        return out
    finally:
        bpy.data.scenes.remove(scene)
