"""Decomposed OpenFOAM cases, split by OpenFOAM's own decomposePar, read without reconstructPar.

Two meshes: the snappyHexMesh flange (scripts/env/foam_cases.sh, the ctest fixture foam_cases) and
a graded blockMesh box made here. Each is split into 2 processors (method simple) and 3 (method
hierarchical; Debian's scotch is a stub), and `hbc` reads `CASE/processor*` (the processors joined
by decomposePar's addressing) against `CASE` (constant/polyMesh, the mesh decomposePar split):
analyze --json (timings aside), check --json and info --json equal, the Python arrays equal item
for item (the addressing gives back decomposePar's numbering), and OpenFOAM's checkMesh on the
undecomposed case counts the same points, faces and cells. A case holding only processor folders
is read decomposed by its folder; processors written in binary and gzip'd ASCII read the same.

Environment (set by ctest): PYTHONPATH holds the built package, HBC_CLI the `hbc` command.
Skipped, with the reason, only where Debian's OpenFOAM is not installed.
"""

import json
import os
import pathlib
import re
import shutil
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BASHRC = pathlib.Path("/usr/share/openfoam/etc/bashrc")
TUTORIAL = pathlib.Path("/usr/share/doc/openfoam-examples/examples/mesh/snappyHexMesh/flange")
pytestmark = pytest.mark.skipif(not BASHRC.exists(), reason="OpenFOAM is not installed (apt-get install openfoam)")

SPLITS = [(2, "simple", "(2 1 1)"), (3, "hierarchical", "(3 1 1)")]


def foam(case, command):
    """Runs an OpenFOAM tool in `case` (its environment sourced as ENVIRONMENT.md says); its output."""
    script = (f"set +eu; export WM_PROJECT_DIR=/usr/share/openfoam; source {BASHRC} >/dev/null 2>&1; "
              f"cd '{case}' && {command}")
    run = subprocess.run(["bash", "-c", script], capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    return run.stdout


def system_files(case):
    (case / "system").mkdir(parents=True, exist_ok=True)
    header = "FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n"
    (case / "system/controlDict").write_text(
        header % "controlDict" + "application none; startFrom startTime; startTime 0; stopAt endTime; endTime 0;"
        " deltaT 1; writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 10;"
        " writeCompression off; timeFormat general; timePrecision 6;\n")
    # checkMesh reads the schemes; the flange tutorial's serve any mesh.
    for name in ("fvSchemes", "fvSolution"):
        shutil.copy(TUTORIAL / "system" / name, case / "system" / name)


def split(case, n, method, counts):
    (case / "system/decomposeParDict").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
        f"numberOfSubdomains {n}; method {method}; coeffs {{ n {counts}; order xyz; }}\n")
    foam(case, "decomposePar -force")
    assert sorted(p.name for p in case.glob("processor*")) == [f"processor{i}" for i in range(n)]


@pytest.fixture(scope="module")
def flange():
    out = subprocess.run(["bash", str(ROOT / "scripts/env/foam_cases.sh")], check=True, capture_output=True, text=True)
    return pathlib.Path(out.stdout.strip().splitlines()[-1])


def copy_mesh(src, dst):
    system_files(dst)
    shutil.copytree(src / "constant/polyMesh", dst / "constant/polyMesh")
    return dst


def block_case(dst):
    """A graded 14 x 10 x 8 box of hexahedra (1120 cells) from blockMesh."""
    system_files(dst)
    (dst / "system/blockMeshDict").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }\n"
        "convertToMeters 1; vertices ((0 0 0) (3 0 0) (3 2 0) (0 2 0) (0 0 1.5) (3 0 1.5) (3 2 1.5) (0 2 1.5));\n"
        "blocks (hex (0 1 2 3 4 5 6 7) (14 10 8) simpleGrading (2 1 0.5)); edges ();\n"
        "boundary (walls { type wall; faces ((0 3 2 1) (4 5 6 7) (0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7)); });\n")
    foam(dst, "blockMesh")
    return dst


@pytest.fixture(scope="module", params=["flange", "block"])
def mesh_case(request, flange, tmp_path_factory):
    base = tmp_path_factory.mktemp(request.param)
    if request.param == "flange":
        return copy_mesh(flange / "ascii", base / "case")
    return block_case(base / "case")


