"""hbc.cell_quality / hbc.cell_depth and `hbc quality --json`: known answers on generated grids, and on
the armadillo a cross-check against Verdict's hex formula computed here with numpy straight from the
MEDIT file's hexahedra in the file's corner order (independent of the library's face-based frames)."""

import json
import subprocess

import numpy as np

import hbc

ARMADILLO = ("hexalab-edge-cone-rectification", "armadillo_out.mesh")

# Verdict's hex corners (V_HexMetric.cpp, hex_scaled_jacobian): corner, then its three edge ends.
VERDICT_CORNERS = np.array([(0, 1, 3, 4), (1, 2, 0, 5), (2, 3, 1, 6), (3, 0, 2, 7),
                            (4, 7, 5, 0), (5, 4, 6, 1), (6, 5, 7, 2), (7, 6, 4, 3)])
HEX_EDGES = np.array([(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
                      (0, 4), (1, 5), (2, 6), (3, 7)])


def generate(hbc_cli, tmp_path, *args):
    out = tmp_path / "generated.ovm"
    subprocess.run([hbc_cli, "generate", *args, "-o", str(out)], check=True, capture_output=True)
    return out


def read_medit_hexes(path):
    """(points (nv, 3), hexes (nc, 8) 0-based) of a MEDIT file holding only hexahedra."""
    tokens = path.read_text().split()
    sections = {}
    i = 0
    while i < len(tokens):
        word = tokens[i]
        if word in ("Vertices", "Quadrilaterals", "Hexahedra", "Triangles", "Edges"):
            n = int(tokens[i + 1])
            width = {"Vertices": 4, "Quadrilaterals": 5, "Hexahedra": 9, "Triangles": 4, "Edges": 3}[word]
            sections[word] = np.array(tokens[i + 2:i + 2 + n * width], dtype=float).reshape(n, width)
            i += 2 + n * width
        elif word in ("MeshVersionFormatted", "Dimension"):
            i += 2
        else:
            assert word not in ("Tetrahedra", "Prisms", "Pyramids"), "a hex-only file was expected"
            i += 1
    return sections["Vertices"][:, :3], sections["Hexahedra"][:, :8].astype(np.int64) - 1


def normalised_det(a, b, c):
    det = np.einsum("ij,ij->i", a, np.cross(b, c))
    return det / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1) * np.linalg.norm(c, axis=1))


def verdict_hex_scaled_jacobian(x):
    """x: (nc, 8, 3) in Verdict's (= MEDIT's) order. The minimum over the 8 corners and the centre."""
    values = [normalised_det(x[:, a] - x[:, v], x[:, b] - x[:, v], x[:, c] - x[:, v])
              for v, a, b, c in VERDICT_CORNERS]
    x1 = (x[:, 1] - x[:, 0]) + (x[:, 2] - x[:, 3]) + (x[:, 5] - x[:, 4]) + (x[:, 6] - x[:, 7])
    x2 = (x[:, 3] - x[:, 0]) + (x[:, 2] - x[:, 1]) + (x[:, 7] - x[:, 4]) + (x[:, 6] - x[:, 5])
    x3 = (x[:, 4] - x[:, 0]) + (x[:, 5] - x[:, 1]) + (x[:, 6] - x[:, 2]) + (x[:, 7] - x[:, 3])
    values.append(normalised_det(x1, x2, x3))
    return np.min(values, axis=0)


def test_grid_is_one_everywhere_and_peels_by_layers(hbc_cli, tmp_path):
    # 10³ cells of side 0.5: every corner and centre frame orthogonal (1.0), all edges equal (1.0).
    # Depth d = min over the indices of min(i, 9 - i): (10-2d)³ - (8-2d)³ cells, 488 296 152 56 8.
    m = hbc.load(generate(hbc_cli, tmp_path, "grid", "--size", "10", "10", "10", "--spacing", "0.5"))
    q = hbc.cell_quality(m)
    assert q["scaled_jacobian"].dtype == np.float64 and q["scaled_jacobian"].shape == (1000,)
    np.testing.assert_allclose(q["scaled_jacobian"], 1.0, atol=1e-12)
    np.testing.assert_allclose(q["edge_ratio"], 1.0, atol=1e-12)
    depth = hbc.cell_depth(m)
    assert depth.dtype == np.int32 and depth.shape == (1000,)
    assert np.bincount(depth).tolist() == [488, 296, 152, 56, 8]
    assert int((depth >= 1).sum()) == 8 * 8 * 8


