"""Plain-pytest tests of the add-on's bpy-free planning (palette, opacity, CSR helpers, line and dot
containers, Table 1 row); the geometry of real meshes is in test_structure.py."""

import numpy as np
import pytest

from hybrid_base_complex.plan import planning as P


def test_package_imports_without_bpy():
    import hybrid_base_complex as addon

    assert addon.bl_info["blender"] == (3, 4, 0)
    assert addon.bpy is None


def test_palette_is_distinct_and_deterministic():
    assert len({tuple(np.round(c, 3)) for c in P.PALETTE}) == P.PALETTE_SIZE
    np.testing.assert_array_equal(P.palette_color([0, 1, P.PALETTE_SIZE]), P.PALETTE[[0, 1, 0]])
    assert tuple(P.palette_color([-1])[0]) == pytest.approx(P.NON_HEX_COLOR)


def test_component_colors_neighbours_differ_rings_darker_non_hex_grey():
    kinds = np.array([0, 0, 1, 3, 0], np.uint8)
    c = P.component_colors(kinds)
    assert c.shape == (5, 4)
    assert not np.allclose(c[0], c[1])
    assert tuple(c[3]) == pytest.approx(P.NON_HEX_COLOR)
    base = P.PALETTE[P.spread_ids([2])[0]]
    np.testing.assert_allclose(c[2, :3], base[:3] * P.RING_DARKEN)


def test_opacity_mapping():
    o = np.array([0.15, 0.5, 1.0], np.float32)
    a = P.opacity_alpha(o, 0.3)
    assert a[0] == pytest.approx(0.3) and a[-1] == pytest.approx(1.0)
    assert np.all(np.diff(a) > 0)
    np.testing.assert_array_equal(P.opacity_alpha(np.ones(3), 0.2), np.ones(3))
    assert P.opacity_alpha(np.zeros(0), 0.2).size == 0


def test_csr_helpers():
    off = np.array([0, 2, 2, 5])
    items = np.array([7, 8, 1, 2, 3])
    np.testing.assert_array_equal(P.csr_rows(off, items, [2, 0]), [1, 2, 3, 7, 8])
    np.testing.assert_array_equal(P.csr_rows(off, items, []), [])
    inv_off, rows = P.csr_invert(np.array([0, 2, 3]), np.array([0, 1, 1]), 3)
    np.testing.assert_array_equal(inv_off, [0, 1, 3, 3])
    np.testing.assert_array_equal(rows, [0, 0, 1])



def test_polylines_colors_alpha_keep():
    # Three polylines of 3, 2 and 3 points (positions as hbc.polylines gives them, one per entry).
    pts = np.arange(24, dtype=np.float32).reshape(8, 3)
    off = np.array([0, 3, 5, 8])
    cols = P.palette_color([0, 1, 2])
    lines = P.lines(pts, off, cols, alpha=np.linspace(0, 1, 8), keep=[True, False, True])
    assert len(lines.positions) == 6
    assert lines.edges.tolist() == [[0, 1], [1, 2], [3, 4], [4, 5]]
    assert lines.polyline.tolist() == [0, 0, 0, 1, 1, 1]
    np.testing.assert_allclose(lines.colors[3, :3], cols[2, :3])
    assert lines.colors[-1, 3] == pytest.approx(1.0)
    ring = P.lines(pts, off, closed=[True, False, False])
    assert ring.edges.tolist() == [[0, 1], [1, 2], [3, 4], [5, 6], [6, 7], [2, 0]]
    both = P.Lines.concat([lines, P.lines(pts[:2], [0, 2], (1, 0, 0, 1))])
    assert both.num_polylines == 3 and both.edges[-1].tolist() == [6, 7]


