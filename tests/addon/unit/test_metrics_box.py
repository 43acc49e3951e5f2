"""plan.metrics_box (the Metrics box's rows), planning.import_report (the import's closing line) and
session.ensure's subsheet rule, without Blender."""
import math
from types import SimpleNamespace

from hybrid_base_complex.plan import metrics_box as MB
from hybrid_base_complex.plan import planning as P
from hybrid_base_complex.plan import session


def test_value_text():
    assert MB.value_text(12) == "12" and MB.value_text(0) == "0"
    assert MB.value_text(0.889315910837817) == "0.889" and MB.value_text(3.0) == "3.000"
    assert MB.value_text(None) == "-" and MB.value_text(math.nan) == "-"


def test_rows_put_the_vector_under_the_score_and_fit_the_sidebar():
    """A made-up metrics object: the score's five entries follow it, indented, in vector_keys'
    order; every label is at most 14 characters with its indent (ui/panels.MAX_LABEL)."""
    keys = list(MB.VECTOR_ROWS)
    metrics = {"summary": {"score": 1.5, "vector": [0.5, 0.0, 1.0, 0.0, 0.0], "vector_keys": keys},
               "census": {"hex_ratio": 1.0}, "sheets": {"sheets": 3, "type3": None}}
    fields = [SimpleNamespace(group="census", key="hex_ratio", meaning="hexahedra / cells")]
    rows = MB.rows(metrics, fields)
    assert [r[0] for r in rows[:6]] == ["Score"] + [MB.VECTOR_ROWS[k][0] for k in keys]
    assert [r[1] for r in rows[:6]] == ["1.500", "0.500", "0.000", "1.000", "0.000", "0.000"]
    assert [r[3] for r in rows[:6]] == [False] + [True] * 5
    by_label = {r[0]: r for r in rows}
    assert by_label["Hex by count"][1:3] == ("1.000", "hexahedra / cells")
    assert by_label["Sheets"][1] == "3" and by_label["type 3"][1] == "-" and by_label["Components"][1] == "-"
    assert len(rows) == len(MB.ROWS) + len(keys)
    assert all(len(("  " if r[3] else "") + r[0]) <= 14 for r in rows)


def test_worst_names_the_place_or_none():
    q = {"quality": {"worst_component": 1254, "worst_component_sj": 0.48831, "worst_sheet": None,
                     "worst_sheet_sj": None}}
    assert MB.worst(q) == [("component", 1254, "1254 (0.488)", "component"), ("sheet", None, "-", "sheet")]
    assert [w[1] for w in MB.worst({"quality": None})] == [None, None]  # --no-quality: no quality group


def test_import_report():
    times = {"load": 1.234, "analysis": 2.0, "scene": 0.5}
    assert P.import_report("cyl", 988000, 1, 3, 4, times, 3.9) == (
        "Imported cyl: 988000 cells, 1 components, 3 sheets, 4 objects in 3.90 s "
        "(load 1.23 s, analysis 2.00 s, scene 0.50 s)")
    assert P.import_report("m", 8, None, None, 1, {"load": 0.1}, 0.2, "dropped 1 cell (1 few_faces)") == (
        "Imported m: 8 cells, 1 object in 0.20 s (load 0.10 s); dropped 1 cell (1 few_faces)")


def test_ensure_analyzes_by_the_rule_asked(generate):
    """session.ensure analyzes a cached mesh again when its analysis used the other rule, and
    keeps it when the rule is the same (the same Analysis object)."""
    mesh, _ = generate("grid", "--size", "2", "2", "2")
    s = session.Structure(mesh)
    s.source = "grid.mesh"
    session.put("grid", s)
    try:
        a = session.ensure("grid", "grid.mesh", 1.0, 0.8, True, log=lambda _: None, subsheet_rule="fewest")
        assert a is s and s.subsheet_rule == "fewest"
        first = s.analysis
        session.ensure("grid", "grid.mesh", 1.0, 0.8, True, log=lambda _: None, subsheet_rule="fewest")
        assert s.analysis is first
        session.ensure("grid", "grid.mesh", 1.0, 0.8, True, log=lambda _: None, subsheet_rule="layers")
        assert s.analysis is not first and s.subsheet_rule == "layers"
        assert s.metrics() is s.metrics()  # computed once per analysis
    finally:
        session.drop("grid")
