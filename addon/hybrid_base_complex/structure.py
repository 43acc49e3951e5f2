"""The analysis of one mesh, turned into the flat geometry of every layer (still no ``bpy``).

`Structure` holds an ``hbc.Mesh`` and (optionally) its analysis, read only through the names of
the hbc Python API; tests pass stand-ins with the same attributes. Every method returns planning
`Soup`/`Lines` objects ready for the scene builders.
"""

from __future__ import annotations

import numpy as np

from . import planning as P


def import_hbc():
    """The hbc module: the copy bundled in the add-on package (release zip), else one on sys.path
    (a development checkout with PYTHONPATH=<build>/python)."""
    try:
        from . import hbc  # type: ignore[attr-defined]
        return hbc
    except ImportError:
        import hbc  # type: ignore[no-redef]
        return hbc


def _csr(obj, name):
    """(offsets, items) of the CSR `name` on obj: `<name>_offsets` with `<name>_items`, or the
    items under another suffix (`_cells`, `_vertices`, ...)."""
    offsets = getattr(obj, f"{name}_offsets")
    for suffix in ("items", "cells", "vertices", "components", "curves"):
        items = getattr(obj, f"{name}_{suffix}", None)
        if items is not None:
            return np.asarray(offsets), np.asarray(items)
    raise AttributeError(f"{type(obj).__name__} has {name}_offsets but no items array")


