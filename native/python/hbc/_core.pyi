"""Type stubs for hbc._core (the compiled half of the hbc package)."""

import os
from typing import Literal, TypedDict

import numpy as np
import numpy.typing as npt

__version__: str

Format = Literal["ovm", "ovmb", "mesh", "medit", "hybrid", "hedra"]

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
