"""The panel's Metrics box: which of Analysis.metrics() (docs/metrics.md, the same object as
`hbc metrics --json`) are key, their labels short enough for the default sidebar, and how their
values are written. No ``bpy`` here.

Key: the summary score and its vector (why the score is what it is), the hex ratio by count and by
volume, the singularities, the components and the share of cells in the largest tenth of the
blocks, the sheets by class, the non-hex regions, and the worst component and worst sheet by
minimum scaled Jacobian (the box's buttons show and select them)."""

from __future__ import annotations

import math

#: (group, key, label, indented): one row each; a label's tooltip is the library's meaning of the
#: metric (hbc.METRIC_FIELDS). Labels are at most 14 characters (ui/panels.MAX_LABEL).
ROWS = (
    ("summary", "score", "Score", False),
    ("census", "hex_ratio", "Hex by count", False),
    ("census", "hex_volume_ratio", "Hex by volume", False),
    ("singular", "singularities", "Singularities", False),
    ("complex", "components", "Components", False),
    ("complex", "largest_tenth_share", "Largest tenth", False),
    ("sheets", "sheets", "Sheets", False),
    ("sheets", "perfect", "perfect", True),
    ("sheets", "type1", "type 1", True),
    ("sheets", "type2", "type 2", True),
    ("sheets", "type3", "type 3", True),
    ("non_hex", "cells", "Non-hex cells", False),
    ("non_hex", "regions", "regions", True),
)

#: summary.vector's entries (summary.vector_keys) as rows under the score: label and meaning
#: (docs/metrics.md, "The refinement-invariant summary").
VECTOR_ROWS = {
    "non_hex_volume_share": ("Non-hex vol.", "1 - hex volume ratio: volume not meshed by hexahedra"),
    "log10_1_plus_interior_curves": ("Inner chains", "log10(1 + singularities off the boundary)"),
    "log10_blocks": ("Blocks (log)", "log10 of the blocks (components of hex cells)"),
    "imperfect_sheet_share": ("Imperfect", "share of the sheets that are not perfect"),
    "cells_outside_perfect_sheets": ("Unreached", "share of the hexahedra in no perfect sheet"),
}

#: The worst places by minimum scaled Jacobian: (kind, id key, scaled Jacobian key, label); the
#: labels stand indented under a row "Worst" ("Worst component" is wider than a label may be).
WORST = (
    ("component", "worst_component", "worst_component_sj", "component"),
    ("sheet", "worst_sheet", "worst_sheet_sj", "sheet"),
)


def value_text(value) -> str:
    """A metric as the box writes it: counts whole, ratios with three decimals (JSON's null, an
    undefined value, as "-")."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, int):
        return str(value)
    return f"{value:.3f}"


def meanings(fields) -> dict:
    """{(group, key): meaning} of hbc.METRIC_FIELDS."""
    return {(f.group, f.key): f.meaning for f in fields}


def rows(metrics: dict, fields=()) -> list[tuple[str, str, str, bool, object]]:
    """The box's rows for one metrics object: (label, value text, tooltip, indented, value), the
    summary vector's entries under the score."""
    what = meanings(fields)
    out = []
    for group, key, label, indented in ROWS:
        value = (metrics.get(group) or {}).get(key)
        out.append((label, value_text(value), what.get((group, key), label), indented, value))
        if (group, key) == ("summary", "score"):
            summary = metrics.get("summary") or {}
            for name, v in zip(summary.get("vector_keys", ()), summary.get("vector", ())):
                vlabel, meaning = VECTOR_ROWS.get(name, (name[:14], name))
                out.append((vlabel, value_text(v), meaning, True, v))
    return out


def worst(metrics: dict) -> list[tuple[str, int | None, str, str]]:
    """(kind, id or None, text, label) of the worst component and the worst sheet: the id with its
    minimum scaled Jacobian ("12 (0.31)"), "-" without quality or without such a place."""
    quality = metrics.get("quality") or {}
    out = []
    for kind, id_key, sj_key, label in WORST:
        i = quality.get(id_key)
        i = None if i is None or i < 0 else int(i)
        text = "-" if i is None else f"{i} ({value_text(quality.get(sj_key))})"
        out.append((kind, i, text, label))
    return out
