"""Real snappyHexMesh output read straight from its case folder.

The flange tutorial of Debian's openfoam-examples, meshed by scripts/env/foam_cases.sh (the ctest
fixture foam_cases makes it once into ~/.cache/hbc-envs/foam-flange) and written three ways by
OpenFOAM itself: ASCII, binary, and gzip-compressed ASCII. Each must give the same analysis as
foamToVTK -poly's internal.vtu of the same mesh, read by hbc's VTU reader (a reading that shares
nothing with the polyMesh reader), in the CLI and in Python.

Environment (set by ctest): PYTHONPATH holds the built package, HBC_CLI the `hbc` command.
"""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def flange():
    # Made by the ctest fixture; a second call only prints the folder.
    out = subprocess.run(["bash", str(ROOT / "scripts/env/foam_cases.sh")], check=True, capture_output=True, text=True)
    return pathlib.Path(out.stdout.strip().splitlines()[-1])


def cli_stats(path):
    out = subprocess.run([os.environ["HBC_CLI"], "analyze", "--json", str(path)], check=True, capture_output=True, text=True)
    stats = json.loads(out.stdout)
    for key in ("file", "timings"):
        stats.pop(key)
    return stats


def test_every_writing_gives_the_vtu_analysis(flange):
    expected = cli_stats(flange / "ascii/VTK/ascii_0/internal.vtu")
    # The tutorial's mesh as Debian's OpenFOAM v1912 makes it (docs: ENVIRONMENT notes).
    assert expected["cells"] == 19314
    assert expected["hex_components"] == 15678
    for path in (flange / "ascii", flange / "binary/binary.foam", flange / "gzip/constant/polyMesh/owner.gz",
                 flange / "ascii/constant/polyMesh"):
        assert cli_stats(path) == expected, path


def test_python_reads_the_case(flange):
    import hbc

    mesh = hbc.load(str(flange / "binary"))
    vtu = hbc.load(str(flange / "ascii/VTK/ascii_0/internal.vtu"))
    assert mesh.num_cells == vtu.num_cells == 19314
    assert (mesh.cell_types == vtu.cell_types).all()
    stats = mesh.analyze().stats
    expected = cli_stats(flange / "ascii/VTK/ascii_0/internal.vtu")
    for key, value in expected.items():
        assert stats[key] == value, key
    assert any(f["name"] == "foam" and f["extension"] == ".foam" for f in hbc.FORMATS)


def test_python_names_a_folder_that_is_no_case(tmp_path):
    import hbc

    with pytest.raises(hbc.MeshFormatError, match="OpenFOAM case"):
        hbc.load(str(tmp_path))


def cli_metrics(path):
    out = subprocess.run([os.environ["HBC_CLI"], "metrics", "--json", str(path)], check=True, capture_output=True,
                         text=True)
    metrics = json.loads(out.stdout)
    for key in ("file", "timings"):
        metrics.pop(key)
    return metrics


def near(a, b):
    """Equal counts; lengths, volumes and qualities equal to 1e-4 (the VTU's points are single
    precision, and the volumes of snappyHexMesh's thin cut cells lose more digits than the points:
    the hex volume share differs by 5e-5); lists of values as multisets (a list ordered by a
    measured length may order ties differently)."""
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(near(a[k], b[k]) for k in a)
    if isinstance(a, list):
        if len(a) != len(b):
            return False
        if all(isinstance(x, (int, float)) for x in a + b):
            a, b = sorted(a), sorted(b)
        return all(near(x, y) for x, y in zip(a, b))
    if isinstance(a, float) or isinstance(b, float):
        return a == pytest.approx(b, rel=1e-4, abs=1e-7)
    return a == b


def test_metrics_of_the_case_equal_those_of_its_vtu(flange):
    # The structural metrics depend on the mesh's connectivity, not on the reader that built it;
    # foamToVTK writes the points in single precision, so what is measured on the geometry
    # (lengths, volumes, scaled Jacobians) agrees to that precision.
    metrics = cli_metrics(flange / "binary")
    vtu = cli_metrics(flange / "ascii/VTK/ascii_0/internal.vtu")
    for group in metrics:
        assert near(metrics[group], vtu[group]), group
    census = metrics["census"]
    assert census["cells"] == 19314
    # snappyHexMesh's cut cells near the flange's surface: non-hex cells in clusters.
    assert 0 < census["hex_ratio"] < 1 and metrics["non_hex"]["regions"] > 0


def test_compare_with_three_other_meshers(flange, tmp_path):
    # snappyHexMesh beside RHDM, LoopyCuts and At-Most-Hexa output (the shared data's SOURCES.md):
    # every column measured, none failing, the case given by its folder.
    data = pathlib.Path(os.environ.get("HBC_DATA_DIR", ROOT.parent / "shared/data")) / "hybrid-base-complex"
    files = [flange / "binary", data / "cube_twist-comp.obj.HYBRID", data / "teapot.hedra", data / "twistcube_s.mesh"]
    out = tmp_path / "out"
    run = subprocess.run([os.environ["HBC_CLI"], "compare", *map(str, files), "-o", str(out), "--no-report"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    result = json.loads((out / "metrics.json").read_text())
    assert not result.get("errors"), result.get("errors")
    assert len(result["meshes"]) == 4
    assert (out / "metrics.csv").read_text().count("\n") == 5  # header + 4 rows
