"""Exports from the panel: the active mesh's analysis as VTU through the library's own writer
(Analysis.to_vtu, the writer of `hbc export-vtu`: cells with their component and sheet ids, and a
second file with the singularity graph), and a built layer as OBJ or PLY.

The library writes OBJ/PLY only for its own face selections (`hbc export-surface`: boundary,
patches, components, sheets), not for what a layer shows (shrunk blocks, tubes, subsheets laid out
beside the mesh), so a layer goes through Blender's own exporters, of exactly its objects as seen."""

from __future__ import annotations

import bpy

from . import compat
from . import scene as S

LAYER_FORMATS = ("OBJ", "PLY")


def export_vtu(structure, path: str, sheet=None) -> list[str]:
    """Writes path (cells) and path_graph.vtu (singular edges); sheet: also the in_sheet and
    subsheet arrays of that sheet. Returns both paths."""
    if structure.analysis is None:
        raise ValueError("The mesh is not analyzed: press Analyze first")
    graph = structure.analysis.to_vtu(path, sheet=sheet)
    return [path, graph]


def export_layer(context, root, layer: str, path: str, fmt: str) -> int:
    """Writes the visible objects of a built layer to path (OBJ or PLY) with Blender's exporter;
    the selection, the active object and the layer's visibility are put back. Returns the number
    of objects written."""
    if fmt not in LAYER_FORMATS:
        raise ValueError(f"Unknown layer format {fmt!r}: expected one of {', '.join(LAYER_FORMATS)}")
    coll = S.find_layer(root, layer)
    if coll is None:
        raise ValueError(f"The {layer} layer is not built")
    vl = context.view_layer
    hidden, coll.hide_viewport = coll.hide_viewport, False
    selected = [ob for ob in vl.objects if ob.select_get()]
    active = vl.objects.active
    try:
        vl.update()
        objects = [ob for ob in S.objects_in(coll) if ob.name in vl.objects and ob.visible_get()]
        if not objects:
            raise ValueError(f"The {layer} layer has no visible object to export")
        for ob in selected:
            ob.select_set(False)
        with S.selectable(objects):
            for ob in objects:
                ob.select_set(True)
            vl.objects.active = objects[0]
            op, kw = compat.layer_exporter(fmt)
            op(filepath=path, **kw)
        return len(objects)
    finally:
        for ob in vl.objects:
            ob.select_set(ob in selected)
        vl.objects.active = active
        coll.hide_viewport = hidden
