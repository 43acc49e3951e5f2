"""The layer plan moved from the add-on's Python into the library (hbc/layer_plan.hpp); everything
drawn stays as it was. data/layer_plan_main.json holds what planning.py gave before the move (main
at 3ed11c3, its own Python palette and legend; written by data/capture_layer_plan.py): the palette,
every colour by role, the legend words for every pair of layers, and the legends of the twisted
pair and of shared meshes from their facts. planning now reads all of it from the library, and
every value must be the same: colours bit for bit as float32, words character for character.
The one intended change since the capture is docs/concepts.md's vocabulary, applied to the file by
hand: the layer `blocks` ("Blocks") is `components` ("Components"), the legend key `non_hex_block`
is `non_hex_component`, the palette words "Hex component" are "Hex-cell component"."""

import json
import pathlib

import numpy as np
import pytest

from hybrid_base_complex.plan import planning as P
from hybrid_base_complex.plan.structure import Structure

REF = json.loads((pathlib.Path(__file__).parent / "data" / "layer_plan_main.json").read_text())


def same(a, b):
    """Equal as the float32 colours Blender and the page draw with, and of the same shape."""
    a, b = np.asarray(a, np.float64), np.asarray(b, np.float64)
    return a.shape == b.shape and np.array_equal(a.astype(np.float32), b.astype(np.float32))


def entries(es):
    return [list(e) for e in es]


def test_palette_and_colours_by_role_unchanged():
    assert [list(x) for x in P.LAYERS] == REF["layers"]
    assert same(P.PALETTE, REF["palette"])
    assert same(P.CELL_TYPE_COLORS, REF["cell_type_colors"])
    assert list(P.CELL_TYPE_NAMES) == REF["cell_type_names"]
    for name, value in REF["constants"].items():
        assert same(getattr(P, name), value), name
    for v, c in REF["valence_colors"].items():
        assert same(P.valence_color(int(v)), c), v


def test_legend_swatches_unchanged_in_order():
    assert list(P.LEGEND_COLORS) == REF["legend_color_keys"]
    for key, c in REF["legend_colors"].items():
        # As doubles too: the panel's swatches take these values as they are.
        assert np.array_equal(np.asarray(P.LEGEND_COLORS[key], np.float64), np.asarray(c, np.float64)), key


def test_owner_colours_unchanged():
    assert same(P.sheet_colors(50), REF["sheet_colors"])
    assert same(P.subsheet_colors(50), REF["subsheet_colors"])
    assert all(same(P.sheet_color(i), c) for i, c in enumerate(REF["sheet_color"]))
    assert same(P.palette_color(np.arange(-3, 50)), REF["palette_color"])
    assert same(P.component_colors(np.array([0, 1, 2, 3] * 13, np.uint8)), REF["component_colors"])


def test_words_unchanged():
    assert list(P.SHEET_TYPE_SHORT) == REF["sheet_type_short"]
    assert entries(P.SHEET_HIGHLIGHTS) == REF["sheet_highlights"]
    assert [P.subsheets_unavailable(t) for t in (None, 0, 1, 2, 3)] == REF["subsheets_unavailable"]
    kinds = [entries(P.wire_kind_legend(t)) for t in ([], [1], [2, 3], [1, 2, 3, 4])]
    assert kinds == REF["wire_kind_legend"]
    for key, expected in REF["palette_legend"].items():
        layers, by_kind = key.split("|")
        assert entries(P.palette_legend(layers.split(","), wire_by_kind=by_kind == "True")) == expected, key


@pytest.fixture(scope="module")
def meshes(generate, shared_data_dir):
    import hbc

    paths = {
        "teapot": "hybrid-base-complex/teapot.hedra",
        "test_2": "hybrid-base-complex/test_2.HYBRID",
        "cube_twist": "hybrid-base-complex/cube_twist-comp.obj.HYBRID",
        "eight_voronoi": "cinolib/eight_voronoi.hedra",
        "NonManifold": "openvolumemesh/NonManifold.ovm",
        "block_out": "hexalab-edge-cone-rectification/block_out.mesh",
    }
    out = {"twisted_pair": generate("twisted-pair", "--section", "2", "--sections", "8")}
    for name, rel in paths.items():
        mesh = hbc.load(str(shared_data_dir / rel))
        out[name] = (mesh, mesh.analyze())
    return out


@pytest.mark.parametrize("name", sorted(REF["meshes"]))
def test_mesh_legends_unchanged(meshes, name):
    ref = REF["meshes"][name]
    mesh, analysis = meshes[name]
    s = Structure(mesh, analysis)
    facts = s.legend_facts()
    assert facts == ref["facts"]
    assert Structure(mesh).legend_facts() == ref["facts_unanalysed"]
    assert same(s.component_colors()[:64], ref["component_colors"])
    for key, expected in ref["legends"].items():
        layers, by_kind, hl = key.split("|")
        highlights = None if hl == "None" else {"unmatched", "self_intersecting"}
        got = P.legend(layers.split(","), highlights=highlights, wire_by_kind=by_kind == "True", **facts)
        assert entries(got) == expected, key
