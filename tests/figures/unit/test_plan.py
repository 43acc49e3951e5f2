"""Decisions of the figure script without Blender: arguments, sheet choice, tiles, camera, outlines."""

import numpy as np
import pytest

from hybrid_base_complex.figures import plan


def test_parse_defaults_and_panels():
    a = plan.parse(["m.mesh", "--out", "o"])
    assert a.mesh == "m.mesh" and a.out == "o" and a.engine == "cycles" and a.samples == 16
    assert tuple(a.resolution) == (640, 480) and a.panels == list(plan.PANEL_KEYS) and a.sheet is None
    a = plan.parse(["m.mesh", "--out", "o", "--panels", "sheet,mesh", "--engine", "workbench", "--sheet", "3",
                    "--resolution", "160", "120", "--samples", "4"])
    assert a.panels == ["mesh", "sheet"] and a.sheet == 3 and a.samples == 4 and a.engine == "workbench"


@pytest.mark.parametrize("argv", [
    ["--out", "o"],                                   # no mesh
    ["m.mesh", "--compare", "a", "b", "--out", "o"],  # both
    ["m.mesh"],                                       # no --out
    ["m.mesh", "--out", "o", "--panels", "nope"],
    ["m.mesh", "--out", "o", "--resolution", "8", "8"],
    ["m.mesh", "--out", "o", "--samples", "0"],
    ["m.mesh", "--out", "o", "--engine", "povray"],
])
def test_parse_refuses(argv, capsys):
    with pytest.raises(SystemExit) as e:
        plan.parse(argv)
    assert e.value.code == 2


def test_script_args():
    assert plan.script_args(["blender", "-b", "--python", "x.py", "--", "a", "--out", "o"]) == ["a", "--out", "o"]
    assert plan.script_args(["blender"]) == []
    # A Python with the bpy wheel runs the script directly: no separator, argv[0] is the script.
    assert plan.script_args(["blender_scripts/render_figures.py", "m.mesh", "--out", "o"]) == ["m.mesh", "--out", "o"]
    assert plan.script_args(["render_figures.py", "--", "m.mesh"]) == ["m.mesh"]


def test_pick_sheet_order_of_preference():
    # types: 0 perfect, 1, 2, 3 self-intersecting
    assert plan.pick_sheet([0, 3, 1, 3], [50, 10, 40, 20]) == 3      # largest self-intersecting
    assert plan.pick_sheet([0, 1, 2, 0], [90, 10, 40, 20]) == 2      # else largest imperfect
    assert plan.pick_sheet([0, 0, 0], [5, 9, 9]) == 1                # else largest, ties to the lower id
    assert plan.pick_sheet([], []) is None
    assert plan.pick_sheet([0, 3], [1, 1], requested=0) == 0
    with pytest.raises(ValueError, match="2 sheets"):
        plan.pick_sheet([0, 3], [1, 1], requested=2)


def test_pick_sheet_prefers_a_sheet_with_a_vsg_wireframe():
    asked = []

    def shows(has):
        def f(i):
            asked.append(i)
            return i in has
        return f

    # The largest self-intersecting sheet (0) has no VSG wireframe: the next largest that has one.
    assert plan.pick_sheet([3, 3, 3, 1], [240, 239, 239, 500], shows_vsg=shows({2})) == 2
    assert asked == [0, 1, 2]  # largest down, ties to the lower id, stops at the first that has one
    asked.clear()
    assert plan.pick_sheet([3, 0, 3], [10, 90, 20], shows_vsg=shows({0, 2})) == 2
    assert asked == [2]  # the largest has one: nothing else asked
    # None in the class has one: the largest of the class, never a sheet of a lower class.
    assert plan.pick_sheet([3, 1, 3], [10, 90, 20], shows_vsg=shows({1})) == 2
    # The class comes first: an imperfect sheet with a wireframe does not beat a self-intersecting one.
    assert plan.pick_sheet([1, 3], [90, 10], shows_vsg=shows({0})) == 1
    assert plan.pick_sheet([0, 2, 1], [9, 5, 7], shows_vsg=shows({1})) == 1
    # A requested sheet is never second-guessed.
    asked.clear()
    assert plan.pick_sheet([3, 3], [5, 9], requested=0, shows_vsg=shows(set())) == 0
    assert asked == []


def test_pick_subsheets_largest_in_id_order():
    assert plan.pick_subsheets([5, 50, 1, 30, 30], 3) == [1, 3, 4]
    assert plan.pick_subsheets([2], 4) == [0]


