"""The import operator's "Skip invalid cells" option (docs/check.md) on the hand-written file with
one defect of each class (tests/data/check/defects.HYBRID, its report derived in
tests/cpp/test_check.cpp): refused without it, naming the importer's own option (not the command
line's or Python's); imported with it, the five refused cells dropped and said in the report, and
read again the same way."""
import pathlib

import bpy
import pytest

DEFECTS = pathlib.Path(__file__).resolve().parents[2] / "data" / "check" / "defects.HYBRID"


def test_refused_without_the_option(clean_scene):
    """The refusal names the importer's own option, not the command line's or Python's."""
    with pytest.raises(RuntimeError, match='tick "Skip invalid cells" in the import options') as refused:
        bpy.ops.import_mesh.hbc(filepath=str(DEFECTS))
    assert "defects.HYBRID" in str(refused.value)
    assert "--skip-invalid" not in str(refused.value) and "skip_invalid=True" not in str(refused.value)


def test_imported_with_the_option(clean_scene):
    from hybrid_base_complex.blender import context as C
    from hybrid_base_complex.plan import session

    assert bpy.ops.import_mesh.hbc(filepath=str(DEFECTS), skip_invalid=True) == {"FINISHED"}
    (root,) = [c for c in bpy.data.collections if c.get("hbc_source") is not None]
    assert root["hbc_cells"] == 5 and root["hbc_skip_invalid"]
    s = session.get(root.name)
    assert session.dropped_text(s.mesh.dropped) == (
        "dropped 5 cells (1 few_faces, 1 degenerate_faces, 1 open_cells, 1 shared_faces, 1 duplicate_cells)")
    session.drop(root.name)  # as after reopening the .blend: read again from the file, skipping again
    assert C.structure_of(root, False, print).num_cells == 5
