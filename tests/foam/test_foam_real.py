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