def test_tile_grid_fills_the_panel():
    (tw, th), cols = plan.tile_grid(3, 1292, 480)
    assert (tw, th) == (430, 240) and len(cols) == 3
    for (x, y), (x2, y2) in cols:
        assert x == x2 and y == 0 and y2 == th and 0 <= x and x + tw <= 1292


def test_view_direction_is_unit_and_up_aware():
    d = plan.view_direction(0, 0, "z")
    assert np.allclose(d, [1, 0, 0])
    d = plan.view_direction(0, 90, "y")
    assert np.allclose(d, [0, 1, 0])
    assert np.isclose(np.linalg.norm(plan.view_direction(-50, 25)), 1.0)


@pytest.mark.parametrize("size", [(640, 480), (160, 240), (300, 300)])
@pytest.mark.parametrize("az,el", [(-50, 25), (30, 60), (10, -20)])
def test_frame_holds_every_point_centred(size, az, el):
    rng = np.random.default_rng(1)
    pts = rng.normal(size=(500, 3)) * [3.0, 1.0, 0.5] + [10, -4, 2]
    cam = plan.frame(pts, plan.view_direction(az, el), "z", *size, margin=0.06)
    uv, depth = cam.project(pts)
    assert (depth > 0).all()
    assert np.abs(uv).max() <= 0.94 + 1e-6          # inside, with the margin
    assert np.abs(uv).max() >= 0.90                  # and tight on its tightest side
    # centred: the middle of the extreme points is the image's centre to within a pixel (uv spans
    # [-1, 1] over the image, so a pixel is 2 / size in uv)
    for axis in (0, 1):
        middle = (uv[:, axis].max() + uv[:, axis].min()) / 2
        assert abs(middle) < 2.0 / size[axis], (axis, middle * size[axis] / 2)
    near, far = plan.clip_range(cam, pts)
    assert 0 < near < depth.min() and far > depth.max()


def test_framing_points_keeps_extent():
    pts = np.random.default_rng(2).random((1000, 3))
    sub = plan.framing_points(pts, limit=100)
    assert len(sub) < 200
    assert np.allclose(sub.min(axis=0), pts.min(axis=0)) and np.allclose(sub.max(axis=0), pts.max(axis=0))


def _cube_soup():
    pos = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], np.float32)
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return pos, np.full(6, 4, np.int32), np.array(quads, np.int32).ravel()


def test_feature_edges_of_a_cube_and_a_flat_patch():
    pos, sizes, fv = _cube_soup()
    e = plan.feature_edges(pos, sizes, fv)
    assert len(e) == 12
    # A flat 2x1 patch: its 6 border edges, not the shared middle one.
    pos = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], np.float32)
    e = plan.feature_edges(pos, [4, 4], [0, 1, 4, 3, 1, 2, 5, 4])
    assert len(e) == 6 and [1, 4] not in e.tolist()
    assert len(plan.all_edges([4, 4], [0, 1, 4, 3, 1, 2, 5, 4])) == 7
    assert plan.feature_edges(np.zeros((0, 3)), [], []).shape == (0, 2)


def test_inspect_panels_only_when_asked():
    """cut and quality are not in the default set; asked for, they come after the pipeline panels."""
    assert "cut" not in plan.parse(["m.mesh", "--out", "o"]).panels
    a = plan.parse(["m.mesh", "--out", "o", "--panels", "quality,complex,cut", "--cut-plane", "1", "2", "3", "0", "0", "2"])
    assert a.panels == ["complex", "cut", "quality"] and a.cut_plane == [1, 2, 3, 0, 0, 2]
    assert (plan.PANEL_LETTER["cut"], plan.PANEL_LETTER["quality"]) == ("h", "i")
    with pytest.raises(SystemExit):
        plan.parse(["m.mesh", "--out", "o", "--cut-plane", "0", "0", "0", "0", "0", "0"])


def test_cut_plane():
    """Default: through the bounding-box centre, normal = the (normalised) view direction; else as given."""
    pts = np.array([[0, 0, 0], [2, 4, 6], [1, 1, 1]], float)
    p, n = plan.cut_plane(pts, (0, 0, 3))
    assert np.allclose(p, (1, 2, 3)) and np.allclose(n, (0, 0, 1))
    p, n = plan.cut_plane(pts, (0, 0, 3), [5, 5, 5, 3, 0, 4])
    assert np.allclose(p, (5, 5, 5)) and np.allclose(n, (0.6, 0, 0.8))


# ---------------------------------------------------------------------------------------------
# Legend strip (--legend)

FACTS = {"non_hex_types": [2, 3], "valences": [3, 5, 7], "has_pseudo": True, "has_non_manifold": False,
         "has_non_hex_blocks": True}


