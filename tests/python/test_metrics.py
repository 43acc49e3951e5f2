"""Structural complexity metrics (docs/metrics.md): the CLI and Python agree, every metric is
defined in the doc, `hbc metrics` works on every shared mesh, and uniform refinement (every hex
into 8) leaves the invariant metrics equal and scales the others as their field says."""

import json
import math
import pathlib
import subprocess
import sys

import pytest

from conftest import MESHES

REPO = pathlib.Path(__file__).resolve().parents[2]
REFINE = REPO / "scripts" / "bench" / "refine_medit_hexes.py"
FACTOR = {"invariant": 1, "x8": 8, "x2": 2, "x4": 4}


def cli_metrics(hbc_cli, path):
    out = subprocess.run([hbc_cli, "metrics", str(path), "--json"], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


@pytest.mark.parametrize("name", MESHES)
def test_python_matches_cli(name, analyzed, hbc_cli, shared_data_dir):
    import hbc

    _, analysis = analyzed[name]
    from_cli = cli_metrics(hbc_cli, shared_data_dir / name)
    del from_cli["file"], from_cli["timings"]
    assert analysis.metrics() == from_cli
    assert analysis.metrics(threads=1) == from_cli  # the same for any thread count
    for f in hbc.METRIC_FIELDS:
        assert f.key in from_cli[f.group]


@pytest.mark.parametrize("name", MESHES)
def test_a_metric_is_a_field_whose_kind_fits_its_values(name, analyzed):
    """A metric is described as the statistics are (hbc.MetricField is an hbc.Field, with notation
    and kind), and its kind holds: a count or an id is a whole number wherever it is defined."""
    import hbc

    _, analysis = analyzed[name]
    metrics = analysis.metrics()
    for f in hbc.METRIC_FIELDS:
        assert isinstance(f, hbc.Field)
        assert f.kind in ("count", "ratio", "value")
        assert (f.kind == "ratio") == (f.unit == "ratio"), f.key
        v = metrics[f.group][f.key]
        if f.kind == "count" and v is not None and not math.isnan(v):
            assert v == int(v), f"{f.group}.{f.key} = {v}"


def test_every_metric_is_defined_in_the_doc():
    import hbc

    doc = (REPO / "docs" / "metrics.md").read_text()
    missing = [f"{f.group}.{f.key}" for f in hbc.METRIC_FIELDS if f"`{f.group}.{f.key}`" not in doc]
    missing += [k for k in hbc.SUMMARY_FIELDS if f"`{k}`" not in doc]
    assert not missing, f"docs/metrics.md does not define {missing}"


def test_metrics_on_every_shared_mesh(shared_mesh, hbc_cli):
    m = cli_metrics(hbc_cli, shared_mesh)
    c = m["census"]
    assert c["cells"] == c["hexahedra"] + c["prisms"] + c["pyramids"] + c["tetrahedra"] + c["polyhedra"]
    assert sum(m["census"]["polyhedra_by_faces"].values()) == c["polyhedra"]
    assert 0 <= c["hex_ratio"] <= 1 and 0 <= c["hex_volume_ratio"] <= 1 + 1e-12
    s = m["singular"]
    assert s["singularities"] == (s["singularities_closed"] + s["singularities_boundary_ends"]
                                  + s["singularities_interior_ends"])
    assert len(s["singularity_edges"]) == s["singularities"]
    # The deprecated keys (docs/concepts.md, retired words) beside the new ones, with their values.
    assert (s["curves"], s["nodes"], s["curve_edges"]) == (s["singularities"], s["singular_vertices"],
                                                           s["singularity_edges"])
    assert m["complex"]["cube_components"] == m["complex"]["hex_components"]
    assert sum(s["valence_interior"].values()) == s["edges_interior"]
    assert sum(s["valence_boundary"].values()) == s["edges_boundary"]
    x = m["complex"]
    assert x["components"] == x["blocks"] + x["non_hex_components"]
    assert sum(x["component_cells"]) + x["non_hex_components"] == c["cells"]
    n = m["non_hex"]
    assert n["cells"] == c["cells"] - c["hexahedra"] == sum(n["region_cells"])
    assert len(m["summary"]["vector"]) == len(m["summary"]["vector_keys"])
    assert m["summary"]["score"] >= 0


def refined_pair(hbc_cli, tmp_path, source):
    """(metrics of `source`, metrics of its uniform refinement), `source` an all-hex MEDIT file.
    The refinement script is imported, not run: inside Blender sys.executable is Blender."""
    sys.path.insert(0, str(REFINE.parent))
    try:
        import refine_medit_hexes as refine
    finally:
        sys.path.pop(0)
    fine = tmp_path / "fine.mesh"
    refine.write_medit_hexes(fine, *refine.refine(*refine.read_medit_hexes(source), 2))
    return cli_metrics(hbc_cli, source), cli_metrics(hbc_cli, fine)


def generated(hbc_cli, tmp_path, *args):
    out = tmp_path / "coarse.mesh"
    subprocess.run([hbc_cli, "generate", *args, "-o", str(out)], check=True, capture_output=True)
    return out


# Hex-only meshes: a valence-5 sector (one interior singular curve), a twisted ring with a
# quarter turn, and a real mesh with many components and curves.
CASES = {
    "sector": ["sector", "--valence", "5", "--rings", "2", "--layers", "3"],
    "twisted-ring": ["twisted-ring", "--section", "4", "--sections", "8", "--quarter-turns", "1"],
    "rockerarm": None,
}


@pytest.mark.parametrize("case", CASES)
def test_refinement_invariance(case, hbc_cli, tmp_path, shared_data_dir):
    import hbc

    source = shared_data_dir / "cinolib/rockerarm.mesh" if CASES[case] is None else generated(hbc_cli, tmp_path, *CASES[case])
    coarse, fine = refined_pair(hbc_cli, tmp_path, source)
    assert fine["census"]["cells"] == 8 * coarse["census"]["cells"]
    checked = 0
    for f in hbc.METRIC_FIELDS:
        if f.refinement == "none":
            continue
        a, b = coarse[f.group][f.key], fine[f.group][f.key]
        if a is None:
            assert b is None, f"{f.group}.{f.key}"
            continue
        assert math.isclose(b, FACTOR[f.refinement] * a, rel_tol=1e-9, abs_tol=1e-12), \
            f"{f.group}.{f.key}: {a} -> {b}, expected {f.refinement}"
        checked += 1
    assert checked > 40
    assert fine["summary"]["vector"] == pytest.approx(coarse["summary"]["vector"], rel=1e-9, abs=1e-12)


def test_doc_tables_are_current():
    """docs/metrics.md's tables are what scripts/metrics_doc.py writes from hbc.METRIC_FIELDS."""
    sys.path.insert(0, str(REPO / "scripts"))
    try:
        import metrics_doc
    finally:
        sys.path.pop(0)
    doc = (REPO / "docs" / "metrics.md").read_text()
    current = doc.split(metrics_doc.BEGIN, 1)[1].split(metrics_doc.END, 1)[0]
    assert current == "\n" + metrics_doc.table(), "run scripts/metrics_doc.py"


def test_without_quality(analyzed, hbc_cli, shared_data_dir):
    """--no-quality / quality=False: the quality group is null, every other value as with it."""
    import hbc

    name = MESHES[0]
    _, analysis = analyzed[name]
    out = subprocess.run([hbc_cli, "metrics", str(shared_data_dir / name), "--json", "--no-quality"],
                         capture_output=True, text=True, check=True)
    from_cli = json.loads(out.stdout)
    del from_cli["file"], from_cli["timings"]
    assert analysis.metrics(quality=False) == from_cli
    full = analysis.metrics()
    for f in hbc.METRIC_FIELDS:
        if f.group == "quality":
            assert from_cli["quality"][f.key] is None
        else:
            assert from_cli[f.group][f.key] == full[f.group][f.key], f"{f.group}.{f.key}"
