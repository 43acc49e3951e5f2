"""Type stubs for hbc._core (the compiled half of the hbc package)."""

import os
from typing import Literal, TypedDict

import numpy as np
import numpy.typing as npt

__version__: str

Format = Literal["ovm", "ovmb", "mesh", "medit", "hybrid", "hedra", "msh", "vtk", "vtu"]
Level = Literal["complex", "mesh"]
SoupWhat = Literal["cells", "components", "sheets", "subsheets", "sheet", "sheet_non_hex", "non_hex", "boundary", "hex"]
I32 = npt.NDArray[np.int32]
U8 = npt.NDArray[np.uint8]
Bool = npt.NDArray[np.bool_]

class MeshFormatError(ValueError):
    """A file or arrays that do not describe a valid mesh; str(err) is 'file:line: expected ...'."""

    file: str
    line: int | None
    byte_offset: int | None
    detail: str

class CellTypeCounts(TypedDict):
    hex: int
    tet: int
    prism: int
    pyramid: int
    polyhedron: int

class MeshInfo(TypedDict):
    vertices: int
    edges: int
    faces: int
    cells: int
    hex_cells: int
    hex_ratio: float
    cell_types: CellTypeCounts
    boundary_faces: int
    non_manifold_vertices: int
    dropped_faces: int
    dropped_edges: int

class Mesh:
    """A conforming polyhedral volume mesh. Array properties are read-only views (no copy)."""

    @property
    def source(self) -> str: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def num_cells(self) -> int: ...
    @property
    def points(self) -> npt.NDArray[np.float32]:
        """(nv, 3) float32, a cached copy."""
    @property
    def points64(self) -> npt.NDArray[np.float64]:
        """(nv, 3) float64, no copy."""
    @property
    def edges(self) -> npt.NDArray[np.int32]:
        """(ne, 2), lower vertex id first."""
    @property
    def face_offsets(self) -> npt.NDArray[np.int32]:
        """(nf + 1,)"""
    @property
    def face_vertices(self) -> npt.NDArray[np.int32]:
        """(face_offsets[-1],) vertex loops."""
    @property
    def face_edges(self) -> npt.NDArray[np.int32]:
        """(face_offsets[-1],) entry i joins loop vertices i and i+1."""
    @property
    def face_cells(self) -> npt.NDArray[np.int32]:
        """(nf, 2), column 1 is -1 on the boundary."""
    @property
    def cell_offsets(self) -> npt.NDArray[np.int32]:
        """(nc + 1,)"""
    @property
    def cell_faces(self) -> npt.NDArray[np.int32]:
        """(cell_offsets[-1],) face ids."""
    @property
    def cell_face_flip(self) -> npt.NDArray[np.uint8]:
        """(cell_offsets[-1],) 1 when the cell sees the face loop reversed."""
    @property
    def cell_types(self) -> npt.NDArray[np.uint8]:
        """(nc,) 0 hex, 1 tet, 2 prism, 3 pyramid, 4 polyhedron."""
    @property
    def face_boundary(self) -> npt.NDArray[np.bool_]:
        """(nf,)"""
    @property
    def edge_boundary(self) -> npt.NDArray[np.bool_]:
        """(ne,)"""
    @property
    def vertex_boundary(self) -> npt.NDArray[np.bool_]:
        """(nv,)"""
    @property
    def vertex_non_manifold(self) -> npt.NDArray[np.bool_]:
        """(nv,)"""
    @property
    def edge_valence(self) -> npt.NDArray[np.int32]:
        """(ne,) cells around each edge; a new array each call."""
    def info(self) -> MeshInfo: ...
    def analyze(
        self,
        rho: float = 0.8,
        level: Level = "complex",
        sheets: bool = True,
        subsheets: bool = True,
        wireframe: bool = True,
    ) -> Analysis:
        """The structure analysis (GIL released); rho in [0, 1] for the wireframe's colour classes."""
    @staticmethod
    def from_arrays(
        points: npt.ArrayLike,
        face_offsets: npt.ArrayLike,
        face_vertices: npt.ArrayLike,
        cell_offsets: npt.ArrayLike,
        cell_faces: npt.ArrayLike,
        cell_face_flip: npt.ArrayLike | None = None,
        source: str = "<arrays>",
    ) -> Mesh: ...

def load(path: str | os.PathLike[str], format: Format | None = None) -> Mesh: ...

class Timings(TypedDict):
    load: float
    singularity_graph: float
    base_complex: float
    sheets: float
    subsheets: float
    vsg_wireframe: float

class AnalysisStats(TypedDict, total=False):
    """`hbc analyze FILE --json` without "file"; keys of stages not run are absent."""

    cells: int
    hex_ratio: float
    singular_edges: int
    singularities: int
    pseudo_singular_edges: int
    non_manifold_edges: int
    singular_vertices: int
    components: int
    hex_components: int
    hex_component_ratio: float
    patches: int
    curves: int
    corners: int
    self_adjacent_faces: int
    sheets: int
    sheets_perfect: int
    sheets_type1: int
    sheets_type2: int
    sheets_type3: int
    subsheets_of_largest_self_intersecting: int
    vsg_edges: int
    wireframe_edges: int
    wireframe_edges_simplified: int
    timings: Timings