def test_soup_select():
    # Two unit squares (owners 0 and 1) with their own 4 points each; keeping owner 1 keeps its
    # 4 points, renumbered 0..3.
    pos = np.arange(24, dtype=np.float32).reshape(8, 3)
    soup = P.Soup(pos, np.array([4, 4], np.int32), np.arange(8, dtype=np.int32), np.array([0, 1], np.int32))
    part = soup.select(soup.face_owner == 1)
    assert part.num_faces == 1 and part.face_vertices.tolist() == [0, 1, 2, 3]
    np.testing.assert_array_equal(part.positions, pos[4:])
    assert P.Soup.empty().num_faces == 0


def test_dots():
    d = P.dots(np.zeros((3, 3)), 0.5, owner=[4, 5, 6])
    assert d.num_faces == 24 and len(d.positions) == 18
    assert set(d.face_owner) == {4, 5, 6}
    assert np.abs(d.positions).max() == pytest.approx(0.5)


def test_names_and_table_row():
    assert P.mesh_name_from_path("/x/cube_twist-comp.obj.HYBRID") == "cube_twist-comp.obj"
    assert P.mesh_name_from_path("teapot.hedra") == "teapot"
    # The Gmsh and VTK formats name their meshes the same way (an import of slab.msh is "slab").
    assert [P.mesh_name_from_path(f"/x/slab.{e}") for e in ("msh", "vtk", "vtu")] == ["slab"] * 3
    assert P.layer_collection_name("teapot", "components") == "teapot / Components"
    row = dict(P.table1_row({"cells": 10, "hex_ratio": 0.5, "components": 4, "hex_components": 3,
                             "sheets": -1, "timings": {"base_complex": 0.0123}}))
    assert row["|C|"] == "10" and row["|H|/|C|"] == "0.5000" and row["|H_B|/|C_B|"] == "0.7500"
    assert row["|G_SH|"] == "-" and row["T_GB"] == "12 ms" and row["T_GS"] == "-"
    # The columns are the library's (hbc.TABLE1_COLUMNS): the same heads as `hbc table`.
    assert list(row) == ["|C|", "|H|/|C|", "|C_B|", "|H_B|/|C_B|", "|G_SH|", "T1", "T2", "T3", "|G_SH*|",
                         "T_GS", "T_GB", "T_VSGW", "T_GSH", "T_GSH*"]


def test_progress_reports_fractions():
    seen = []
    p = P.Progress(2, lambda f, m: seen.append((f, m)))
    p.step("a")
    p.step("b")
    p.step("c")
    assert seen == [(0.5, "a"), (1.0, "b"), (1.0, "c")]


def test_legend_words_fit_beside_a_swatch():
    every = P.legend([k for k, _ in P.LAYERS], valences=[1, 2, 3, 4, 5, 6, 7], has_pseudo=True,
                     has_non_manifold=True, non_hex_types=[1, 2, 3, 4])
    assert all(key in P.LEGEND_COLORS for key, _ in every)
    assert max(len(words) for _, words in every) <= P.LEGEND_MAX
    # Valences without a colour of their own share the "other" colour.
    assert ("valence_other", "Valence 4 edge") in every and ("valence5", "Valence 5 edge") in every
    assert P.legend(["wireframe"]) == []


def test_table1_text_markdown_and_csv():
    stats = {"cells": 10, "hex_ratio": 0.5, "components": 4, "hex_components": 3}
    md = P.table1_text("a|b", stats).splitlines()
    # Header, rule and one row; '|' inside a cell is escaped.
    assert len(md) == 3 and md[0].startswith("| Mesh | \\|C\\| |") and md[1] == "|" + "---|" * 15
    assert md[2].startswith("| a\\|b | 10 | 0.5000 | 4 | 0.7500 | - |")
    csv = P.table1_text("x,y", stats, "CSV").splitlines()
    assert csv[0].split(",")[:3] == ["Mesh", "|C|", "|H|/|C|"] and csv[1].startswith('"x,y",10,0.5000,4,0.7500,-')
    assert all(P.table1_meaning(label) for label, _ in P.table1_row(stats))


