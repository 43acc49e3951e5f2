"""Everything the add-on decides without Blender: palettes, colour and opacity mapping, the names
of collections and layers, and the containers of every layer's geometry as flat numpy arrays
(soups, polylines, dots); the faces and line points themselves come from hbc. No ``bpy`` here, so
plain pytest tests it (tests/addon/unit).

Arrays follow the hbc module's conventions: int32 ids, float32 positions, CSR lists as
(offsets, items) pairs.
"""

from __future__ import annotations

import functools
import os
import re
from dataclasses import dataclass

import numpy as np

from . import native

# ---------------------------------------------------------------------------------------------
# The layer plan: layers, colours and legend words are the library's (hbc/layer_plan.hpp), the one
# source the add-on, its figures and the web viewer draw from. Read when first asked: this module
# must import before the compiled hbc is known to load (the add-on registers without it).

#: Names served from the library's plan (module __getattr__): LAYERS (key, title) in building
#: order, LAYER_TITLES, the colours by role (linear RGBA), the words of legends and sheet rows.
_PLAN_NAMES = frozenset({
    "LAYERS", "LAYER_TITLES", "PALETTE_SIZE", "PALETTE", "NON_HEX_COLOR", "RING_DARKEN", "HEX_COLOR",
    "CELL_TYPE_COLORS", "VALENCE_COLORS", "OTHER_VALENCE_COLOR", "PSEUDO_COLOR",
    "NON_MANIFOLD_COLOR", "UNMATCHED_COLOR", "SHARED_COLOR", "SELF_PARALLEL_EDGE_COLOR",
    "SELF_INTERSECTING_COLOR", "WIRE_SEVERAL_COLOR", "WIRE_HEX_COLOR", "SHEET_TYPE_SHORT", "LEGEND_COLORS",
    "LEGEND_MAX", "SHEET_HIGHLIGHTS", "WIRE_OPACITY_FLOOR", "SPREAD_GAP", "LAYER_REQUESTS"})


@functools.lru_cache(maxsize=1)
def _plan() -> dict:
    hbc = native.import_hbc()
    p = hbc.layer_palette()
    palette = np.array(p["cycle"], np.float32)
    palette.flags.writeable = False  # shared by every caller
    cell_types = np.array(p["cell_type"], np.float32)
    cell_types.flags.writeable = False
    legend_colors = hbc.legend_colors()
    return {
        "LAYERS": tuple(hbc.LAYERS), "LAYER_TITLES": dict(hbc.LAYERS), "PALETTE_SIZE": int(hbc.PALETTE_SIZE),
        "PALETTE": palette, "NON_HEX_COLOR": p["non_hex"], "RING_DARKEN": p["ring_darken"],
        "HEX_COLOR": legend_colors["hex"], "CELL_TYPE_COLORS": cell_types,
        "VALENCE_COLORS": dict(p["valence"]), "OTHER_VALENCE_COLOR": p["other_valence"],
        "PSEUDO_COLOR": p["pseudo"], "NON_MANIFOLD_COLOR": p["non_manifold"], "UNMATCHED_COLOR": p["unmatched"],
        "SHARED_COLOR": p["shared"], "SELF_PARALLEL_EDGE_COLOR": p["self_parallel"],
        "SELF_INTERSECTING_COLOR": p["self_intersecting"], "WIRE_SEVERAL_COLOR": p["wire_several"],
        "WIRE_HEX_COLOR": p["wire_hex"], "SHEET_TYPE_SHORT": tuple(hbc.SHEET_TYPE_SHORT),
        "LEGEND_COLORS": legend_colors, "LEGEND_MAX": int(hbc.LEGEND_MAX_WORDS),
        "SHEET_HIGHLIGHTS": tuple(hbc.SHEET_HIGHLIGHTS), "WIRE_OPACITY_FLOOR": float(hbc.WIRE_OPACITY_FLOOR),
        "SPREAD_GAP": float(hbc.SPREAD_GAP),
        "LAYER_REQUESTS": tuple(dict(r) for r in hbc.LAYER_REQUESTS),
    }


def legend_color_keys() -> list:
    """The keys of LEGEND_COLORS, none when the compiled module is not usable here (the add-on then
    registers without legend swatches: nothing can be analysed to show a legend for)."""
    return [] if native.module_problem() else list(_plan()["LEGEND_COLORS"])


