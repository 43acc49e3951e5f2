"""hbc: structure analysis of hex-dominant volume meshes.

The work is done by the compiled module ``hbc._core``; this package re-exports its public names
so that user code never imports ``_core`` directly.

    >>> import hbc
    >>> mesh = hbc.load("model.mesh")
    >>> mesh.info()["hex_ratio"]
    >>> a = mesh.analyze(rho=0.8, level="complex")
    >>> a.stats["hex_components"], a.num_sheets
    >>> soup = hbc.block_soup(mesh, a, "components", shrink=0.1)
    >>> q = hbc.cell_quality(mesh)["scaled_jacobian"]; depth = hbc.cell_depth(mesh)
    >>> [(f.label, f.unit) for f in hbc.STAT_FIELDS]  # what each statistic means
"""

from ._core import (
    CELL_TYPES,
    COMPONENT_KINDS,
    FORMATS,
    METRIC_FIELDS,
    SHEET_TYPES,
    SUMMARY_FIELDS,
    STAT_FIELDS,
    TABLE1_COLUMNS,
    TIMING_FIELDS,
    WIREFRAME_COUNT_FIELDS,
    Analysis,
    Field,
    BaseComplex,
    MetricField,
    Mesh,
    MeshFormatError,
    SingularityGraph,
    Subsheets,
    Wireframe,
    __version__,
    block_soup,
    cell_centroids,
    cell_depth,
    check,
    cell_quality,
    kept_surface_soup,
    load,
    polygon_edges,  # a viewer's helper (the Blender add-on's mesh edges), not in __all__
    polylines,
)
# The layer plan (hbc/layer_plan.hpp): the layers, colours by role and legend words the add-on, its
# figures and the web viewer draw with, and what each layer draws (LAYER_REQUESTS); viewers' helpers,
# not in __all__.
from ._core import (  # noqa: F401
    LAYERS,
    LAYER_REQUESTS,
    LEGEND_MAX_WORDS,
    PALETTE_SIZE,
    SHEET_HIGHLIGHTS,
    SHEET_TYPE_SHORT,
    SPREAD_GAP,
    WIRE_OPACITY_FLOOR,
    component_colors,
    layer_palette,
    legend,
    legend_colors,
    legend_facts,
    palette_colors,
    palette_legend,
    spread_colors,
    spread_ids,
    subsheets_unavailable,
    wire_kind_legend,
)
from .comparison import compare  # hbc compare from Python (docs/compare.md)


def gallery(paths, out, *, executor=None, **options) -> dict:
    """hbc gallery from Python (docs/gallery.md): the static site of the meshes at ``paths`` in the
    folder ``out``, each mesh one work unit on ``executor`` (any concurrent.futures.Executor; None:
    a thread pool of ``jobs``); the options and the summary returned: hbc._gallery.gallery. Imported
    when called, so that ``python -m hbc._gallery`` (what the command runs) imports it once."""
    from ._gallery import gallery as run

    return run(paths, out, executor=executor, **options)

__all__ = [
    "Mesh", "MeshFormatError", "load", "check", "__version__",
    "Analysis", "SingularityGraph", "BaseComplex", "Subsheets", "Wireframe", "block_soup", "polylines",
    "cell_quality", "cell_depth", "cell_centroids", "kept_surface_soup",
    "Field", "STAT_FIELDS", "TIMING_FIELDS", "WIREFRAME_COUNT_FIELDS", "TABLE1_COLUMNS",
    "SHEET_TYPES", "CELL_TYPES", "COMPONENT_KINDS", "FORMATS",
    "MetricField", "METRIC_FIELDS", "SUMMARY_FIELDS", "compare", "gallery",
]