class WireframeCounts(TypedDict):
    vsg_edges: int
    wireframe_edges: int
    wireframe_edges_simplified: int
    vsg_chains: int
    singular_vertices: int
    vsg_mesh_edges: int
    wireframe_mesh_edges: int
    wireframe_mesh_edges_simplified: int
    reference_components: int
    shown_components: int

class BlockSoup(TypedDict):
    positions: npt.NDArray[np.float32]  # (np, 3)
    point_vertex: I32  # (np,) mesh vertex of each point
    face_sizes: I32  # (nf,)
    face_vertices: I32  # (face_sizes.sum(),) point ids, loops outward
    face_owner: I32  # (nf,) grouped by increasing owner
    face_source: I32  # (nf,) mesh face ids
    face_cell: I32  # (nf,) mesh cell on the owner's side (the face points out of it)

class SingularityGraph:
    """Views into an Analysis (SPEC section 1). Chains: a closed one does not repeat its first vertex."""

    @property
    def edge_class(self) -> U8:
        """(ne,) 0 regular, 1 singular, 2 pseudo-singular, 3 non-manifold."""
    @property
    def edge_irregular(self) -> Bool: ...
    @property
    def edge_chain(self) -> I32:
        """(ne,) singularity of a singular edge, else -1."""
    @property
    def chain_vertex_offsets(self) -> I32: ...
    @property
    def chain_vertex_items(self) -> I32: ...
    @property
    def chain_edge_offsets(self) -> I32: ...
    @property
    def chain_edge_items(self) -> I32: ...
    @property
    def chain_valence(self) -> I32: ...
    @property
    def chain_boundary(self) -> Bool: ...
    @property
    def chain_closed(self) -> Bool: ...
    @property
    def singular_vertices(self) -> I32: ...
    @property
    def pseudo_singular_vertices(self) -> I32: ...
    @property
    def pseudo_singular_edges(self) -> I32: ...
    @property
    def non_manifold_edges(self) -> I32: ...
    @property
    def num_singularities(self) -> int: ...

class BaseComplex:
    """Views into an Analysis (SPEC section 2). A closed curve does not repeat its first vertex."""

    @property
    def cell_component(self) -> I32: ...
    @property
    def component_kind(self) -> U8:
        """(ncomp,) 0 cube, 1 ring, 2 other, 3 non-hex."""
    @property
    def component_cell_offsets(self) -> I32: ...
    @property
    def component_cell_items(self) -> I32: ...
    @property
    def component_adjacency_offsets(self) -> I32: ...
    @property
    def component_adjacency_items(self) -> I32: ...
    @property
    def face_separation(self) -> Bool: ...
    @property
    def face_patch(self) -> I32: ...
    @property
    def patch_face_offsets(self) -> I32: ...
    @property
    def patch_face_items(self) -> I32: ...
    @property
    def curve_vertex_offsets(self) -> I32: ...
    @property
    def curve_vertex_items(self) -> I32: ...
    @property
    def curve_edge_offsets(self) -> I32: ...
    @property
    def curve_edge_items(self) -> I32: ...
    @property
    def curve_closed(self) -> Bool: ...
    @property
    def edge_curve(self) -> I32: ...
    @property
    def corners(self) -> I32: ...
    @property
    def self_adjacent_faces(self) -> I32: ...
    @property
    def num_components(self) -> int: ...
    @property
    def num_patches(self) -> int: ...
    @property
    def num_curves(self) -> int: ...

class Subsheets:
    """The subsheets of one self-intersecting sheet; CSRs as <name>_offsets (count + 1,) and <name>_items."""

    @property
    def sheet(self) -> int: ...
    @property
    def count(self) -> int: ...
    @property
    def type(self) -> U8: ...
    @property
    def flags(self) -> Bool:
        """(count, 3) type-1, type-2, type-3 configurations present."""
    @property
    def component_offsets(self) -> I32: ...
    @property
    def component_items(self) -> I32: ...
    @property
    def cell_offsets(self) -> I32: ...
    @property
    def cell_items(self) -> I32: ...
    @property
    def curve_offsets(self) -> I32: ...
    @property
    def curve_items(self) -> I32: ...
    @property
    def unmatched_offsets(self) -> I32: ...
    @property
    def unmatched_items(self) -> I32: ...
    @property
    def shared_offsets(self) -> I32: ...
    @property
    def shared_items(self) -> I32: ...
    @property
    def self_parallel_offsets(self) -> I32: ...
    @property
    def self_parallel_items(self) -> I32: ...
    @property
    def self_intersecting_offsets(self) -> I32: ...
    @property
    def self_intersecting_items(self) -> I32: ...