def layer_items() -> list:
    """[(key, title, description)] of LAYERS for the layer choices of the operators, none when the
    compiled module is not usable here. The same list every time: Blender keeps no copy of the
    strings of an enum's items callback."""
    return [] if native.module_problem() else _layer_items()


@functools.lru_cache(maxsize=1)
def _layer_items() -> list:
    return [(k, title, f"Build the {title.lower()} layer") for k, title in _plan()["LAYERS"]]


def root_name(mesh_name: str) -> str:
    return mesh_name


def layer_collection_name(mesh_name: str, layer: str) -> str:
    """`<mesh> / Components` etc.: unique per mesh so two imported meshes never share a layer."""
    return f"{mesh_name} / {_plan()['LAYER_TITLES'][layer]}"


def mesh_extensions():
    """The file extensions the readers take (hbc.FORMATS), longest first so that .ovmb wins over
    .ovm; none when the compiled module is not usable here (the import then says why)."""
    if native.module_problem():
        return []
    formats = native.import_hbc().FORMATS
    return sorted((e for f in formats for e in f.get("extensions", [f["extension"]])), key=len, reverse=True)


# Files without a format extension that name a mesh: OpenFOAM's polyMesh/owner stands for its case.
MESH_FILE_NAMES = ("owner", "owner.gz")


def mesh_name_from_path(path: str) -> str:
    base = os.path.basename(path)
    if base in MESH_FILE_NAMES:
        # CASE/constant/polyMesh/owner: the case's name.
        parts = os.path.normpath(os.path.abspath(path)).split(os.sep)
        return parts[-4] if len(parts) >= 4 and parts[-3:-1] == ["constant", "polyMesh"] else parts[-2]
    for suffix in mesh_extensions():
        if base.lower().endswith(suffix.lower()):
            return base[: -len(suffix)] or base
    return base


# ---------------------------------------------------------------------------------------------
# Colours (linear RGBA, float)

#: hbc.CELL_TYPES, here too: the inspection's per-type settings are registered before the compiled
#: module is known to load.
CELL_TYPE_NAMES = ("hex", "tet", "prism", "pyramid", "polyhedron")


