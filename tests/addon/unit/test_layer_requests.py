"""What each layer draws is the library's (hbc.LAYER_REQUESTS, hbc/layer_plan.hpp), for the add-on
as for the web viewer (tests/wasm/layer_requests_test.mjs): the add-on builds the library's layers,
names only parts the library requests and every soup and dots part it requests, and what it asks
hbc for and colours is what it asked for before the table (the block_soup kinds, sheets and shrinks
and colours it spelled out itself, written out again here)."""

import ast
import pathlib

import numpy as np
import pytest

from hybrid_base_complex.plan import planning as P
from hybrid_base_complex.plan.structure import Structure

ADDON = pathlib.Path(__file__).resolve().parents[3] / "addon" / "hybrid_base_complex"


def _calls(names):
    """(function name, literal string arguments) of every call of `names` in the add-on's plan/
    and blender/ modules."""
    out = []
    for path in [*(ADDON / "plan").glob("*.py"), *(ADDON / "blender").glob("*.py")]:
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in names:
                args = [a.value for a in node.args if isinstance(a, ast.Constant) and isinstance(a.value, str)]
                out.append((node.func.attr, tuple(args)))
    return out


def test_the_addon_builds_the_librarys_layers():
    import hbc

    tree = ast.parse((ADDON / "blender" / "layers.py").read_text())
    builders = next(n.value for n in tree.body if isinstance(n, ast.Assign) and n.targets[0].id == "BUILDERS")
    assert [k.value for k in builders.keys] == [k for k, _ in hbc.LAYERS]
    assert [r["layer"] for r in hbc.LAYER_REQUESTS] == sorted(
        (r["layer"] for r in hbc.LAYER_REQUESTS), key=[k for k, _ in hbc.LAYERS].index)
    assert {r["layer"] for r in hbc.LAYER_REQUESTS} == {k for k, _ in hbc.LAYERS}


def test_the_addon_names_only_requested_parts_and_every_soup_and_dots_part():
    import hbc

    table = {(r["layer"], r["part"]): r for r in hbc.LAYER_REQUESTS}
    named = {args[:2] for _, args in _calls({"part_request", "part_soup", "part_vertices"}) if len(args) >= 2}
    assert named and named <= set(table), named - set(table)
    # The lines parts: the graph's through layer_requests("graph"), the wireframes through
    # Structure.wireframe (its "wire" colours come with its arrays), the self-parallel curves by name.
    assert {k for k, r in table.items() if r["geometry"] != "lines"} <= named
    assert ("graph",) in {args for f, args in _calls({"layer_requests"})}
    assert {r["color"] for r in table.values() if r["geometry"] == "lines" and r["source"] == "wireframe"} == {"wire"}


@pytest.fixture(scope="module")
def twisted(generate):
    mesh, analysis = generate("twisted-pair", "--section", "2", "--sections", "8")
    return Structure(mesh, analysis)


def _same_soup(a, b):
    return (np.array_equal(a.positions, b.positions) and np.array_equal(a.face_sizes, b.face_sizes)
            and np.array_equal(a.face_vertices, b.face_vertices) and np.array_equal(a.face_owner, b.face_owner))


def test_soups_are_the_ones_the_addon_asked_for(twisted):
    s = twisted
    sheet = next(i for i, t in enumerate(s.sheet_types()) if t == 3)
    asked = {  # (kind, sheet, shrink) as the add-on's Structure spelled them before the table
        ("direct", "boundary"): ("boundary", None, 0.0), ("direct", "hex"): ("hex", None, 0.0),
        ("direct", "non_hex"): ("non_hex", None, 0.3), ("components", "components"): ("components", None, 0.3),
        ("sheets", "sheets"): ("sheets", None, 0.3), ("sheet", "sheet"): ("sheet", sheet, 0.3),
        ("subsheets", "subsheets"): ("subsheets", sheet, 0.3)}
    for (layer, part), (kind, on, shrink) in asked.items():
        assert _same_soup(s.part_soup(layer, part, sheet, 0.3), s._soup(kind, on, shrink)), (layer, part)
    comps = P.csr_row(np.asarray(s.analysis.sheet_self_intersecting_components_offsets),
                      np.asarray(s.analysis.sheet_self_intersecting_components_items), sheet)
    assert len(comps)
    blocks = s._soup("components")
    assert _same_soup(s.part_soup("sheet", "self_intersecting", sheet, 0.3),
                      blocks.select(np.isin(blocks.face_owner, comps)))
    sub = s.subsheets(sheet)
    for k in range(int(sub.count)):
        off, items = np.asarray(sub.subsheet_unmatched_vertices_offsets), np.asarray(sub.subsheet_unmatched_vertices_items)
        assert np.array_equal(s.subsheet_unmatched(sub, k), items[off[k]:off[k + 1]])


def test_colours_are_the_ones_the_addon_drew(twisted):
    s = twisted
    req = P.part_request
    n = 50
    assert np.array_equal(P.part_colors(req("sheets", "sheets"), np.arange(n)), P.sheet_colors(n))
    assert np.array_equal(P.part_colors(req("subsheets", "subsheets"), np.arange(n)), P.subsheet_colors(n))
    kinds = s.component_kinds()
    assert np.array_equal(s.component_colors(), P.component_colors(kinds))
    owners = np.arange(7)
    shade = 0.8 + 0.2 * ((owners * 7) % 3) / 2.0
    oc = np.tile(np.asarray(P.sheet_color(3), np.float32), (7, 1))
    oc[:, :3] *= shade[:, None]
    got = P.part_colors(req("sheet", "sheet"), owners, sheet=3)
    assert got.dtype == oc.dtype and np.array_equal(got, oc)
    for part, old in (("unmatched", P.UNMATCHED_COLOR), ("shared", P.SHARED_COLOR),
                      ("self_intersecting", P.SELF_INTERSECTING_COLOR)):
        assert np.array_equal(P.part_colors(req("sheet", part), np.zeros(16)), np.tile(old, (16, 1))), part
    assert P.role_color(req("direct", "boundary")) == P.HEX_COLOR == P.role_color(req("direct", "hex"))
    types = np.asarray(s.mesh.cell_types, np.int64)
    cells = np.arange(len(types))
    assert np.array_equal(s.cell_type_colors(cells), P.CELL_TYPE_COLORS[types[cells]])


def test_graph_groups_unchanged(twisted):
    groups = twisted.singularity_lines()
    g = twisted.analysis.graph
    valences = np.unique(np.asarray(g.chain_valence))
    names = [f"Valence {int(v)}" for v in valences]
    cls = np.asarray(g.edge_class)
    names += [name for value, name in ((2, "Pseudo-singular"), (3, "Non-manifold")) if np.any(cls == value)]
    assert [name for name, _, _ in groups] == names
    for (name, color, _), v in zip(groups, valences):
        assert color == P.valence_color(v), name
