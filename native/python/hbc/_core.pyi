"""Type stubs for hbc._core (the compiled half of the hbc package)."""

import os
from collections.abc import Sequence
from typing import Any, Literal, TypedDict

import numpy as np
import numpy.typing as npt

__version__: str

Format = Literal["ovm", "ovmb", "mesh", "medit", "hybrid", "hedra", "msh", "vtk", "vtu", "foam", "openfoam"]
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
    """A conforming polyhedral volume mesh. Array properties are read-only views (no copy); every
    CSR is <name>_offsets, int32 (rows + 1,), with <name>_items, int32 (<name>_offsets[-1],)."""

    @property
    def source(self) -> str: ...
    @property
    def dropped(self) -> Dropped | None:
        """What load(skip_invalid=True) dropped; None without skip_invalid."""
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
    def edges(self) -> I32:
        """(ne, 2), lower vertex id first."""
    @property
    def face_vertices_offsets(self) -> I32:
        """(nf + 1,) face f's vertex loop is face_vertices_items[offsets[f]:offsets[f + 1]]."""
    @property
    def face_vertices_items(self) -> I32:
        """(face_vertices_offsets[-1],) the vertex loop of each face."""
    @property
    def face_edges_offsets(self) -> I32:
        """(nf + 1,) equal to face_vertices_offsets."""
    @property
    def face_edges_items(self) -> I32:
        """(face_edges_offsets[-1],) aligned with face_vertices_items: entry i joins loop vertices i and i+1."""
    @property
    def face_cells(self) -> I32:
        """(nf, 2), column 1 is -1 on the boundary."""
    @property
    def cell_faces_offsets(self) -> I32:
        """(nc + 1,) cell c's faces are cell_faces_items[offsets[c]:offsets[c + 1]]."""
    @property
    def cell_faces_items(self) -> I32:
        """(cell_faces_offsets[-1],) the face ids of each cell."""
    @property
    def cell_face_flip(self) -> U8:
        """(ncf,) aligned with cell_faces_items: 1 when the cell sees the face loop reversed."""
    @property
    def cell_types(self) -> U8:
        """(nc,) 0 hex, 1 tet, 2 prism, 3 pyramid, 4 polyhedron."""
    @property
    def face_boundary(self) -> Bool:
        """(nf,)"""
    @property
    def edge_boundary(self) -> Bool:
        """(ne,)"""
    @property
    def vertex_boundary(self) -> Bool:
        """(nv,)"""
    @property
    def vertex_non_manifold(self) -> Bool:
        """(nv,)"""
    @property
    def edge_valence(self) -> I32:
        """(ne,) cells around each edge; a new array each call."""
    def info(self) -> MeshInfo: ...
    def analyze(
        self,
        *,
        rho: float = 0.8,
        level: Level = "complex",
        sheets: bool = True,
        subsheets: bool = True,
        wireframe: bool = True,
        threads: int | None = None,
        subsheet_rule: Literal["layers", "fewest"] = "layers",
        search_steps: int = 100000,
    ) -> Analysis:
        """The structure analysis (GIL released), its options read by the library (ANALYZE_OPTIONS,
        the CLI's and JavaScript's reader too: an unknown one is a TypeError); rho in [0, 1]: the colour-class threshold of
        the wireframes that wireframe() styles without one (presentation only: the analysis does
        not depend on it); threads for the stages (None:
        HBC_THREADS, else every core; results do not depend on it); subsheet_rule: 'layers' (the
        paper's authors' decomposition) or 'fewest' (the fewest subsheets with a lower bound;
        search_steps caps the exact search per sheet)."""
    @staticmethod
    def from_arrays(
        points: npt.ArrayLike,
        face_vertices_offsets: npt.ArrayLike,
        face_vertices_items: npt.ArrayLike,
        cell_faces_offsets: npt.ArrayLike,
        cell_faces_items: npt.ArrayLike,
        cell_face_flip: npt.ArrayLike | None = None,
        source: str = "<arrays>",
    ) -> Mesh:
        """The mesh of these arrays, laid out as the properties of the same names (copied)."""

def load(path: str | os.PathLike[str], format: Format | None = None, *, threads: int | None = None,
         skip_invalid: bool = False) -> Mesh: ...

