"""What the figure script decides without Blender (no ``bpy``; tested with plain pytest):
command line, the panels and their titles, which sheet and subsheets to show, the camera that
frames a set of points, the feature edges that outline soups, and what each panel's legend strip
lists and where its swatches and words go.
"""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass

import numpy as np

#: The paper's pipeline panels (Fig. 1 a-g): key, letter, title.
PANELS = (
    ("mesh", "a", "Mesh"),
    ("graph", "b", "Hybrid singularity graph"),
    ("complex", "c", "Hybrid base complex"),
    ("sheet", "d", "Sheet"),
    ("vsg", "e", "VSG"),
    ("wireframe", "f", "Simplified VSG wireframe"),
    ("subsheets", "g", "Subsheets"),
)
#: Inspection panels, rendered only when asked for with --panels: the base complex's
#: components cut by a plane, and the cells coloured by scaled Jacobian (viridis), cut the same way.
INSPECT_PANELS = (
    ("cut", "h", "Base complex, cut"),
    ("quality", "i", "Scaled Jacobian (viridis, 0 purple to 1 yellow), cut"),
)
PANEL_KEYS = tuple(k for k, _, _ in PANELS)  # the default set
ALL_PANEL_KEYS = PANEL_KEYS + tuple(k for k, _, _ in INSPECT_PANELS)
PANEL_LETTER = {k: l for k, l, _ in PANELS + INSPECT_PANELS}
PANEL_TITLE = {k: t for k, _, t in PANELS + INSPECT_PANELS}

#: Rows of the comparison figure (the paper's Figs. 8-10): mesh, singularity graph, base complex,
#: VSG wireframe of the whole mesh, a representative (imperfect) sheet.
COMPARE_ROWS = (
    ("mesh", "Mesh"),
    ("graph", "Singularity graph"),
    ("complex", "Base complex"),
    ("mesh_wireframe", "VSG wireframe"),
    ("sheet", "Sheet"),
)

ENGINES = ("cycles", "eevee", "workbench")


@dataclass(frozen=True)
class Look:
    """How stills and animations are dressed (--look); the legend's colours are never changed."""

    background: float  # grey of the background as shown (display value)
    outline: tuple  # linear RGBA of the components' and sheets' outlines
    mesh_edge: tuple  # linear RGBA of the mesh's cell edges
    ink: tuple  # linear RGBA of captions drawn on frames
    clay: bool  # one neutral material: blocks told apart by ambient occlusion and edges only


#: paper: today's white figures; slide: a dark background, outlines and text light so the colours
#: stay legible on a projector; clay: paper's background and edges over one neutral grey material.
LOOKS = {
    "paper": Look(0.94, (0.03, 0.03, 0.035, 1.0), (0.18, 0.18, 0.2, 0.55), (0.02, 0.02, 0.025, 1.0), False),
    "slide": Look(0.09, (0.80, 0.80, 0.82, 1.0), (0.55, 0.55, 0.6, 0.55), (0.92, 0.92, 0.92, 1.0), False),
    "clay": Look(0.94, (0.03, 0.03, 0.035, 1.0), (0.18, 0.18, 0.2, 0.55), (0.02, 0.02, 0.025, 1.0), True),
}
CLAY_COLOR = (0.62, 0.60, 0.57, 1.0)  # linear RGBA of the clay material


def script_args(argv):
    """The script's own arguments: those after Blender's '--' separator when Blender runs the
    script (`blender -b --python render_figures.py -- ARGS`), else, when a Python with the `bpy`
    module runs it as a script (`python render_figures.py ARGS`), everything after its name."""
    if "--" in argv:
        return list(argv[argv.index("--") + 1:])
    if argv and argv[0].endswith(".py"):
        return list(argv[1:])
    return []


