"""File > Import of an OpenFOAM case: its .foam marker file or its polyMesh owner file.

The two-hexahedra case of tests/data/formats/foam (counts in tests/cpp/test_foam.cpp).
"""

import pathlib

import pytest

bpy = pytest.importorskip("bpy")

CASES = pathlib.Path(__file__).resolve().parents[2] / "data" / "formats" / "foam"


def roots():
    return [c for c in bpy.context.scene.collection.children if "hbc_source" in c]


@pytest.mark.parametrize("rel", ["hex2_ascii/hex2_ascii.foam", "hex2_binary/constant/polyMesh/owner",
                                 "hex2_gzip/constant/polyMesh/owner.gz"])
def test_import_a_case(clean_scene, rel):
    from hybrid_base_complex.ui import operators

    assert "*.foam" in operators.FILTER.split(";") and "owner" in operators.FILTER.split(";")
    assert bpy.ops.import_mesh.hbc(filepath=str(CASES / rel)) == {"FINISHED"}
    (root,) = roots()
    assert root["hbc_cells"] == 2
    # Named after the case, not after its owner file.
    assert root.name == rel.split("/")[0]
