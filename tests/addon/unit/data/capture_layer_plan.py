"""Captures the layer plan as the add-on's Python planning gave it before the plan moved into the
library (run on main at 3ed11c3's addon/, with any built hbc module for loading and analysing):
planning's colours, legends and words, and the legends of the twisted pair and of shared meshes,
as the JSON tests/addon/unit/test_layer_plan_unchanged.py compares the library's plan with.
usage: capture_layer_plan.py ADDON_DIR HBC_CLI DATA_DIR OUT"""
import json, subprocess, sys, tempfile, pathlib
addon, cli, data, out = sys.argv[1:]
sys.path.insert(0, addon)
import numpy as np
import hbc
from hybrid_base_complex.plan import planning as P
from hybrid_base_complex.plan.structure import Structure

def f(x):
    return np.asarray(x, np.float64).tolist()

LAYERS = [k for k, _ in P.LAYERS]
ref = {
    "layers": [list(l) for l in P.LAYERS],
    "palette": f(P.PALETTE), "cell_type_colors": f(P.CELL_TYPE_COLORS),
    "cell_type_names": list(P.CELL_TYPE_NAMES),
    "legend_colors": {k: f(v) for k, v in P.LEGEND_COLORS.items()},
    "legend_color_keys": list(P.LEGEND_COLORS),  # their order (the JSON's keys are sorted)
    "valence_colors": {str(v): f(P.valence_color(v)) for v in range(0, 17)},
    "constants": {k: f(getattr(P, k)) for k in ["NON_HEX_COLOR", "HEX_COLOR", "PSEUDO_COLOR", "NON_MANIFOLD_COLOR",
        "UNMATCHED_COLOR", "SHARED_COLOR", "SELF_PARALLEL_EDGE_COLOR", "SELF_INTERSECTING_COLOR",
        "WIRE_SEVERAL_COLOR", "WIRE_HEX_COLOR", "OTHER_VALENCE_COLOR", "RING_DARKEN"]},
    "sheet_colors": f(P.sheet_colors(50)), "subsheet_colors": f(P.subsheet_colors(50)),
    "sheet_color": [f(P.sheet_color(i)) for i in range(30)],
    "palette_color": f(P.palette_color(np.arange(-3, 50))),
    "component_colors": f(P.component_colors(np.array([0, 1, 2, 3] * 13, np.uint8))),
    "sheet_type_short": list(P.SHEET_TYPE_SHORT),
    "sheet_highlights": [list(e) for e in P.SHEET_HIGHLIGHTS],
    "subsheets_unavailable": [P.subsheets_unavailable(t) for t in (None, 0, 1, 2, 3)],
    "wire_kind_legend": [[list(e) for e in P.wire_kind_legend(t)] for t in ([], [1], [2, 3], [1, 2, 3, 4])],
    "palette_legend": {},
    "meshes": {},
}
# Each layer alone, the pairs whose entries meet (highlights, wireframes by kind, the palette's
# shared entries), and all of them.
subsets = [[l] for l in LAYERS] + [["sheet", "subsheets"], ["wireframe", "subsheets"], ["direct", "wireframe"],
                                   ["blocks", "sheets"], ["graph", "blocks"]] + [LAYERS]
for layers in subsets:
    for k in (False, True):
        ref["palette_legend"][f"{','.join(layers)}|{k}"] = [list(e) for e in P.palette_legend(layers, wire_by_kind=k)]

def add(name, mesh, analysis):
    s = Structure(mesh, analysis)
    facts = s.legend_facts()
    m = {"facts": facts, "facts_unanalysed": Structure(mesh).legend_facts(), "legends": {},
         "component_colors": f(s.component_colors()[:64])}  # its first 64 components
    for layers in subsets:
        for k in (False, True):
            for hl in (None, ("unmatched", "self_intersecting")):
                key = f"{','.join(layers)}|{k}|{hl}"
                m["legends"][key] = [list(e) for e in P.legend(layers, highlights=None if hl is None else set(hl), wire_by_kind=k, **facts)]
    ref["meshes"][name] = m

tmp = pathlib.Path(tempfile.mkdtemp())
subprocess.run([cli, "generate", "twisted-pair", "--section", "2", "--sections", "8", "-o", str(tmp / "pair.mesh")], check=True)
for name, path in [("twisted_pair", tmp / "pair.mesh"),
                   ("teapot", f"{data}/hybrid-base-complex/teapot.hedra"),
                   ("test_2", f"{data}/hybrid-base-complex/test_2.HYBRID"),
                   ("cube_twist", f"{data}/hybrid-base-complex/cube_twist-comp.obj.HYBRID"),
                   ("eight_voronoi", f"{data}/cinolib/eight_voronoi.hedra"),
                   ("NonManifold", f"{data}/openvolumemesh/NonManifold.ovm"),
                   ("block_out", f"{data}/hexalab-edge-cone-rectification/block_out.mesh")]:
    mesh = hbc.load(str(path))
    add(name, mesh, mesh.analyze())
pathlib.Path(out).write_text(json.dumps(ref, separators=(",", ":"), sort_keys=True) + "\n")
print("wrote", out, len(json.dumps(ref)))
