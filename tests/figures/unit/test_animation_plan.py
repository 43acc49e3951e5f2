"""Decisions of the animations without Blender: options, turntable cameras, explode offsets and keys,
sheet choice and segments, the slice plane's path, the GIF command."""

import numpy as np
import pytest

from hybrid_base_complex.figures import animation_plan as AP
from hybrid_base_complex.figures import plan


def parse(*extra):
    return plan.parse(["m.mesh", "--out", "o", *map(str, extra)], (AP,))


def test_animate_options():
    a = parse("--animate", "slice,turntable", "--engine", "workbench", "--frames", 12, "--fps", 24,
              "--sheets", "4", "--look", "slide")
    assert a.animate == ["turntable", "slice"]  # the kinds' own order
    assert a.frames == 12 and a.fps == 24 and a.format == "mp4" and a.look == "slide"
    assert a.layers == ["complex"] and a.sheets == ("largest", 4)
    a = parse("--animate", "sheets", "--sheets", "3,1,3", "--layers", "mesh,graph")
    assert a.sheets == ("list", [3, 1, 3]) and a.layers == ["mesh", "graph"]
    assert parse().animate is None and parse().look == "paper"


@pytest.mark.parametrize("extra", [
    ("--animate", "spin"), ("--animate", ""), ("--animate", "explode", "--frames", 1),
    ("--animate", "explode", "--resolution", 161, 120), ("--animate", "turntable", "--layers", "sheet"),
    ("--animate", "sheets", "--sheets", "0"), ("--animate", "sheets", "--sheets", "a,b"), ("--look", "neon"),
])
def test_animate_refuses(extra):
    with pytest.raises(SystemExit) as e:
        parse(*extra)
    assert e.value.code == 2


def test_gif_and_odd_sides_are_allowed():
    assert parse("--animate", "explode", "--format", "gif", "--resolution", 161, 121).format == "gif"


def test_output_names():
    assert AP.output_name("teapot", "explode", "mp4") == "teapot_explode.mp4"
    assert AP.output_name("teapot", "sheets", "png") == "teapot_sheets"


def test_orbit_keeps_distance_and_turns_once():
    rng = np.random.default_rng(1)
    pts = rng.normal(size=(500, 3)) * [3.0, 1.0, 0.5]
    args = parse("--animate", "turntable", "--resolution", 320, 180)
    cams = AP.orbit_cameras(pts, args, 24)
    center = (pts.min(axis=0) + pts.max(axis=0)) / 2.0
    dist = [c.matrix[:, 2] @ (c.location - center) for c in cams]
    assert np.ptp(dist) < 1e-9  # the same distance: no zooming in and out
    for c in cams:  # every frame holds the whole mesh
        uv, depth = c.project(pts)
        assert (depth > 0).all() and np.abs(uv).max() <= 1.0
    # The first is the stills' view; the view directions turn once around z.
    first = plan.view_direction(args.azimuth, args.elevation, "z")
    assert np.allclose(cams[0].matrix[:, 2], first)
    az = np.unwrap([np.arctan2(c.matrix[1, 2], c.matrix[0, 2]) for c in cams])
    assert np.all(np.diff(az) > 0) and az[-1] - az[0] == pytest.approx(2 * np.pi * 23 / 24)


def test_explode_moves_along_centre_to_centroid_and_back():
    # Two unit quads, owners 0 and 1, either side of the origin; a third at the centre.
    pos = np.array([[x + dx, y, 0.0] for dx in (-3.0, 3.0, 0.0) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))])
    pos -= [0.5, 0.5, 0.0]
    cen, owner = AP.owner_centroids(pos, [4, 4, 4], np.arange(12), [0, 1, 2], 3)
    assert np.allclose(cen, [[-3, 0, 0], [3, 0, 0], [0, 0, 0]]) and list(owner) == [0] * 4 + [1] * 4 + [2] * 4
    off = AP.explode_offsets(cen, [0, 0, 0], 0.5)
    assert np.allclose(off, [[-1.5, 0, 0], [1.5, 0, 0], [0, 0, 0]])  # scaled by distance; the centre stays
    keys = AP.explode_keys(9)
    assert keys == [(1, 0.0), (5, 1.0), (9, 0.0)]
    cam = plan.frame(np.concatenate([pos, pos + 1.5 * np.sign(pos[:, :1]) * [1, 0, 0]]), [0, -1, 1])
    sep = [AP.screen_separation(cam, cen, off, AP.weight_at(keys, f)) for f in range(1, 10)]
    assert all(b > a for a, b in zip(sep[:4], sep[1:5])) and all(b < a for a, b in zip(sep[4:], sep[5:]))
    assert AP.apart_keys(9)[-1] == (9, 1.0)


def test_pick_sheets_and_segments():
    cells = [5, 9, 9, 1]
    assert AP.pick_sheets(cells) == [1, 2, 0, 3]
    assert AP.pick_sheets(cells, ("largest", 2)) == [1, 2]
    assert AP.pick_sheets(cells, ("list", [3, 0, 3])) == [3, 0]
    with pytest.raises(ValueError, match="4 sheets"):
        AP.pick_sheets(cells, ("list", [4]))
    assert AP.segments(3, 10) == [(1, 4), (5, 7), (8, 10)]
    with pytest.raises(ValueError):
        AP.segments(5, 4)
    assert AP.intersecting_sheet([0, 3, 3, 1], [1, 2, 7, 9]) == 2
    assert AP.intersecting_sheet([0, 3, 3, 1], [1, 2, 7, 9], preferred=1) == 1
    assert AP.intersecting_sheet([0, 1], [1, 2], preferred=1) is None


def test_slice_sweeps_from_the_camera_side():
    pts = np.array([[0, 0, 0], [4, 2, 1]], float)
    k, n = AP.slice_axis([-0.9, 0.3, 0.2])
    assert k == 0 and list(n) == [-1, 0, 0]  # towards the camera
    assert AP.slice_axis([-0.9, 0.3, 0.2], "z")[0] == 2
    ps = AP.slice_points(pts, n, 5)
    s = [p @ n for p in ps]
    assert s[0] > 0 and np.all(np.diff(s) < 0)  # starts beyond the near side (x = 0), moves away
    assert s[-1] == pytest.approx(-4 + 0.4)  # stops a tenth before the far side
    assert all(p[1] == pytest.approx(1.0) and p[2] == pytest.approx(0.5) for p in ps)  # through the centre's line


def test_gif_command():
    cmd = AP.gif_command("/usr/bin/ffmpeg", "/t/f_%04d.png", 12, "/o/a.gif")
    assert cmd[0] == "/usr/bin/ffmpeg" and cmd[-1] == "/o/a.gif" and "-loop" in cmd and "0" in cmd
    assert any("palettegen" in c and "paletteuse" in c for c in cmd)


def test_looks_keep_the_legend_and_differ_in_background():
    assert set(plan.LOOKS) == {"paper", "slide", "clay"}
    assert plan.LOOKS["slide"].background < 0.2 < plan.LOOKS["paper"].background
    assert plan.LOOKS["clay"].clay and not plan.LOOKS["paper"].clay
