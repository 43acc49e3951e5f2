"""Exodus II and CGNS through the binding: hbc.FORMATS lists them, hbc.load reads the real-tool
twins of tests/data/formats/real (meshio's Exodus writer, CGNS's aflr3_to_cgns) with the counts of
their MEDIT original, and a bad file raises MeshFormatError naming it."""

import pathlib

import pytest

import hbc

REAL = pathlib.Path(__file__).resolve().parents[1] / "data" / "formats" / "real"


def test_formats_lists_every_extension():
    extensions = {f["extension"] for f in hbc.FORMATS}
    assert {".exo", ".e", ".g", ".cgns"} <= extensions


@pytest.mark.parametrize("twin", ["slab_hdf5.exo", "slab_cdf5.e", "slab.cgns", "slab_adf.cgns"])
def test_twin_reads_as_its_medit_original(twin):
    ref, mesh = hbc.load(str(REAL / "slab.mesh")), hbc.load(str(REAL / twin))
    assert (mesh.num_cells, mesh.num_faces, mesh.num_edges, mesh.num_vertices) == (
        ref.num_cells, ref.num_faces, ref.num_edges, ref.num_vertices)


@pytest.mark.parametrize("name", ["bad.exo", "bad.cgns"])
def test_bad_file_raises_mesh_format_error(tmp_path, name):
    path = tmp_path / name
    path.write_bytes(b"MeshVersionFormatted 2\n")
    with pytest.raises(hbc.MeshFormatError, match=name):
        hbc.load(str(path))
