"""The animations of `render_figures.py --animate` in Blender: each kind is built as keyframes in
the figures' studio scene (camera path, shape keys that move the components apart, visibility keys
of the sheets, the cutting plane's path), so that a saved .blend (--blend) can be edited and
rendered as any Blender animation; the frames are rendered as PNG files, captions and the legend
strip are drawn onto them, and they are encoded (animation_plan decides what moves where).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field

import bpy
import numpy as np

from ..blender import compat
from . import animation_plan as AP
from . import compose as C
from . import plan
from . import render as R


@dataclass
class Shot:
    """One kind built in the scene: what renders, the captions by frame range, the legend's panel."""

    colls: list
    captions: list = field(default_factory=list)  # [(first, last, text)]
    panel: str = "complex"
    highlights: set = field(default_factory=set)


def progress(kind, frames):
    def report(scene, *_):
        print(f"render_figures: {kind}: frame {scene.frame_current}/{frames}", file=sys.stderr, flush=True)
    return report


def frame_on(scene, subject, points):
    """The stills' camera (direction, lens, margin), framed on `points`."""
    w, h = subject.args.resolution
    cam = plan.frame(plan.framing_points(points), subject.direction, subject.args.up, w, h)
    R.place_camera(scene.camera, cam)
    scene.camera.data.clip_start, scene.camera.data.clip_end = plan.clip_range(cam, plan.bbox_corners(points))


def key_value(owner, path, keys):
    """Keyframes (frame, value) on owner's property `path`."""
    for f, v in keys:
        setattr(owner, path, v)
        owner.keyframe_insert(path, frame=int(f))


def apart_objects(subject, coll, name, soup, colors, by_face, scale):
    """The soup as one object coloured by owner, with its feature-edge outlines, each with a shape key
    "Apart" that moves every owner along centre -> centroid (animation_plan.explode_offsets). Returns
    the shape keys and every point where it ends up (to frame the camera on)."""
    S, P = subject.addon.S, subject.addon.P
    count = int(soup.face_owner.max()) + 1 if soup.num_faces else 0
    cen, point_owner = AP.owner_centroids(soup.positions, soup.face_sizes, soup.face_vertices, soup.face_owner, count)
    center = (subject.points.min(axis=0) + subject.points.max(axis=0)) / 2.0
    moved = np.asarray(soup.positions, np.float64) + AP.explode_offsets(cen, center, scale)[point_owner]
    edges = plan.feature_edges(soup.positions, soup.face_sizes, soup.face_vertices, 35.0)
    used, inv = np.unique(edges.ravel(), return_inverse=True)
    with S.Transaction() as tx:
        if by_face:
            ob = S.soup_object(tx, coll, name, soup, np.asarray(colors)[soup.face_owner], None, {"hbc_mesh": subject.name})
        else:
            ob = S.soup_object(tx, coll, name, soup, None, None, {"hbc_mesh": subject.name}, owner_colors=colors)
        lines = P.Lines(np.asarray(soup.positions, np.float32)[used], inv.reshape(-1, 2).astype(np.int32),
                        np.tile(np.asarray(subject.look.outline, np.float32), (len(used), 1)),
                        np.zeros(len(used), np.int32))
        outline = S.lines_object(tx, coll, f"{name} outlines", lines, 0.55 * subject.pixel,
                                 {"hbc_mesh": subject.name, "hbc_outline": True}) if len(used) else None
    keys = []
    for target, co in ((ob, moved), (outline, moved[used] if len(used) else None)):
        if target is None:
            continue
        target.shape_key_add(name="Basis", from_mix=False)
        key = target.shape_key_add(name="Apart", from_mix=False)
        key.data.foreach_set("co", np.ascontiguousarray(co, np.float32).ravel())
        keys.append(key)
    return keys, moved


# ---------------------------------------------------------------------------------------------
# The kinds

