"""`hbc check`, hbc.check(), --skip-invalid / skip_invalid=True (docs/check.md) on the hand-written
file with one defect of each class (tests/data/check/defects.HYBRID; its report is derived in
tests/cpp/test_check.cpp): the binding's dicts equal the CLI's JSON key for key, and the exit
statuses are 0 clean, 1 defects, 2 unreadable."""

import json
import os
import pathlib
import subprocess

import pytest

import hbc

DEFECTS = pathlib.Path(__file__).resolve().parents[1] / "data" / "check" / "defects.HYBRID"
KEYS = ["bad_index", "degenerate_faces", "few_faces", "face_twice", "open_cells", "shared_faces", "not_simple",
        "inverted", "zero_volume", "duplicate_cells", "coincident_vertices", "unused_vertices", "disconnected_pieces"]


def cli(*args):
    return subprocess.run([os.environ["HBC_CLI"], *map(str, args)], capture_output=True, text=True)


def test_check_dict_is_the_cli_json():
    run = cli("check", DEFECTS, "--json")
    assert run.returncode == 1, run.stderr
    report = hbc.check(DEFECTS)
    assert report == json.loads(run.stdout)
    assert list(report["defects"]) == KEYS
    assert report["defects"]["few_faces"]["first"] == [{"id": 2, "line": 72}, {"id": 3, "line": 74}]
    assert report["defects"]["not_simple"]["count"] == 2
    assert not report["clean"]


def test_check_exit_statuses(tmp_path):
    clean = cli("check", DEFECTS.parent.parent / "formats" / "prism.mesh")
    assert clean.returncode == 0, clean.stdout + clean.stderr
    assert "no defects" in clean.stdout
    (tmp_path / "bad.HYBRID").write_text("4 4\n")
    assert cli("check", tmp_path / "bad.HYBRID").returncode == 2
    with pytest.raises(hbc.MeshFormatError):
        hbc.check(tmp_path / "bad.HYBRID")


def test_skip_invalid_drops_and_reports():
    with pytest.raises(hbc.MeshFormatError, match="skip_invalid"):
        hbc.load(DEFECTS)
    refused = cli("analyze", DEFECTS, "--json")
    assert refused.returncode == 2 and "--skip-invalid" in refused.stderr
    mesh = hbc.load(DEFECTS, skip_invalid=True)
    assert mesh.num_cells == 5
    run = cli("analyze", DEFECTS, "--skip-invalid", "--json", "--no-wireframe")
    assert run.returncode == 0, run.stderr
    assert "5 cell(s) dropped" in run.stderr
    dropped = json.loads(run.stdout)["dropped"]
    assert dropped == mesh.dropped
    assert dropped["by_reason"] == {"few_faces": 1, "degenerate_faces": 1, "open_cells": 1, "shared_faces": 1,
                                    "duplicate_cells": 1}
    assert [c["id"] for c in dropped["cells"]] == [2, 3, 4, 5, 6]
    assert hbc.load(DEFECTS.parent.parent / "formats" / "prism.mesh").dropped is None


# A unit cube, a flat cell of three faces that close (the quad 8 9 10 11 and the triangles 8 9 10,
# 8 10 11; line 25) and a cell of that quad alone (line 27): both have fewer than 4 faces, only the
# second is open, so --skip-invalid drops it alone (derived in tests/cpp/test_check.cpp, kFlatCell).
FLAT = ("12 9 9\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n5 0 0\n6 0 0\n6 1 0\n5 1 0\n"
        "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n4 8 9 10 11\n3 8 9 10\n3 8 10 11\n"
        "6 0 1 2 3 4 5\n6 0 0 0 0 0 0\n3 6 7 8\n3 0 0 0\n1 6\n1 0\n0\n0\n0\n")


@pytest.mark.parametrize("path", ["flat", DEFECTS])
def test_check_says_what_skip_invalid_drops(path, tmp_path):
    """`hbc check` and hbc.check() say exactly what the load with --skip-invalid drops: the same
    "dropped" object as `hbc analyze --skip-invalid --json` and Mesh.dropped, per class how many
    of its elements go, and in the text the load's own sentence."""
    if path == "flat":
        path = tmp_path / "flat.HYBRID"
        path.write_text(FLAT)
    run = cli("check", path, "--json")
    assert run.returncode == 1, run.stderr
    report = json.loads(run.stdout)
    assert hbc.check(path) == report
    loaded = hbc.load(path, skip_invalid=True)
    assert report["dropped"] == loaded.dropped
    analyzed = cli("analyze", path, "--skip-invalid", "--json", "--no-wireframe")
    assert report["dropped"] == json.loads(analyzed.stdout)["dropped"]
    assert report["cells"] - report["dropped"]["count"] == loaded.num_cells
    # A class is "refused" when the load drops every element of it.
    for key, cls in report["defects"].items():
        assert cls["refused"] == (key in ("bad_index", "degenerate_faces", "face_twice", "open_cells", "shared_faces"))
        if cls["refused"]:
            assert cls["dropped"] == cls["count"], key
    few = report["defects"]["few_faces"]
    text = cli("check", path).stdout
    warning = [ln for ln in analyzed.stderr.splitlines() if "cell(s) dropped" in ln][0]
    assert "with --skip-invalid: " + warning.split(": ", 3)[3] in text
    few_line = [ln for ln in text.splitlines() if ln.lstrip().startswith("few_faces")][0]
    if path.name == "flat.HYBRID":
        assert (few["count"], few["dropped"]) == (2, 1)
        assert report["dropped"]["by_reason"] == {"few_faces": 1}
        assert "[--skip-invalid drops 1 of them]" in few_line and "refused" not in few_line
    else:
        assert (few["count"], few["dropped"]) == (2, 2)
        assert "[refused; --skip-invalid drops them]" in few_line
