"""Looking inside a mesh, the part decided without Blender: the quality colour map and histogram,
the per-cell arrays the filters read (computed in C++), the cell-type bit mask, and the cells the
filters keep (the live surface's mask). blender/inspect.py puts them on Blender data.

- Quality colours: the scaled Jacobian with viridis (perceptually uniform and readable with the
  common colour-vision deficiencies), sampled from matplotlib's table (CC0) at 9 points and
  interpolated linearly: 0 (and inverted cells, < 0) dark purple, 1 (ideal) yellow.
- The cut: a cell is kept or hidden whole, by its centroid; `kept_cells` applies the same rules as
  the geometry-nodes group (blender/inspect.py) does to faces, so the live surface of a large mesh
  and the filtered cells of a small one show the same cells.
"""

from __future__ import annotations

import numpy as np

from . import planning as P
from .native import import_hbc

#: The layers whose objects carry per-cell attributes and the filter modifier.
INSPECT_LAYERS = ("direct", "components", "sheets", "sheet", "subsheets")
TYPE_NAMES = P.CELL_TYPE_NAMES
ALL_TYPES = (1 << len(TYPE_NAMES)) - 1

#: viridis (matplotlib's _viridis_data, CC0) at entries 0, 32, ..., 224, 255: sRGB.
VIRIDIS_SRGB = np.array([
    (0.267004, 0.004874, 0.329415),
    (0.278826, 0.175490, 0.483397),
    (0.229739, 0.322361, 0.545706),
    (0.172719, 0.448791, 0.557885),
    (0.127568, 0.566949, 0.550556),
    (0.157851, 0.683765, 0.501686),
    (0.369214, 0.788888, 0.382914),
    (0.678489, 0.863742, 0.189503),
    (0.993248, 0.906157, 0.143936),
])
HIST_BINS = 10  # over [0, 1], plus one bin for inverted cells (< 0)
LEGEND_VALUES = (0.0, 0.25, 0.5, 0.75, 1.0)


def quality_colors(sj) -> np.ndarray:
    """Linear RGBA (n, 4) float32 of scaled Jacobians: viridis over [0, 1], clamped."""
    t = np.clip(np.nan_to_num(np.asarray(sj, np.float64), nan=0.0), 0.0, 1.0)
    x = np.linspace(0.0, 1.0, len(VIRIDIS_SRGB))
    rgb = np.stack([np.interp(t, x, VIRIDIS_SRGB[:, k]) for k in range(3)], axis=-1)
    out = np.ones(t.shape + (4,), np.float32)
    out[..., :3] = P.srgb_to_linear(rgb)
    return out


def quality_histogram(sj):
    """(labels, counts): inverted cells, then HIST_BINS equal bins over [0, 1]."""
    sj = np.asarray(sj, np.float64)
    counts = [int(np.sum(sj < 0))] + np.histogram(np.clip(sj[sj >= 0], 0, 1), HIST_BINS, (0.0, 1.0))[0].tolist()
    edges = np.linspace(0, 1, HIST_BINS + 1)
    labels = ["< 0"] + [f"{edges[i]:.1f}-{edges[i + 1]:.1f}" for i in range(HIST_BINS)]
    return labels, counts


# ---------------------------------------------------------------------------------------------
# Per-cell data (C++), cached on the Structure for as long as its analysis is the same

