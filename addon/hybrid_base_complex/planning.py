"""Everything the add-on decides without Blender: palettes, colour and opacity mapping, the names
of collections and layers, and the geometry of every layer as flat numpy arrays (block soups,
polylines, dots). No ``bpy`` here, so plain pytest tests it (tests/addon_unit).

Arrays follow the hbc module's conventions: int32 ids, float32 positions, CSR lists as
(offsets, items) pairs.
"""

from __future__ import annotations

import colorsys
from dataclasses import dataclass

import numpy as np

# ---------------------------------------------------------------------------------------------
# Layers and names

#: Layer keys in building order, with the collection name each lives in under `<mesh>`.
LAYERS = (
    ("direct", "Direct view"),
    ("graph", "Singularity graph"),
    ("blocks", "Blocks"),
    ("sheets", "Sheets"),
    ("sheet", "Picked sheet"),
    ("subsheets", "Subsheets"),
    ("wireframe", "Wireframe"),
)
LAYER_TITLES = dict(LAYERS)


def root_name(mesh_name: str) -> str:
    return mesh_name


def layer_collection_name(mesh_name: str, layer: str) -> str:
    """`<mesh> / Blocks` etc.: unique per mesh so two imported meshes never share a layer."""
    return f"{mesh_name} / {LAYER_TITLES[layer]}"


def mesh_name_from_path(path: str) -> str:
    import os

    base = os.path.basename(path)
    for suffix in (".ovmb", ".ovm", ".mesh", ".hybrid", ".hedra"):
        if base.lower().endswith(suffix):
            return base[: -len(suffix)] or base
    return base


# ---------------------------------------------------------------------------------------------
# Colours (linear RGBA, float)