def test_legend_option():
    assert plan.parse(["m.mesh", "--out", "o"]).legend is False
    assert plan.parse(["m.mesh", "--out", "o", "--legend"]).legend is True


def test_panel_legends_are_the_addons_words_and_colours():
    """Each panel's strip lists what the add-on's Legend panel lists for the layers the panel
    shows, in the add-on's words and with its colours (the very values of planning.LEGEND_COLORS)."""
    from hybrid_base_complex.plan import planning as P

    def legend(key, highlights=()):
        entries = plan.panel_legend(P, key, FACTS, highlights)
        for k, words, color in entries:
            assert color == tuple(float(c) for c in P.LEGEND_COLORS[k])
        return [(k, words) for k, words, _ in entries]

    assert legend("mesh") == [("hex", "Boundary, hex cells"), ("prism", "Prism cells"), ("pyramid", "Pyramid cells")]
    assert legend("graph") == [("valence3", "Valence 3 edge"), ("valence5", "Valence 5 edge"),
                               ("valence_other", "Valence 7 edge"), ("pseudo", "Pseudo-singular")]
    assert legend("complex") == legend("cut") == [("non_hex_component", "Non-hex component")]
    # Only the highlights the panel draws, in the add-on's order.
    assert legend("sheet", {"self_intersecting", "unmatched"}) == [
        ("unmatched", "Dot: unmatched"), ("self_intersecting", "Self-intersecting")]
    assert legend("subsheets", {"unmatched"}) == [("unmatched", "Dot: unmatched")]
    assert legend("sheet") == []  # a sheet without highlights: nothing to name
    # Palette-only panels (a colour per chain) and the quality panel have no strip.
    for key in ("vsg", "wireframe", "mesh_wireframe", "quality"):
        assert legend(key, {"unmatched"}) == []
    # Every panel of the script is covered.
    assert set(plan.LEGEND_LAYERS) == set(plan.ALL_PANEL_KEYS) | {k for k, _ in plan.COMPARE_ROWS}
    # A mesh without non-hex components has no "Non-hex component" entry.
    assert plan.panel_legend(P, "complex", dict(FACTS, has_non_hex_blocks=False)) == []


@pytest.mark.parametrize("width", [160, 320, 640, 1292])
def test_legend_layout_aligns_swatches_in_columns(width):
    m = plan.LegendMetrics.for_panel(480)
    words = [88, 140, 61, 120, 97, 150, 75]
    layout = plan.legend_layout(words, width, m)
    n = len(words)
    assert layout.columns >= 1 and layout.rows == -(-n // layout.columns)
    cell = m.swatch + m.gap + max(words)
    xs = {}
    for i, ((x, y, side), (wx, wy)) in enumerate(zip(layout.swatches, layout.words)):
        r, c = divmod(i, layout.columns)
        xs.setdefault(c, set()).add(x)
        assert side == m.swatch and wx == x + m.swatch + m.gap
        assert wy == m.margin + r * m.row and y == wy + (m.row - m.swatch) // 2  # swatch centred on its row
        assert y >= 0 and y + side <= plan.strip_height(m, layout.rows)
    assert all(len(v) == 1 for v in xs.values())  # one x per column: swatches line up
    lefts = sorted(x.pop() for x in xs.values())
    assert all(b - a == cell + m.column_gap for a, b in zip(lefts, lefts[1:]))
    block = layout.columns * cell + (layout.columns - 1) * m.column_gap
    if layout.columns > 1 or block <= width - 2 * m.margin:
        assert lefts[0] + block <= width - m.margin  # inside the strip
        assert abs(lefts[0] - (width - lefts[0] - block)) <= 1  # centred
    # As many columns as fit: one more would not.
    if layout.columns < n:
        assert (layout.columns + 1) * cell + layout.columns * m.column_gap > width - 2 * m.margin


def test_legend_layout_centres_fewer_rows_in_a_shared_strip():
    m = plan.LegendMetrics.for_panel(480)
    one = plan.legend_layout([100], 640, m, strip_rows=3)
    assert one.rows == 1 and one.words[0][1] == m.margin + m.row  # the middle row of three
    assert plan.strip_height(m, 3) == 2 * m.margin + 3 * m.row and plan.strip_height(m, 0) == 0
    assert plan.legend_layout([], 640, m).rows == 0
    # An entry wider than the strip starts at the margin.
    wide = plan.legend_layout([900], 320, m)
    assert wide.columns == 1 and wide.swatches[0][0] == m.margin