def build_turntable(scene, subject, args, frames):
    colls = []
    for key in args.layers:
        colls += getattr(subject, f"panel_{key}")() or []
    cams = AP.orbit_cameras(subject.points, args, frames)
    ob = scene.camera
    ob.data.clip_start, ob.data.clip_end = plan.clip_range(cams[0], plan.bbox_corners(subject.points))
    prev = None
    for f, cam in enumerate(cams, start=1):
        R.place_camera(ob, cam)
        rot = ob.matrix_world.to_euler("XYZ", prev) if prev is not None else ob.matrix_world.to_euler("XYZ")
        ob.rotation_euler = prev = rot  # each key the nearest equivalent of the last: no spin at ±180°
        ob.keyframe_insert("location", frame=f)
        ob.keyframe_insert("rotation_euler", frame=f)
    return Shot(colls, [(1, frames, f"{subject.name}, turntable")], "complex")


def build_explode(scene, subject, args, frames):
    s = subject.s
    coll = subject._new_coll("explode")
    keys, moved = apart_objects(subject, coll, f"{subject.name} components apart", s.blocks(subject.st().shrink),
                                s.component_colors(), False, AP.EXPLODE_SCALE)
    for key in keys:
        key_value(key, "value", AP.explode_keys(frames))
    frame_on(scene, subject, np.concatenate([subject.points, moved]))
    return Shot([coll], [(1, frames, f"{subject.name}, base complex exploded")], "complex")


def build_sheets(scene, subject, args, frames):
    s = subject.s
    if not s.num_sheets:
        return None
    ids = AP.pick_sheets(s.sheet_sizes()[0], args.sheets)
    types = s.sheet_types()
    colls, captions, highlights = [], [], set()
    for i, (a, b) in zip(ids, AP.segments(len(ids), frames)):
        mine = [subject.sheet_layer(i, f"sheet {i}")]
        wire = subject.build(f"sheet {i} wireframe", "wireframe", wireframe_scope="SHEET", simplified=True, sheet_index=i)
        mine.append(wire)
        for c in mine:
            for ob in c.objects:
                keys = [(1, a > 1), (a, False), (b + 1, True)] if a > 1 else [(1, False), (b + 1, True)]
                key_value(ob, "hide_render", keys)
                if ob.get("hbc_highlight"):
                    highlights.add(ob["hbc_highlight"])
        colls += mine
        captions.append((a, b, f"sheet {i}, {subject.addon.P.SHEET_TYPES[int(types[i])]}"))
    frame_on(scene, subject, subject.points)
    return Shot(colls + subject.shell(), captions, "sheet", highlights)


def build_slice(scene, subject, args, frames):
    coll = subject.build("slice", "components")
    plane = subject.cut(coll)
    k, n = AP.slice_axis(subject.direction, args.axis)
    plane.rotation_euler = subject.addon.inspect.plane_rotation(tuple(n))
    for f, p in enumerate(AP.slice_points(subject.points, n, frames), start=1):
        plane.location = tuple(p)
        plane.keyframe_insert("location", frame=f)
    frame_on(scene, subject, subject.points)
    return Shot([coll], [(1, frames, f"{subject.name}, cut along {'xyz'[k]}")], "cut")


def build_subsheets(scene, subject, args, frames):
    s = subject.s
    sheet = AP.intersecting_sheet(s.sheet_types() if s.num_sheets else [], s.sheet_sizes()[0] if s.num_sheets else [],
                                  subject.sheet)
    if sheet is None:
        return None
    count = int(s.subsheets(sheet).count)
    coll = subject._new_coll("subsheets apart")
    keys, moved = apart_objects(subject, coll, f"{subject.name} sheet {sheet} subsheets",
                                s.subsheet_soup(sheet, subject.st().shrink), subject.addon.P.subsheet_colors(count),
                                True, AP.SUBSHEET_SCALE)
    for key in keys:
        key_value(key, "value", AP.apart_keys(frames))
    frame_on(scene, subject, np.concatenate([subject.points, moved]))
    return Shot([coll], [(1, frames, f"sheet {sheet}: {count} subsheets")], "subsheets")


BUILDERS = {"turntable": build_turntable, "explode": build_explode, "sheets": build_sheets, "slice": build_slice,
            "subsheets": build_subsheets}


# ---------------------------------------------------------------------------------------------
# Frames, captions, legend, encoding

