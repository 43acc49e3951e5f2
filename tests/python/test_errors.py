"""Bad input raises hbc.MeshFormatError (a ValueError) naming the file and the line, or the byte
offset for binary files. Bad files are small hand-written ones or shared meshes with one line
changed, written to a temporary folder."""

import re

import pytest

import hbc


def corrupt(src, dst, line, text):
    """dst = src with 1-based `line` replaced by `text`."""
    lines = src.read_text().splitlines()
    lines[line - 1] = text
    dst.write_text("\n".join(lines) + "\n")
    return dst


def expect_error(path, line, detail_pattern):
    with pytest.raises(hbc.MeshFormatError) as info:
        hbc.load(path)
    err = info.value
    assert isinstance(err, ValueError)
    assert str(err).startswith(f"{path}:{line}: ")
    assert err.file == str(path)
    assert err.line == line
    assert err.byte_offset is None
    assert re.search(detail_pattern, err.detail), err.detail
    assert str(err).endswith(err.detail)
    return err


MEDIT_BAD_INDEX = """MeshVersionFormatted 1
Dimension 3
Vertices
3
0 0 0 0
1 0 0 0
0 1 0 0
Hexahedra
1
1 2 3 9 1 2 3 4 0
End
"""


def test_medit_index_out_of_range(tmp_path):
    path = tmp_path / "bad_index.mesh"
    path.write_text(MEDIT_BAD_INDEX)
    expect_error(path, 10, r"vertex index .*found 9")


def test_medit_not_a_number(tmp_path):
    path = tmp_path / "bad_number.mesh"
    path.write_text(MEDIT_BAD_INDEX.replace("1 0 0 0", "1 zero 0 0"))
    expect_error(path, 6, r"zero")


def test_hybrid_bad_coordinate(tmp_path, shared_data_dir):
    src = shared_data_dir / "hybrid-base-complex" / "test_2.HYBRID"
    expect_error(corrupt(src, tmp_path / "bad.HYBRID", 4, "1.0 abc 0.0"), 4, r"abc")


def test_hedra_face_index_out_of_range(tmp_path, shared_data_dir):
    src = shared_data_dir / "hybrid-base-complex" / "teapot.hedra"
    # Line 2978 is the first face (1 header line + 2976 vertices).
    expect_error(corrupt(src, tmp_path / "bad.hedra", 2978, "4 1 2 3 99999"), 2978, r"99999")


def test_hedra_cell_listing_a_face_twice(tmp_path, shared_data_dir):
    # Found by the topology builder rather than the parser: the line of the cell is still named.
    src = shared_data_dir / "hybrid-base-complex" / "teapot.hedra"
    path = corrupt(src, tmp_path / "twice.hedra", 10702, "6 4648 4652 4656 7 1 1")
    expect_error(path, 10702, r"cell 0 lists the face .* twice")


def test_truncated_ovm_names_a_line(tmp_path, shared_data_dir):
    src = shared_data_dir / "openvolumemesh" / "Cylinder.ovm"
    path = tmp_path / "truncated.ovm"
    path.write_text("\n".join(src.read_text().splitlines()[:300]) + "\n")
    with pytest.raises(hbc.MeshFormatError) as info:
        hbc.load(path)
    assert info.value.line is not None and info.value.line >= 1
    assert str(info.value).startswith(f"{path}:{info.value.line}: ")


def test_truncated_ovmb_names_a_byte_offset(tmp_path, shared_data_dir):
    src = shared_data_dir / "openvolumemesh" / "Cylinder.ovmb"
    path = tmp_path / "truncated.ovmb"
    path.write_bytes(src.read_bytes()[:300])
    with pytest.raises(hbc.MeshFormatError) as info:
        hbc.load(path)
    err = info.value
    assert err.line is None
    assert 0 <= err.byte_offset <= 300
    assert str(err).startswith(f"{path}: byte {err.byte_offset}: ")


def test_missing_file(tmp_path):
    path = tmp_path / "absent.mesh"
    with pytest.raises(hbc.MeshFormatError, match=re.escape(str(path))) as info:
        hbc.load(path)
    assert info.value.line is None


def test_unknown_extension(tmp_path):
    path = tmp_path / "model.stl"
    path.write_text("solid x\n")
    with pytest.raises(ValueError, match=r"\.ovm, \.ovmb, \.mesh"):
        hbc.load(path)


def test_wrong_format_for_the_content(shared_data_dir):
    path = shared_data_dir / "hybrid-base-complex" / "teapot.hedra"
    with pytest.raises(hbc.MeshFormatError, match=re.escape(f"{path}:1: ")):
        hbc.load(path, format="mesh")


def test_non_utf8_token_reaches_python_as_mesh_format_error(tmp_path):
    # The reader quotes the rejected token (b"z\xff\xfe" is not UTF-8): the message must still
    # arrive whole, file and line included, with U+FFFD for each undecodable byte.
    path = tmp_path / "latin1.mesh"
    path.write_bytes(MEDIT_BAD_INDEX.replace("1 0 0 0", "1 z\udcff\udcfe 0 0").encode("utf-8", "surrogateescape"))
    err = expect_error(path, 6, "z\ufffd\ufffd")
    assert "\ufffd" in str(err)