def _hsv_palette(n: int) -> np.ndarray:
    """n well-separated saturated colours: hue by the golden ratio, two value levels."""
    out = np.empty((n, 4), np.float32)
    for i in range(n):
        h = (i * 0.618033988749895) % 1.0
        s = 0.85 if i % 2 == 0 else 0.6
        v = 0.95 if (i // 2) % 2 == 0 else 0.7
        out[i, :3] = srgb_to_linear(colorsys.hsv_to_rgb(h, s, v))
        out[i, 3] = 1.0
    return out


def srgb_to_linear(c):
    """Display (sRGB) values to the scene-linear values Blender's colours hold."""
    c = np.asarray(c, np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


PALETTE_SIZE = 24
PALETTE = _hsv_palette(PALETTE_SIZE)

NON_HEX_COLOR = (0.35, 0.35, 0.38, 1.0)
RING_DARKEN = 0.6  # ring-like hex components: darker shade of their colour
HEX_COLOR = (0.80, 0.80, 0.80, 1.0)
CELL_TYPE_COLORS = np.array([
    HEX_COLOR,                  # hex
    (0.90, 0.25, 0.20, 1.0),    # tet
    (0.20, 0.55, 0.90, 1.0),    # prism
    (0.95, 0.70, 0.15, 1.0),    # pyramid
    (0.60, 0.30, 0.80, 1.0),    # polyhedron
], np.float32)
CELL_TYPE_NAMES = ("hex", "tet", "prism", "pyramid", "polyhedron")

VALENCE_COLORS = {
    1: (0.0, 0.8, 0.8, 1.0),
    2: (0.1, 0.3, 1.0, 1.0),
    3: (0.1, 0.3, 1.0, 1.0),
    5: (1.0, 0.15, 0.1, 1.0),
    6: (1.0, 0.0, 0.9, 1.0),
}
OTHER_VALENCE_COLOR = (1.0, 0.85, 0.0, 1.0)
PSEUDO_COLOR = (0.1, 0.8, 0.2, 1.0)
NON_MANIFOLD_COLOR = (1.0, 0.5, 0.0, 1.0)
UNMATCHED_COLOR = (1.0, 0.0, 0.0, 1.0)
SHARED_COLOR = (1.0, 0.85, 0.0, 1.0)
SELF_PARALLEL_EDGE_COLOR = (1.0, 0.55, 0.0, 1.0)
SELF_INTERSECTING_COLOR = (0.85, 0.1, 0.85, 1.0)

COMPONENT_KINDS = ("cube", "ring", "other", "non-hex")
SHEET_TYPES = ("perfect", "type 1", "type 2 (self-parallel)", "type 3 (self-intersecting)")


def palette_color(index) -> np.ndarray:
    """Palette colour(s) of integer index/indices; negative indices give the non-hex grey."""
    idx = np.asarray(index, np.int64)
    out = PALETTE[np.mod(idx, PALETTE_SIZE)]
    if out.ndim == 2:
        out = out.copy()
        out[idx < 0] = NON_HEX_COLOR
    elif idx < 0:
        out = np.array(NON_HEX_COLOR, np.float32)
    return out


def spread_ids(ids) -> np.ndarray:
    """Permutes ids so that consecutive ids (often neighbours) get distant palette entries."""
    return (np.asarray(ids, np.int64) * 7) % PALETTE_SIZE


def component_colors(kinds) -> np.ndarray:
    """(n,4) colours of base complex components: palette by id, rings darker, non-hex grey."""
    kinds = np.asarray(kinds, np.uint8)
    colors = PALETTE[spread_ids(np.arange(len(kinds)))].copy()
    ring = kinds == 1
    colors[ring, :3] *= RING_DARKEN
    colors[kinds == 3] = NON_HEX_COLOR
    return colors


def sheet_colors(n: int) -> np.ndarray:
    return PALETTE[spread_ids(np.arange(n))].copy()


def valence_color(valence: int):
    return VALENCE_COLORS.get(int(valence), OTHER_VALENCE_COLOR)


def opacity_alpha(opacity, floor: float) -> np.ndarray:
    """Maps the analysis' per-point opacity to alpha: its own range [min, 1] is stretched onto
    [floor, 1] so the user's floor decides how faint the far edges get; 1 stays 1."""
    o = np.clip(np.asarray(opacity, np.float32), 0.0, 1.0)
    floor = float(min(max(floor, 0.0), 1.0))
    if o.size == 0:
        return o
    lo = float(o.min())
    if lo >= 1.0:
        return np.ones_like(o)
    return (floor + (1.0 - floor) * (o - lo) / (1.0 - lo)).astype(np.float32)


# ---------------------------------------------------------------------------------------------
# CSR helpers

def csr_row(offsets, items, row: int) -> np.ndarray:
    return np.asarray(items)[int(offsets[row]): int(offsets[row + 1])]


def csr_rows(offsets, items, rows) -> np.ndarray:
    """Concatenation of the given rows (vectorised)."""
    offsets = np.asarray(offsets, np.int64)
    items = np.asarray(items)
    rows = np.asarray(rows, np.int64)
    if rows.size == 0:
        return items[:0]
    starts, ends = offsets[rows], offsets[rows + 1]
    lengths = ends - starts
    idx = np.repeat(starts - np.concatenate(([0], np.cumsum(lengths)[:-1])), lengths) + np.arange(lengths.sum())
    return items[idx]


def csr_invert(offsets, items, n_items: int):
    """(offsets, rows) listing for every item the rows holding it, rows ascending."""
    offsets = np.asarray(offsets, np.int64)
    items = np.asarray(items, np.int64)
    rows = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))
    order = np.lexsort((rows, items))
    counts = np.bincount(items, minlength=n_items)
    inv_offsets = np.concatenate(([0], np.cumsum(counts))).astype(np.int32)
    return inv_offsets, rows[order].astype(np.int32)


def label_cells(num_cells: int, offsets, items, rows=None) -> np.ndarray:
    """int32 label per cell: the row (of a rows->cells CSR) holding it, -1 for none. With `rows`
    only those rows are labelled (their position in `rows` is the label)."""
    offsets = np.asarray(offsets, np.int64)
    items = np.asarray(items, np.int64)
    label = np.full(num_cells, -1, np.int32)
    if rows is None:
        label[items] = np.repeat(np.arange(len(offsets) - 1, dtype=np.int32), np.diff(offsets))
    else:
        rows = np.asarray(rows, np.int64)
        sizes = offsets[rows + 1] - offsets[rows]
        label[csr_rows(offsets, items, rows)] = np.repeat(np.arange(len(rows), dtype=np.int32), sizes)
    return label


# ---------------------------------------------------------------------------------------------
# Geometry as flat arrays

