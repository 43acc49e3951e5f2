"""The non-hex kinds of the wireframe's chains (docs/concepts.md, "Non-hex kinds") through the
binding: numpy CSRs of kind codes per polyline of the complete and the simplified wireframe, the
same as the `non_hex` lists of `hbc wireframe --json`, named from hbc.CELL_TYPES."""

import json
import subprocess

import numpy as np

import hbc

from conftest import TABLE1


def rows(offsets, items):
    offsets = np.asarray(offsets)
    return [np.asarray(items)[offsets[i]:offsets[i + 1]].tolist() for i in range(len(offsets) - 1)]


def named(codes):
    return [{"type": hbc.CELL_TYPES[c >> 16], "faces": c & 0xFFFF} for c in codes]


def test_arrays_have_a_row_per_polyline(analyzed):
    # twistcube_s holds prisms, tets, a pyramid and polyhedra: its whole wireframe names some.
    _, a = analyzed[TABLE1 + "twistcube_s.mesh"]
    w = a.wireframe()
    assert w.non_hex_offsets.dtype == np.int32 and w.non_hex_items.dtype == np.int32
    assert len(w.non_hex_offsets) == w.count + 1 and w.non_hex_offsets[-1] == len(w.non_hex_items)
    assert len(w.simplified_non_hex_offsets) == len(w.simplified_polylines_offsets)
    assert len(w.non_hex_items) > 0
    types = w.non_hex_items >> 16
    assert set(types.tolist()) <= {1, 2, 3, 4}  # never hex
    for row in rows(w.non_hex_offsets, w.non_hex_items):
        assert row == sorted(set(row))


def test_same_as_the_cli(analyzed, hbc_cli, shared_data_dir):
    _, a = analyzed[TABLE1 + "cube_twist-comp.obj.HYBRID"]
    w = a.wireframe()
    path = shared_data_dir / TABLE1 / "cube_twist-comp.obj.HYBRID"
    out = json.loads(subprocess.run([hbc_cli, "wireframe", str(path), "--json"], capture_output=True, text=True,
                                    check=True).stdout)
    assert [e["non_hex"] for e in out["edges"]] == [named(r) for r in rows(w.non_hex_offsets, w.non_hex_items)]
    simplified = rows(w.simplified_non_hex_offsets, w.simplified_non_hex_items)
    assert [e["non_hex"] for e in out["simplified_polylines"]] == [named(r) for r in simplified]
    assert [e["vertices"] for e in out["simplified_polylines"]] == rows(w.simplified_polylines_offsets,
                                                                       w.simplified_polylines_items)


def test_all_hex_mesh_names_none(shared_data_dir):
    w = hbc.load(shared_data_dir / "openvolumemesh" / "Cylinder.ovm").analyze().wireframe()
    assert len(w.non_hex_items) == 0 and len(w.non_hex_offsets) == w.count + 1