def parser(extensions=()):
    ap = argparse.ArgumentParser(
        prog="render_figures.py",
        description="Renders the paper's pipeline panels (a-g) of a hex-dominant mesh, or with --compare "
                    "the comparison layout of two meshes, as PNG files plus one labelled contact sheet.")
    ap.add_argument("mesh", nargs="?", help="the mesh (.ovm .ovmb .mesh .HYBRID .hedra)")
    ap.add_argument("--compare", nargs=2, metavar=("A", "B"), help="comparison figure of two meshes")
    ap.add_argument("--out", required=True, help="output folder (created)")
    ap.add_argument("--engine", choices=ENGINES, default="cycles")
    ap.add_argument("--samples", type=int, default=None, help="render samples (cycles 16, eevee 16)")
    ap.add_argument("--denoise", choices=("auto", "on", "off"), default="auto",
                    help="Cycles denoising with OpenImageDenoise: auto (where this Blender has it), on "
                         "(fail without it), off")
    ap.add_argument("--resolution", type=int, nargs=2, metavar=("W", "H"), default=(640, 480))
    ap.add_argument("--sheet", type=int, default=None,
                    help="sheet of panels d-g (default: the largest self-intersecting sheet, else the "
                         "largest imperfect one, else the largest; within that class the largest with a "
                         "non-empty VSG wireframe first)")
    ap.add_argument("--panels", default=",".join(PANEL_KEYS),
                    help="comma-separated subset of " + ",".join(ALL_PANEL_KEYS) + " (default: the first seven)")
    ap.add_argument("--cut-plane", type=float, nargs=6, metavar=("PX", "PY", "PZ", "NX", "NY", "NZ"), default=None,
                    help="plane of the cut and quality panels: a point and a normal pointing to the hidden "
                         "side (default: through the bounding-box centre, facing the camera)")
    ap.add_argument("--max-subsheets", type=int, default=4, help="largest subsheets shown in panel g")
    ap.add_argument("--up", choices=("x", "y", "z"), default="z", help="the mesh's up axis")
    ap.add_argument("--azimuth", type=float, default=-50.0, help="view azimuth in degrees around up")
    ap.add_argument("--elevation", type=float, default=25.0, help="view elevation in degrees")
    ap.add_argument("--rho", type=float, default=0.8, help="partial-parallel threshold of the wireframe colours")
    ap.add_argument("--subsheet-rule", choices=("layers", "fewest"), default="layers",
                    help="how self-intersecting sheets are split into subsheets (the add-on's Subsheets setting)")
    ap.add_argument("--wire-colors", choices=("class", "kind"), default="class",
                    help="colour the VSG wireframes by partial-parallel class (the paper's) or by the non-hex "
                         "kinds of their chains (the cell types they end at or run beside)")
    ap.add_argument("--addon", default=None,
                    help="blender_scripts/render_figures.py: the add-on whose figures run (default: "
                         "$HBC_ADDON_DIR, else <repo>/build/addon/hybrid_base_complex); the add-on's own "
                         "figures/render_figures.py runs its own package")
    ap.add_argument("--blend", action="store_true", help="also save the scene as a .blend next to the images")
    ap.add_argument("--legend", action="store_true",
                    help="add under every panel a strip of colour swatches with words for what it shows (the "
                         "add-on's legend), and write <name>_legend.json")
    ap.add_argument("--look", choices=tuple(LOOKS), default="paper",
                    help="paper (white background), slide (dark background), clay (one neutral material, "
                         "blocks told apart by ambient occlusion and edges); stills and animations alike")
    for ext in extensions:
        ext.add_arguments(ap)
    return ap


def parse(argv, extensions=()):
    """Parses the script's own arguments (after '--'); raises SystemExit(2) on misuse. `extensions`:
    modules adding options (add_arguments) and their checks (check), e.g. animation_plan, which
    imports this module."""
    ap = parser(extensions)
    args = ap.parse_args(argv)
    if (args.mesh is None) == (args.compare is None):
        ap.error("give one MESH, or --compare A B")
    w, h = args.resolution
    if w < 16 or h < 16 or w > 8192 or h > 8192:
        ap.error("--resolution: each side between 16 and 8192")
    if args.samples is not None and args.samples < 1:
        ap.error("--samples must be at least 1")
    keys = [k.strip() for k in args.panels.split(",") if k.strip()]
    bad = [k for k in keys if k not in ALL_PANEL_KEYS]
    if bad or not keys:
        ap.error(f"--panels: unknown {','.join(bad) or '(none)'}; choose from {','.join(ALL_PANEL_KEYS)}")
    args.panels = [k for k in ALL_PANEL_KEYS if k in keys]
    if args.cut_plane is not None and not np.any(np.asarray(args.cut_plane[3:])):
        ap.error("--cut-plane: the normal must not be zero")
    if args.max_subsheets < 1:
        ap.error("--max-subsheets must be at least 1")
    if args.samples is None:
        args.samples = 16
    for ext in extensions:
        ext.check(ap, args)
    return args