def cell_data(s) -> dict:
    """{"type", "quality" (scaled Jacobian), "depth", "centroid" (placed like s.points: the
    filters compare it with the plane in the layer objects' coordinates), "component" (component id,
    -1 without an analysis), "histogram"} of every cell of the Structure `s`."""
    cache = getattr(s, "_hbc_inspect", None)
    if cache is not None and cache["analysis"] is s.analysis and np.array_equal(cache["offset"], s.offset):
        return cache
    hbc = import_hbc()
    nc = s.num_cells
    block = (np.asarray(s.analysis.complex.cell_component, np.int32) if s.analysis is not None
             else np.full(nc, -1, np.int32))
    cache = {
        "analysis": s.analysis,
        "offset": s.offset.copy(),
        "type": np.asarray(s.mesh.cell_types, np.int32),
        "quality": np.asarray(hbc.cell_quality(s.mesh)["scaled_jacobian"], np.float32),
        "depth": np.asarray(hbc.cell_depth(s.mesh), np.int32),
        "centroid": s.place(hbc.cell_centroids(s.mesh)),
        "component": block,
    }
    cache["histogram"] = quality_histogram(cache["quality"])
    s._hbc_inspect = cache
    return cache


def computed_histogram(s):
    """The quality histogram of `s` once cell_data has computed it (for any analysis: the quality
    is the mesh's own), else None: the panel draws it without starting the computation."""
    cache = getattr(s, "_hbc_inspect", None)
    return cache["histogram"] if cache is not None else None


def sheet_mask(s, sheet: int) -> np.ndarray:
    """(nc,) int32: 1 for the cells of `sheet` (none when there is no such sheet)."""
    mask = np.zeros(s.num_cells, np.int32)
    if s.analysis is not None and 0 <= sheet < s.num_sheets:
        mask[np.asarray(s.sheet_cells(sheet), np.int64)] = 1
    return mask


# ---------------------------------------------------------------------------------------------
# Filters

def type_mask(ins) -> int:
    """The `Types` bit mask of the settings `ins` (bit t for CellType t)."""
    return sum(1 << t for t, n in enumerate(TYPE_NAMES) if getattr(ins, f"show_{n}"))


def kept_cells(s, ins, plane, sheet: int) -> np.ndarray:
    """(nc,) bool: the cells the settings `ins` keep, as the node group decides for faces. plane:
    (point, unit normal) of the slicing plane in the coordinates of the cells' centroids, None
    without one; sheet: the sheet picked in the list."""
    data = cell_data(s)
    keep = np.ones(s.num_cells, bool)
    if not ins.enabled:
        return keep
    if ins.slice and plane is not None:
        p, n = plane
        far = (data["centroid"] - np.asarray(p, np.float32)) @ np.asarray(n, np.float32) > 0
        keep &= far == bool(ins.flip)
    if ins.peel > 0:
        keep &= data["depth"] >= ins.peel
    if type_mask(ins) != ALL_TYPES:
        keep &= ((type_mask(ins) >> data["type"]) & 1).astype(bool)
    if ins.sheet_only:
        keep &= sheet_mask(s, sheet).astype(bool)
    if ins.filter_quality:
        keep &= (data["quality"] >= ins.quality_min) & (data["quality"] <= ins.quality_max)
    return keep


# ---------------------------------------------------------------------------------------------
# Cell geometry (C++)

def cell_soup(s, shrink=0.0) -> P.Soup:
    """Every cell with all its faces (hbc.block_soup 'cells', C++), placed like s.points (beside
    the meshes imported before, as the boundary is)."""
    soup = P.Soup.from_dict(import_hbc().block_soup(s.mesh, s.analysis, "cells", shrink=float(shrink)))
    soup.positions = s.place(soup.positions)
    return soup


def surface_soup(s, keep, shrink=0.0) -> P.Soup:
    """The surface of the kept cells (hbc.kept_surface_soup, C++), placed like cell_soup."""
    soup = P.Soup.from_dict(import_hbc().kept_surface_soup(s.mesh, np.asarray(keep, np.uint8), shrink=float(shrink)))
    soup.positions = s.place(soup.positions)
    return soup


def cell_colors(s, soup, by_quality: bool) -> np.ndarray:
    """Per-face colours of a cell soup: quality colour map, or the cell-type colours."""
    if by_quality:
        return quality_colors(cell_data(s)["quality"][soup.face_cell])
    return s.cell_type_colors(soup.face_cell)