def render_frames(scene, kind, args, folder):
    """PNG frames f_0001.png ... of the scene's animation into `folder`, progress on stderr."""
    scene.frame_start, scene.frame_end = 1, args.frames
    scene.render.fps = args.fps
    if args.engine == "workbench":
        # One sample smoothed by FXAA, not the stills' 8: each sample draws the scene again, and in
        # software OpenGL that is most of a frame's time (motion hides what FXAA leaves).
        scene.display.render_aa = "FXAA"
    compat.image_output(scene)
    scene.render.filepath = os.path.join(folder, "f_####")
    handler = progress(kind, args.frames)
    bpy.app.handlers.render_write.append(handler)
    try:
        with R.quiet_stdout():
            bpy.ops.render.render(animation=True, scene=scene.name)
    finally:
        bpy.app.handlers.render_write.remove(handler)
    files = sorted(f for f in os.listdir(folder) if f.startswith("f_") and f.endswith(".png"))
    if len(files) != args.frames:
        raise RuntimeError(f"{kind}: {len(files)} frames rendered, {args.frames} expected")
    return [os.path.join(folder, f) for f in files]


def legend_strip(subject, shot, width):
    """The legend strip of the shot's panel, `width` wide (None when its panel names no colours)."""
    entries = plan.panel_legend(subject.addon.P, shot.panel, subject.s.legend_facts(), shot.highlights,
                                subject.args.wire_colors == "kind")
    if not entries:
        return None
    m = plan.LegendMetrics.for_panel(subject.args.resolution[1])
    texts = [w for _, w, _ in entries]
    tmp = tempfile.mkdtemp(prefix="hbc_anim_")
    images = R.render_labels(texts, 20 * m.row, m.row, tmp)
    os.rmdir(tmp)
    words = []
    for img in images:
        ink = C.ink_columns(img)
        words.append(img[:, ink[0]:ink[1]] if ink is not None else img[:, :1])
    layout = plan.legend_layout([wd.shape[1] for wd in words], width, m)
    height = plan.strip_height(m, layout.rows)
    height += height % 2  # videos need even sides
    return C.legend_strip(width, height, [c for _, _, c in entries], words, layout)


def caption_images(subject, shot, width):
    """{text: (label image)} of the shot's captions, as the stills' labels are drawn."""
    h = max(14, round(subject.args.resolution[1] * 0.07))
    tmp = tempfile.mkdtemp(prefix="hbc_anim_")
    texts = sorted({t for _, _, t in shot.captions})
    images = R.render_labels(texts, width, h, tmp)
    os.rmdir(tmp)
    return dict(zip(texts, images))


def dress_frames(subject, kind, shot, files):
    """Captions (in the look's ink, at the top) and the legend strip (below) drawn onto the frames."""
    args = subject.args
    captions = args.caption == "on" or (args.caption == "auto" and kind in ("sheets", "subsheets"))
    if not captions and not args.legend:
        return
    w = args.resolution[0]
    labels = caption_images(subject, shot, w) if captions else {}
    strip = legend_strip(subject, shot, w) if args.legend else None
    ink = np.asarray(subject.look.ink[:3], np.float32)
    for f, path in enumerate(files, start=1):
        img = R.load_png(path)
        text = next((t for a, b, t in shot.captions if a <= f <= b), None) if captions else None
        if text is not None:
            lab = labels[text]
            alpha = lab[..., 3:4]
            top = img[:lab.shape[0], :lab.shape[1]]
            top[..., :3] = top[..., :3] * (1.0 - alpha) + ink * alpha
        if strip is not None:
            img = C.stack(img, strip)
        R.save_png(img, path)


def frame_strip(files, count, path):
    """Frames (animation_plan.strip_frames) side by side on the background, one gap apart."""
    imgs = [R.load_png(files[i]) for i in AP.strip_frames(len(files), count)]
    h, w = imgs[0].shape[:2]
    strip = C.canvas(len(imgs) * w + (len(imgs) - 1) * C.PAD, h, tuple(imgs[0][0, 0]))
    for k, img in enumerate(imgs):
        C.paste(strip, img, k * (w + C.PAD), 0)
    return R.save_png(strip, path)


