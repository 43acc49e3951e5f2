"""What the animations (`render_figures.py --animate KIND[,KIND...]`) decide without Blender (no
``bpy``; tested with plain pytest): the kinds and their files, the camera of every turntable frame,
how far each component drifts in `explode` and when, which sheets `sheets` shows and for how many
frames each, where the `slice` plane is at each frame, and the GIF encoder's command line.
"""

from __future__ import annotations

import math

import numpy as np

from . import plan

#: The kinds of animation, in the order they render: key, what moves.
KINDS = (
    ("turntable", "the camera orbits the mesh once"),
    ("explode", "the base complex's components drift out from the centre and back"),
    ("sheets", "each sheet in turn, highlighted with its VSG wireframe"),
    ("slice", "a cutting plane sweeps through the base complex"),
    ("subsheets", "a self-intersecting sheet taken apart into its subsheets"),
)
KIND_KEYS = tuple(k for k, _ in KINDS)
FORMATS = ("mp4", "webm", "gif", "png")
#: The panel whose look (and legend) each kind shares.
KIND_PANEL = {"turntable": "complex", "explode": "complex", "sheets": "sheet", "slice": "cut",
              "subsheets": "subsheets"}
#: Layers the turntable can show (--layers): the still panels that need no sheet.
TURNTABLE_LAYERS = ("mesh", "graph", "complex", "mesh_wireframe")
EXPLODE_SCALE = 0.8  # a component moves this fraction of its centroid's distance from the centre
SUBSHEET_SCALE = 1.2  # subsheets overlap where the sheet crosses itself: they move farther
DEFAULT_SHEETS = 6  # `sheets` without --sheets: the largest ones


def add_arguments(ap):
    """The animation options of render_figures.py's parser (figures/plan.parser)."""
    ap.add_argument("--animate", default=None, metavar="KIND[,KIND...]",
                    help="render animations instead of the still panels: " + ", ".join(f"{k} ({d})" for k, d in KINDS))
    ap.add_argument("--format", choices=FORMATS, default="mp4",
                    help="animation output: mp4 (H.264) or webm (VP9) through Blender's FFmpeg, gif (a looping "
                         "palette GIF made by the ffmpeg program), png (the frames, in a folder)")
    ap.add_argument("--frames", type=int, default=120, help="frames of each animation")
    ap.add_argument("--fps", type=int, default=30, help="frames per second of the video")
    ap.add_argument("--layers", default=None,
                    help="turntable: comma-separated panels shown together, from " + ",".join(TURNTABLE_LAYERS) +
                         " (default: complex in Workbench, which draws the boundary opaque; mesh,complex otherwise)")
    ap.add_argument("--sheets", default=None,
                    help=f"sheets animation: N (the N largest sheets) or a list of sheet ids (default: the "
                         f"{DEFAULT_SHEETS} largest)")
    ap.add_argument("--axis", choices=("x", "y", "z"), default=None,
                    help="slice: the axis the plane sweeps along (default: the one closest to the view direction)")
    ap.add_argument("--caption", choices=("auto", "on", "off"), default="auto",
                    help="a caption on the frames: auto (sheets and subsheets say which), on (every kind), off")
    ap.add_argument("--strip", type=int, default=0, metavar="N",
                    help="also write <name>_<kind>_strip.png: N frames, evenly spaced, side by side")


