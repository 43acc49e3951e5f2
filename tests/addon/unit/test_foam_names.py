"""Mesh names of OpenFOAM cases: the .foam file's stem, or the case folder of a polyMesh/owner file."""

from hybrid_base_complex.plan import planning as P


def test_owner_file_names_its_case():
    assert P.mesh_name_from_path("/runs/flange/constant/polyMesh/owner") == "flange"
    assert P.mesh_name_from_path("/runs/flange/constant/polyMesh/owner.gz") == "flange"
    assert P.mesh_name_from_path("/elsewhere/owner") == "elsewhere"
    assert P.mesh_name_from_path("/runs/flange/flange.foam") == "flange"