class DefectItem(TypedDict, total=False):
    id: int        # 0-based, in file order: a cell, face or vertex as the class's "of" says
    line: int      # where the reader knows it (text files)
    byte: int      # ... (binary files)
    volume: float  # inverted and zero_volume only

class DefectClass(TypedDict):
    count: int
    of: str        # "cells", "faces" or "vertices"
    refused: bool  # build_mesh refuses the file for any one of them (skip_invalid drops them all)
    dropped: int   # of `count`, those skip_invalid drops (few_faces, duplicate_cells: some, or none)
    first: list[DefectItem]

class DroppedCell(TypedDict, total=False):
    id: int
    reason: str
    line: int
    byte: int

class Dropped(TypedDict):
    """`dropped` of `hbc analyze --skip-invalid --json` (docs/check.md)."""
    count: int
    by_reason: dict[str, int]
    cells: list[DroppedCell]

class CheckReport(TypedDict):
    """`hbc check --json`, key for key (docs/check.md)."""
    file: str
    vertices: int
    cells: int
    clean: bool
    defects: dict[str, DefectClass]  # every class of docs/check.md, in its order
    dropped: Dropped  # what a skip_invalid load drops: that load's Mesh.dropped

def check(path: str | os.PathLike[str], format: Format | None = None, *, first: int = 10,
          threads: int | None = None) -> CheckReport: ...

class Timings(TypedDict):
    load: float
    singularity_graph: float
    base_complex: float
    sheets: float
    subsheets: float
    vsg_wireframe: float

class Field:
    """One reported number, described once in the library (see docs/concepts.md)."""

    @property
    def key(self) -> str: ...
    @property
    def label(self) -> str: ...
    @property
    def notation(self) -> str: ...
    @property
    def latex(self) -> str: ...
    @property
    def meaning(self) -> str: ...
    @property
    def unit(self) -> str: ...
    @property
    def kind(self) -> Literal["count", "ratio", "seconds", "value"]: ...

# The statistics of Analysis.stats (and `hbc analyze --json`) in output order; its "timings";
# Wireframe.counts; the paper's Table 1 columns in its order, each (field, is a timing).
STAT_FIELDS: tuple[Field, ...]
TIMING_FIELDS: tuple[Field, ...]
WIREFRAME_COUNT_FIELDS: tuple[Field, ...]
TABLE1_COLUMNS: tuple[tuple[Field, bool], ...]

class MetricField(Field):
    """One structural metric (docs/metrics.md): a Field with its group and refinement rule (hbc/metrics.hpp)."""

    @property
    def group(self) -> Literal["census", "singular", "complex", "sheets", "non_hex", "quality", "summary"]: ...
    @property
    def refinement(self) -> Literal["invariant", "x8", "x2", "x4", "none"]: ...

# Every scalar of Analysis.metrics() (and `hbc metrics --json`) in output order, as
# metrics()[field.group][field.key]; the names of metrics()["summary"]["vector"]'s entries.
METRIC_FIELDS: tuple[MetricField, ...]
SUMMARY_FIELDS: tuple[str, ...]
# Name tables, index = the value stored in the arrays: SHEET_TYPES[t] = (JSON name, label);
# CELL_TYPES[t] and COMPONENT_KINDS[k] = names; FORMATS: every format the readers take.
SHEET_TYPES: tuple[tuple[str, str], ...]
CELL_TYPES: tuple[str, ...]
COMPONENT_KINDS: tuple[str, ...]
class FormatInfo(TypedDict):
    name: str  # the format= / --format name, and the extension in lower case
    alias: str  # another accepted name, or ""
    extension: str  # as files usually spell it, with the dot
    extensions: list[str]  # every extension read as it: `extension` first (".bdf", ".nas")
    title: str  # what writes it
    writable: bool  # write_mesh / `hbc generate` write it too

FORMATS: tuple[FormatInfo, ...]

