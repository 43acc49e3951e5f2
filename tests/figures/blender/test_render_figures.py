"""blender_scripts/render_figures.py end to end, in background mode, at a tiny size: every panel
of twistcube_s.mesh (Cycles, 4 samples) and of the demo's generated default (Workbench), and a
comparison (Workbench). Run inside Blender by tests/run_pytest_in_blender.py (the images
are read back with bpy.data.images); the figure script itself runs in a child Blender, as a user
runs it.

Environment: HBC_ADDON_DIR (the built add-on), HBC_DATA_DIR (the shared meshes), HBC_CLI (the
built hbc, which generates the demo's default).
"""

import itertools
import os
import pathlib
import re
import subprocess
import sys
import time

import numpy as np
import pytest

bpy = pytest.importorskip("bpy")

ROOT = pathlib.Path(__file__).resolve().parents[3]
SCRIPT = ROOT / "blender_scripts" / "render_figures.py"
if os.environ.get("HBC_ADDON_DIR"):  # the figure code ships in the add-on: the built one's
    sys.path.insert(0, str(pathlib.Path(os.environ["HBC_ADDON_DIR"]).parent))
from hybrid_base_complex.figures import compose as C  # noqa: E402
from hybrid_base_complex.figures import plan  # noqa: E402
from hybrid_base_complex.figures.render import load_png  # noqa: E402

W, H = 160, 120
MIN_STD = 0.02  # RGB standard deviation of a panel: a blank (background only) image gives 0


def data(name):
    d = os.environ.get("HBC_DATA_DIR")
    if not d or not os.path.isdir(d):
        pytest.fail(f"HBC_DATA_DIR={d} is not a folder")
    p = pathlib.Path(d) / "hybrid-base-complex" / name
    if not p.is_file():
        pytest.fail(f"missing test mesh {p}")
    return p


def run(args, timeout=240):
    if not os.environ.get("HBC_ADDON_DIR"):
        pytest.fail("HBC_ADDON_DIR is not set (the built add-on)")
    if bpy.app.binary_path:  # a Blender executable runs the script as a user does
        cmd = [bpy.app.binary_path, "-b", "--factory-startup", "--python-exit-code", "1", "--python", str(SCRIPT),
               "--", *map(str, args)]
    else:  # the bpy module (PyPI wheel): its Python runs the script directly
        cmd = [sys.executable, str(SCRIPT), *map(str, args)]
    t = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    p.seconds = time.perf_counter() - t
    return p


def written(proc):
    return [line[len("wrote "):] for line in proc.stdout.splitlines() if line.startswith("wrote ")]


def load(path):
    return load_png(str(path))


@pytest.fixture(scope="module")
def pipeline(tmp_path_factory):
    out = tmp_path_factory.mktemp("figures")
    # Not denoised: OpenImageDenoise leaves a few off-colour pixels in the corners of so small and
    # so noisy an image, and the framing checks below compare against the corner pixel.
    p = run([data("twistcube_s.mesh"), "--out", out, "--engine", "cycles", "--samples", 4, "--resolution", W, H,
             "--denoise", "off"])
    print(p.stdout[-3000:], p.stderr[-3000:])
    assert p.returncode == 0, p.stderr[-3000:]
    return out, p


def test_every_panel_is_written_and_printed(pipeline):
    out, p = pipeline
    names = [f"twistcube_s_{plan.PANEL_LETTER[k]}_{k}.png" for k in plan.PANEL_KEYS] + ["twistcube_s_contact.png"]
    files = [pathlib.Path(f) for f in written(p)]
    assert [f.name for f in files] == names
    for f in files:
        assert f.parent == out.resolve() and f.is_file() and f.stat().st_size > 0
    assert "| twistcube_s | 1301 |" in p.stdout  # the Table 1 row


def test_panels_are_not_blank_and_all_differ(pipeline):
    out, _ = pipeline
    imgs = {k: load(out / f"twistcube_s_{plan.PANEL_LETTER[k]}_{k}.png") for k in plan.PANEL_KEYS}
    for k, img in imgs.items():
        expect = (H, 2 * W + C.PAD) if k == "subsheets" else (H, W)
        assert img.shape[:2] == expect, k
        assert C.pixel_std(img) > MIN_STD, f"panel {k} is blank (std {C.pixel_std(img):.4f})"
    for a, b in itertools.combinations(plan.PANEL_KEYS, 2):
        assert C.differs(imgs[a], imgs[b]), f"panels {a} and {b} are the same"