@dataclass
class Soup:
    """Polygons with their own vertices: positions (n,3) float32, face_sizes (m,), face_vertices
    (sum sizes,) int32 into positions, face_owner (m,) int32 (the block a face belongs to)."""

    positions: np.ndarray
    face_sizes: np.ndarray
    face_vertices: np.ndarray
    face_owner: np.ndarray
    face_cell: np.ndarray | None = None  # mesh cell each face was taken from, when known

    @property
    def num_faces(self) -> int:
        return int(len(self.face_sizes))

    def loop_starts(self) -> np.ndarray:
        return (np.cumsum(self.face_sizes) - self.face_sizes).astype(np.int32)

    @staticmethod
    def empty() -> "Soup":
        return Soup(np.zeros((0, 3), np.float32), np.zeros(0, np.int32), np.zeros(0, np.int32),
                    np.zeros(0, np.int32))

    @staticmethod
    def from_dict(d) -> "Soup":
        return Soup(np.asarray(d["positions"], np.float32).reshape(-1, 3),
                    np.asarray(d["face_sizes"], np.int32), np.asarray(d["face_vertices"], np.int32),
                    np.asarray(d["face_owner"], np.int32),
                    np.asarray(d["face_cell"], np.int32) if "face_cell" in d else None)

    def select(self, face_mask) -> "Soup":
        """The faces where mask holds, with only the vertices they use."""
        face_mask = np.asarray(face_mask, bool)
        loop_mask = np.repeat(face_mask, self.face_sizes)
        fv = self.face_vertices[loop_mask]
        used, inverse = np.unique(fv, return_inverse=True)
        return Soup(self.positions[used], self.face_sizes[face_mask], inverse.astype(np.int32),
                    self.face_owner[face_mask], None if self.face_cell is None else self.face_cell[face_mask])


def block_soup(points, face_offsets, face_vertices, face_cells, cell_offsets, cell_faces,
               cell_face_flip, cell_label, shrink: float = 0.0) -> Soup:
    """Surfaces of blocks given by a label per cell (-1: not shown). A face is drawn for the block
    of each labelled cell it bounds when the cell on its other side has another label (or there is
    none), oriented outward from that cell; each block gets its own copy of its vertices, pulled
    towards the block's vertex centroid by `shrink` (0 none, 1 to a point). face_owner = label."""
    points = np.asarray(points, np.float32).reshape(-1, 3)
    face_offsets = np.asarray(face_offsets, np.int64)
    face_vertices = np.asarray(face_vertices, np.int64)
    face_cells = np.asarray(face_cells, np.int64).reshape(-1, 2)
    cell_offsets = np.asarray(cell_offsets, np.int64)
    cell_faces = np.asarray(cell_faces, np.int64)
    flip = np.asarray(cell_face_flip, np.uint8) if cell_face_flip is not None else np.zeros(len(cell_faces), np.uint8)
    label = np.asarray(cell_label, np.int64)

    # One entry per (cell, face) incidence whose cell is labelled.
    inc_cell = np.repeat(np.arange(len(cell_offsets) - 1), np.diff(cell_offsets))
    keep = label[inc_cell] >= 0
    inc_cell, inc_face, inc_flip = inc_cell[keep], cell_faces[keep], flip[keep]
    fc = face_cells[inc_face]
    other = np.where(fc[:, 0] == inc_cell, fc[:, 1], fc[:, 0])
    other_label = np.where(other >= 0, label[np.maximum(other, 0)], -1)
    own = label[inc_cell]
    show = other_label != own
    inc_cell, inc_face, inc_flip, own = inc_cell[show], inc_face[show], inc_flip[show], own[show]
    if inc_face.size == 0:
        return Soup.empty()

    sizes = (face_offsets[inc_face + 1] - face_offsets[inc_face]).astype(np.int32)
    starts = face_offsets[inc_face]
    total = int(sizes.sum())
    loop_face = np.repeat(np.arange(len(sizes)), sizes)
    pos_in_face = np.arange(total) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    # Reversed loops for flipped incidences (the cell sees the stored loop reversed).
    rev = np.repeat(inc_flip.astype(bool), sizes)
    k = np.where(rev, (np.repeat(sizes, sizes) - pos_in_face) % np.repeat(sizes, sizes), pos_in_face)
    loops = face_vertices[np.repeat(starts, sizes) + k]

    # One vertex copy per (label, mesh vertex).
    owner_per_loop = own[loop_face]
    key = owner_per_loop * (len(points) + 1) + loops
    ukey, inverse = np.unique(key, return_inverse=True)
    vert = ukey % (len(points) + 1)
    vlabel = ukey // (len(points) + 1)
    pos = points[vert].astype(np.float32)
    if shrink > 0.0:
        ulab, vgroup = np.unique(vlabel, return_inverse=True)
        counts = np.bincount(vgroup).astype(np.float64)
        centroid = np.stack([np.bincount(vgroup, weights=pos[:, i]) for i in range(3)], axis=1) / counts[:, None]
        pos = (centroid[vgroup] + (pos - centroid[vgroup]) * (1.0 - float(shrink))).astype(np.float32)
    return Soup(pos, sizes, inverse.astype(np.int32), own.astype(np.int32), inc_cell.astype(np.int32))


