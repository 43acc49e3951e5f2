"""One schema for what hbc reports: the statistics fields and name tables come from the library,
and the type stub, the Python results and the CLI's JSON agree with them, so that a field added in
C++ without its stub entry (or under another key in one output) is caught."""

import ast
import json
import pathlib
import subprocess

import hbc

from conftest import TABLE1

# The wireframe counts' deprecated keys (docs/concepts.md, retired words), written after the others.
WIREFRAME_COUNT_ALIASES = {"reference_components": "wireframe_components",
                           "shown_components": "wireframe_components_simplified"}


def stub_typed_dict(name):
    """The (key, annotation) pairs of TypedDict `name` in the stub, in order."""
    tree = ast.parse(pathlib.Path(hbc.__file__).with_name("_core.pyi").read_text())
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and node.name == name:
            return [(n.target.id, ast.unparse(n.annotation)) for n in node.body if isinstance(n, ast.AnnAssign)]
    raise AssertionError(f"{name} is not in the stub")


def python_type(field):
    return {"count": "int", "ratio": "float", "seconds": "float", "value": "float"}[field.kind]


def test_stub_lists_every_field_in_order_with_its_type():
    stats = stub_typed_dict("AnalysisStats")
    assert stats[-1] == ("timings", "Timings")
    assert stats[:-1] == [(f.key, python_type(f)) for f in hbc.STAT_FIELDS]
    assert stub_typed_dict("Timings") == [(f.key, "float") for f in hbc.TIMING_FIELDS]
    assert stub_typed_dict("WireframeCounts") == [(f.key, python_type(f)) for f in hbc.WIREFRAME_COUNT_FIELDS] + [
        (old, "int") for old in WIREFRAME_COUNT_ALIASES]


def test_fields_are_described():
    for fields in (hbc.STAT_FIELDS, hbc.TIMING_FIELDS, hbc.WIREFRAME_COUNT_FIELDS):
        keys = [f.key for f in fields]
        assert len(set(keys)) == len(keys) > 0
        for f in fields:
            assert f.label and f.meaning and f.unit, f
            assert bool(f.notation) == bool(f.latex), f
    # The paper's Table 1: 9 counts then 5 stage times, each with the paper's notation.
    cols = hbc.TABLE1_COLUMNS
    assert [timing for _, timing in cols] == [False] * 9 + [True] * 5
    assert [f.notation for f, _ in cols] == ["|C|", "|H|/|C|", "|C_B|", "|H_B|/|C_B|", "|G_SH|", "T1", "T2", "T3",
                                            "|G_SH*|", "T_GS", "T_GB", "T_VSGW", "T_GSH", "T_GSH*"]
    for f, timing in cols:
        assert f in (hbc.TIMING_FIELDS if timing else hbc.STAT_FIELDS)


def test_results_follow_the_schema(analyzed):
    mesh, a = analyzed[TABLE1 + "teapot.hedra"]
    stats = a.stats
    # Every stage ran, so every field is there, in the schema's order, with its kind's type.
    assert list(stats) == [f.key for f in hbc.STAT_FIELDS] + ["timings"]
    for f in hbc.STAT_FIELDS:
        assert type(stats[f.key]).__name__ == python_type(f), f.key
    assert list(stats["timings"]) == [f.key for f in hbc.TIMING_FIELDS]
    counts = a.wireframe().counts
    assert list(counts) == [f.key for f in hbc.WIREFRAME_COUNT_FIELDS] + list(WIREFRAME_COUNT_ALIASES)
    for old, key in WIREFRAME_COUNT_ALIASES.items():  # a deprecated key holds its new key's value
        assert counts[old] == counts[key]


def test_cli_json_uses_the_same_keys(hbc_cli, shared_data_dir):
    path = shared_data_dir / TABLE1 / "teapot.hedra"
    out = json.loads(subprocess.run([hbc_cli, "analyze", str(path), "--json"], capture_output=True, text=True,
                                    check=True).stdout)
    assert list(out) == ["file"] + [f.key for f in hbc.STAT_FIELDS] + ["timings"]
    wire = json.loads(subprocess.run([hbc_cli, "wireframe", str(path), "--json"], capture_output=True, text=True,
                                     check=True).stdout)
    keys = list(wire)
    start = keys.index(hbc.WIREFRAME_COUNT_FIELDS[0].key)
    assert keys[start:start + len(hbc.WIREFRAME_COUNT_FIELDS)] == [f.key for f in hbc.WIREFRAME_COUNT_FIELDS]
    for old, key in WIREFRAME_COUNT_ALIASES.items():
        assert wire[old] == wire[key]
    csv_head = subprocess.run([hbc_cli, "analyze", str(path), "--csv"], capture_output=True, text=True,
                              check=True).stdout.splitlines()[0].split(",")
    assert csv_head == ["mesh"] + [f.key for f in hbc.STAT_FIELDS] + ["t_" + f.key for f in hbc.TIMING_FIELDS]