# The binding surface described once (hbc/exports.hpp), which this stub, the objects and the
# JavaScript binding are checked against: every exported array {holder, name, dtype, csr, rows,
# width, python, js, deprecated, meaning}; what each rows symbol counts; analyze()'s options
# {key, type, default, choices, min, max, meaning}.
EXPORTED_ARRAYS: tuple[dict[str, Any], ...]
DIMENSIONS: dict[str, str]
ANALYZE_OPTIONS: tuple[dict[str, Any], ...]

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
    vsg_chains: int
    singular_vertices: int  # the wireframe's, not SingularityGraph.singular_vertices
    wireframe_edges: int  # polylines of the complete wireframe
    wireframe_edges_simplified: int  # polylines of the simplified wireframe
    vsg_mesh_edges: int
    wireframe_mesh_edges: int
    wireframe_mesh_edges_simplified: int
    wireframe_components: int  # connected pieces of the complete wireframe
    wireframe_components_simplified: int  # connected pieces of the simplified wireframe
    reference_components: int  # deprecated key of wireframe_components
    shown_components: int  # deprecated key of wireframe_components_simplified

class BlockSoup(TypedDict):
    """block_soup's polygon soup, faces grouped by owner (cell, component, sheet, ...)."""

    positions: npt.NDArray[np.float32]  # (np, 3)
    point_vertex: I32  # (np,) mesh vertex of each point
    face_vertices_offsets: I32  # (nsf + 1,) nsf: the soup's faces
    face_vertices_items: I32  # (face_vertices_offsets[-1],) point ids, loops outward
    face_owner: I32  # (nsf,) grouped by increasing owner
    face_source: I32  # (nsf,) mesh face ids
    face_cell: I32  # (nsf,) mesh cell on the owner's side (the face points out of it)

class SingularityGraph:
    """The hybrid singularity graph (paper §3.2) of an Analysis, as views; ne edges, ns
    singularities (chains). Chains: a closed one does not repeat its first vertex."""

    @property
    def edge_class(self) -> U8:
        """(ne,) 0 regular, 1 singular, 2 pseudo-singular, 3 non-manifold."""
    @property
    def edge_irregular(self) -> Bool:
        """(ne,) valence other than 4 inside / 2 on the boundary."""
    @property
    def edge_chain(self) -> I32:
        """(ne,) singularity of a singular edge, else -1."""
    @property
    def chain_vertices_offsets(self) -> I32:
        """(ns + 1,)"""
    @property
    def chain_vertices_items(self) -> I32:
        """(chain_vertices_offsets[-1],) ordered vertices of each singularity."""
    @property
    def chain_edges_offsets(self) -> I32:
        """(ns + 1,)"""
    @property
    def chain_edges_items(self) -> I32:
        """(chain_edges_offsets[-1],) ordered edges; edge i joins chain vertices i and i+1 (mod n)."""
    @property
    def chain_valence(self) -> I32:
        """(ns,)"""
    @property
    def chain_boundary(self) -> Bool:
        """(ns,) all its edges on the boundary."""
    @property
    def chain_closed(self) -> Bool:
        """(ns,)"""
    @property
    def singular_vertices(self) -> I32:
        """(k,) sorted singularity ends that are not pseudo-singular (not the wireframe's singular vertices)."""
    @property
    def pseudo_singular_vertices(self) -> I32:
        """(k,) sorted ends of pseudo-singular and non-manifold edges."""
    @property
    def pseudo_singular_edges(self) -> I32:
        """(k,) sorted edges touching a non-hex cell."""
    @property
    def non_manifold_edges(self) -> I32:
        """(k,) sorted edges touching a non-manifold vertex."""
    @property
    def num_singularities(self) -> int: ...