def cut_plane(points, direction, requested=None):
    """(point, unit normal) of the cut panels: `requested` (px py pz nx ny nz), else through the
    bounding-box centre with the normal towards the camera (`direction`), so the near half is
    hidden and the cut faces the viewer."""
    if requested is not None:
        p, n = np.asarray(requested[:3], np.float64), np.asarray(requested[3:], np.float64)
    else:
        pts = np.asarray(points, np.float64).reshape(-1, 3)
        p, n = (pts.min(axis=0) + pts.max(axis=0)) / 2.0, np.asarray(direction, np.float64)
    return p, n / np.linalg.norm(n)


# ---------------------------------------------------------------------------------------------
# Choices

def pick_sheet(types, cells, requested=None, shows_vsg=None):
    """The sheet of panels d-g: `requested` if given (checked), else the largest (by cells)
    self-intersecting sheet, else the largest imperfect one, else the largest; None when there are
    no sheets. `shows_vsg` (sheet id -> bool, optional): whether a sheet's VSG wireframe has
    something to draw (panels e and f). Within the class chosen, the largest sheet that has one
    comes first: a sheet whose region is the same all along (a twisted ring's, with no cell that
    ends its VSG chains) has an empty wireframe and would leave e and f out. It is asked about the
    class's sheets from the largest down, until one has one; if none has, the largest."""
    types = np.asarray(types, np.int64)
    cells = np.asarray(cells, np.int64)
    n = len(types)
    if requested is not None:
        if not (0 <= requested < n):
            raise ValueError(f"--sheet {requested}: the mesh has {n} sheets (0..{n - 1})")
        return int(requested)
    if n == 0:
        return None
    for mask in (types == 3, types > 0, np.ones(n, bool)):
        if mask.any():
            idx = np.nonzero(mask)[0]
            # Largest first; ties to the lower id.
            order = [int(i) for i in idx[np.lexsort((idx, -cells[idx]))]]
            if shows_vsg is not None:
                for i in order:
                    if shows_vsg(i):
                        return i
            return order[0]
    return None


def pick_subsheets(sizes, limit):
    """Ids of the `limit` largest subsheets (by cells), in id order."""
    sizes = np.asarray(sizes, np.int64)
    order = np.lexsort((np.arange(len(sizes)), -sizes))[: max(int(limit), 0)]
    return sorted(int(i) for i in order)


def tile_grid(count, width, height):
    """Panel g: `count` subsheets as columns, each a subsheet above its wireframe. Returns the tile
    size (w, h) and the (x, y) of the top-left corner of the subsheet tile and of the wireframe
    tile of every column; the tiles fill width x height."""
    count = max(int(count), 1)
    tw = width // count
    th = height // 2
    spare = width - tw * count
    cols = []
    for k in range(count):
        x = spare // 2 + k * tw
        cols.append(((x, 0), (x, th)))
    return (tw, th), cols


# ---------------------------------------------------------------------------------------------
# Camera

AXES = {"x": 0, "y": 1, "z": 2}


def up_vector(up: str) -> np.ndarray:
    v = np.zeros(3)
    v[AXES[up]] = 1.0
    return v


def view_direction(azimuth_deg: float, elevation_deg: float, up: str = "z") -> np.ndarray:
    """Unit vector from the target towards the camera: azimuth around the up axis (0: along the
    axis after `up` in xyz order, i.e. +x for up=z), elevation above the horizontal plane."""
    a, e = math.radians(azimuth_deg), math.radians(elevation_deg)
    u = AXES[up]
    h1, h2 = (u + 1) % 3, (u + 2) % 3
    d = np.zeros(3)
    d[h1] = math.cos(e) * math.cos(a)
    d[h2] = math.cos(e) * math.sin(a)
    d[u] = math.sin(e)
    return d / np.linalg.norm(d)