def test_panels_are_not_clipped(pipeline):
    """Same camera, framed on the mesh: something is drawn, and not on the frame's edge."""
    out, _ = pipeline
    for k in ("mesh", "graph", "complex", "sheet"):
        img = load(out / f"twistcube_s_{plan.PANEL_LETTER[k]}_{k}.png")
        box = C.foreground_bbox(img, tol=0.03)
        assert box is not None, k
        x0, y0, x1, y1 = box
        assert x0 > 0 and y0 > 0 and x1 < W and y1 < H, (k, box)
        assert (x1 - x0) > W * 0.4 or (y1 - y0) > H * 0.6, (k, box)  # fills the frame


def test_contact_sheet_size(pipeline):
    out, _ = pipeline
    img = load(out / "twistcube_s_contact.png")
    spans = [1] * 6 + [2]
    label_h = max(14, round(H * 0.07))
    assert img.shape[:2][::-1] == C.sheet_size(spans, C.contact_columns(spans), W, H, label_h)
    assert C.pixel_std(img) > MIN_STD


def demo_default(tmp_path):
    """The first mesh scripts/demo.sh generates, generated here with the same arguments (read from
    the script, so this follows it) by the built hbc ($HBC_CLI)."""
    cli = os.environ.get("HBC_CLI")
    if not cli or not os.path.isfile(cli):
        pytest.fail(f"HBC_CLI={cli} is not the built hbc")
    text = (ROOT / "scripts" / "demo.sh").read_text()
    m = re.search(r'^\./build/bin/hbc generate (.+) -o "\$OUT/([\w.-]+)"$', text, re.M)
    assert m, "scripts/demo.sh generates no mesh"
    out = tmp_path / m.group(2)
    p = subprocess.run([cli, "generate", *m.group(1).split(), "-o", str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return out


def test_demo_default_fills_every_panel(tmp_path):
    """The demo's first default (without ../shared/data) has a self-intersecting sheet whose region holds
    non-hex cells, so every panel a-g is drawn - none skipped - and the contact sheet holds all."""
    mesh = demo_default(tmp_path)
    name = mesh.stem
    p = run([mesh, "--out", tmp_path, "--engine", "workbench", "--resolution", W, H])
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    assert "skipped" not in p.stdout, p.stdout[-3000:]
    assert "self-intersecting" in p.stdout  # the sheet of panels d-g
    names = [f"{name}_{plan.PANEL_LETTER[k]}_{k}.png" for k in plan.PANEL_KEYS] + [f"{name}_contact.png"]
    assert [pathlib.Path(f).name for f in written(p)] == names
    imgs = {k: load(tmp_path / n) for k, n in zip(plan.PANEL_KEYS, names)}
    for k, img in imgs.items():
        assert C.pixel_std(img) > MIN_STD, f"panel {k} is blank"
    for a, b in itertools.combinations(plan.PANEL_KEYS, 2):
        assert C.differs(imgs[a], imgs[b]), f"panels {a} and {b} are the same"
    spans = [1] * 6 + [2]
    label_h = max(14, round(H * 0.07))
    sheet = load(tmp_path / names[-1])
    assert sheet.shape[:2][::-1] == C.sheet_size(spans, C.contact_columns(spans), W, H, label_h)


def test_denoised_where_available(tmp_path):
    """Default (--denoise auto): denoised exactly where this Blender's Cycles has OpenImageDenoise
    (the bpy wheels do, Debian's 3.4 does not), and the panel is drawn."""
    import _cycles

    has = bool(getattr(_cycles, "with_openimagedenoise", False))
    p = run([data("test_2.HYBRID"), "--out", tmp_path, "--samples", 4, "--resolution", W, H, "--panels", "complex"])
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    assert ("denoised (OpenImageDenoise)" in p.stdout) == has, p.stdout[-2000:]
    assert ("not denoised" in p.stdout) == (not has)
    img = load(tmp_path / "test_2_c_complex.png")
    assert float(img[..., :3].std()) > MIN_STD


def test_eevee_renders_headless(tmp_path):
    """EEVEE (BLENDER_EEVEE_NEXT in 4.2-4.5, BLENDER_EEVEE before and from 5.0) renders in
    background mode on software EGL in every Blender of the matrix: a panel that is not blank."""
    p = run([data("test_2.HYBRID"), "--out", tmp_path, "--engine", "eevee", "--samples", 1,
             "--resolution", 64, 48, "--panels", "complex"], timeout=300)
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    img = load(tmp_path / "test_2_c_complex.png")
    assert float(img[..., :3].std()) > MIN_STD


def test_compare_layout(tmp_path):
    a, b = data("twistcube_s.mesh"), data("cube_twist-comp.obj.HYBRID")
    p = run(["--compare", a, b, "--out", tmp_path, "--engine", "workbench", "--resolution", W, H])
    assert p.returncode == 0, p.stderr[-3000:]
    files = [pathlib.Path(f).name for f in written(p)]
    rows = [k for k, _ in plan.COMPARE_ROWS]
    assert files == [f"twistcube_s_{k}.png" for k in rows] + [f"cube_twist-comp.obj_{k}.png" for k in rows] + \
        ["compare_twistcube_s_cube_twist-comp.obj.png"]
    img = load(tmp_path / files[-1])
    label_h = max(14, round(H * 0.07))
    row_w = max(120, round(W * 0.4))
    assert img.shape[:2] == (C.PAD + label_h + 4 + len(rows) * (H + C.PAD), C.PAD + row_w + 4 + 2 * (W + C.PAD))
    for f in files[:-1]:
        assert C.pixel_std(load(tmp_path / f)) > MIN_STD, f


@pytest.mark.parametrize("args,pattern", [
    (["/nonexistent/mesh.mesh", "--out", "{tmp}"], r"mesh\.mesh"),
    (["--out", "{tmp}"], r"give one MESH"),
    (["{mesh}", "--out", "{tmp}", "--sheet", "999"], r"--sheet 999: the mesh has 20 sheets"),
])
def test_failures_exit_non_zero(tmp_path, args, pattern):
    args = [a.format(tmp=tmp_path, mesh=data("twistcube_s.mesh")) for a in args]
    p = run(args + ["--engine", "workbench", "--resolution", W, H], timeout=120)
    assert p.returncode != 0
    assert re.search(pattern, p.stdout + p.stderr), (p.stdout[-2000:], p.stderr[-2000:])
    assert not list(tmp_path.glob("*.png"))


def test_cut_and_quality_panels(tmp_path):
    """--panels complex,cut,quality: both inspection panels are drawn, in the contact sheet, and
    differ from the uncut blocks; the cut (near half hidden) draws fewer pixels than the blocks."""
    p = run([data("twistcube_s.mesh"), "--out", tmp_path, "--engine", "workbench", "--resolution", W, H,
             "--panels", "complex,cut,quality"])
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    names = [pathlib.Path(f).name for f in written(p)]
    assert names == ["twistcube_s_c_complex.png", "twistcube_s_h_cut.png", "twistcube_s_i_quality.png",
                     "twistcube_s_contact.png"]
    imgs = {k: load(tmp_path / n) for k, n in zip(("complex", "cut", "quality"), names)}
    for k, img in imgs.items():
        assert C.pixel_std(img) > MIN_STD, k
    assert C.differs(imgs["complex"], imgs["cut"]) and C.differs(imgs["cut"], imgs["quality"])

    def drawn(img):
        x0, y0, x1, y1 = C.foreground_bbox(img, tol=0.03)
        return (x1 - x0) * (y1 - y0)

    assert drawn(imgs["cut"]) < drawn(imgs["complex"])
    sheet = load(tmp_path / names[-1])
    label_h = max(14, round(H * 0.07))
    assert sheet.shape[:2][::-1] == C.sheet_size([1] * 3, C.contact_columns([1] * 3), W, H, label_h)


# ---------------------------------------------------------------------------------------------
# --legend: a strip of swatches and words under each panel

LW, LH = 320, 240
LEGEND_PANELS = ("mesh", "graph", "complex", "sheet", "vsg", "subsheets")


@pytest.fixture(scope="module")
def legend_pair(tmp_path_factory):
    """The same panels rendered by Workbench (the same pixels every time) without and with
    --legend."""
    outs = []
    for extra in ([], ["--legend"]):
        out = tmp_path_factory.mktemp("legend" if extra else "plain")
        p = run([data("twistcube_s.mesh"), "--out", out, "--engine", "workbench", "--resolution", LW, LH,
                 "--panels", ",".join(LEGEND_PANELS), *extra])
        assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
        outs.append((out, p))
    return outs


def expected_legends():
    """{panel: [(key, words, colour)]} worked out here, apart from the script: the add-on's legend
    for the layers each panel shows, with the facts of this mesh's analysis and the highlights the
    picked sheet and its largest subsheets have."""
    import importlib

    addon = os.environ["HBC_ADDON_DIR"]
    sys.path.insert(0, os.path.dirname(addon))
    name = os.path.basename(addon)
    P = importlib.import_module(name + ".plan.planning")
    session = importlib.import_module(name + ".plan.session")
    s = session.load(str(data("twistcube_s.mesh")), 1.0, lambda *_: None)
    session.analyze(s, 0.8, lambda *_: None)
    facts = s.legend_facts()
    sheet = plan.pick_sheet(s.sheet_types(), s.sheet_sizes()[0])
    unmatched, shared, edges, cells = s.sheet_highlights(sheet, 0.01)
    drawn = {"unmatched": unmatched.num_faces, "shared": shared.num_faces, "self_parallel": edges.positions.size,
             "self_intersecting": cells.num_faces}
    sub = s.subsheets(sheet)
    picked = plan.pick_subsheets(np.diff(np.asarray(sub.subsheet_cells_offsets)), 4)
    sub_unmatched = any(len(s.subsheet_unmatched(sub, k)) for k in picked)
    highlights = {"sheet": {k for k, n in drawn.items() if n}, "subsheets": {"unmatched"} if sub_unmatched else set()}
    return P, {key: plan.panel_legend(P, key, facts, highlights.get(key, ())) for key in LEGEND_PANELS}


def test_legend_strip_under_each_panel(legend_pair):
    """Every panel with something to name grew by one strip (the same height for all) under the
    very render it had without --legend; each swatch shows its colour (display values of the add-on's
    colour) framed, beside its words, at the place <name>_legend.json gives, the swatches lined up
    in columns; panels coloured by chain (VSG) are unchanged; the contact sheet grew by the strips."""
    import json

    (plain, _), (legend, p) = legend_pair
    P, expected = expected_legends()
    info = json.loads((legend / "twistcube_s_legend.json").read_text())
    assert str((legend / "twistcube_s_legend.json").resolve()) in written(p)
    strip = info["strip_height"]
    m = plan.LegendMetrics.for_panel(LH)
    assert info["row"] == m.row and strip > 0 and (strip - 2 * m.margin) % m.row == 0
    listed = {q["panel"]: q for q in info["panels"]}
    assert sorted(listed) == sorted(k for k, e in expected.items() if e)
    assert {"mesh", "graph", "complex", "sheet", "subsheets"} <= set(listed)  # this mesh has them all
    for key in LEGEND_PANELS:
        name = f"twistcube_s_{plan.PANEL_LETTER[key]}_{key}.png"
        before, after = load(plain / name), load(legend / name)
        if key not in listed:
            assert after.shape == before.shape, key
            continue
        q = listed[key]
        assert q["file"] == name and q["height_without_strip"] == before.shape[0] == LH
        assert after.shape[0] == before.shape[0] + strip and after.shape[1] == before.shape[1], key
        assert np.abs(after[:LH, :, :3] - before[..., :3]).max() < 2.5 / 255, key  # the render itself is unchanged
        assert [(e["key"], e["words"]) for e in q["entries"]] == [(k, w) for k, w, _ in expected[key]]
        rows = {}
        for e, (k, _, color) in zip(q["entries"], expected[key]):
            want = C.linear_to_srgb(P.LEGEND_COLORS[k][:3])
            assert np.allclose(e["srgb"], want, atol=1e-4), (key, k)
            x, y, side = e["swatch"]
            assert y >= LH and y + side <= LH + strip and side == m.swatch
            inner = after[y + 1:y + side - 1, x + 1:x + side - 1, :3]
            assert np.abs(inner - want).max() < 1.5 / 255, (key, k, inner.mean(axis=(0, 1)), want)
            assert np.abs(after[y, x + side // 2, :3] - C.SWATCH_EDGE[:3]).max() < 1.5 / 255  # framed
            wx, wy, ww, wh = e["words_at"]
            assert wx == x + side + m.gap and wy <= y and y + side <= wy + wh  # beside it, on its row
            ink = after[wy:wy + wh, wx:wx + ww, :3].min(axis=2)
            assert ink.min() < 0.35, (key, e["words"])  # the words are drawn, dark on the strip
            assert wx + ww <= after.shape[1]
            rows.setdefault(wy, []).append(x)
        xs = [sorted(v) for _, v in sorted(rows.items())]
        for r in xs[1:]:
            assert r == xs[0][:len(r)], (key, xs)  # every row starts at the first one's columns
    # The contact sheet: both of its rows hold a panel with a strip.
    a, b = load(plain / "twistcube_s_contact.png"), load(legend / "twistcube_s_contact.png")
    assert b.shape[1] == a.shape[1] and b.shape[0] == a.shape[0] + 2 * strip
