#!/usr/bin/env python3
"""Writes the web viewer's colours and legend words as JSON, taken from the add-on's planning
module (addon/hybrid_base_complex/plan/planning.py), the one definition the add-on and the figures
use. Run at build time by scripts/build_web.sh; needs numpy (Debian's /usr/bin/python3 has it).

The legend of planning.legend() depends on facts of the mesh (valences, cell types, ...); this
script evaluates it for one fact at a time, so the page composes the same entries in the same order
without holding a word or a colour of its own. Table 1's columns need the compiled hbc module
(planning.table1_columns); without it "table1" is null and the page takes them from the
WebAssembly module's schema.

usage: export_legend.py OUT.json
"""

from __future__ import annotations

import inspect
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "addon"))

from hybrid_base_complex.plan import planning as P  # noqa: E402
from hybrid_base_complex.plan.structure import Structure  # noqa: E402

#: Valences the page can name: planning's words are made for each (far beyond any real mesh).
MAX_VALENCE = 16


def rgba(c):
    return [round(float(x), 6) for x in c]


def entries(items):
    return [[key, words] for key, words in items]


def table1():
    """planning.table1_columns, each with its kind (count, ratio or seconds: how the page prints it,
    as `hbc table` does) from the library's schema."""
    try:
        # A key alone is not enough: "sheets" is a count and a time.
        kinds = {(f.key, bool(t)): f.kind for f, t in P.native.import_hbc().TABLE1_COLUMNS}
        return [{"key": k, "notation": n, "meaning": m, "kind": kinds[k, bool(t)], "timing": bool(t)}
                for k, n, m, t in P.table1_columns()]
    except Exception:  # the compiled module is not importable here
        return None


def subsheet_notes():
    """planning.subsheets_unavailable per sheet type (its words name the type: the compiled module)."""
    try:
        return {str(t): P.subsheets_unavailable(t) for t in range(len(P.SHEET_TYPE_SHORT))}
    except Exception:
        return None


def main(out: str) -> None:
    types = range(1, len(P.CELL_TYPE_NAMES))
    data = {
        "source": "addon/hybrid_base_complex/plan/planning.py",
        "colors_are": "linear RGBA (the page converts to sRGB for CSS swatches)",
        "layers": entries(P.LAYERS),
        "cell_type_names": list(P.CELL_TYPE_NAMES),
        "cell_type_colors": [rgba(c) for c in P.CELL_TYPE_COLORS],
        "palette": [rgba(c) for c in P.PALETTE],
        # planning.spread_ids is periodic in the palette size: one period gives every id's entry.
        "spread": [int(i) for i in P.spread_ids(range(P.PALETTE_SIZE))],
        # planning.subsheet_colors: subsheet k's palette entry, one period.
        "subsheet_spread": [int(i) for i in P.spread_ids([-1 - k for k in range(P.PALETTE_SIZE)])],
        "ring_darken": float(P.RING_DARKEN),
        "non_hex_color": rgba(P.NON_HEX_COLOR),
        "valence_colors": {str(v): rgba(P.valence_color(v)) for v in range(0, MAX_VALENCE + 1)},
        "pseudo_color": rgba(P.PSEUDO_COLOR),
        "non_manifold_color": rgba(P.NON_MANIFOLD_COLOR),
        "unmatched_color": rgba(P.UNMATCHED_COLOR),
        "shared_color": rgba(P.SHARED_COLOR),
        "self_parallel_color": rgba(P.SELF_PARALLEL_EDGE_COLOR),
        "self_intersecting_color": rgba(P.SELF_INTERSECTING_COLOR),
        "wire_several_color": rgba(P.WIRE_SEVERAL_COLOR),
        "wire_hex_color": rgba(P.WIRE_HEX_COLOR),
        "sheet_type_short": list(P.SHEET_TYPE_SHORT),
        # The wireframe's default opacity floor and the subsheets' spacing, as the add-on's defaults.
        "wire_floor": inspect.signature(Structure.wireframe).parameters["floor"].default,
        "spread_gap": inspect.signature(P.spread_translation).parameters["gap"].default,
        "legend_colors": {k: rgba(c) for k, c in P.LEGEND_COLORS.items()},
        # planning.legend for one fact each, in the order planning.legend lists them.
        "legend": {
            "direct": entries(P.legend(["direct"])),
            "cell_type": {str(t): entries(P.legend(["direct"], non_hex_types=[t])[1:]) for t in types},
            "valence": {str(v): entries(P.legend(["graph"], valences=[v])) for v in range(0, MAX_VALENCE + 1)},
            "pseudo": entries(P.legend(["graph"], has_pseudo=True)),
            "non_manifold": entries(P.legend(["graph"], has_non_manifold=True)),
            "components": entries(P.legend(["components"], has_non_hex_blocks=True)),
            "highlights": entries(P.legend(["sheet"])),
            "wire_kind_type": {str(t): entries(P.wire_kind_legend([t])[:1]) for t in types},
            "wire_kind_rest": entries(P.wire_kind_legend([])),
            "palette": {layer: entries(P.palette_legend([layer])) for layer, _ in P.LAYERS},
        },
        "table1": table1(),
        "subsheets_unavailable": subsheet_notes(),
    }
    pathlib.Path(out).write_text(json.dumps(data, separators=(",", ":")) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[-1])
    main(sys.argv[1])