def test_describe_error_and_subsheet_reason():
    assert P.describe_error(ValueError("f.mesh:3: expected x")) == "f.mesh:3: expected x"
    assert P.describe_error(FileNotFoundError(2, "No such file or directory", "/x.ovm")) == \
        "/x.ovm: No such file or directory"
    assert P.describe_error(RuntimeError()) == "unexpected failure (RuntimeError)"
    assert P.subsheets_unavailable(3) is None
    assert P.subsheets_unavailable(1).startswith("Sheet is type 1 (non-hex): only self-intersecting")
    assert P.subsheets_unavailable(None) == "Pick a sheet in the list first"


def test_refused_cell_names_the_importers_own_option():
    """The library's error about a refused cell (the real one, on the hand-written file with a
    defect of each class) names `--skip-invalid` and `skip_invalid=True`; the add-on says it with
    the importer's own *Skip invalid cells* option instead, the rest of the message unchanged."""
    import pathlib

    import hbc

    defects = pathlib.Path(__file__).resolve().parents[2] / "data" / "check" / "defects.HYBRID"
    with pytest.raises(hbc.MeshFormatError) as refused:
        hbc.load(str(defects))
    library = str(refused.value)
    assert "--skip-invalid" in library and "skip_invalid=True" in library  # what the CLI and Python say
    text = P.describe_error(refused.value)
    assert '"Skip invalid cells"' in text and "import options" in text, text
    assert "--skip-invalid" not in text and "skip_invalid" not in text, text
    assert text.split(" (`hbc check")[0] == library.split(" (`hbc check")[0]  # file, line and defect kept
    # A wording the add-on does not know still gets the remedy, after the library's.
    assert P.describe_error(ValueError("f:1: bad cell (use --skip-invalid)")).endswith(
        '(use --skip-invalid) (tick "Skip invalid cells" in the import options to load the other cells)')


def test_with_extension_follows_the_format():
    """The layer export's file name when its format changes: x.obj becomes x.ply, not x.obj.ply."""
    others = (".obj", ".ply")
    assert P.with_extension("/d/x.obj", ".ply", others) == "/d/x.ply"
    assert P.with_extension("/d/x.ply", ".obj", others) == "/d/x.obj"
    assert P.with_extension("/d/x.PLY", ".ply", others) == "/d/x.PLY"
    assert P.with_extension("/d/x", ".ply", others) == "/d/x.ply"
    assert P.with_extension("/d/x.v2", ".ply", others) == "/d/x.v2.ply"  # not a format's: kept
    assert P.with_extension("/d/x.obj", ".vtu") == "/d/x.obj.vtu"  # no other format: appended


def test_sheet_order_and_placement():
    types, cells = [3, 0, 2, 0], [5, 9, 9, 1]
    assert P.sheet_order(types, cells, "INDEX") == [0, 1, 2, 3]
    assert P.sheet_order(types, cells, "SIZE") == [1, 2, 0, 3]  # ties keep index order
    assert P.sheet_order(types, cells, "TYPE") == [1, 3, 2, 0]
    # A model spanning x in [-1, 1] beside one ending at x = 10: gap a quarter of its width (0.5).
    assert P.beside([((0, 0, 0), (10, 5, 5))], (-1, -1, -1), (1, 1, 1)) == (11.5, 0.0, 0.0)
    assert P.beside([], (0, 0, 0), (1, 1, 1)) == (0.0, 0.0, 0.0)


def test_subsheet_k_is_never_drawn_in_sheet_k_colour():
    # Sheet k is palette entry 7k mod 24 and subsheet k entry -7(k+1) mod 24: their sum 14k+7 is
    # odd, so the two never meet; neighbouring subsheets stay 7 entries apart, as sheets do.
    n = 3 * P.PALETTE_SIZE
    sheets, subsheets = P.sheet_colors(n), P.subsheet_colors(n)
    assert all(not np.array_equal(sheets[k], subsheets[k]) for k in range(n))
    assert all(not np.array_equal(subsheets[k], subsheets[k + 1]) for k in range(n - 1))
    assert np.array_equal(subsheets[0], P.PALETTE[P.PALETTE_SIZE - 7])