def test_armadillo_matches_an_independent_verdict(shared_data_dir):
    path = shared_data_dir.joinpath(*ARMADILLO)
    points, hexes = read_medit_hexes(path)
    x = points[hexes]
    ref = verdict_hex_scaled_jacobian(x)
    # The file uses MEDIT's (= Verdict's) positive orientation; build_mesh orients each connected
    # group to positive volume, which agrees: most cells positive in the file's order.
    assert (ref > 0).mean() > 0.99
    edge = np.linalg.norm(x[:, HEX_EDGES[:, 1]] - x[:, HEX_EDGES[:, 0]], axis=2)
    ref_ratio = edge.max(axis=1) / edge.min(axis=1)

    m = hbc.load(path)
    assert m.num_cells == len(hexes)
    q = hbc.cell_quality(m)
    sj = q["scaled_jacobian"]
    assert abs(sj.min() - ref.min()) < 1e-12
    assert abs(sj.mean() - ref.mean()) < 1e-12
    # Cells keep the file's order, so the values agree cell by cell too.
    np.testing.assert_allclose(sj, ref, atol=1e-12)
    np.testing.assert_allclose(q["edge_ratio"], ref_ratio, rtol=1e-12)


def test_cli_json_matches_the_arrays(hbc_cli, shared_data_dir):
    path = shared_data_dir.joinpath(*ARMADILLO)
    out = subprocess.run([hbc_cli, "quality", str(path), "--json"], check=True, capture_output=True, text=True)
    doc = json.loads(out.stdout)
    q = hbc.cell_quality(hbc.load(path))
    sj, er = q["scaled_jacobian"], q["edge_ratio"]
    assert doc["cells"] == len(sj)
    assert doc["inverted"] == int((sj < 0).sum()) == doc["scaled_jacobian"]["inverted"]
    for key, values in (("scaled_jacobian", sj), ("edge_ratio", er)):
        d = doc[key]
        assert d["count"] == len(values)
        assert abs(d["min"] - values.min()) < 1e-8
        assert abs(d["mean"] - values.mean()) < 1e-8
        assert abs(d["max"] - values.max()) < 1e-8
        edges = np.array(d["bin_edges"])
        assert len(d["histogram"]) == len(edges) - 1
        # The library's bins: [e_i, e_{i+1}), the end bins also holding what lies beyond.
        bins = np.clip(np.searchsorted(edges, values, side="right") - 1, 0, len(edges) - 2)
        assert d["histogram"] == np.bincount(bins, minlength=len(edges) - 1).tolist()
        assert d["per_type"]["hex"]["count"] == len(values)
        assert d["per_type"]["tet"]["count"] == 0 and d["per_type"]["tet"]["min"] is None


def test_cli_json_per_type_on_a_split_grid(hbc_cli, tmp_path):
    # The centre cell of a 3³ grid split into 6 pyramids of apex height 1/2 over a unit square:
    # each sqrt(2/3) (cell_quality.hpp); the 26 hexes stay 1.
    path = generate(hbc_cli, tmp_path, "split", "--size", "3", "3", "3", "--split", "pyramids", "--cells", "1,1,1")
    out = subprocess.run([hbc_cli, "quality", str(path), "--json"], check=True, capture_output=True, text=True)
    doc = json.loads(out.stdout)
    per = doc["scaled_jacobian"]["per_type"]
    assert per["pyramid"]["count"] == 6 and per["hex"]["count"] == 26
    assert abs(per["pyramid"]["min"] - np.sqrt(2 / 3)) < 1e-8
    assert abs(per["pyramid"]["max"] - np.sqrt(2 / 3)) < 1e-8
    assert abs(per["hex"]["min"] - 1.0) < 1e-8
    assert doc["inverted"] == 0


def test_quality_releases_the_gil(hbc_cli, tmp_path, main_thread_share, held_gil_share):
    m = hbc.load(generate(hbc_cli, tmp_path, "grid", "--size", "60", "60", "60"))

    def work():
        hbc.cell_quality(m)
        hbc.cell_depth(m)

    share, elapsed = main_thread_share(work)
    assert elapsed > 0.1, "the calls were too quick to tell"
    assert share > 0.15 or share > 3 * held_gil_share, (share, held_gil_share, elapsed)
