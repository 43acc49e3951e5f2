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

    # -- a layer's parts, as the library requests them (planning.layer_requests) -------------
    def wants(self, request) -> bool:
        """Whether a part is drawn for this mesh: the mesh holds what it needs (its settings
        switches, when="setting", are the scene's)."""
        return request["when"] != "non_hex_cells" or bool(np.any(np.asarray(self.mesh.cell_types) != 0))

    def part_soup(self, layer: str, part: str, sheet=None, shrink: float = 0.0) -> P.Soup:
        """The soup a soup request names: its block_soup kind, the picked sheet where it takes one,
        `shrink` where the layer's shrink applies, only the owners its `select` row lists."""
        r = P.part_request(layer, part)
        owners = P.csr_row(*_csr(self.analysis, r["select"]), sheet) if r["select"] else None
        if owners is not None and not len(owners):
            return P.Soup.empty()  # nothing selected: no soup asked for
        soup = self._soup(r["source"], sheet if r["sheet"] else None, shrink if r["shrink"] else 0.0)
        return soup if owners is None else soup.select(np.isin(soup.face_owner, owners))

    def part_vertices(self, layer: str, part: str, row: int, holder=None) -> np.ndarray:
        """The mesh vertices a dots request names: row `row` of its CSR, on the analysis or (a
        subsheet's) on `holder`, the sheet's subsheets."""
        r = P.part_request(layer, part)
        return P.csr_row(*_csr(self.analysis if holder is None else holder, r["source"]), row)

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
        return self.part_soup("direct", "boundary")

    def hex_region(self) -> P.Soup:
        """Surface of the hex region, owner 0."""
        return self.part_soup("direct", "hex")

    def non_hex_cells(self, shrink=0.0) -> P.Soup:
        """Every non-hex cell as its own piece, owner = cell id (colour by its type)."""
        return self.part_soup("direct", "non_hex", shrink=shrink)

    def cell_type_colors(self, owners) -> np.ndarray:
        return P.part_colors(P.part_request("direct", "non_hex"), owners, cell_types=self.mesh.cell_types)

    # -- singularity graph ------------------------------------------------------------------
    #: The graph's groups by part (the objects' names).
    GRAPH_GROUPS = {"pseudo": "Pseudo-singular", "non_manifold": "Non-manifold"}

    def singularity_lines(self):
        """[(name, colour, Lines)]: one group per singularity valence, then the edge classes the
        graph layer requests (pseudo-singular and non-manifold edges), those present."""
        g = self.analysis.graph
        groups = []
        for r in P.layer_requests("graph"):
            if r["source"] == "chains":
                offsets, verts = _csr(g, "chain_vertices")
                valence = np.asarray(g.chain_valence)
                closed = np.asarray(g.chain_closed, bool)
                for v in np.unique(valence):
                    keep = valence == v
                    color = P.valence_color(v)
                    groups.append((f"Valence {int(v)}", color,
                                   self._lines(offsets, verts, color, keep=keep, closed=closed)))
            elif r["source"] == "edges":
                edges = np.asarray(self.mesh.edges).reshape(-1, 2)
                sel = edges[np.asarray(g.edge_class) == r["edge_class"]]
                if len(sel) or not r["optional"]:
                    color = P.role_color(r)
                    groups.append((self.GRAPH_GROUPS[r["part"]], color, self._edges(sel, color)))
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
        return self.part_soup("components", "components", shrink=shrink)

    def component_colors(self) -> np.ndarray:
        return P.part_colors(P.part_request("components", "components"), np.arange(self.num_components),
                             kinds=self.component_kinds())

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
        return self.part_soup("sheets", "sheets", shrink=shrink)

    def sheet_blocks(self, sheet: int, shrink: float) -> P.Soup:
        """One sheet's cells with the component partition kept (its blocks), owner = component."""
        return self.part_soup("sheet", "sheet", sheet, shrink)

    def sheet_highlights(self, sheet: int, radius: float):
        """The picked sheet's highlights: (unmatched dots, shared dots, self-parallel edge lines,
        self-intersecting cells soup)."""
        unmatched = self.part_vertices("sheet", "unmatched", sheet)
        shared = self.part_vertices("sheet", "shared", sheet)
        r = P.part_request("sheet", "self_parallel")
        curves = P.csr_row(*_csr(self.analysis, r["select"]), sheet)
        cx = self.analysis.complex
        if len(curves):
            closed = np.asarray(cx.curve_closed, bool)[np.asarray(curves, np.int64)]
            lines = self._lines(*self._curve_subset(cx, curves), P.role_color(r), closed=closed)
        else:
            lines = P.Lines.concat([])
        # The blocks (components) holding a type 3 pair, each its own piece.
        cells = self.part_soup("sheet", "self_intersecting", sheet)
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
        return self.part_soup("subsheets", "subsheets", sheet, shrink)

    def subsheet_unmatched(self, sub, index: int) -> np.ndarray:
        return self.part_vertices("subsheets", "unmatched", index, sub)

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