@dataclass
class Lines:
    """Polylines as a vertex/edge graph: positions (n,3), edges (m,2) into positions, per point
    colours (n,4) whose alpha is the opacity, and per point polyline id."""

    positions: np.ndarray
    edges: np.ndarray
    colors: np.ndarray
    polyline: np.ndarray

    @property
    def num_polylines(self) -> int:
        return int(self.polyline.max()) + 1 if self.polyline.size else 0

    @staticmethod
    def concat(parts) -> "Lines":
        parts = [p for p in parts if p.positions.size]
        if not parts:
            return Lines(np.zeros((0, 3), np.float32), np.zeros((0, 2), np.int32),
                         np.zeros((0, 4), np.float32), np.zeros(0, np.int32))
        pos, edges, cols, poly = [], [], [], []
        nv = npoly = 0
        for p in parts:
            pos.append(p.positions)
            edges.append(p.edges + nv)
            cols.append(p.colors)
            poly.append(p.polyline + npoly)
            nv += len(p.positions)
            npoly += p.num_polylines
        return Lines(np.concatenate(pos), np.concatenate(edges).astype(np.int32), np.concatenate(cols),
                     np.concatenate(poly).astype(np.int32))


def polylines(points, offsets, vertices, colors=None, alpha=None, keep=None, closed=None) -> Lines:
    """Polylines given by mesh-vertex CSR (offsets, vertices). colors: one RGBA for all, or (k,4)
    per polyline; alpha: optional per point (aligned with vertices). keep: optional bool per
    polyline; closed: optional bool per polyline (an edge joins its last point to its first, the
    hbc convention for closed chains and curves, which do not repeat their first vertex). Every
    polyline gets its own copies of its points."""
    points = np.asarray(points, np.float32).reshape(-1, 3)
    offsets = np.asarray(offsets, np.int64)
    vertices = np.asarray(vertices, np.int64)
    k = len(offsets) - 1
    sizes = np.diff(offsets)
    point_poly = np.repeat(np.arange(k), sizes)
    if colors is None:
        colors = (1.0, 1.0, 1.0, 1.0)
    colors = np.asarray(colors, np.float32)
    per_poly = np.broadcast_to(colors, (k, 4)) if colors.ndim == 1 else colors.reshape(k, 4)
    point_colors = np.array(per_poly[point_poly], np.float32) if k else np.zeros((0, 4), np.float32)
    if alpha is not None:
        point_colors[:, 3] = np.asarray(alpha, np.float32)
    point_mask = np.ones(len(vertices), bool)
    if keep is not None:
        keep = np.asarray(keep, bool)
        point_mask = keep[point_poly]
    # Edges between consecutive points of one polyline.
    idx = np.arange(len(vertices))
    nxt = idx[:-1]
    same = point_poly[1:] == point_poly[:-1] if len(vertices) else np.zeros(0, bool)
    mask = same & point_mask[:-1]
    edges = np.stack([nxt[mask], nxt[mask] + 1], axis=1) if len(vertices) else np.zeros((0, 2), np.int64)
    if closed is not None and len(vertices):
        closed = np.asarray(closed, bool) & (sizes > 2)
        if keep is not None:
            closed &= keep
        rows = np.nonzero(closed)[0]
        edges = np.concatenate([edges, np.stack([offsets[rows + 1] - 1, offsets[rows]], axis=1)])
    # Drop unused points (filtered polylines) and renumber.
    new_id = np.cumsum(point_mask) - 1
    lines = Lines(points[vertices[point_mask]], new_id[edges].astype(np.int32).reshape(-1, 2),
                  point_colors[point_mask], np.zeros(0, np.int32))
    kept_poly = point_poly[point_mask]
    _, lines.polyline = np.unique(kept_poly, return_inverse=True)
    lines.polyline = lines.polyline.astype(np.int32)
    return lines


