"""Stand-ins for an hbc Mesh and its analysis, made of plain numpy arrays with the names of the
hbc Python API, so the add-on's bpy-free planning code is tested without the compiled module
(and the Blender tests can exercise every layer builder even before the analysis binding lands).

make_grid(nx, ny, nz): an nx*ny*nz hex grid; with `tets` the last cell is replaced by a
"polyhedron" marker (cell type 4) keeping its faces, enough to exercise non-hex colouring.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

# Faces of a hex (local vertex ids 0..7, x fastest, then y, then z), outward loops.
_HEX_FACES = ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5))


class FakeMesh:
    def __init__(self, nx, ny, nz, non_hex_last=False):
        def vid(i, j, k):
            return i + (nx + 1) * (j + (ny + 1) * k)

        pts = np.array([(i, j, k) for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)],
                       np.float32)
        faces, face_index, face_cells = [], {}, []
        cell_faces, cell_flip, cell_offsets = [], [], [0]
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    c = len(cell_offsets) - 1
                    corner = [vid(i + a, j + b, k + d) for d in (0, 1) for b in (0, 1) for a in (0, 1)]
                    for f in _HEX_FACES:
                        loop = tuple(corner[x] for x in f)
                        key = frozenset(loop)
                        if key in face_index:
                            fid = face_index[key]
                            face_cells[fid][1] = c
                            cell_flip.append(1)
                        else:
                            fid = len(faces)
                            face_index[key] = fid
                            faces.append(loop)
                            face_cells.append([c, -1])
                            cell_flip.append(0)
                        cell_faces.append(fid)
                    cell_offsets.append(len(cell_faces))
        self.points = pts
        self.face_offsets = np.arange(0, 4 * len(faces) + 1, 4, dtype=np.int32)
        self.face_vertices = np.array(faces, np.int32).ravel()
        self.face_cells = np.array(face_cells, np.int32)
        self.cell_offsets = np.array(cell_offsets, np.int32)
        self.cell_faces = np.array(cell_faces, np.int32)
        self.cell_face_flip = np.array(cell_flip, np.uint8)
        nc = len(cell_offsets) - 1
        self.cell_types = np.zeros(nc, np.uint8)
        if non_hex_last:
            self.cell_types[-1] = 4
        self.face_boundary = self.face_cells[:, 1] < 0
        edges = set()
        for loop in faces:
            for a, b in zip(loop, loop[1:] + loop[:1]):
                edges.add((min(a, b), max(a, b)))
        self.edges = np.array(sorted(edges), np.int32)
        self.num_cells = nc
        self.num_vertices = len(pts)
        self.source = f"<grid {nx}x{ny}x{nz}>"

    def info(self):
        hexes = int(np.sum(self.cell_types == 0))
        return {"cells": self.num_cells, "hex_cells": hexes, "hex_ratio": hexes / self.num_cells}

    def analyze(self, **kwargs):
        return FakeAnalysis(self)


def _csr(rows):
    offsets = np.concatenate(([0], np.cumsum([len(r) for r in rows]))).astype(np.int32)
    items = np.array([x for r in rows for x in r], np.int32)
    return offsets, items


class FakeAnalysis:
    """Components: pairs of cells along x (cell // 2). Sheets: 0 = components {0,1} (perfect),
    1 = every component (type 3, with subsheets), 2 = component {last} (type 2)."""

    def __init__(self, mesh):
        nc = mesh.num_cells
        comp = (np.arange(nc) // 2).astype(np.int32)
        ncomp = int(comp.max()) + 1
        kinds = np.zeros(ncomp, np.uint8)
        if mesh.cell_types[-1] != 0:
            comp[-1] = ncomp
            kinds = np.append(kinds, 3).astype(np.uint8)
            ncomp += 1
        self.complex = SimpleNamespace(
            cell_component=comp, component_kind=kinds,
            component_cell_offsets=None, component_cell_items=None, curve_vertex_offsets=None, curve_vertex_items=None)
        self.complex.component_cell_offsets, self.complex.component_cell_items = _csr(
            [list(np.nonzero(comp == c)[0]) for c in range(ncomp)])
        e = mesh.edges
        self.complex.curve_vertex_offsets, self.complex.curve_vertex_items = _csr([list(e[0]), list(e[1]), list(e[2])])
        ne = len(e)
        edge_class = np.zeros(ne, np.uint8)
        edge_class[:3] = 1
        edge_class[3:5] = 2
        edge_class[5] = 3
        chains = [list(e[0]), list(e[1]), list(e[2])]
        self.graph = SimpleNamespace(edge_class=edge_class, chain_valence=np.array([3, 5, 3], np.int32))
        self.graph.chain_vertex_offsets, self.graph.chain_vertex_items = _csr(chains)
        sheet_components = [[0, 1] if ncomp > 1 else [0], list(range(ncomp)), [ncomp - 1]]
        self.num_sheets = 3
        self.sheet_type = np.array([0, 3, 2], np.uint8)
        self.sheet_component_offsets, self.sheet_component_items = _csr(sheet_components)
        self.sheet_cell_offsets, self.sheet_cell_items = _csr(
            [sorted(int(x) for c in comps for x in np.nonzero(comp == c)[0]) for comps in sheet_components])
        self.sheet_unmatched_offsets, self.sheet_unmatched_items = _csr([[], [0, 1], [2]])
        self.sheet_shared_offsets, self.sheet_shared_items = _csr([[], [], [3]])
        self.sheet_self_parallel_offsets, self.sheet_self_parallel_items = _csr([[], [], [0, 1]])
        self.sheet_self_intersecting_offsets, self.sheet_self_intersecting_items = _csr([[], [0], []])
        self.largest_self_intersecting = 1
        self.self_intersecting_sheets = np.array([1], np.int32)
        self._mesh = mesh
        self.stats = {"cells": nc, "hex_ratio": float(np.mean(mesh.cell_types == 0)), "components": ncomp,
                      "hex_components": int(np.sum(kinds != 3)), "sheets": 3, "sheets_type1": 0,
                      "sheets_type2": 1, "sheets_type3": 1, "subsheets_of_largest_self_intersecting": 2,
                      "timings": {"singularity_graph": 0.001, "base_complex": 0.002}}

    def subsheets(self, sheet):
        if sheet != 1:
            raise ValueError("not self-intersecting")
        ncomp = len(self.complex.component_kind)
        halves = [list(range(0, max(1, ncomp // 2))), list(range(max(1, ncomp // 2), ncomp))]
        comp = self.complex.cell_component
        cells = [sorted(int(x) for c in h for x in np.nonzero(comp == c)[0]) for h in halves]
        sub = SimpleNamespace(count=2, type=np.array([1, 0], np.uint8))
        sub.component_offsets, sub.component_items = _csr(halves)
        sub.cell_offsets, sub.cell_items = _csr(cells)
        sub.curve_offsets, sub.curve_items = _csr([[0], [1]])
        return sub

    def wireframe(self, sheet=None, subsheet=None):
        e = self._mesh.edges
        k = 4 if sheet is None else 2
        polys = [list(e[i]) for i in range(k)]
        off, verts = _csr(polys)
        return SimpleNamespace(polyline_offsets=off, polyline_items=verts,
                               point_opacity=np.linspace(0.15, 1.0, len(verts)).astype(np.float32),
                               kind=np.zeros(k, np.uint8), shown=np.array([True] * (k - 1) + [False]),
                               color=np.arange(k, dtype=np.int32))