def encode(frames_dir, files, fmt, out, args):
    """The frames as `out`: a video through Blender's FFmpeg, a GIF through the ffmpeg program, or
    (png) the folder of frames itself."""
    if fmt == "png":
        if os.path.isdir(out):
            shutil.rmtree(out)
        shutil.move(frames_dir, out)
        return out
    if fmt == "gif":
        ffmpeg = shutil.which("ffmpeg")
        if ffmpeg is None:
            raise RuntimeError("--format gif needs the ffmpeg program on PATH (Debian's ffmpeg package)")
        cmd = AP.gif_command(ffmpeg, os.path.join(frames_dir, "f_%04d.png"), args.fps, out)
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0 or not os.path.isfile(out):
            raise RuntimeError(f"ffmpeg could not make {out}: {p.stderr.strip()[-500:]}")
        return out
    return encode_video(files, fmt, out, args)


def encode_video(files, fmt, out, args):
    """The PNG frames as an image strip in a scene of their own, rendered through Blender's FFmpeg."""
    first = R.load_png(files[0])
    h, w = first.shape[:2]
    vs = bpy.data.scenes.new("Figures Video")
    try:
        r = vs.render
        r.resolution_x, r.resolution_y, r.resolution_percentage = w, h, 100
        r.fps = args.fps
        vs.frame_start, vs.frame_end = 1, len(files)
        vs.view_settings.view_transform = "Standard"  # the frames are display colours already
        vs.view_settings.look = "None"
        strips = compat.sequencer_strips(vs)
        strip = strips.new_image(name="frames", filepath=files[0], channel=1, frame_start=1)
        for f in files[1:]:
            strip.elements.append(os.path.basename(f))
        compat.video_output(vs, fmt)
        r.use_file_extension = False
        r.filepath = out
        with R.quiet_stdout():
            bpy.ops.render.render(animation=True, scene=vs.name)
    finally:
        bpy.data.scenes.remove(vs)
    if not os.path.isfile(out):
        raise RuntimeError(f"Blender's FFmpeg did not write {out}")
    return out


def reset_kind(scene, subject):
    """Back to the stills' camera, no keys: each kind starts from the same scene."""
    scene.camera.animation_data_clear()
    R.place_camera(scene.camera, subject.camera)
    scene.frame_set(1)


def animate(args, start, wrote):
    """Every kind of args.animate for args.mesh, one file (or folder) each; `start` and `wrote` are
    the figure script's (the studio scene around the analysed mesh; a written file printed)."""
    scene, subject = start(args, args.mesh)
    os.makedirs(args.out, exist_ok=True)
    written = []
    for kind in args.animate:
        reset_kind(scene, subject)
        t = time.perf_counter()
        shot = BUILDERS[kind](scene, subject, args, args.frames)
        if shot is None:
            R.log(f"render_figures: {kind} skipped: {subject.name} has no "
                  f"{'self-intersecting sheet' if kind == 'subsheets' else 'sheets'}")
            continue
        subject.show(shot.colls)
        folder = tempfile.mkdtemp(prefix=f"hbc_{kind}_")
        try:
            files = render_frames(scene, kind, args, folder)
            t_render = time.perf_counter() - t
            dress_frames(subject, kind, shot, files)
            out = os.path.abspath(os.path.join(args.out, AP.output_name(subject.name, kind, args.format)))
            if args.strip:
                wrote(frame_strip(files, args.strip, os.path.abspath(
                    os.path.join(args.out, f"{subject.name}_{kind}_strip.png"))), written)
            encode(folder, files, args.format, out, args)
        finally:
            if os.path.isdir(folder):
                shutil.rmtree(folder)
        R.log(f"render_figures: {kind}: {args.frames} frames in {t_render:.1f} s, "
              f"{time.perf_counter() - t:.1f} s with encoding")
        wrote(out, written)
    if args.blend:
        blend = os.path.abspath(os.path.join(args.out, f"{subject.name}_animation.blend"))
        bpy.ops.wm.save_as_mainfile(filepath=blend, check_existing=False)
        wrote(blend, written)
    if not written:
        raise RuntimeError("no animation rendered")
    return written