class BaseComplex:
    """The hybrid base complex (paper §3.3) of an Analysis, as views; ncomp components, npatch
    patches, ncurve curves. A closed curve does not repeat its first vertex."""

    @property
    def cell_component(self) -> I32:
        """(nc,)"""
    @property
    def component_kind(self) -> U8:
        """(ncomp,) 0 cube, 1 ring, 2 other, 3 non-hex."""
    @property
    def component_cells_offsets(self) -> I32:
        """(ncomp + 1,)"""
    @property
    def component_cells_items(self) -> I32:
        """(component_cells_offsets[-1],) sorted cells of each component."""
    @property
    def component_adjacency_offsets(self) -> I32:
        """(ncomp + 1,)"""
    @property
    def component_adjacency_items(self) -> I32:
        """(component_adjacency_offsets[-1],) sorted components sharing a separation face."""
    @property
    def face_separation(self) -> Bool:
        """(nf,)"""
    @property
    def face_patch(self) -> I32:
        """(nf,) patch of a separation face, else -1."""
    @property
    def patch_faces_offsets(self) -> I32:
        """(npatch + 1,)"""
    @property
    def patch_faces_items(self) -> I32:
        """(patch_faces_offsets[-1],) sorted mesh faces of each patch."""
    @property
    def curve_vertices_offsets(self) -> I32:
        """(ncurve + 1,)"""
    @property
    def curve_vertices_items(self) -> I32:
        """(curve_vertices_offsets[-1],) mesh vertex polyline of each curve."""
    @property
    def curve_edges_offsets(self) -> I32:
        """(ncurve + 1,)"""
    @property
    def curve_edges_items(self) -> I32:
        """(curve_edges_offsets[-1],) ordered mesh edges of each curve."""
    @property
    def curve_closed(self) -> Bool:
        """(ncurve,) no corner on it."""
    @property
    def edge_curve(self) -> I32:
        """(ne,) curve of a complex edge, else -1."""
    @property
    def corners(self) -> I32:
        """(k,) sorted corner vertices."""
    @property
    def self_adjacent_faces(self) -> I32:
        """(k,) interior separation faces with one component on both sides."""
    @property
    def num_components(self) -> int: ...
    @property
    def num_patches(self) -> int: ...
    @property
    def num_curves(self) -> int: ...

class Subsheets:
    """The subsheets of one self-intersecting sheet, `count` rows; every CSR is
    subsheet_<name>_offsets (count + 1,) with subsheet_<name>_items (subsheet_<name>_offsets[-1],)."""

    @property
    def sheet(self) -> int: ...
    @property
    def count(self) -> int: ...
    @property
    def rule(self) -> Literal["layers", "fewest"]: ...
    @property
    def lower_bound(self) -> int:
        """'fewest': no split has fewer subsheets; 0 for 'layers'."""
    @property
    def proven(self) -> bool:
        """'fewest': count equals lower_bound (the count is the minimum)."""
    @property
    def subsheet_type(self) -> U8:
        """(count,) 0 perfect, 1 type 1 (non-hex), 2 type 2 (self-parallel), 3 type 3 (self-intersecting)."""
    @property
    def subsheet_flags(self) -> Bool:
        """(count, 3) type 1, type 2, type 3 configurations present."""
    @property
    def subsheet_components_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def subsheet_components_items(self) -> I32:
        """(subsheet_components_offsets[-1],) sorted base-complex components of each subsheet."""
    @property
    def subsheet_cells_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def subsheet_cells_items(self) -> I32:
        """(subsheet_cells_offsets[-1],) sorted mesh hex cells of each subsheet."""
    @property
    def subsheet_curves_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def subsheet_curves_items(self) -> I32:
        """(subsheet_curves_offsets[-1],) sorted parallel curves (mesh edges at level 'mesh')."""
    @property
    def subsheet_unmatched_vertices_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def subsheet_unmatched_vertices_items(self) -> I32:
        """(subsheet_unmatched_vertices_offsets[-1],) mesh vertices left unmatched by a maximum matching."""
    @property
    def subsheet_shared_vertices_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def subsheet_shared_vertices_items(self) -> I32:
        """(subsheet_shared_vertices_offsets[-1],) mesh vertices shared by two parallel curves."""
    @property
    def subsheet_self_parallel_curves_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def subsheet_self_parallel_curves_items(self) -> I32:
        """(subsheet_self_parallel_curves_offsets[-1],) curves of type 2 (self-parallel) pairs."""
    @property
    def subsheet_self_intersecting_components_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def subsheet_self_intersecting_components_items(self) -> I32:
        """(subsheet_self_intersecting_components_offsets[-1],) components holding two parallel curves sharing an end (type 3 pairs)."""