@dataclass
class Camera:
    location: np.ndarray  # (3,)
    matrix: np.ndarray  # (3,3) columns: right, up, backward (Blender camera looks along -Z)
    lens: float  # focal length in mm with a 36 mm sensor fitted to the larger side
    width: int
    height: int

    def project(self, points):
        """Normalised image coordinates: (x, y) in [-1, 1] inside the frame."""
        p = np.asarray(points, np.float64).reshape(-1, 3) - self.location
        cam = p @ self.matrix  # components along right, up, backward
        depth = -cam[:, 2]
        tx, ty = half_tangents(self.lens, self.width, self.height)
        return np.stack([cam[:, 0] / (depth * tx), cam[:, 1] / (depth * ty)], axis=1), depth


def half_tangents(lens, width, height, sensor=36.0):
    """tan of the half field of view along x and y (Blender's AUTO sensor fit: the larger side)."""
    t = sensor / (2.0 * lens)
    if width >= height:
        return t, t * height / width
    return t * width / height, t


def bbox_corners(points):
    p = np.asarray(points, np.float64).reshape(-1, 3)
    lo, hi = p.min(axis=0), p.max(axis=0)
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def framing_points(points, limit=200000):
    """The points the camera frames: the mesh's points (tighter than its bounding box's corners,
    and everything drawn is made of them), subsampled evenly above `limit`, plus the box's
    extreme points along each axis so that the subsample keeps the full extent."""
    p = np.asarray(points, np.float64).reshape(-1, 3)
    if len(p) == 0:
        return np.zeros((1, 3))
    if len(p) > limit:
        step = int(math.ceil(len(p) / limit))
        ext = np.concatenate([p.argmin(axis=0), p.argmax(axis=0)])
        p = np.concatenate([p[::step], p[ext]])
    return p


def frame(points, direction, up="z", width=640, height=480, lens=50.0, margin=0.06) -> Camera:
    """A perspective camera looking along -direction that holds every point (use the bounding
    box corners: then anything inside the box is in frame) with `margin` (fraction of the half
    frame) left on the tightest side, the points' projection centred in the frame."""
    pts = np.asarray(points, np.float64).reshape(-1, 3)
    back = np.asarray(direction, np.float64)
    back = back / np.linalg.norm(back)
    upv = up_vector(up) if isinstance(up, str) else np.asarray(up, np.float64)
    right = np.cross(upv, back)
    if np.linalg.norm(right) < 1e-9:  # looking along up: any right vector
        right = np.cross(np.array([0.0, 1.0, 0.0]) if abs(back[1]) < 0.9 else np.array([1.0, 0.0, 0.0]), back)
    right /= np.linalg.norm(right)
    cam_up = np.cross(back, right)
    basis = np.stack([right, cam_up, back], axis=1)
    tx, ty = half_tangents(lens, width, height)
    tx, ty = tx * (1.0 - margin), ty * (1.0 - margin)
    center = (pts.min(axis=0) + pts.max(axis=0)) / 2.0
    rel = (pts - center) @ basis  # components in the camera's axes
    # Camera at center + shift (in the image plane) + d * back. A point holds when
    # |x - sx| <= (d - z) tx and |y - sy| <= (d - z) ty. Iterate: the best d for the current
    # shift, then the shift that centres the projection at that d.
    sx = sy = 0.0
    d = 0.0
    for _ in range(30):
        d = max(np.max(np.abs(rel[:, 0] - sx) / tx + rel[:, 2]), np.max(np.abs(rel[:, 1] - sy) / ty + rel[:, 2]))
        depth = d - rel[:, 2]
        u = (rel[:, 0] - sx) / depth
        v = (rel[:, 1] - sy) / depth
        # Move the camera so that the extreme rays become symmetric.
        du = (u.max() + u.min()) / 2.0
        dv = (v.max() + v.min()) / 2.0
        if abs(du) < 1e-7 and abs(dv) < 1e-7:
            break
        sx += du * float(np.median(depth))
        sy += dv * float(np.median(depth))
    d = max(np.max(np.abs(rel[:, 0] - sx) / tx + rel[:, 2]), np.max(np.abs(rel[:, 1] - sy) / ty + rel[:, 2]))
    loc = center + basis @ np.array([sx, sy, d])
    return Camera(loc, basis, float(lens), int(width), int(height))