def cli_json(command, path, drop=("file", "timings")):
    run = subprocess.run([os.environ["HBC_CLI"], command, "--json", str(path)], capture_output=True, text=True)
    assert run.returncode in (0, 1), run.stderr  # check: 1 when it finds defects
    out = json.loads(run.stdout)
    for key in drop:
        out.pop(key, None)
    return out, run.stderr


def checkmesh_counts(case):
    """points, faces, internal faces and cells as checkMesh prints them for the undecomposed mesh."""
    out = foam(case, "checkMesh -constant")
    counts = {}
    for key in ("points", "faces", "internal faces", "cells"):
        counts[key] = int(re.search(rf"^\s*{key}:\s+(\d+)", out, re.M).group(1))
    return counts


@pytest.mark.parametrize("n,method,counts", SPLITS)
def test_joined_processors_give_the_undecomposed_analysis(mesh_case, n, method, counts):
    split(mesh_case, n, method, counts)
    joined = f"{mesh_case}/processor*"
    for command in ("analyze", "check", "info"):
        whole, _ = cli_json(command, mesh_case)
        parts, err = cli_json(command, joined)
        assert parts == whole, command
        if command != "check":  # check lists defects, not the reading's warnings
            assert f"decomposed case: {n} processor folders joined" in err, err
    info, _ = cli_json("info", joined)
    foam_counts = checkmesh_counts(mesh_case)
    assert (info["vertices"], info["faces"], info["cells"]) == (foam_counts["points"], foam_counts["faces"], foam_counts["cells"])
    assert info["faces"] - info["boundary_faces"] == foam_counts["internal faces"]


@pytest.mark.parametrize("n,method,counts", SPLITS)
def test_python_arrays_equal_item_for_item(mesh_case, n, method, counts):
    import hbc

    split(mesh_case, n, method, counts)
    whole = hbc.load(str(mesh_case))
    joined = hbc.load(f"{mesh_case}/processor*", threads=2)
    assert any("decomposed case" in w for w in joined.warnings)
    for name in ("points64", "face_vertices_offsets", "face_vertices_items", "face_cells", "cell_faces_offsets",
                 "cell_faces_items", "cell_face_flip", "cell_types", "edges"):
        assert (getattr(joined, name) == getattr(whole, name)).all(), name


def test_a_case_of_processor_folders_only_is_read_by_its_folder(flange, tmp_path):
    case = copy_mesh(flange / "ascii", tmp_path / "case")
    split(case, 3, "hierarchical", "(3 1 1)")
    whole, _ = cli_json("analyze", case)
    shutil.rmtree(case / "constant/polyMesh")
    (case / "case.foam").touch()
    for path in (case, case / "case.foam"):
        joined, err = cli_json("analyze", path)
        assert joined == whole, path
        assert "decomposed case: 3 processor folders joined" in err
    assert whole["cells"] == 19314


def test_a_missing_processor_is_an_error_naming_it(tmp_path):
    case = block_case(tmp_path / "case")
    split(case, 3, "simple", "(3 1 1)")
    shutil.rmtree(case / "processor2")
    run = subprocess.run([os.environ["HBC_CLI"], "info", f"{case}/processor*"], capture_output=True, text=True)
    assert run.returncode == 2
    assert "processor1/constant/polyMesh/boundary:" in run.stderr and "processor2" in run.stderr, run.stderr
    import hbc

    with pytest.raises(hbc.MeshFormatError, match="expected the folder processor2 that patch procBoundary1to2 faces"):
        hbc.load(f"{case}/processor*")


@pytest.mark.parametrize("fmt,compression", [("binary", "off"), ("ascii", "on")])
def test_binary_and_gzip_processors(flange, tmp_path, fmt, compression):
    # decomposePar writes the processors in the controlDict's writeFormat and writeCompression.
    case = copy_mesh(flange / "ascii", tmp_path / "case")
    for key, value in (("writeFormat", fmt), ("writeCompression", compression)):
        foam(case, f"foamDictionary -entry {key} -set {value} system/controlDict >/dev/null")
    split(case, 2, "simple", "(2 1 1)")
    polymesh = case / "processor1/constant/polyMesh"
    assert (polymesh / "faces.gz").exists() == (compression == "on")
    whole, _ = cli_json("analyze", case)
    joined, err = cli_json("analyze", f"{case}/processor*")
    assert joined == whole and whole["cells"] == 19314
    assert "decomposed case: 2 processor folders joined" in err
