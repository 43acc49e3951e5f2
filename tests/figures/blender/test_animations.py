"""render_figures.py --animate, end to end in background mode, short and small (Workbench): every kind
of twistcube_s.mesh (hexes with prisms, pyramids, tets and polyhedra; self-intersecting sheets) as
MP4, whose frame count and codec ffprobe reads and whose decoded frames are not blank, not all equal,
and in `explode` spread out on screen and come back; WebM and GIF, the slide and clay looks, captions
and the legend strip.
"""

import json
import shutil
import subprocess

import numpy as np
import pytest

pytest.importorskip("bpy")

from test_render_figures import data, run, written  # noqa: E402
from hybrid_base_complex.figures import animation_plan as AP  # noqa: E402

W, H, FRAMES = 96, 64, 6
BG = 0.94  # the paper look's background (display value)


def probe(path):
    """(frame count, codec name, width, height) of a video's first stream, read by ffprobe."""
    if shutil.which("ffprobe") is None:
        pytest.fail("ffprobe is missing (Debian's ffmpeg package: scripts/env/deps.sh)")
    p = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                        "stream=nb_read_frames,codec_name,width,height", "-of", "json", str(path)],
                       capture_output=True, text=True, check=True)
    s = json.loads(p.stdout)["streams"][0]
    return int(s["nb_read_frames"]), s["codec_name"], int(s["width"]), int(s["height"])


def decode(path, w, h):
    """The video's frames as (n, h, w, 3) floats in [0, 1]."""
    p = subprocess.run(["ffmpeg", "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                       capture_output=True, check=True)
    return np.frombuffer(p.stdout, np.uint8).reshape(-1, h, w, 3) / 255.0


def spread(frame, tol=0.08):
    """Width + height of the box around everything that is not background: how far the blocks reach."""
    fg = np.abs(frame - BG).max(axis=2) > tol
    ys, xs = np.nonzero(fg)
    return (xs.max() - xs.min()) + (ys.max() - ys.min()) if len(xs) else 0


@pytest.fixture(scope="module")
def every_kind(tmp_path_factory):
    out = tmp_path_factory.mktemp("animations")
    p = run([data("twistcube_s.mesh"), "--out", out, "--engine", "workbench", "--resolution", W, H,
             "--animate", ",".join(AP.KIND_KEYS), "--frames", FRAMES, "--fps", 8])
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return out, p


def test_every_kind_is_an_h264_video_of_the_frames(every_kind):
    out, p = every_kind
    names = [f"twistcube_s_{k}.mp4" for k in AP.KIND_KEYS]
    assert [f.rsplit("/", 1)[-1] for f in written(p)] == names
    for name in names:
        assert probe(out / name) == (FRAMES, "h264", W, H), name
    # Progress, frame by frame, on stderr.
    for f in range(1, FRAMES + 1):
        assert f"render_figures: explode: frame {f}/{FRAMES}" in p.stderr


def test_frames_are_not_blank_and_move(every_kind):
    out, _ = every_kind
    for kind in AP.KIND_KEYS:
        frames = decode(out / f"twistcube_s_{kind}.mp4", W, H)
        assert len(frames) == FRAMES
        for k, f in enumerate(frames):
            assert f.std() > 0.02, f"{kind} frame {k + 1} is blank"
        moved = max(np.abs(frames[k] - frames[0]).max() for k in range(1, FRAMES))
        assert moved > 0.2, f"{kind}: all frames are the same"


def test_explode_spreads_out_and_comes_back(every_kind):
    out, _ = every_kind
    s = [spread(f) for f in decode(out / "twistcube_s_explode.mp4", W, H)]
    mid = (FRAMES + 1) // 2 - 1  # the keys: together, apart at the middle frame, together
    assert s[mid] > 1.2 * s[0] and s[mid] > 1.2 * s[-1], s
    assert all(b >= a for a, b in zip(s[:mid], s[1:mid + 1])), s  # growing
    assert all(b <= a for a, b in zip(s[mid:], s[mid + 1:])), s  # then shrinking
    assert abs(s[-1] - s[0]) <= 2, s


def test_webm_gif_looks_and_legend(tmp_path):
    mesh = data("twistcube_s.mesh")
    common = ["--engine", "workbench", "--resolution", W, H, "--frames", 4]
    p = run([mesh, "--out", tmp_path, *common, "--animate", "turntable", "--format", "webm", "--look", "slide"])
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    assert probe(tmp_path / "twistcube_s_turntable.webm") == (4, "vp9", W, H)
    dark = decode(tmp_path / "twistcube_s_turntable.webm", W, H)
    corners = dark[0][[0, 0, -1, -1], [0, -1, 0, -1]]
    assert corners.max() < 0.2  # the slide look's dark background
    p = run([mesh, "--out", tmp_path, *common, "--animate", "sheets,slice", "--format", "gif", "--look", "clay",
             "--sheets", "2", "--legend"])
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    for kind in ("sheets", "slice"):
        n, codec, w, h = probe(tmp_path / f"twistcube_s_{kind}.gif")
        assert (n, codec, w) == (4, "gif", W) and h > H, kind  # the legend strip below the frames
    h = probe(tmp_path / "twistcube_s_sheets.gif")[3]
    frames = decode(tmp_path / "twistcube_s_sheets.gif", W, h)
    # Two sheets, two frames each, captioned: the caption's rows differ between the halves.
    assert np.abs(frames[0][:10] - frames[3][:10]).max() > 0.2
    assert np.abs(frames[0][H:] - frames[3][H:]).mean() < 0.02  # one legend for the whole animation


@pytest.mark.parametrize("look", ["slide", "clay"])
def test_looks_of_stills(tmp_path, look):
    """--look dresses the still panels too: slide's background dark, clay's blocks without colour."""
    from test_render_figures import load

    p = run([data("twistcube_s.mesh"), "--out", tmp_path, "--engine", "workbench", "--resolution", W, H,
             "--panels", "complex", "--look", look])
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    img = load(tmp_path / "twistcube_s_c_complex.png")[..., :3]
    corners = img[[0, 0, -1, -1], [0, -1, 0, -1]]
    chroma = img.max(axis=2) - img.min(axis=2)
    if look == "slide":
        assert corners.max() < 0.2
    else:
        assert corners.min() > 0.8 and np.percentile(chroma, 95) < 0.12  # grey clay on paper's background