def clip_range(camera: Camera, points):
    """(clip_start, clip_end) holding the points with room to spare."""
    _, depth = camera.project(points)
    near, far = float(depth.min()), float(depth.max())
    return max(near * 0.5, 1e-4), far * 2.0 + 1e-3


# ---------------------------------------------------------------------------------------------
# Outlines

def feature_edges(positions, face_sizes, face_vertices, angle_deg=35.0):
    """(m, 2) vertex pairs of a polygon soup's feature edges: border edges (one face),
    non-manifold ones (three or more) and edges whose two faces' normals differ by more than
    `angle_deg`. Faces with their own vertex copies per owner (block_soup's soups) give each
    owner's own corner edges, never the seams between owners."""
    pos = np.asarray(positions, np.float64).reshape(-1, 3)
    sizes = np.asarray(face_sizes, np.int64)
    fv = np.asarray(face_vertices, np.int64)
    if sizes.size == 0:
        return np.zeros((0, 2), np.int32)
    starts = np.cumsum(sizes) - sizes
    face_of = np.repeat(np.arange(len(sizes)), sizes)
    pos_in = np.arange(len(fv)) - np.repeat(starts, sizes)
    nxt = np.where(pos_in + 1 == np.repeat(sizes, sizes), np.repeat(starts, sizes), np.arange(len(fv)) + 1)
    a, b = fv, fv[nxt]
    # Newell normals.
    pa, pb = pos[a], pos[b]
    n = np.zeros((len(sizes), 3))
    cr = np.stack([(pa[:, 1] - pb[:, 1]) * (pa[:, 2] + pb[:, 2]),
                   (pa[:, 2] - pb[:, 2]) * (pa[:, 0] + pb[:, 0]),
                   (pa[:, 0] - pb[:, 0]) * (pa[:, 1] + pb[:, 1])], axis=1)
    for i in range(3):
        n[:, i] = np.bincount(face_of, weights=cr[:, i], minlength=len(sizes))
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    key = lo * (len(pos) + 1) + hi
    order = np.argsort(key, kind="stable")
    key_s = key[order]
    uniq, first, counts = np.unique(key_s, return_index=True, return_counts=True)
    keep = counts != 2
    two = np.nonzero(counts == 2)[0]
    f1 = face_of[order[first[two]]]
    f2 = face_of[order[first[two] + 1]]
    cosang = np.sum(n[f1] * n[f2], axis=1)
    sharp = np.zeros(len(uniq), bool)
    sharp[two] = cosang < math.cos(math.radians(angle_deg))
    sel = keep | sharp
    e = uniq[sel]
    return np.stack([e // (len(pos) + 1), e % (len(pos) + 1)], axis=1).astype(np.int32)


def all_edges(face_sizes, face_vertices):
    """(m, 2) unique vertex pairs of every polygon edge."""
    sizes = np.asarray(face_sizes, np.int64)
    fv = np.asarray(face_vertices, np.int64)
    if sizes.size == 0:
        return np.zeros((0, 2), np.int32)
    starts = np.cumsum(sizes) - sizes
    pos_in = np.arange(len(fv)) - np.repeat(starts, sizes)
    nxt = np.where(pos_in + 1 == np.repeat(sizes, sizes), np.repeat(starts, sizes), np.arange(len(fv)) + 1)
    e = np.sort(np.stack([fv, fv[nxt]], axis=1), axis=1)
    return np.unique(e, axis=0).astype(np.int32)


# ---------------------------------------------------------------------------------------------
# Legend strip (--legend)

#: The add-on layers whose legend (hybrid_base_complex.plan.planning.legend) each panel shows. Panels
#: coloured from the palette only (VSG, wireframes: one colour per chain, meaning nothing beyond
#: telling chains apart) have no entries; nor has the quality panel, whose title names its colour map.
LEGEND_LAYERS = {
    "mesh": ("direct",),
    "graph": ("graph",),
    "complex": ("components",),
    "sheet": ("sheet",),
    "vsg": (),
    "wireframe": (),
    "subsheets": ("subsheets",),
    "cut": ("components",),
    "quality": (),
    "mesh_wireframe": (),
}


#: The panels whose wireframes a colouring by non-hex kind colours, with the layer whose legend
#: then names the kinds (planning.legend's wire_by_kind).
WIRE_PANELS = {"wireframe": "wireframe", "mesh_wireframe": "wireframe", "subsheets": "subsheets"}


def panel_legend(P, key, facts, highlights=(), wire_by_kind=False):
    """[(colour key, words, linear RGBA)] of panel `key`: the add-on's legend (P: its planning
    module, the one place that defines the colours and words) for the layers the panel shows.
    facts: Structure.legend_facts(); highlights: the sheet highlights the panel draws;
    wire_by_kind: the wireframes are coloured by non-hex kind (--wire-colors kind)."""
    layers = LEGEND_LAYERS.get(key, ())
    if wire_by_kind and key in WIRE_PANELS:
        layers = tuple(dict.fromkeys(layers + (WIRE_PANELS[key],)))
    if not layers:
        return []
    return [(k, words, tuple(float(c) for c in P.LEGEND_COLORS[k]))
            for k, words in P.legend(layers, highlights=set(highlights), wire_by_kind=wire_by_kind, **facts)]


@dataclass
class LegendMetrics:
    """Sizes of a legend strip in pixels, all from the row height: words are rendered at the
    labels' proportion of a row (render.render_labels), the swatch is a square a little taller
    than the words' capitals."""

    row: int  # height of one row of entries (and of a rendered word image)
    swatch: int  # side of a colour swatch
    gap: int  # between a swatch and its words
    column_gap: int  # between two columns of entries
    margin: int  # above the first row, below the last and left/right of the widest row

    @staticmethod
    def for_panel(height):
        row = max(24, round(0.065 * height))
        return LegendMetrics(row, max(7, round(0.55 * row)), max(3, round(0.3 * row)),
                             max(8, round(1.1 * row)), max(4, round(0.4 * row)))


@dataclass
class LegendLayout:
    """Where each entry goes in a strip `width` wide: swatch boxes (x, y, side) and word origins (x,
    y) of the row images, entries in reading order on a grid whose columns line up."""

    width: int
    rows: int
    columns: int
    swatches: list
    words: list

def strip_height(metrics: LegendMetrics, rows: int) -> int:
    """Height of a strip of `rows` rows (0: no strip)."""
    return 0 if rows <= 0 else 2 * metrics.margin + rows * metrics.row


def legend_layout(word_widths, width, metrics: LegendMetrics, strip_rows=None) -> LegendLayout:
    """Entries (their words `word_widths` pixels wide) on a grid of equal columns as many as fit in
    `width`, filled row by row, the grid centred (also vertically in a strip of `strip_rows` rows,
    when the strips of a figure share the height of the fullest): every swatch of a column at the
    same x, every row the same height, so the strip reads as a table. An entry wider than the strip
    keeps its place at the margin (its words are cut at the edge)."""
    n = len(word_widths)
    if n == 0:
        return LegendLayout(int(width), 0, 0, [], [])
    m = metrics
    cell = m.swatch + m.gap + max(int(w) for w in word_widths)
    usable = width - 2 * m.margin
    columns = max(1, min(n, (usable + m.column_gap) // (cell + m.column_gap)))
    rows = -(-n // columns)
    block = columns * cell + (columns - 1) * m.column_gap
    x0 = max(m.margin, (width - block) // 2)
    y0 = m.margin + max(0, (strip_rows or rows) - rows) * m.row // 2
    swatches, words = [], []
    for i in range(n):
        r, c = divmod(i, columns)
        x = x0 + c * (cell + m.column_gap)
        y = y0 + r * m.row
        swatches.append((x, y + (m.row - m.swatch) // 2, m.swatch))
        words.append((x + m.swatch + m.gap, y))
    return LegendLayout(int(width), rows, columns, swatches, words)