class Wireframe:
    """A VSG wireframe (paper §5): the complete wireframe's `count` polylines of mesh vertices (a
    closed chain repeats its first vertex) and the simplified wireframe's; polylines and
    simplified_polylines are CSRs (<name>_offsets, <name>_items). point_opacity, color and
    color_class are its style at `rho` (paper §6.2; the render layer's step, not the analysis):
    restyled(rho) gives them at another rho without computing the wireframe again."""

    @property
    def count(self) -> int: ...
    @property
    def rho(self) -> float:
        """The colour-class threshold of this wireframe's style."""
    def restyled(self, rho: float) -> Wireframe:
        """The same wireframe (shared) styled at `rho` in [0, 1]; no analysis runs."""
    @property
    def polylines_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def polylines_items(self) -> I32:
        """(polylines_offsets[-1],) mesh vertices along each polyline."""
    @property
    def point_opacity(self) -> npt.NDArray[np.float32]:
        """(npp,) aligned with polylines_items (npp = polylines_offsets[-1])."""
    @property
    def kind(self) -> U8:
        """(count,) 0 chain of VSG (irregular) edges only, 1 other chain."""
    @property
    def valence(self) -> I32:
        """(count,)"""
    @property
    def stop(self) -> U8:
        """(count,) 0 closed chain, 1 singular vertex of the wireframe, 2 boundary, 3 neither."""
    @property
    def shown(self) -> Bool:
        """(count,) on the simplified wireframe."""
    @property
    def non_important(self) -> U8:
        """(count,) 0 kept, 1 both ends redundant, 2 in a removable pair."""
    @property
    def reactivated(self) -> Bool:
        """(count,)"""
    @property
    def simplified_polylines_offsets(self) -> I32:
        """(nsimp + 1,) nsimp = counts['wireframe_edges_simplified']."""
    @property
    def simplified_polylines_items(self) -> I32:
        """(simplified_polylines_offsets[-1],) mesh vertices along each simplified polyline."""
    @property
    def color(self) -> I32:
        """(count,) palette index."""
    @property
    def color_class(self) -> I32:
        """(count,)"""
    @property
    def non_hex_offsets(self) -> I32:
        """(count + 1,)"""
    @property
    def non_hex_items(self) -> I32:
        """(non_hex_offsets[-1],) non-hex kinds of each polyline, sorted: code >> 16 indexes
        CELL_TYPES, code & 0xffff is the face count (docs/concepts.md)."""
    @property
    def simplified_non_hex_offsets(self) -> I32:
        """(nsimp + 1,)"""
    @property
    def simplified_non_hex_items(self) -> I32:
        """(simplified_non_hex_offsets[-1],) non-hex kinds of each simplified polyline, as non_hex."""
    @property
    def counts(self) -> WireframeCounts: ...

class Analysis:
    """Mesh.analyze()'s result. Per-sheet CSRs: sheet_<name>_offsets (num_sheets + 1,) with
    sheet_<name>_items (sheet_<name>_offsets[-1],). Curve ids are base-complex curves at level
    'complex', mesh edges at 'mesh'."""

    @property
    def mesh(self) -> Mesh: ...
    @property
    def level(self) -> Level: ...
    @property
    def rho(self) -> float:
        """Mesh.analyze(rho=...): the rho of wireframe() without one (presentation only)."""
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
    def metrics(self, threads: int | None = None, quality: bool = True) -> dict[str, dict[str, Any]]:
        """Structural complexity metrics (docs/metrics.md): `hbc metrics --json` without "file" and
        "timings"; NaN values are None. Computed with the GIL released. quality=False skips the
        scaled Jacobians (the quality group's values are None), as `--no-quality` does."""
    @property
    def graph(self) -> SingularityGraph: ...
    @property
    def complex(self) -> BaseComplex: ...
    @property
    def num_sheets(self) -> int: ...
    @property
    def sheet_type(self) -> U8:
        """(num_sheets,) 0 perfect, 1 type 1 (non-hex), 2 type 2 (self-parallel), 3 type 3 (self-intersecting)."""
    @property
    def sheet_flags(self) -> Bool:
        """(num_sheets, 3) type 1, type 2, type 3 configurations present."""
    @property
    def sheet_components_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_components_items(self) -> I32:
        """(sheet_components_offsets[-1],) sorted base-complex components of each sheet."""
    @property
    def sheet_cells_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_cells_items(self) -> I32:
        """(sheet_cells_offsets[-1],) sorted mesh hex cells of each sheet."""
    @property
    def sheet_curves_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_curves_items(self) -> I32:
        """(sheet_curves_offsets[-1],) sorted parallel curves E_P of each sheet."""
    @property
    def sheet_edges_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_edges_items(self) -> I32:
        """(sheet_edges_offsets[-1],) sorted mesh edges of each sheet's parallel curves."""
    @property
    def sheet_non_hex_cells_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_non_hex_cells_items(self) -> I32:
        """(sheet_non_hex_cells_offsets[-1],) sorted non-hex cells adjacent to each sheet."""
    @property
    def sheet_unmatched_vertices_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_unmatched_vertices_items(self) -> I32:
        """(sheet_unmatched_vertices_offsets[-1],) mesh vertices left unmatched by a maximum matching."""
    @property
    def sheet_shared_vertices_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_shared_vertices_items(self) -> I32:
        """(sheet_shared_vertices_offsets[-1],) mesh vertices shared by two parallel curves."""
    @property
    def sheet_self_parallel_curves_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_self_parallel_curves_items(self) -> I32:
        """(sheet_self_parallel_curves_offsets[-1],) curves of type 2 (self-parallel) pairs."""
    @property
    def sheet_self_intersecting_components_offsets(self) -> I32:
        """(num_sheets + 1,)"""
    @property
    def sheet_self_intersecting_components_items(self) -> I32:
        """(sheet_self_intersecting_components_offsets[-1],) components holding two parallel curves sharing an end (type 3 pairs)."""
    @property
    def largest_self_intersecting(self) -> int | None:
        """The self-intersecting sheet with most cells; None without one (or without sheets)."""
    @property
    def self_intersecting_sheets(self) -> I32:
        """(k,) increasing: the sheets with a subsheet decomposition."""
    def subsheets(self, sheet: int) -> Subsheets: ...
    def wireframe(self, sheet: int | None = None, subsheet: int | None = None, rho: float | None = None) -> Wireframe:
        """The whole mesh's wireframe (kept by the analysis) or a sheet's / subsheet's (computed
        now), styled at rho (None: the analysis' rho); a new rho restyles only."""
    def to_vtu(self, path: str, sheet: int | None = None, ascii: bool = False) -> str: ...

