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