def check(ap, args):
    """Validates and normalises the animation options (ap.error on misuse)."""
    if args.animate is None:
        return
    kinds = [k.strip() for k in args.animate.split(",") if k.strip()]
    bad = [k for k in kinds if k not in KIND_KEYS]
    if bad or not kinds:
        ap.error(f"--animate: unknown {','.join(bad) or '(none)'}; choose from {','.join(KIND_KEYS)}")
    if args.compare:
        ap.error("--animate takes one MESH, not --compare")
    args.animate = [k for k in KIND_KEYS if k in kinds]
    if args.frames < 2 or args.frames > 100000:
        ap.error("--frames: between 2 and 100000")
    if args.fps < 1 or args.fps > 240:
        ap.error("--fps: between 1 and 240")
    if args.format in ("mp4", "webm") and (args.resolution[0] % 2 or args.resolution[1] % 2):
        ap.error("--resolution: H.264 and VP9 need even sides")
    if args.strip < 0 or args.strip > args.frames:
        ap.error("--strip: between 0 and --frames")
    if args.layers is not None:
        layers = [k.strip() for k in args.layers.split(",") if k.strip()]
        if not layers or any(k not in TURNTABLE_LAYERS for k in layers):
            ap.error(f"--layers: choose from {','.join(TURNTABLE_LAYERS)}")
        args.layers = layers
    else:
        args.layers = ["complex"] if args.engine == "workbench" else ["mesh", "complex"]
    if args.sheets is not None:
        try:
            ids = [int(v) for v in args.sheets.split(",") if v.strip()]
        except ValueError:
            ap.error("--sheets: N or a comma-separated list of sheet ids")
        if not ids or any(i < 0 for i in ids) or ("," not in args.sheets and ids[0] == 0):
            ap.error("--sheets: N >= 1 or sheet ids >= 0")
        args.sheets = ("list", ids) if "," in args.sheets else ("largest", ids[0])


def output_name(mesh_name, kind, fmt):
    """`<name>_<kind>.<ext>`; the png format is a folder of frames of that name."""
    return f"{mesh_name}_{kind}" if fmt == "png" else f"{mesh_name}_{kind}.{fmt}"


# ---------------------------------------------------------------------------------------------
# turntable

def orbit_cameras(points, args, frames):
    """The camera of every frame of one full turn around the up axis, starting at the stills'
    view: each frame framed as a still is (plan.frame), then all pushed back to the farthest of
    their distances, so the mesh keeps its size on screen and never leaves the frame."""
    pts = plan.framing_points(points)
    center = (pts.min(axis=0) + pts.max(axis=0)) / 2.0
    w, h = args.resolution
    cams = [plan.frame(pts, plan.view_direction(args.azimuth + 360.0 * f / frames, args.elevation, args.up),
                       args.up, w, h) for f in range(frames)]
    rel = [c.matrix.T @ (c.location - center) for c in cams]  # (shift x, shift y, distance) in each view
    far = max(r[2] for r in rel)
    for c, r in zip(cams, rel):
        c.location = center + c.matrix @ np.array([r[0], r[1], far])
    return cams


# ---------------------------------------------------------------------------------------------
# explode and subsheets

def owner_centroids(positions, face_sizes, face_vertices, face_owner, count):
    """(count, 3) mean position of each owner's points (a point counted once per face corner) and the
    owner of every point (the last face's owner where faces of several owners share one)."""
    pos = np.asarray(positions, np.float64).reshape(-1, 3)
    fv = np.asarray(face_vertices, np.int64)
    corner_owner = np.repeat(np.asarray(face_owner, np.int64), np.asarray(face_sizes, np.int64))
    point_owner = np.zeros(len(pos), np.int64)
    point_owner[fv] = corner_owner
    n = np.maximum(np.bincount(corner_owner, minlength=count), 1)
    cen = np.stack([np.bincount(corner_owner, weights=pos[fv, i], minlength=count) for i in range(3)], axis=1)
    return cen / n[:, None], point_owner


def explode_offsets(centroids, center, scale=EXPLODE_SCALE):
    """Each owner's full displacement: along the line from the centre to its centroid, as long as
    `scale` times that distance (the farther out, the farther it goes; the centre one stays)."""
    return (np.asarray(centroids, np.float64) - np.asarray(center, np.float64)) * float(scale)