def block_soup(mesh: Mesh, analysis: Analysis | None, what: SoupWhat, sheet: int | None = None, shrink: float = 0.0) -> BlockSoup:
    """sheet: required for 'subsheets', 'sheet' and 'sheet_non_hex', ignored otherwise."""
def kept_surface_soup(mesh: Mesh, kept: npt.ArrayLike, shrink: float = 0.0) -> BlockSoup:
    """Faces of kept cells (kept: (num_cells,) bool) whose other side is not kept; owner = cell."""
def polygon_edges(offsets: npt.ArrayLike, items: npt.ArrayLike, num_points: int) -> dict[str, I32]:
    """The edges of polygons given as a CSR of point ids (e.g. a BlockSoup's face_vertices):
    'edges' (ne, 2) distinct undirected edges, lower point first, grouped by lower point;
    'corner_edge' (len(items),) the edge from each corner to the next corner of its polygon."""
def cell_centroids(mesh: Mesh) -> npt.NDArray[np.float64]:
    """(num_cells, 3) the mean of each cell's distinct vertices."""
def polylines(mesh: Mesh, offsets: npt.ArrayLike, items: npt.ArrayLike) -> npt.NDArray[np.float32]:
    """(len(items), 3) the positions of a CSR of mesh vertex ids (e.g. a Wireframe's polylines)."""

class CellQuality(TypedDict):
    scaled_jacobian: npt.NDArray[np.float64]  # (num_cells,) Verdict's; < 0 for inverted cells
    edge_ratio: npt.NDArray[np.float64]  # (num_cells,) longest / shortest edge, >= 1

def cell_quality(mesh: Mesh) -> CellQuality: ...
def cell_depth(mesh: Mesh) -> I32:
    """(num_cells,) cell layers from the boundary: 0 with a boundary vertex, else BFS over faces."""

# The layer plan (hbc/layer_plan.hpp): what the add-on, its figures and the web viewer draw with.
# Colours are linear RGBA; legend entries are (colour key of legend_colors(), words).
Rgba = tuple[float, float, float, float]
F32 = npt.NDArray[np.float32]
LegendEntry = tuple[str, str]
LAYERS: tuple[tuple[str, str], ...]  # (key, title) in building order
PALETTE_SIZE: int  # 24: one colour per owner
LEGEND_MAX_WORDS: int  # the longest legend words (beside a swatch in the sidebar)
WIRE_OPACITY_FLOOR: float  # the wireframe's faintest opacity by default
SPREAD_GAP: float  # the gap between copies laid side by side, a fraction of the model's width
SHEET_TYPE_SHORT: tuple[str, ...]  # by sheet type, for narrow list rows: "perfect", "type 1", ...
SHEET_HIGHLIGHTS: tuple[LegendEntry, ...]  # a picked sheet's highlights in legend order

