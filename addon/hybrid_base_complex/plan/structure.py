"""The analysis of one mesh, turned into the flat geometry of every layer (still no ``bpy``).

`Structure` holds an ``hbc.Mesh`` and (optionally) its analysis. Every face and line point comes
from hbc (``hbc.block_soup``, ``hbc.polylines``: C++ is the one source of render geometry); this
module only picks what each layer shows and its colours, as planning `Soup`/`Lines` objects ready
for the scene builders.
"""

from __future__ import annotations

import numpy as np

from . import planning as P
from .native import import_hbc


def _csr(obj, name):
    """(offsets, items) of the CSR `name` on an hbc object: its `<name>_offsets` and `<name>_items`."""
    return np.asarray(getattr(obj, f"{name}_offsets")), np.asarray(getattr(obj, f"{name}_items"))


class Structure:
    """A loaded mesh (hbc.Mesh) and, once analyzed, its hbc.Analysis; positions are placed with
    `scale` then `offset` (where the mesh sits beside earlier imports)."""

    def __init__(self, mesh, analysis=None, scale: float = 1.0, offset=(0.0, 0.0, 0.0)):
        self.mesh = mesh
        self.analysis = analysis
        self.scale = float(scale)
        self.set_offset(offset)
        self._component_sheets = None
        self.subsheet_rule = "layers"  # the rule the analysis split sheets by (session.analyze sets it)
        # ρ of the wireframes' colour classes (session.analyze, session.restyle): presentation only,
        # a new ρ restyles the wireframes and keeps the analysis.
        self.rho = 0.8
        self.analyses = 0  # how many times session.analyze ran on this mesh (a restyle runs none)
        self._metrics = (None, None)  # (the analysis they were computed on, Analysis.metrics())

    def set_offset(self, offset):
        """Moves the model (every position made from now on) to `offset`."""
        self.offset = np.asarray(offset, np.float32).reshape(3)
        self.points = self.place(np.asarray(self.mesh.points, np.float32).reshape(-1, 3))

    def place(self, positions) -> np.ndarray:
        """Positions in the file's coordinates as this model shows them: scaled, then moved to `offset`."""
        return (np.asarray(positions, np.float32) * np.float32(self.scale) + self.offset).astype(np.float32)

    # -- geometry, all made by hbc (render_geometry.hpp) -----------------------------------------
    def _soup(self, what: str, sheet: int | None = None, shrink: float = 0.0) -> P.Soup:
        """hbc.block_soup as a planning Soup, placed like self.points."""
        sheet = None if sheet is None else int(sheet)
        soup = P.Soup.from_dict(import_hbc().block_soup(self.mesh, self.analysis, what, sheet=sheet,
                                                        shrink=float(shrink)))
        soup.positions = self.place(soup.positions)
        return soup

    def _lines(self, offsets, vertices, colors, alpha=None, keep=None, closed=None) -> P.Lines:
        """Polylines of mesh vertices (a CSR), their points placed by hbc.polylines."""
        offsets = np.ascontiguousarray(offsets, np.int32)
        vertices = np.ascontiguousarray(vertices, np.int32)
        positions = self.place(import_hbc().polylines(self.mesh, offsets, vertices))
        return P.lines(positions, offsets, colors, alpha, keep, closed)

    def _edges(self, edges, color) -> P.Lines:
        """Single mesh edges (m, 2) as 2-point polylines of one colour."""
        edges = np.asarray(edges, np.int32).reshape(-1, 2)
        return self._lines(np.arange(0, 2 * len(edges) + 1, 2), edges.ravel(), color)

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

    def metrics(self) -> dict | None:
        """Analysis.metrics() (docs/metrics.md; `hbc metrics --json` without file and timings),
        computed once per analysis (the scaled Jacobians take a pass over the cells); None before
        the mesh is analyzed."""
        if self.analysis is None:
            return None
        done_on, metrics = self._metrics
        if done_on is not self.analysis:
            metrics = self.analysis.metrics()
            self._metrics = (self.analysis, metrics)
        return metrics

    @property
    def length(self) -> float:
        return P.characteristic_length(self.points)

    def bbox(self):
        return P.bbox(self.points)

    # -- direct view ----------------------------------------------------------------------
    def direct_boundary(self) -> P.Soup:
        """The mesh's boundary surface (outward loops), owner = cell type of each face's cell."""
        return self._soup("boundary")

    def hex_region(self) -> P.Soup:
        """Surface of the hex region, owner 0."""
        return self._soup("hex")

    def non_hex_cells(self, shrink=0.0) -> P.Soup:
        """Every non-hex cell as its own piece, owner = cell id (colour by its type)."""
        return self._soup("non_hex", shrink=shrink)

    def cell_type_colors(self, owners) -> np.ndarray:
        types = np.asarray(self.mesh.cell_types, np.int64)
        return P.CELL_TYPE_COLORS[types[np.asarray(owners, np.int64)]]

    # -- singularity graph ------------------------------------------------------------------
    def singularity_lines(self):
        """[(name, colour, Lines)]: one group per singularity valence, then pseudo-singular and
        non-manifold edges."""
        g = self.analysis.graph
        offsets, verts = _csr(g, "chain_vertices")
        valence = np.asarray(g.chain_valence)
        closed = np.asarray(g.chain_closed, bool)
        groups = []
        for v in np.unique(valence):
            keep = valence == v
            color = P.valence_color(v)
            groups.append((f"Valence {int(v)}", color, self._lines(offsets, verts, color, keep=keep, closed=closed)))
        cls = np.asarray(g.edge_class)
        edges = np.asarray(self.mesh.edges).reshape(-1, 2)
        for value, name, color in ((2, "Pseudo-singular", P.PSEUDO_COLOR), (3, "Non-manifold", P.NON_MANIFOLD_COLOR)):
            sel = edges[cls == value]
            if len(sel):
                groups.append((name, color, self._edges(sel, color)))
        return groups

    # -- legend -------------------------------------------------------------------------------
    def legend_facts(self) -> dict:
        """planning.legend's facts about this mesh (hbc.legend_facts): its non-hex cell types and,
        analysed, the singularity valences, whether pseudo-singular and non-manifold edges and
        non-hex components occur. Keyed as planning.legend's arguments (and the facts a saved file
        keeps, blender/layers.py)."""
        facts = dict(import_hbc().legend_facts(self.mesh, self.analysis))
        if "has_non_hex_components" in facts:
            facts["has_non_hex_blocks"] = facts.pop("has_non_hex_components")
        return facts

    # -- base complex -----------------------------------------------------------------------
    @property
    def num_components(self) -> int:
        return int(len(self.analysis.complex.component_kind))

    def component_kinds(self) -> np.ndarray:
        return np.asarray(self.analysis.complex.component_kind, np.uint8)

    def blocks(self, shrink: float) -> P.Soup:
        """Every component as its own piece, owner = component id."""
        return self._soup("components", shrink=shrink)

    def component_colors(self) -> np.ndarray:
        return P.component_colors(self.component_kinds())

    def component_cell_types(self, component: int) -> list:
        """[(cell type name, cells)] of the cells in `component`, in CellType order, types it has only."""
        cells = np.asarray(self.analysis.complex.cell_component) == int(component)
        counts = np.bincount(np.asarray(self.mesh.cell_types, np.int64)[cells], minlength=len(P.CELL_TYPE_NAMES))
        return [(P.CELL_TYPE_NAMES[t], int(n)) for t, n in enumerate(counts) if n]

    def component_sheets(self, component: int) -> np.ndarray:
        """Sheets holding a component."""
        if self._component_sheets is None:
            off, items = _csr(self.analysis, "sheet_components")
            self._component_sheets = P.csr_invert(off, items, self.num_components)
        off, rows = self._component_sheets
        return P.csr_row(off, rows, component)

    # -- sheets -------------------------------------------------------------------------------
    @property
    def num_sheets(self) -> int:
        return int(self.analysis.num_sheets) if self.analysis is not None else 0

    def sheet_types(self) -> np.ndarray:
        return np.asarray(self.analysis.sheet_type, np.uint8)

    def sheet_sizes(self):
        """(cells, components) per sheet."""
        co, _ = _csr(self.analysis, "sheet_cells")
        po, _ = _csr(self.analysis, "sheet_components")
        return np.diff(np.asarray(co)), np.diff(np.asarray(po))

    def sheet_cells(self, sheet: int) -> np.ndarray:
        off, items = _csr(self.analysis, "sheet_cells")
        return P.csr_row(off, items, sheet)

    def all_sheets(self, shrink: float) -> P.Soup:
        """Every sheet as one large piece (the boundary of its cell set), owner = sheet id; a cell
        in two sheets is in both pieces."""
        return self._soup("sheets", shrink=shrink)

    def sheet_blocks(self, sheet: int, shrink: float) -> P.Soup:
        """One sheet's cells with the component partition kept (its blocks), owner = component."""
        return self._soup("sheet", sheet, shrink)

    def sheet_highlights(self, sheet: int, radius: float):
        """The picked sheet's highlights: (unmatched dots, shared dots, self-parallel edge lines,
        self-intersecting cells soup)."""
        a = self.analysis
        off, items = _csr(a, "sheet_unmatched_vertices")
        unmatched = P.csr_row(off, items, sheet)
        off, items = _csr(a, "sheet_shared_vertices")
        shared = P.csr_row(off, items, sheet)
        off, items = _csr(a, "sheet_self_parallel_curves")
        curves = P.csr_row(off, items, sheet)
        cx = a.complex
        if len(curves):
            closed = np.asarray(cx.curve_closed, bool)[np.asarray(curves, np.int64)]
            lines = self._lines(*self._curve_subset(cx, curves), P.SELF_PARALLEL_EDGE_COLOR, closed=closed)
        else:
            lines = P.Lines.concat([])
        off, items = _csr(a, "sheet_self_intersecting_components")
        comps = P.csr_row(off, items, sheet)
        if len(comps):
            # The blocks (components) holding a type 3 pair, each its own piece.
            blocks = self._soup("components")
            cells = blocks.select(np.isin(blocks.face_owner, comps))
        else:
            cells = P.Soup.empty()
        return (P.dots(self.points[unmatched], radius, unmatched), P.dots(self.points[shared], radius * 0.8, shared),
                lines, cells)

    @staticmethod
    def _curve_subset(cx, curves):
        off, verts = _csr(cx, "curve_vertices")
        curves = np.asarray(curves, np.int64)
        off = np.asarray(off, np.int64)
        sizes = off[curves + 1] - off[curves]
        return np.concatenate(([0], np.cumsum(sizes))), P.csr_rows(off, verts, curves)

    # -- subsheets ----------------------------------------------------------------------------
    def subsheets(self, sheet: int):
        return self.analysis.subsheets(int(sheet))

    def subsheet_soup(self, sheet: int, shrink: float) -> P.Soup:
        """Every subsheet of `sheet` as its own piece, owner = subsheet (the ids of self.subsheets(sheet):
        hbc.block_soup takes the decomposition from the analysis)."""
        return self._soup("subsheets", sheet, shrink)

    def subsheet_unmatched(self, sub, index: int) -> np.ndarray:
        off, items = _csr(sub, "subsheet_unmatched_vertices")
        return P.csr_row(off, items, index)

    # -- VSG wireframe ------------------------------------------------------------------------
    def wireframe(self, sheet=None, subsheet=None, floor=None, simplified=True, by_kind=False, rho=None) -> P.Lines:
        """VSG wireframe polylines coloured by palette class at `rho` (None: self.rho; by_kind: by
        non-hex kind, planning.chain_kind_colors), alpha = opacity (floor mapped; None: the layer
        plan's WIRE_OPACITY_FLOOR, the web page's too)."""
        floor = P.WIRE_OPACITY_FLOOR if floor is None else floor
        a = self.analysis
        kwargs = {"rho": float(self.rho if rho is None else rho)}
        if sheet is not None and sheet >= 0:
            kwargs["sheet"] = int(sheet)
            if subsheet is not None and subsheet >= 0:
                kwargs["subsheet"] = int(subsheet)
        w = a.wireframe(**kwargs)
        off, verts = _csr(w, "polylines")
        k = len(off) - 1
        colors = P.palette_color(np.asarray(w.color, np.int64)) if k else np.zeros((0, 4), np.float32)
        if by_kind:
            colors = P.chain_kind_colors(*_csr(w, "non_hex"))
        keep = np.asarray(w.shown, bool) if simplified else None
        alpha = P.opacity_alpha(np.asarray(w.point_opacity, np.float32), floor)
        return self._lines(off, verts, colors, alpha, keep)