def explode_keys(frames):
    """(frame, weight) keys of the explode: together, fully apart at the middle frame, together again
    (Blender's default Bézier keys ease in and out between them)."""
    return [(1, 0.0), ((frames + 1) // 2, 1.0), (frames, 0.0)]


def apart_keys(frames):
    """(frame, weight) keys of the subsheets: apart over the first half, then held apart."""
    return [(1, 0.0), ((frames + 1) // 2, 1.0), (frames, 1.0)]


def weight_at(keys, frame):
    """The weight at `frame` of piecewise-linear keys (the Bézier keys' shape, without easing): what
    the explode test expects to grow and shrink."""
    f, v = zip(*keys)
    return float(np.interp(frame, f, v))


def intersecting_sheet(types, cells, preferred=None):
    """The sheet the subsheets animation takes apart: `preferred` when it is self-intersecting, else
    the largest self-intersecting sheet (ties to the lower id); None without one."""
    types = np.asarray(types, np.int64)
    if preferred is not None and 0 <= preferred < len(types) and types[preferred] == 3:
        return int(preferred)
    idx = np.nonzero(types == 3)[0]
    if not len(idx):
        return None
    cells = np.asarray(cells, np.int64)
    return int(idx[np.lexsort((idx, -cells[idx]))][0])


def screen_separation(camera, centroids, offsets, weight):
    """Mean distance on screen (normalised image units) of the owners' centroids from their mean,
    at `weight` of the full displacement: what the explode test watches grow and shrink."""
    uv, _ = camera.project(np.asarray(centroids) + weight * np.asarray(offsets))
    return float(np.mean(np.linalg.norm(uv - uv.mean(axis=0), axis=1)))


# ---------------------------------------------------------------------------------------------
# sheets

def pick_sheets(cells, request=None, default=DEFAULT_SHEETS):
    """Sheet ids the `sheets` animation shows, in order: the listed ones (checked), else the N
    largest (by cells; ties to the lower id), largest first."""
    cells = np.asarray(cells, np.int64)
    n = len(cells)
    if request is not None and request[0] == "list":
        bad = [i for i in request[1] if i >= n]
        if bad:
            raise ValueError(f"--sheets: the mesh has {n} sheets (0..{n - 1}), not {bad}")
        return list(dict.fromkeys(request[1]))
    count = request[1] if request is not None else default
    return [int(i) for i in np.lexsort((np.arange(n), -cells))[:count]]


def segments(count, frames):
    """[(first, last)] frame ranges (1-based, inclusive) sharing `frames` among `count` items in
    turn, the first items one frame longer when it does not divide."""
    if count <= 0:
        return []
    if frames < count:
        raise ValueError(f"--frames {frames}: fewer frames than the {count} sheets to show")
    base, extra = divmod(frames, count)
    out, f = [], 1
    for k in range(count):
        n = base + (1 if k < extra else 0)
        out.append((f, f + n - 1))
        f += n
    return out


# ---------------------------------------------------------------------------------------------
# slice

def slice_axis(direction, axis=None):
    """(axis index, unit normal): the requested axis or the one closest to the view direction, the
    normal signed towards the camera so the near part goes first and the cut faces the viewer."""
    d = np.asarray(direction, np.float64)
    k = plan.AXES[axis] if axis else int(np.argmax(np.abs(d)))
    n = np.zeros(3)
    n[k] = 1.0 if d[k] >= 0 else -1.0
    return k, n


def slice_points(points, normal, frames, keep=0.1):
    """The plane's point at every frame: from just beyond the mesh on the camera's side (nothing
    cut) to `keep` of the extent before its far side (a slab left), linearly."""
    pts = np.asarray(points, np.float64).reshape(-1, 3)
    n = np.asarray(normal, np.float64)
    s = pts @ n
    lo, hi = float(s.min()), float(s.max())
    span = max(hi - lo, 1e-12)
    center = (pts.min(axis=0) + pts.max(axis=0)) / 2.0
    base = center - (center @ n) * n  # the centre, moved onto the plane through the origin
    start, end = hi + 0.01 * span, lo + keep * span
    return [base + (start + (end - start) * f / max(frames - 1, 1)) * n for f in range(frames)]


# ---------------------------------------------------------------------------------------------
# Output

def strip_frames(frames, count):
    """0-based indices of `count` frames evenly spaced over `frames`, the first and last included."""
    return sorted({int(round(v)) for v in np.linspace(0, frames - 1, count)})


def gif_command(ffmpeg, pattern, fps, out):
    """ffmpeg's command for a looping GIF of a PNG sequence with one palette made from its frames."""
    return [ffmpeg, "-v", "error", "-y", "-framerate", str(int(fps)), "-start_number", "1", "-i", pattern,
            "-filter_complex", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=sierra2_4a",
            "-loop", "0", out]
