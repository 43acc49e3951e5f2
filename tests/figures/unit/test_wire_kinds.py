"""The figures' colouring of the wireframes by non-hex kind, without Blender: the option, and the
legend each wireframe panel then gets (the add-on's planning.legend, the one definition)."""

from hybrid_base_complex.figures import plan
from hybrid_base_complex.plan import planning as P

FACTS = {"non_hex_types": [1, 2, 4], "valences": [3, 5], "has_pseudo": True, "has_non_manifold": False,
         "has_non_hex_blocks": True}


def test_option_defaults_to_the_colour_classes():
    assert plan.parse(["m.mesh", "--out", "o"]).wire_colors == "class"
    assert plan.parse(["m.mesh", "--out", "o", "--wire-colors", "kind"]).wire_colors == "kind"


def test_wireframe_panels_name_the_kinds_when_coloured_by_them():
    kinds = [("tet", "Wire at tet"), ("prism", "Wire at prism"), ("polyhedron", "Wire at polyhedron"),
             ("wire_several", "Wire at 2+ types"), ("wire_hex", "Wire at hexes only")]
    for key in ("wireframe", "mesh_wireframe"):
        assert plan.panel_legend(P, key, FACTS) == []  # class colours name nothing
        got = plan.panel_legend(P, key, FACTS, wire_by_kind=True)
        assert [(k, w) for k, w, _ in got] == kinds
        assert all(c == tuple(float(x) for x in P.LEGEND_COLORS[k]) for k, _, c in got)
    # The subsheets panel keeps its highlights and adds the kinds of its wireframes.
    sub = plan.panel_legend(P, "subsheets", FACTS, {"unmatched"}, wire_by_kind=True)
    assert [k for k, _, _ in sub] == ["unmatched"] + [k for k, _ in kinds]
    # Panels without a wireframe are unchanged.
    assert plan.panel_legend(P, "graph", FACTS, wire_by_kind=True) == plan.panel_legend(P, "graph", FACTS)