class Structure:
    def __init__(self, mesh, analysis=None, scale: float = 1.0):
        self.mesh = mesh
        self.analysis = analysis
        self.scale = float(scale)
        self.points = np.asarray(mesh.points, np.float32).reshape(-1, 3) * np.float32(self.scale)
        self._component_sheets = None

    # -- basic facts -----------------------------------------------------------------------
    @property
    def num_cells(self) -> int:
        return int(len(self.mesh.cell_types))

    @property
    def has_analysis(self) -> bool:
        return self.analysis is not None

    def stats(self) -> dict:
        if self.analysis is not None:
            return dict(self.analysis.stats)
        info = self.mesh.info()
        return {"cells": info["cells"], "hex_ratio": info["hex_ratio"]}

    @property
    def length(self) -> float:
        return P.characteristic_length(self.points)

    def _native_soup(self, what, sheet=-1, shrink=0.0):
        """hbc.block_soup (native, much faster) as a planning Soup, or None when the module has
        none; positions scaled like self.points."""
        if self.analysis is None:
            return None
        try:
            hbc = import_hbc()
        except ImportError:
            return None
        fn = getattr(hbc, "block_soup", None) or getattr(getattr(hbc, "_core", None), "block_soup", None)
        if fn is None or not isinstance(self.mesh, hbc.Mesh):  # stand-ins in tests: numpy path
            return None
        soup = P.Soup.from_dict(fn(self.mesh, self.analysis, what, sheet=int(sheet), shrink=float(shrink)))
        if self.scale != 1.0:
            soup.positions = soup.positions * np.float32(self.scale)
        return soup

    def _soup(self, label, shrink=0.0) -> P.Soup:
        m = self.mesh
        return P.block_soup(self.points, m.face_offsets, m.face_vertices, m.face_cells, m.cell_offsets,
                            m.cell_faces, m.cell_face_flip, label, shrink)

    # -- direct view ----------------------------------------------------------------------
    def direct_boundary(self) -> P.Soup:
        """The mesh's boundary surface (outward loops), owner = cell of each face."""
        soup = self._soup(np.zeros(self.num_cells, np.int32))
        soup.face_owner = soup.face_cell
        return soup

    def direct_cells(self, hex_cells: bool) -> P.Soup:
        """Surface of the hex (or of the non-hex) region, owner = cell type."""
        types = np.asarray(self.mesh.cell_types, np.int32)
        mask = (types == 0) if hex_cells else (types != 0)
        label = np.where(mask, 0, -1)
        soup = self._soup(label)
        soup.face_owner = np.zeros_like(soup.face_owner)
        return soup

    def non_hex_cells(self, shrink=0.0) -> P.Soup:
        """Every non-hex cell as its own block, owner = cell id (colour by its type)."""
        native = self._native_soup("non_hex", shrink=shrink)
        if native is not None:
            return native
        types = np.asarray(self.mesh.cell_types, np.int32)
        label = np.where(types != 0, np.arange(len(types)), -1)
        return self._soup(label, shrink)

    def cell_type_colors(self, owners) -> np.ndarray:
        types = np.asarray(self.mesh.cell_types, np.int64)
        return P.CELL_TYPE_COLORS[types[np.asarray(owners, np.int64)]]

    # -- singularity graph ------------------------------------------------------------------
    def singularity_lines(self):
        """[(name, colour, Lines)]: one group per singularity valence, then pseudo-singular and
        non-manifold edges."""
        g = self.analysis.graph
        offsets, verts = np.asarray(g.chain_vertex_offsets), np.asarray(g.chain_vertex_items)
        valence = np.asarray(g.chain_valence)
        closed = getattr(g, "chain_closed", None)
        groups = []
        for v in np.unique(valence):
            keep = valence == v
            color = P.valence_color(v)
            groups.append((f"Valence {int(v)}", color, P.polylines(self.points, offsets, verts, color, keep=keep, closed=closed)))
        cls = np.asarray(g.edge_class)
        edges = np.asarray(self.mesh.edges).reshape(-1, 2)
        for value, name, color in ((2, "Pseudo-singular", P.PSEUDO_COLOR), (3, "Non-manifold", P.NON_MANIFOLD_COLOR)):
            sel = edges[cls == value]
            if len(sel):
                groups.append((name, color, P.edge_lines(self.points, sel, color)))
        return groups

    # -- base complex -----------------------------------------------------------------------
    @property
    def num_components(self) -> int:
        return int(len(self.analysis.complex.component_kind))

    def component_kinds(self) -> np.ndarray:
        return np.asarray(self.analysis.complex.component_kind, np.uint8)

    def blocks(self, shrink: float) -> P.Soup:
        """Every component as a block, owner = component id."""
        native = self._native_soup("components", shrink=shrink)
        if native is not None:
            return native
        label = np.asarray(self.analysis.complex.cell_component, np.int32)
        return self._soup(label, shrink)

    def component_colors(self) -> np.ndarray:
        return P.component_colors(self.component_kinds())

    def component_sheets(self, component: int) -> np.ndarray:
        """Sheets holding a component."""
        if self._component_sheets is None:
            off, items = _csr(self.analysis, "sheet_component")
            self._component_sheets = P.csr_invert(off, items, self.num_components)
        off, rows = self._component_sheets
        return P.csr_row(off, rows, component)

    # -- sheets -------------------------------------------------------------------------------
    @property
    def num_sheets(self) -> int:
        a = self.analysis
        return int(a.num_sheets) if a is not None and getattr(a, "num_sheets", None) is not None else 0

    def sheet_types(self) -> np.ndarray:
        return np.asarray(self.analysis.sheet_type, np.uint8)

    def sheet_sizes(self):
        """(cells, components) per sheet."""
        co, _ = _csr(self.analysis, "sheet_cell")
        po, _ = _csr(self.analysis, "sheet_component")
        return np.diff(np.asarray(co)), np.diff(np.asarray(po))

    def sheet_cells(self, sheet: int) -> np.ndarray:
        off, items = _csr(self.analysis, "sheet_cell")
        return P.csr_row(off, items, sheet)

    def all_sheets(self, shrink: float) -> P.Soup:
        """Every sheet as one large block (the boundary of its cell set), owner = sheet id; a cell
        in two sheets is in both blocks."""
        native = self._native_soup("sheets", shrink=shrink)
        if native is not None:
            return native
        off, items = _csr(self.analysis, "sheet_cell")
        return self._cell_sets(off, items, range(self.num_sheets), shrink)

    def _cell_sets(self, off, items, rows, shrink) -> P.Soup:
        parts = []
        for r in rows:
            label = np.full(self.num_cells, -1, np.int32)
            label[P.csr_row(off, items, r)] = 0
            parts.append(self._soup(label, shrink))
        return concat_soups(parts, owners=list(rows))

    def sheet_blocks(self, sheet: int, shrink: float) -> P.Soup:
        """One sheet's cells with the component partition kept (its blocks), owner = component."""
        native = self._native_soup("sheet", sheet, shrink)
        if native is not None:
            return native
        cells = self.sheet_cells(sheet)
        label = np.full(self.num_cells, -1, np.int32)
        comp = np.asarray(self.analysis.complex.cell_component, np.int32)
        label[cells] = comp[cells]
        return self._soup(label, shrink)

    def sheet_highlights(self, sheet: int, radius: float):
        """Highlights per SPEC §6: (unmatched dots, shared dots, self-parallel edge lines,
        self-intersecting cells soup)."""
        a = self.analysis
        off, items = _csr(a, "sheet_unmatched")
        unmatched = P.csr_row(off, items, sheet)
        off, items = _csr(a, "sheet_shared")
        shared = P.csr_row(off, items, sheet)
        off, items = _csr(a, "sheet_self_parallel")
        curves = P.csr_row(off, items, sheet)
        cx = a.complex
        if len(curves):
            closed = getattr(cx, "curve_closed", None)
            closed = None if closed is None else np.asarray(closed, bool)[np.asarray(curves, np.int64)]
            lines = P.polylines(self.points, *self._curve_subset(cx, curves), P.SELF_PARALLEL_EDGE_COLOR,
                                closed=closed)
        else:
            lines = P.Lines.concat([])
        off, items = _csr(a, "sheet_self_intersecting")
        comps = P.csr_row(off, items, sheet)
        if len(comps):
            coff, citems = _csr(cx, "component_cell")
            label = P.label_cells(self.num_cells, coff, citems, comps)
            cells = self._soup(label, 0.0)
        else:
            cells = P.Soup.empty()
        return (P.dots(self.points[unmatched], radius, unmatched), P.dots(self.points[shared], radius * 0.8, shared),
                lines, cells)

    @staticmethod
    def _curve_subset(cx, curves):
        off, verts = _csr(cx, "curve_vertex")
        curves = np.asarray(curves, np.int64)
        off = np.asarray(off, np.int64)
        sizes = off[curves + 1] - off[curves]
        return np.concatenate(([0], np.cumsum(sizes))), P.csr_rows(off, verts, curves)

    # -- subsheets ----------------------------------------------------------------------------
    def subsheets(self, sheet: int):
        return self.analysis.subsheets(int(sheet))

    def subsheet_soup(self, sheet: int, sub, shrink: float) -> P.Soup:
        """Every subsheet of `sheet` (sub = self.subsheets(sheet)) as a block, owner = subsheet."""
        native = self._native_soup("subsheets", sheet, shrink)
        if native is not None:
            return native
        off, items = _csr(sub, "cell")
        return self._cell_sets(off, items, range(int(sub.count)), shrink)

    def subsheet_unmatched(self, sub, index: int) -> np.ndarray:
        try:
            off, items = _csr(sub, "unmatched")
        except AttributeError:
            return np.zeros(0, np.int32)
        return P.csr_row(off, items, index)

    # -- VSG wireframe ------------------------------------------------------------------------
    def wireframe(self, sheet=None, subsheet=None, floor=0.15, simplified=True) -> P.Lines:
        """VSG wireframe polylines coloured by palette class, alpha = opacity (floor mapped)."""
        a = self.analysis
        kwargs = {}
        if sheet is not None and sheet >= 0:
            kwargs["sheet"] = int(sheet)
            if subsheet is not None and subsheet >= 0:
                kwargs["subsheet"] = int(subsheet)
        w = a.wireframe(**kwargs)
        off = np.asarray(w.polyline_offsets)
        verts = np.asarray(w.polyline_items)
        k = len(off) - 1
        color_idx = np.asarray(getattr(w, "color", np.zeros(k, np.int32)), np.int64)
        colors = P.palette_color(color_idx) if k else np.zeros((0, 4), np.float32)
        shown = getattr(w, "shown", None)
        keep = np.asarray(shown, bool) if (simplified and shown is not None) else None
        alpha = P.opacity_alpha(np.asarray(w.point_opacity, np.float32), floor)
        return P.polylines(self.points, off, verts, colors, alpha, keep)


def concat_soups(parts, owners=None) -> P.Soup:
    """Soups side by side; with `owners`, every face of part i gets owner owners[i]."""
    parts = list(parts)
    if not parts:
        return P.Soup.empty()
    pos, sizes, fv, own = [], [], [], []
    nv = 0
    for i, s in enumerate(parts):
        pos.append(s.positions)
        sizes.append(s.face_sizes)
        fv.append(s.face_vertices + nv)
        own.append(np.full(s.num_faces, owners[i], np.int32) if owners is not None else s.face_owner)
        nv += len(s.positions)
    return P.Soup(np.concatenate(pos).astype(np.float32), np.concatenate(sizes).astype(np.int32),
                  np.concatenate(fv).astype(np.int32), np.concatenate(own).astype(np.int32))