class PartRequest(TypedDict):
    """One part of a layer as the front ends request it (hbc/layer_plan.hpp, PartRequest)."""
    layer: str  # a key of LAYERS
    part: str  # unique in the layer; a sheet highlight's part is its key
    geometry: str  # "soup", "lines" or "dots"
    source: str  # soup: block_soup's what; lines: chains, edges, curves, wireframe; dots: a CSR's name
    select: str  # the CSR whose picked sheet's row lists the owners or curves drawn; "" all
    edge_class: int  # edges: the EdgeClass drawn; else -1
    sheet: bool  # takes the picked sheet
    shrink: bool  # the layer's shrink applies
    color: str  # role, cell_type, valence, component, spread, sheet_shaded, subsheet, wire
    role: str  # color "role": a key of legend_colors()
    split: str  # "merged", or "owner": a piece per owner
    when: str  # "", "non_hex_cells", or "setting" (a front end's switch, default default_on)
    default_on: bool
    optional: bool  # left out when it has nothing to draw

LAYER_REQUESTS: tuple[PartRequest, ...]  # every layer's parts, layers in LAYERS' order

class LayerPalette(TypedDict):
    cycle: F32  # (PALETTE_SIZE, 4)
    cell_type: F32  # (5, 4) by CELL_TYPES; [0] the hex boundary's grey
    valence: dict[int, Rgba]  # singularities of these valences; any other: other_valence
    ring_darken: float  # ring-like hex components: their colour times this
    non_hex: Rgba
    other_valence: Rgba
    pseudo: Rgba
    non_manifold: Rgba
    unmatched: Rgba
    shared: Rgba
    self_parallel: Rgba
    self_intersecting: Rgba
    wire_several: Rgba
    wire_hex: Rgba

class LegendFacts(TypedDict, total=False):
    non_hex_types: list[int]  # CELL_TYPES indices present other than hex, ascending
    valences: list[int]  # singularity valences, ascending (with an analysis only, as the rest)
    has_pseudo: bool
    has_non_manifold: bool
    has_non_hex_components: bool

def layer_palette() -> LayerPalette:
    """Every colour of the layers by its role."""
def legend_colors() -> dict[str, Rgba]:
    """Every colour a legend entry names, by key, in the legend's order."""
def spread_ids(ids: npt.ArrayLike) -> I32:
    """(n,) palette entries of owner ids: consecutive ids far apart."""
def spread_colors(ids: npt.ArrayLike) -> F32:
    """(n, 4) the spread palette entries of owner ids (sheets: 0..n-1; subsheets: -1-k)."""
def palette_colors(index: npt.ArrayLike) -> F32:
    """(n, 4) palette entries by index; a negative index is the non-hex grey."""
def component_colors(kinds: npt.ArrayLike) -> F32:
    """(n, 4) components by id and kind: palette, rings darker, non-hex grey."""
def legend_facts(mesh: Mesh, analysis: Analysis | None = None) -> LegendFacts:
    """What a legend names of this mesh (and its analysis)."""
def legend(layers: Sequence[str], *, non_hex_types: Sequence[int] = (), valences: Sequence[int] = (),
           has_pseudo: bool = False, has_non_manifold: bool = False, has_non_hex_components: bool = True,
           highlights: Sequence[str] | None = None, wire_by_kind: bool = False) -> list[LegendEntry]:
    """What each colour, dot and edge of the shown layers means; highlights: those drawn, None all."""
def palette_legend(layers: Sequence[str], wire_by_kind: bool = False) -> list[LegendEntry]:
    """What the palette colours of the shown layers mean, each entry once."""
def wire_kind_legend(non_hex_types: Sequence[int] = ()) -> list[LegendEntry]:
    """A wireframe coloured by non-hex kind: per type, then 2+ types, hexes only."""
def subsheets_unavailable(sheet_type: int | None) -> str | None:
    """Why the subsheets layer cannot be built for a picked sheet of this type, or None."""
