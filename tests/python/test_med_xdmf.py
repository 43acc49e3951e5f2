"""Salome MED and XDMF3 through the binding: hbc.FORMATS lists them, hbc.load reads meshio's twins
of tests/data/formats/real (make_med_files.py, make_xdmf_files.py) with the counts of their MEDIT
original, and a bad file raises MeshFormatError naming it."""

import pathlib

import pytest

import hbc

FORMATS = pathlib.Path(__file__).resolve().parents[1] / "data" / "formats"


def test_formats_lists_med_and_xdmf():
    assert {".med", ".xdmf"} <= {f["extension"] for f in hbc.FORMATS}
    assert [f["extensions"] for f in hbc.FORMATS if f["name"] == "xdmf"] == [[".xdmf", ".xmf"]]


@pytest.mark.parametrize("twin, original", [("real/slab_meshio.med", "real/slab.mesh"),
                                            ("real/mixed4_meshio.med", "mixed4.mesh"),
                                            ("real/mixed4_med_order.med", "mixed4.mesh"),
                                            ("real/slab_meshio.xdmf", "real/slab.mesh"),
                                            ("real/slab_series.xdmf", "real/slab.mesh"),
                                            ("real/mixed4_meshio.xdmf", "mixed4.mesh")])
def test_twin_reads_as_its_medit_original(twin, original):
    ref, mesh = hbc.load(str(FORMATS / original)), hbc.load(str(FORMATS / twin))
    assert (mesh.num_cells, mesh.num_faces, mesh.num_edges, mesh.num_vertices) == (
        ref.num_cells, ref.num_faces, ref.num_edges, ref.num_vertices)
    assert (mesh.cell_types == ref.cell_types).all()


@pytest.mark.parametrize("name", ["bad.med", "bad.xdmf"])
def test_bad_file_raises_mesh_format_error(tmp_path, name):
    path = tmp_path / name
    path.write_bytes(b"MeshVersionFormatted 2\n")
    with pytest.raises(hbc.MeshFormatError, match=name):
        hbc.load(str(path))