def test_name_tables_index_the_arrays(analyzed, shared_data_dir):
    mesh, a = analyzed[TABLE1 + "teapot.hedra"]
    # Sheet types: index = the value of Analysis.sheet_type; JSON names as `hbc sheets --json` writes.
    assert [name for name, _ in hbc.SHEET_TYPES] == ["perfect", "type1", "type2", "type3"]
    counts = [int((a.sheet_type == t).sum()) for t in range(len(hbc.SHEET_TYPES))]
    assert counts[1:] == [a.stats["sheets_type1"], a.stats["sheets_type2"], a.stats["sheets_type3"]]
    # Cell types: index = the value of Mesh.cell_types; names as `hbc info --json` writes them.
    info = mesh.info()["cell_types"]
    assert set(info) == set(hbc.CELL_TYPES)
    for t, name in enumerate(hbc.CELL_TYPES):
        assert int((mesh.cell_types == t).sum()) == info[name]
    # Formats: every name loads through format=, and each real mesh's extension is listed.
    names = {f["name"] for f in hbc.FORMATS} | {f["alias"] for f in hbc.FORMATS if f["alias"]}
    assert {"ovm", "ovmb", "mesh", "medit", "hybrid", "hedra", "msh", "vtk", "vtu", "foam", "openfoam",
            "su2", "ugrid", "fluent", "exo", "exodus", "e", "g", "cgns", "med", "xdmf", "xmf",
            "inp", "abaqus", "bdf", "nas", "k", "key"} == names
    # Every extension of a format names it (format_from_path), the first being `extension`.
    for f in hbc.FORMATS:
        assert f["extensions"][0] == f["extension"]
    assert [f["extensions"] for f in hbc.FORMATS if f["name"] in ("bdf", "k")] == [[".bdf", ".nas"], [".k", ".key"]]
    extensions = {f["extension"].lower() for f in hbc.FORMATS}
    assert {p.suffix.lower() for p in shared_data_dir.rglob("*") if p.suffix.lower() in extensions}
    assert hbc.load(shared_data_dir / TABLE1 / "teapot.hedra", format="hedra").num_cells == mesh.num_cells


def test_csv_rows_survive_a_comma_and_a_quote_in_the_name(hbc_cli, shared_data_dir, tmp_path):
    # RFC 4180: a name holding `,` or `"` is quoted (quotes doubled), so a CSV reader gets the
    # header's number of fields and the name back unchanged; `hbc table` reads each child's row past
    # that name and gives the same values as `hbc analyze --csv`.
    import csv
    import io
    import shutil
    odd = tmp_path / 'teapot, the "odd" one.hedra'
    shutil.copy(shared_data_dir / TABLE1 / "teapot.hedra", odd)
    broken = tmp_path / "broken, too.mesh"
    broken.write_text("MeshVersionFormatted 1\nDimension 3\nVertices\n2\n0 0 0 0\n")
    analyze = list(csv.reader(io.StringIO(subprocess.run([hbc_cli, "analyze", str(odd), "--csv"], capture_output=True,
                                                          text=True, check=True).stdout)))
    assert len(analyze) == 2 and len(analyze[1]) == len(analyze[0]) and analyze[1][0] == str(odd)
    table = list(csv.reader(io.StringIO(subprocess.run([hbc_cli, "table", "--csv", str(odd), str(broken)],
                                                       capture_output=True, text=True, check=True).stdout)))
    assert table[0] == analyze[0] + ["error"]
    rows = {r[0]: r for r in table[1:]}
    assert set(rows) == {str(odd), str(broken)} and all(len(r) == len(table[0]) for r in table[1:])
    timed = [i for i, k in enumerate(analyze[0]) if k.startswith("t_")]
    assert [v for i, v in enumerate(rows[str(odd)][:-1]) if i not in timed] == \
        [v for i, v in enumerate(analyze[1]) if i not in timed]
    assert rows[str(odd)][-1] == ""
    assert "broken, too.mesh" in rows[str(broken)][-1]