def edge_lines(points, edges, color) -> Lines:
    """Single mesh edges (m,2) as 2-point polylines of one colour."""
    edges = np.asarray(edges, np.int64).reshape(-1, 2)
    m = len(edges)
    offsets = np.arange(0, 2 * m + 1, 2)
    return polylines(points, offsets, edges.ravel(), color)


# Unit octahedron: dots that render in every engine without instancing.
_OCT_V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], np.float32)
_OCT_F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]],
                  np.int32)


def dots(centers, radius: float, owner=None) -> Soup:
    """A small octahedron at every centre; owner: per dot id (default 0..n-1)."""
    centers = np.asarray(centers, np.float32).reshape(-1, 3)
    n = len(centers)
    pos = (centers[:, None, :] + _OCT_V[None, :, :] * float(radius)).reshape(-1, 3)
    fv = (_OCT_F[None, :, :] + 6 * np.arange(n, dtype=np.int32)[:, None, None]).reshape(-1)
    owner = np.arange(n, dtype=np.int32) if owner is None else np.asarray(owner, np.int32)
    return Soup(pos.astype(np.float32), np.full(8 * n, 3, np.int32), fv.astype(np.int32), np.repeat(owner, 8))


def bbox(points):
    p = np.asarray(points, np.float32).reshape(-1, 3)
    if p.size == 0:
        return np.zeros(3, np.float32), np.zeros(3, np.float32)
    return p.min(axis=0), p.max(axis=0)


def characteristic_length(points) -> float:
    lo, hi = bbox(points)
    d = float(np.linalg.norm(hi - lo))
    return d if d > 0 else 1.0


def spread_translation(index: int, points, gap: float = 0.25, below: bool = False):
    """Offset laying out the index-th of several copies of a model side by side along X (and, with
    `below`, one row lower along -Z: the wireframe beneath its subsheet)."""
    lo, hi = bbox(points)
    size = hi - lo
    dx = float(size[0]) * (1.0 + gap) * index
    dz = -float(size[2]) * (1.0 + gap) if below else 0.0
    return (dx, 0.0, dz)


# ---------------------------------------------------------------------------------------------
# Table 1 row

TABLE1_FIELDS = (
    ("cells", "|C|", "{:d}"),
    ("hex_ratio", "|H|/|C|", "{:.1%}"),
    ("components", "|C_B|", "{:d}"),
    ("hex_component_ratio", "|H_B|/|C_B|", "{:.1%}"),
    ("sheets", "#Sheets", "{:d}"),
    ("sheets_type1", "#Type 1", "{:d}"),
    ("sheets_type2", "#Type 2", "{:d}"),
    ("sheets_type3", "#Type 3", "{:d}"),
    ("subsheets_of_largest_self_intersecting", "#Subsheets", "{:d}"),
)
TIMING_FIELDS = (
    ("singularity_graph", "T_GS"),
    ("base_complex", "T_GB"),
    ("vsg_wireframe", "T_VSGW"),
    ("sheets", "T_GSH"),
    ("subsheets", "T_GSH*"),
)


def table1_row(stats: dict):
    """[(label, text)] of the paper's Table 1 for one mesh; missing or -1 values show as '-'."""
    rows = []
    if "hex_component_ratio" not in stats and stats.get("components"):
        stats = dict(stats, hex_component_ratio=stats.get("hex_components", 0) / stats["components"])
    for key, label, fmt in TABLE1_FIELDS:
        v = stats.get(key)
        if v is None or (isinstance(v, (int, np.integer)) and v < 0):
            rows.append((label, "-"))
        else:
            rows.append((label, fmt.format(int(v) if "d" in fmt else float(v))))
    timings = stats.get("timings") or {}
    for key, label in TIMING_FIELDS:
        v = timings.get(key)
        rows.append((label, "-" if v is None else f"{1000.0 * float(v):.0f} ms"))
    return rows


class Progress:
    """Counts steps of long work, calling `report(fraction, message)` (window manager progress
    and/or a print in background mode)."""

    def __init__(self, total: int, report):
        self.total = max(int(total), 1)
        self.done = 0
        self.report = report

    def step(self, message: str):
        self.done += 1
        self.report(min(self.done / self.total, 1.0), message)