class Wireframe:
    """A VSG wireframe: polylines of mesh vertices (a closed VSG chain repeats its first vertex)."""

    @property
    def count(self) -> int: ...
    @property
    def polyline_offsets(self) -> I32: ...
    @property
    def polyline_items(self) -> I32: ...
    @property
    def point_opacity(self) -> npt.NDArray[np.float32]:
        """Aligned with polyline_items."""
    @property
    def kind(self) -> U8:
        """(count,) 0 chain of VSG (irregular) edges only, 1 other chain."""
    @property
    def valence(self) -> I32: ...
    @property
    def stop(self) -> U8: ...
    @property
    def shown(self) -> Bool: ...
    @property
    def non_important(self) -> U8: ...
    @property
    def reactivated(self) -> Bool: ...
    @property
    def simplified_offsets(self) -> I32:
        """(counts['wireframe_edges_simplified'] + 1,) row offsets of simplified_items."""
    @property
    def simplified_items(self) -> I32:
        """Mesh vertices along each polyline of the simplified wireframe."""
    @property
    def color(self) -> I32: ...
    @property
    def color_class(self) -> I32: ...
    @property
    def counts(self) -> WireframeCounts: ...

class Analysis:
    """Mesh.analyze()'s result. Per-sheet CSRs: sheet_<name>_offsets (num_sheets + 1,) and
    sheet_<name>_items. Curve ids are base-complex curves at level 'complex', mesh edges at 'mesh'."""

    @property
    def mesh(self) -> Mesh: ...
    @property
    def level(self) -> Level: ...
    @property
    def rho(self) -> float: ...
    @property
    def has_sheets(self) -> bool:
        """The sheet stage ran (else the per-sheet arrays are empty)."""
    @property
    def has_subsheets(self) -> bool:
        """The subsheet stage ran (else subsheets() raises ValueError)."""
    @property
    def has_wireframe(self) -> bool:
        """The whole-mesh wireframe stage ran (else wireframe() computes it on demand)."""
    @property
    def stats(self) -> AnalysisStats: ...
    @property
    def graph(self) -> SingularityGraph: ...
    @property
    def complex(self) -> BaseComplex: ...
    @property
    def num_sheets(self) -> int: ...
    @property
    def sheet_type(self) -> U8:
        """(num_sheets,) 0 perfect, 1..3 type."""
    @property
    def sheet_flags(self) -> Bool:
        """(num_sheets, 3) type-1, type-2, type-3 configurations present."""
    @property
    def sheet_component_offsets(self) -> I32: ...
    @property
    def sheet_component_items(self) -> I32: ...
    @property
    def sheet_cell_offsets(self) -> I32: ...
    @property
    def sheet_cell_items(self) -> I32: ...
    @property
    def sheet_curve_offsets(self) -> I32: ...
    @property
    def sheet_curve_items(self) -> I32: ...
    @property
    def sheet_edge_offsets(self) -> I32: ...
    @property
    def sheet_edge_items(self) -> I32: ...
    @property
    def sheet_non_hex_offsets(self) -> I32: ...
    @property
    def sheet_non_hex_items(self) -> I32: ...
    @property
    def sheet_unmatched_offsets(self) -> I32: ...
    @property
    def sheet_unmatched_items(self) -> I32: ...
    @property
    def sheet_shared_offsets(self) -> I32: ...
    @property
    def sheet_shared_items(self) -> I32: ...
    @property
    def sheet_self_parallel_offsets(self) -> I32: ...
    @property
    def sheet_self_parallel_items(self) -> I32: ...
    @property
    def sheet_self_intersecting_offsets(self) -> I32: ...
    @property
    def sheet_self_intersecting_items(self) -> I32: ...
    @property
    def largest_self_intersecting(self) -> int | None:
        """The self-intersecting sheet with most cells; None without one (or without sheets)."""
    @property
    def self_intersecting_sheets(self) -> I32: ...
    def subsheets(self, sheet: int) -> Subsheets: ...
    def wireframe(self, sheet: int | None = None, subsheet: int | None = None) -> Wireframe: ...
    def to_vtu(self, path: str, sheet: int | None = None, ascii: bool = False) -> str: ...

def block_soup(mesh: Mesh, analysis: Analysis | None, what: SoupWhat, sheet: int | None = None, shrink: float = 0.0) -> BlockSoup:
    """sheet: required for 'subsheets', 'sheet' and 'sheet_non_hex', ignored otherwise."""
def kept_surface_soup(mesh: Mesh, kept: npt.ArrayLike, shrink: float = 0.0) -> BlockSoup:
    """Faces of kept cells (kept: (num_cells,) bool) whose other side is not kept; owner = cell."""
def cell_centroids(mesh: Mesh) -> npt.NDArray[np.float64]:
    """(num_cells, 3) the mean of each cell's distinct vertices."""
def polylines(mesh: Mesh, offsets: npt.ArrayLike, vertices: npt.ArrayLike) -> npt.NDArray[np.float32]: ...

class CellQuality(TypedDict):
    scaled_jacobian: npt.NDArray[np.float64]  # (num_cells,) Verdict's; < 0 for inverted cells
    edge_ratio: npt.NDArray[np.float64]  # (num_cells,) longest / shortest edge, >= 1

def cell_quality(mesh: Mesh) -> CellQuality: ...
def cell_depth(mesh: Mesh) -> I32:
    """(num_cells,) cell layers from the boundary: 0 with a boundary vertex, else BFS over faces."""