def srgb_to_linear(c):
    """Display (sRGB) values to the scene-linear values Blender's colours hold."""
    c = np.asarray(c, np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def __getattr__(name):
    # The plan's names (_PLAN_NAMES) and the names the library defines once (hbc.COMPONENT_KINDS,
    # hbc.SHEET_TYPES' labels), read when first asked.
    if name in _PLAN_NAMES:
        return _plan()[name]
    if name == "COMPONENT_KINDS":
        return native.import_hbc().COMPONENT_KINDS
    if name == "SHEET_TYPES":
        return tuple(label for _, label in native.import_hbc().SHEET_TYPES)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _ids(values) -> np.ndarray:
    return np.ascontiguousarray(np.asarray(values, np.int64).reshape(-1))


def palette_color(index) -> np.ndarray:
    """Palette colour(s) of integer index/indices; negative indices give the non-hex grey."""
    idx = np.asarray(index, np.int64)
    return native.import_hbc().palette_colors(_ids(idx)).reshape(idx.shape + (4,))


#: Colouring the wireframe by the non-hex kinds of its chains (hbc.Wireframe.non_hex_*; docs/concepts.md,
#: "Non-hex kinds"): a chain whose kinds are all of one cell type takes that type's colour
#: (CELL_TYPE_COLORS, as the direct view's cells), one with kinds of several types WIRE_SEVERAL_COLOR,
#: one with none (hex cells only around it and at its ends) WIRE_HEX_COLOR.
WIRE_SEVERAL_COLOR = (0.05, 0.05, 0.05, 1.0)
WIRE_HEX_COLOR = (0.62, 0.62, 0.62, 1.0)
#: The wireframe's colourings (the add-on's "Colour" setting, the figures' --wire-colors).
WIRE_COLORINGS = (("CLASS", "Class", "Colour classes of partially parallel chains (paper section 6.2)"),
                  ("KIND", "Non-hex", "The cell types of the non-hex cells each chain ends at or runs beside"))


def kind_types(items) -> np.ndarray:
    """The cell type (index of hbc.CELL_TYPES) of non-hex kind codes."""
    return np.asarray(items, np.int64) >> 16


def kind_faces(items) -> np.ndarray:
    """The face count of non-hex kind codes."""
    return np.asarray(items, np.int64) & 0xFFFF


def chain_kind_types(offsets, items) -> np.ndarray:
    """(n,) per chain of a kinds CSR: the one cell type of its kinds, 0 (hex) for none, -1 for
    several types."""
    offsets = np.asarray(offsets, np.int64)
    n = len(offsets) - 1
    out = np.zeros(n, np.int64)
    rows = np.flatnonzero(np.diff(offsets) > 0)
    if rows.size:
        types = kind_types(items)
        lo = np.minimum.reduceat(types, offsets[rows])
        hi = np.maximum.reduceat(types, offsets[rows])
        out[rows] = np.where(lo == hi, lo, -1)
    return out


def chain_kind_colors(offsets, items) -> np.ndarray:
    """(n,4) colours of n chains by their non-hex kinds (see WIRE_SEVERAL_COLOR)."""
    t = chain_kind_types(offsets, items)
    plan = _plan()
    out = plan["CELL_TYPE_COLORS"][np.clip(t, 0, 4)].copy()
    out[t == 0] = plan["WIRE_HEX_COLOR"]
    out[t < 0] = plan["WIRE_SEVERAL_COLOR"]
    return out


def spread_ids(ids) -> np.ndarray:
    """Permutes ids so that consecutive ids (often neighbours) get distant palette entries."""
    return np.asarray(native.import_hbc().spread_ids(_ids(ids)), np.int64)


def component_colors(kinds) -> np.ndarray:
    """(n,4) colours of base complex components: palette by id, rings darker, non-hex grey."""
    return native.import_hbc().component_colors(np.ascontiguousarray(kinds, np.uint8).reshape(-1))


def sheet_colors(n: int) -> np.ndarray:
    return native.import_hbc().spread_colors(np.arange(n, dtype=np.int64))


def subsheet_colors(n: int) -> np.ndarray:
    """(n,4) colours of a sheet's subsheets: never sheet k's colour for subsheet k (hbc.spread_colors
    of -1-k; hbc/layer_plan.hpp says why)."""
    return native.import_hbc().spread_colors(-1 - np.arange(n, dtype=np.int64))


def sheet_color(sheet: int) -> tuple:
    """The colour of one sheet (sheet_colors' entry for it): the sheets layer's and the picked-sheet
    layer's, and the legend's *Picked sheet* swatch."""
    return tuple(float(x) for x in native.import_hbc().spread_colors(np.array([int(sheet)], np.int64))[0])


def valence_color(valence: int):
    plan = _plan()
    return plan["VALENCE_COLORS"].get(int(valence), plan["OTHER_VALENCE_COLOR"])


def layer_requests(layer: str) -> list:
    """The parts of `layer` in drawing order, as the library requests them (hbc.LAYER_REQUESTS,
    hbc/layer_plan.hpp): each part's geometry, its source and options, its colour rule. The web
    viewer draws from the same table; Structure asks hbc for what a request names."""
    return [r for r in _plan()["LAYER_REQUESTS"] if r["layer"] == layer]


def part_request(layer: str, part: str) -> dict:
    return next(r for r in layer_requests(layer) if r["part"] == part)


def role_color(request) -> tuple:
    """The one colour of a request coloured by role (LEGEND_COLORS[role])."""
    return _plan()["LEGEND_COLORS"][request["role"]]


def part_colors(request, owners, *, cell_types=None, kinds=None, sheet=None) -> np.ndarray:
    """(n, 4) colours of n owners of a part (a soup's owners, dots) by the request's colour rule:
    cell_types per cell (rule cell_type), kinds per component (component), the picked sheet
    (sheet_shaded). The lines' rules come with their arrays: the singularities one group per
    valence (Structure.singularity_lines, valence_color), the wireframe's classes or kinds
    (Structure.wireframe)."""
    rule = request["color"]
    owners = np.asarray(owners, np.int64).reshape(-1)
    if rule == "role":
        return np.tile(role_color(request), (len(owners), 1))
    if rule == "cell_type":
        return _plan()["CELL_TYPE_COLORS"][np.asarray(cell_types, np.int64)[owners]]
    if rule == "component":
        return component_colors(kinds)[owners]
    if rule == "spread":
        return native.import_hbc().spread_colors(owners)
    if rule == "subsheet":
        return native.import_hbc().spread_colors(-1 - owners)
    if rule == "sheet_shaded":
        # The sheet's colour, each owner (component) a little lighter or darker so blocks stay visible.
        shade = 0.8 + 0.2 * ((owners * 7) % 3) / 2.0
        oc = np.tile(np.asarray(sheet_color(sheet), np.float32), (len(owners), 1))
        oc[:, :3] *= shade[:, None]
        return oc
    raise ValueError(f"no colours of rule {rule!r} by owner")


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


# ---------------------------------------------------------------------------------------------
# Geometry as flat arrays

@dataclass
class Soup:
    """Polygons with their own vertices: positions (n,3) float32, face_sizes (m,), face_vertices
    (sum sizes,) int32 into positions, face_owner (m,) int32 (the owner a face belongs to). Sizes,
    as Blender's loop totals; hbc's soups come as a CSR (from_dict)."""

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
        """A soup from hbc.block_soup's dict."""
        return Soup(np.asarray(d["positions"], np.float32).reshape(-1, 3),
                    np.diff(np.asarray(d["face_vertices_offsets"], np.int32)).astype(np.int32),
                    np.asarray(d["face_vertices_items"], np.int32),
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


def lines(positions, offsets, colors=None, alpha=None, keep=None, closed=None) -> Lines:
    """Polylines whose points (hbc.polylines' positions, one per CSR entry) are grouped by
    `offsets`. colors: one RGBA for all, or (k,4) per polyline; alpha: optional per point. keep:
    optional bool per polyline; closed: optional bool per polyline (an edge joins its last point to
    its first, the hbc convention for closed chains and curves, which do not repeat their first
    vertex). Every polyline keeps its own copies of its points."""
    positions = np.asarray(positions, np.float32).reshape(-1, 3)
    offsets = np.asarray(offsets, np.int64)
    n = len(positions)
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
    point_mask = np.ones(n, bool)
    if keep is not None:
        keep = np.asarray(keep, bool)
        point_mask = keep[point_poly]
    # Edges between consecutive points of one polyline.
    idx = np.arange(n)
    nxt = idx[:-1]
    same = point_poly[1:] == point_poly[:-1] if n else np.zeros(0, bool)
    mask = same & point_mask[:-1]
    edges = np.stack([nxt[mask], nxt[mask] + 1], axis=1) if n else np.zeros((0, 2), np.int64)
    if closed is not None and n:
        closed = np.asarray(closed, bool) & (sizes > 2)
        if keep is not None:
            closed &= keep
        rows = np.nonzero(closed)[0]
        edges = np.concatenate([edges, np.stack([offsets[rows + 1] - 1, offsets[rows]], axis=1)])
    # Drop unused points (filtered polylines) and renumber.
    new_id = np.cumsum(point_mask) - 1
    lines = Lines(positions[point_mask], new_id[edges].astype(np.int32).reshape(-1, 2),
                  point_colors[point_mask], np.zeros(0, np.int32))
    _, lines.polyline = np.unique(point_poly[point_mask], return_inverse=True)
    lines.polyline = lines.polyline.astype(np.int32)
    return lines


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


def spread_translation(index: int, points, gap: float | None = None, below: bool = False):
    """Offset laying out the index-th of several copies of a model side by side along X (and, with
    `below`, one row lower along -Z: the wireframe beneath its subsheet); gap: a fraction of the
    model's size, SPREAD_GAP (the web viewer's too) unless given."""
    gap = _plan()["SPREAD_GAP"] if gap is None else gap
    lo, hi = bbox(points)
    size = hi - lo
    dx = float(size[0]) * (1.0 + gap) * index
    dz = -float(size[2]) * (1.0 + gap) if below else 0.0
    return (dx, 0.0, dz)


# ---------------------------------------------------------------------------------------------
# Table 1 row

def table1_columns():
    """[(key, notation, meaning, is a time)] of the paper's Table 1 in its order, from the library's
    one description of what it reports (hbc.TABLE1_COLUMNS): the panel, the copied row and
    `hbc table` share the notation, and the panel's tooltips say what each means."""
    hbc = native.import_hbc()
    return [(f.key, f.notation, f"{f.label}: {f.meaning}" + (" (seconds)" if timing else ""), timing)
            for f, timing in hbc.TABLE1_COLUMNS]


def table1_meaning(label: str) -> str:
    """What the Table 1 column headed `label` means, in words (the panel's tooltip)."""
    return next(meaning for _, notation, meaning, _ in table1_columns() if notation == label)


def table1_row(stats: dict):
    """[(label, text)] of the paper's Table 1 for one mesh; missing or -1 values show as '-'."""
    if "hex_component_ratio" not in stats and stats.get("components"):
        stats = dict(stats, hex_component_ratio=stats.get("hex_components", 0) / stats["components"])
    timings = stats.get("timings") or {}
    rows = []
    for key, label, _, timing in table1_columns():
        v = (timings if timing else stats).get(key)
        if v is None or (isinstance(v, (int, np.integer)) and v < 0):
            rows.append((label, "-"))
        elif timing:
            rows.append((label, f"{1000.0 * float(v):.0f} ms"))
        elif isinstance(v, (int, np.integer)):
            rows.append((label, f"{int(v):d}"))
        else:
            # As `hbc table` and the web viewer print them (and the paper's Table 1: a fraction).
            rows.append((label, f"{float(v):.4f}"))
    return rows


def table1_text(name: str, stats: dict, fmt: str = "MARKDOWN") -> str:
    """The Table 1 row of one mesh as a Markdown table (header, rule, row) or as CSV (header, row)."""
    rows = table1_row(stats)
    head = ["Mesh"] + [label for label, _ in rows]
    values = [name] + [text for _, text in rows]
    if fmt == "CSV":
        def cell(t):
            return '"' + t.replace('"', '""') + '"' if any(ch in t for ch in ',"\n') else t
        return ",".join(cell(t) for t in head) + "\n" + ",".join(cell(t) for t in values) + "\n"
    def md(cells):
        return "| " + " | ".join(t.replace("|", "\\|") for t in cells) + " |"
    return "\n".join([md(head), "|" + "---|" * len(head), md(values)]) + "\n"


# ---------------------------------------------------------------------------------------------
# Words for the panel

#: The remedy the library adds to an error about a cell it refuses (hbc/check.hpp kSkipInvalidHint)
#: names the command line's and Python's option; a Blender user has the importer's own instead.
SKIP_INVALID_HINT = re.compile(r"--skip-invalid, in Python skip_invalid=True, loads the other cells")
SKIP_INVALID_REMEDY = 'tick "Skip invalid cells" in the import options to load the other cells'


def describe_error(error: BaseException) -> str:
    """What a failure says to a user: the message itself (hbc's name the file, the line and what
    was expected), never the Python class; the class only when there is no message at all. A
    refused cell's remedy is the importer's *Skip invalid cells* option, in place of the options
    of the command line and of Python the library's message names."""
    text = str(error).strip()
    if isinstance(error, OSError) and error.filename and error.strerror:
        text = f"{error.filename}: {error.strerror}"
    if "--skip-invalid" in text or "skip_invalid=True" in text:
        named = SKIP_INVALID_HINT.sub(SKIP_INVALID_REMEDY, text)
        text = named if named != text else f"{text} ({SKIP_INVALID_REMEDY})"
    return text or f"unexpected failure ({type(error).__name__})"


def with_extension(path: str, ext: str, others=()) -> str:
    """`path` ending in `ext` (".ply"): already so, unchanged; ending in one of `others` (the other
    formats the same file browser writes, ".obj"), that extension replaced, so switching the format
    renames x.obj to x.ply instead of x.obj.ply; else `ext` appended. Case-insensitive."""
    root, old = os.path.splitext(path)
    if old.lower() == ext.lower():
        return path
    if old.lower() in {o.lower() for o in others}:
        return root + ext
    return path + ext


def wrap_message(text: str, width: int = 60) -> list[str]:
    """A message as lines of at most `width` characters for a popup, nothing cut: the lines hold
    every character of the message in order, only the spaces where lines break dropped; a word
    longer than a line (a path) is split."""
    lines = []
    for paragraph in str(text).splitlines() or [""]:
        line = ""
        for word in paragraph.split(" "):
            candidate = f"{line} {word}" if line else word
            if line and len(candidate) > width:
                lines.append(line)
                candidate = word
            while len(candidate) > width:
                lines.append(candidate[:width])
                candidate = candidate[width:]
            line = candidate
        lines.append(line)
    return lines


def subsheets_unavailable(sheet_type) -> str | None:
    """Why the subsheets layer cannot be built for a picked sheet of this type, or None."""
    return native.import_hbc().subsheets_unavailable(None if sheet_type is None else int(sheet_type))


def sheet_order(types, cells, by: str) -> list:
    """Sheet indices in list order: by "TYPE" (then size, largest first), by "SIZE" (cells,
    largest first), else by index."""
    types = np.asarray(types, np.int64)
    cells = np.asarray(cells, np.int64)
    idx = np.arange(len(types))
    if by == "TYPE":
        return np.lexsort((idx, -cells, types)).tolist()
    if by == "SIZE":
        return np.lexsort((idx, -cells)).tolist()
    return idx.tolist()


def wire_kind_legend(non_hex_types=()):
    """The legend of a wireframe coloured by non-hex kind (chain_kind_colors): one entry per cell
    type of the mesh's non-hex cells, then several types and none."""
    return native.import_hbc().wire_kind_legend([int(t) for t in non_hex_types])


def legend(layers, valences=(), has_pseudo=False, has_non_manifold=False, non_hex_types=(),
           has_non_hex_blocks=True, highlights=None, wire_by_kind=False):
    """[(colour key of LEGEND_COLORS, words)] for the layers shown: what each colour, dot and
    edge means (hbc.legend). The add-on's Legend panel and the figure script's legend strip
    (figures/) both show exactly this. The facts are Structure.legend_facts()'.
    highlights: the sheet highlights drawn (keys of SHEET_HIGHLIGHTS), None for all of them.
    wire_by_kind: the wireframes (the wireframe layer, the subsheets' wireframes) are coloured by
    non-hex kind; the palette's class colours mean nothing beyond telling chains apart."""
    return native.import_hbc().legend(
        list(layers), non_hex_types=[int(t) for t in non_hex_types], valences=[int(v) for v in valences],
        has_pseudo=bool(has_pseudo), has_non_manifold=bool(has_non_manifold),
        has_non_hex_components=bool(has_non_hex_blocks),
        # The panel gathers highlights from objects, some of which hold none (None).
        highlights=None if highlights is None else sorted(h for h in highlights if h is not None),
        wire_by_kind=bool(wire_by_kind))


def beside(boxes, lo, hi, gap: float = 0.25):
    """Offset (x, y, z) moving a new model with bounding box (lo, hi) to the right (+x) of the
    models whose boxes (lo, hi) are given, `gap` of its width apart; none when there are none."""
    if not boxes:
        return (0.0, 0.0, 0.0)
    right = max(float(b[1][0]) for b in boxes)
    return (right + gap * float(hi[0] - lo[0]) - float(lo[0]), 0.0, 0.0)


def palette_legend(layers, wire_by_kind=False) -> list:
    """[(colour key, words)] for the palette colours of the layers shown (the panel's legend: each
    shown layer says what its colours mean; the figures' legend strips leave them out). The
    wireframe's class colours only when it is coloured by class."""
    return native.import_hbc().palette_legend(list(layers), wire_by_kind=bool(wire_by_kind))


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


def import_report(name: str, cells: int, components, sheets, objects: int, times: dict, total: float,
                  dropped: str = "") -> str:
    """The closing line of an import: what it made and where the time went, e.g. "Imported cyl:
    988000 cells, 1 components, 3 sheets, 4 objects in 12.3 s (load 2.1 s, analysis 4.0 s, scene
    6.2 s)". components/sheets None: not analyzed; times: seconds by step (load, analysis, scene)."""
    counts = [f"{cells} cells"]
    if components is not None:
        counts += [f"{components} components", f"{sheets} sheets"]
    counts.append(f"{objects} object{'s' if objects != 1 else ''}")
    steps = ", ".join(f"{k} {v:.2f} s" for k, v in times.items())
    text = f"Imported {name}: {', '.join(counts)} in {total:.2f} s" + (f" ({steps})" if steps else "")
    return text + (f"; {dropped}" if dropped else "")
