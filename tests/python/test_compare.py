"""`hbc compare` (docs/compare.md): three meshes of three meshers and one broken file.

The three meshes are the paper's test data (SOURCES.md of the shared data): cube_twist-comp.obj.HYBRID
from Robust Hex-Dominant Meshing, teapot.hedra from LoopyCuts, twistcube_s.mesh from At-Most-Hexa.
The broken file is a MEDIT file whose vertex section ends early. The comparison runs once per
module, and once more through hbc.compare() in this process, whose outputs must be the CLI's; the
tests read them. The CLI's report is drawn by Debian's Python (HBC_PYTHON, default
/usr/bin/python3, which has python3-matplotlib: scripts/env/deps.sh) and opened in headless
Chromium (Debian's chromium, same list). Executors and the locating rules: test_compare_executors.py,
test_locate.py.
"""

import csv
from html import escape as html_escape
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

from hbc import report

MESHES = [("RHDM cube_twist", "hybrid-base-complex/cube_twist-comp.obj.HYBRID"),
          ("LoopyCuts teapot", "hybrid-base-complex/teapot.hedra"),
          ("At-Most-Hexa_twistcube 100%", "hybrid-base-complex/twistcube_s.mesh")]
BROKEN_NAME = "broken & cut"
# A MEDIT file announcing 3 vertices and giving 1: the reader names the file and the line.
BROKEN = "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n"
REPO = pathlib.Path(__file__).resolve().parents[2]


def report_env(extra=None):
    env = dict(os.environ)
    env.setdefault("HBC_PYTHON", "/usr/bin/python3")
    env.update(extra or {})
    return env


@pytest.fixture(scope="module")
def compared(hbc_cli, shared_data_dir, tmp_path_factory):
    """(out dir, completed process, the files in column order) of one `hbc compare` run."""
    tmp = tmp_path_factory.mktemp("compare")
    broken = tmp / "broken.mesh"
    broken.write_text(BROKEN)
    files = [str(shared_data_dir / rel) for _, rel in MESHES]
    files.insert(1, str(broken))  # a failure in the middle: the columns after it must still be there
    names = [n for n, _ in MESHES]
    names.insert(1, BROKEN_NAME)
    out = tmp / "out"
    run = subprocess.run([hbc_cli, "compare", *files, "-o", str(out), "--names", ",".join(names)],
                         capture_output=True, text=True, env=report_env())
    return out, run, files, names


def test_a_broken_file_fails_its_column_alone(compared):
    out, run, files, names = compared
    assert run.returncode == 2, run.stderr
    assert "1 of 4 mesh(es) failed" in run.stderr
    # Progress: one line per mesh.
    assert len(re.findall(r"hbc compare: \[\d/4\]", run.stderr)) == 4, run.stderr
    data = json.loads((out / "metrics.json").read_text())
    assert list(data["errors"]) == [BROKEN_NAME]
    # The reader's message: file and line (line 4 announces 3 vertices; the file holds 1).
    assert data["errors"][BROKEN_NAME].startswith(f"{files[1]}:4: ")
    assert [m["name"] for m in data["meshes"]] == names
    assert data["metrics"][1] is None and data["scaled_jacobian_histograms"]["by_type"][1] is None
    for i in (0, 2, 3):
        assert data["meshes"][i]["error"] is None
        assert data["values"]["census.cells"][i] > 0
    for name in ("metrics.csv", "metrics.tex", "report.html"):
        assert (out / name).stat().st_size > 0, name
    html = (out / "report.html").read_text()
    assert "broken.mesh" in html and "Failed meshes" in html


def cli_metrics(hbc_cli, path):
    run = subprocess.run([hbc_cli, "metrics", path, "--json"], capture_output=True, text=True, check=True)
    m = json.loads(run.stdout)
    del m["timings"]
    return m


def same(a, b):
    if a is None or b is None:
        return a is None and b is None
    return a == b or math.isclose(a, b, rel_tol=1e-9, abs_tol=0)


def test_json_and_csv_equal_hbc_metrics(compared, hbc_cli):
    out, _, files, names = compared
    data = json.loads((out / "metrics.json").read_text())
    with open(out / "metrics.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["name"] for r in rows] == names
    keys = [f["key"] for f in data["fields"]]
    assert keys == [f"{f.group}.{f.key}" for f in __import__("hbc").METRIC_FIELDS]
    for i, path in enumerate(files):
        if i == 1:
            assert all(rows[i][k] == "" for k in keys) and rows[i]["error"] == data["errors"][BROKEN_NAME]
            continue
        ref = cli_metrics(hbc_cli, path)
        got = dict(data["metrics"][i])
        got.pop("timings")
        assert got == ref  # the whole `hbc metrics --json` object, distributions included
        for k in keys:
            group, key = k.split(".")
            assert same(data["values"][k][i], ref[group][key]), k
            assert same(float(rows[i][k]) if rows[i][k] else None, ref[group][key]), k
        assert rows[i]["error"] == "" and rows[i]["mesh"] == path
        # The scaled Jacobian histograms count every cell once, by type.
        census = {"hex": "hexahedra", "prism": "prisms", "pyramid": "pyramids", "tet": "tetrahedra",
                  "polyhedron": "polyhedra"}
        hist = data["scaled_jacobian_histograms"]["by_type"][i]
        for t, counts in hist.items():
            assert len(counts) == 20 and sum(counts) == ref["census"][census[t]], t


def latex_rows(tex):
    body = tex[tex.index("\\toprule"):tex.index("\\end{tabular}")]
    return [ln for ln in body.splitlines() if ln and not re.fullmatch(r"\\(toprule|midrule|bottomrule)", ln)]


def test_latex_table(compared):
    out, _, _, names = compared
    tex = (out / "metrics.tex").read_text()
    ncol = 2 + len(names)
    spec = re.search(r"\\begin\{tabular\}\{([a-z]+)\}", tex).group(1)
    assert len(spec) == ncol
    for rule in ("\\toprule", "\\midrule", "\\bottomrule"):
        assert rule in tex
    # Names escaped: _ % & of the column names.
    assert "At-Most-Hexa\\_twistcube 100\\%" in tex and "broken \\& cut" in tex
    for ln in latex_rows(tex):
        assert ln.endswith("\\\\"), ln
        cells = re.split(r"(?<!\\)&", ln[:-2])
        if ln.startswith("\\multicolumn"):
            assert len(cells) == 1 and ln.startswith(f"\\multicolumn{{{ncol}}}"), ln
        else:
            assert len(cells) == ncol, ln
        assert ln.count("{") == ln.count("}"), ln
    if shutil.which("pdflatex"):
        doc = out / "doc.tex"
        doc.write_text("\\documentclass{article}\\usepackage{booktabs}\\usepackage[margin=1cm,landscape]"
                       "{geometry}\\begin{document}\\input{metrics.tex}\\end{document}\n")
        run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "doc.tex"], cwd=out,
                             capture_output=True, text=True)
        assert run.returncode == 0, run.stdout[-2000:]


def test_report_is_self_contained(compared):
    out, _, _, _ = compared
    html = (out / "report.html").read_text()
    # Nothing fetched on opening: no external script, style sheet, image or font.
    assert not re.search(r"<(link|iframe|object|embed)\b", html)
    assert not re.search(r"""\bsrc\s*=\s*["'](?!data:)""", html)
    assert "url(" not in html and "@import" not in html
    imgs = re.findall(r'<img class="plot"[^>]*src="data:image/png;base64,', html)
    assert len(imgs) == 4  # bar charts, valences, component sizes, scaled Jacobian per type
    data = json.loads((out / "metrics.json").read_text())
    for f in data["fields"]:
        assert html_escape(f["meaning"]) in html, f["key"]
    # Each group links to its heading in docs/metrics.md, and that heading exists.
    doc = (REPO / "docs" / "metrics.md").read_text()
    for group, title in report.GROUP_TITLES.items():
        assert f"#### {title}" in doc
        assert f"metrics.md#{report.anchor(group)}" in html


def test_missing_matplotlib_still_writes_the_tables(hbc_cli, shared_data_dir, tmp_path):
    fake = tmp_path / "fake"
    (fake / "matplotlib").mkdir(parents=True)
    (fake / "matplotlib" / "__init__.py").write_text("raise ImportError('no matplotlib here')\n")
    out = tmp_path / "out"
    env = report_env({"PYTHONPATH": f"{fake}:{os.environ.get('PYTHONPATH', '')}"})
    run = subprocess.run([hbc_cli, "compare", str(shared_data_dir / MESHES[0][1]), "-o", str(out)],
                         capture_output=True, text=True, env=env)
    assert run.returncode == 2
    assert "matplotlib is not installed" in run.stderr and "report.html not written" in run.stderr
    for name in ("metrics.json", "metrics.csv", "metrics.tex"):
        assert (out / name).is_file()
    assert not (out / "report.html").exists()


@pytest.fixture(scope="module")
def python_compared(compared, tmp_path_factory):
    """(out dir, returned dict) of hbc.compare() on the files and names of `compared`, in this
    process, with no process started (a guard fails the run if one is: no Python -> CLI loop)."""
    _, _, files, names = compared
    out = tmp_path_factory.mktemp("python-compare") / "out"
    import hbc

    real = subprocess.Popen

    def forbidden(*args, **kwargs):
        raise AssertionError(f"hbc.compare started a process: {args[0] if args else kwargs}")

    subprocess.Popen = forbidden
    try:
        data = hbc.compare(files, out, names=names)
    finally:
        subprocess.Popen = real
    return out, data


def test_python_compare_writes_what_the_cli_writes(compared, python_compared, same_but_timings):
    """hbc.compare() measures in this process through the compiled module and writes the CLI's
    metrics.json, metrics.csv and metrics.tex byte for byte (timings aside), the failed column
    with the CLI's error text; then report.html, drawn here."""
    cli_out, _, _, names = compared
    out, data = python_compared
    for name in ("metrics.json", "metrics.csv", "metrics.tex"):
        assert same_but_timings(out / name, cli_out / name), name
    # The mask hides only the timings' numbers: three per measured mesh.
    assert len(same_but_timings.pattern.findall((out / "metrics.json").read_text())) == 3 * 3
    assert data == json.loads((out / "metrics.json").read_text())
    assert list(data["errors"]) == [BROKEN_NAME] and [m["name"] for m in data["meshes"]] == names
    html = (out / "report.html").read_text()
    assert "broken.mesh" in html and "Failed meshes" in html
    assert len(re.findall(r'<img class="plot"[^>]*src="data:image/png;base64,', html)) == 4


def test_python_compare_check_raises_for_a_failed_mesh(compared, tmp_path):
    import hbc

    _, _, files, names = compared
    with pytest.raises(hbc.comparison.CompareError, match=re.escape(BROKEN_NAME)):
        hbc.compare(files[:2], tmp_path / "o", names=names[:2], check=True, report=False)
    # The tables are written before it raises, and no report was asked for.
    assert (tmp_path / "o" / "metrics.csv").is_file() and not (tmp_path / "o" / "report.html").exists()
    data = hbc.compare(files[:1], tmp_path / "p", names=["a"], check=True, report=False)
    assert data["errors"] == {} and data["meshes"][0]["name"] == "a"


def one_cell_broken(source, target):
    """The shared RHDM file with its first cell's last face taken out: one open cell, so that the
    file is refused without --skip-invalid and loses that cell alone with it."""
    lines = source.read_text().split("\n")
    nv, nf, _ = map(int, lines[0].split())
    at = 1 + nv + nf  # the first cell's face line, then its orientation flags
    faces, flags = lines[at].split(), lines[at + 1].split()
    lines[at] = " ".join([str(int(faces[0]) - 1), *faces[1:-1]])
    lines[at + 1] = " ".join([str(int(flags[0]) - 1), *flags[1:-1]])
    target.write_text("\n".join(lines))


def test_skip_invalid_reads_a_broken_file(hbc_cli, shared_data_dir, tmp_path, same_but_timings):
    """hbc compare and hbc.compare() take the reading options: a published file with one broken cell
    fails its column without --skip-invalid (the message advising that option) and is measured with
    it exactly as `hbc metrics --skip-invalid --json` measures it; metrics.json says what went."""
    source = shared_data_dir / MESHES[0][1]
    broken = tmp_path / "cube_twist-broken.txt"  # an extension no format claims: --format says it
    one_cell_broken(source, broken)
    without = subprocess.run([hbc_cli, "compare", str(source), str(broken), "-o", str(tmp_path / "a"),
                              "--format", "hybrid", "--no-report"], capture_output=True, text=True)
    assert without.returncode == 2, without.stderr
    data = json.loads((tmp_path / "a" / "metrics.json").read_text())
    error = data["meshes"][1]["error"]
    assert error.startswith(f"{broken}:") and "--skip-invalid" in error
    assert "dropped" not in data["meshes"][0]
    run = subprocess.run([hbc_cli, "compare", str(source), str(broken), "-o", str(tmp_path / "b"),
                          "--format", "hybrid", "--threads", "1", "--skip-invalid", "--no-report"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert f"hbc: warning: {broken}: 1 cell(s) dropped (1 open_cells): cell 0" in run.stderr
    data = json.loads((tmp_path / "b" / "metrics.json").read_text())
    assert data["errors"] == {}
    assert data["values"]["census.cells"] == [493, 492]
    assert data["meshes"][0]["dropped"]["count"] == 0
    assert data["meshes"][1]["dropped"]["by_reason"] == {"open_cells": 1}
    ref = json.loads(subprocess.run([hbc_cli, "metrics", str(broken), "--format", "hybrid", "--skip-invalid", "--json"],
                                    capture_output=True, text=True, check=True).stdout)
    got = dict(data["metrics"][1])
    got.pop("timings"), ref.pop("timings")
    assert got == ref
    # The same from Python, with hbc.load's keywords: the CLI's tables, "dropped" included.
    import hbc

    hbc.compare([source, broken], tmp_path / "py", format="hybrid", threads=1, skip_invalid=True, report=False)
    for name in ("metrics.json", "metrics.csv", "metrics.tex"):
        assert same_but_timings(tmp_path / "py" / name, tmp_path / "b" / name), name
    refused = hbc.compare([broken], tmp_path / "c", format="hybrid", report=False)
    assert "--skip-invalid" in refused["errors"]["cube_twist-broken.txt"]
    measured = hbc.compare([broken], tmp_path / "d", format="hybrid", threads=1, skip_invalid=True, check=True,
                           report=False)
    assert measured["metrics"][0]["census"] == ref["census"]
    assert measured["meshes"][0]["dropped"] == data["meshes"][1]["dropped"]
    # Refused before any work: nothing is written.
    for bad in ({"format": "stl"}, {"threads": 0}, {"jobs": 0}, {"names": ["a", "b"]}):
        with pytest.raises(ValueError):
            hbc.compare([broken], tmp_path / "e", **bad)
        assert not (tmp_path / "e").exists(), bad


STUB_BLENDER = """#!/usr/bin/env python3
# Stands in for Blender: records its command line and HBC_ADDON_DIR, writes the comparison figure
# render_figures.py --compare would write (a copy of PNG) and says so as render_figures.py does.
import json, os, shutil, sys
args = sys.argv[1:]
with open(@LOG@, "a") as f:
    f.write(json.dumps({"argv": args, "addon": os.environ.get("HBC_ADDON_DIR")}) + "\\n")
a, b = args[args.index("--compare") + 1:args.index("--compare") + 3]
out = args[args.index("--out") + 1]
stem = lambda p: os.path.basename(p).split(".")[0]
path = os.path.join(out, f"compare_{stem(a)}_{stem(b)}.png")
shutil.copy(@PNG@, path)
print("wrote " + path)
"""


def test_figures_run_render_figures_per_pair(compared, tmp_path):
    """--figures: the add-on's figures/render_figures.py --compare (the add-on found by hbc.locate:
    the build's, beside this package) on the measured meshes two by two (the failed one left out;
    the odd last beside the first), each figure embedded. Blender itself is stubbed here (the
    panels are tested in tests/figures/)."""
    out, _, files, _ = compared
    work = tmp_path / "out"
    shutil.copytree(out, work)
    png = work / "panel.png"
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib import pyplot as plt
    fig = plt.figure(figsize=(2, 1))
    fig.text(0.5, 0.5, "panel")
    fig.savefig(png)
    log = tmp_path / "blender.log"
    stub = tmp_path / "blender"
    stub.write_text(STUB_BLENDER.replace("@LOG@", repr(str(log))).replace("@PNG@", repr(str(png))))
    stub.chmod(0o755)
    env = {k: v for k, v in os.environ.items() if k not in ("HBC_ADDON_DIR", "HBC_RENDER_FIGURES")}
    run = subprocess.run([sys.executable, "-m", "hbc.report", str(work), "--figures", "--blender", str(stub)],
                         capture_output=True, text=True, env=env)
    assert run.returncode == 0, run.stderr
    calls = [json.loads(ln) for ln in log.read_text().splitlines()]
    pairs = [c["argv"][c["argv"].index("--compare") + 1:][:2] for c in calls]
    assert pairs == [[files[0], files[2]], [files[3], files[0]]]
    import hbc

    addon = pathlib.Path(hbc.__file__).resolve().parents[2] / "addon" / "hybrid_base_complex"
    for c in calls:
        script = pathlib.Path(c["argv"][c["argv"].index("--python") + 1])
        assert script == addon / "figures" / "render_figures.py" and script.is_file()
        assert c["addon"] == str(addon)
    html = (work / "report.html").read_text()
    import base64
    embedded = base64.b64encode(png.read_bytes()).decode("ascii")
    assert html.count(embedded) == 2 and "Structure side by side" in html


def test_figures_rendered_by_blender(hbc_cli, shared_data_dir, tmp_path):
    """`hbc compare --figures` with the real Blender (Debian's, HBC_BLENDER overrides) and the build's
    add-on: one pair of meshes gives one comparison panel, embedded as a PNG that is not blank."""
    blender = os.environ.get("HBC_BLENDER") or shutil.which("blender")
    if not blender:
        pytest.fail("blender is not installed (scripts/env/deps.sh installs it)")
    files = [str(shared_data_dir / "hybrid-base-complex/cube_twist-comp.obj.HYBRID"),
             str(shared_data_dir / "hybrid-base-complex/twistcube_s.mesh")]
    out = tmp_path / "out"
    run = subprocess.run([hbc_cli, "compare", *files, "-o", str(out), "--figures"], capture_output=True, text=True,
                         env=report_env({"HBC_BLENDER": blender}), timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    html = (out / "report.html").read_text()
    import base64
    import io
    assert "Structure side by side" in html
    section = html.split("Structure side by side", 1)[1].split("<h2>Definitions</h2>", 1)[0]
    panels = re.findall(r'src="data:image/png;base64,([^"]+)"', section)
    assert len(panels) == 1, "one pair, one panel"
    from matplotlib import image as mpimg
    pixels = [mpimg.imread(io.BytesIO(base64.b64decode(b)), format="png") for b in panels]
    assert any(p.shape[0] >= 200 and p.shape[1] >= 300 and float(p[..., :3].std()) > 0.02 for p in pixels)


# ---- Chromium ------------------------------------------------------------------------------

def chromium():
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if not exe:
        pytest.fail("chromium is not installed (scripts/env/deps.sh installs it)")
    return exe


def chromium_run(url, tmp_path, *args):
    # No network (every host unresolvable), so that a fetch the report should not make fails and
    # shows up as a console error; logging of the page's console to stderr.
    cmd = [chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
           f"--user-data-dir={tmp_path / 'profile'}", "--host-resolver-rules=MAP * ~NOTFOUND",
           "--enable-logging=stderr", "--v=0", "--force-device-scale-factor=1", *args, url]
    env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}  # the sanitizer runtimes are for hbc
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, env=env)


def console_messages(stderr):
    return [ln for ln in stderr.splitlines() if "CONSOLE" in ln or "Uncaught" in ln or "net::ERR" in ln]


def test_report_in_chromium(compared, tmp_path):
    out, _, _, _ = compared
    url = (out / "report.html").resolve().as_uri()
    # The scan below must catch a console error: check it on a copy that makes one.
    bad = out / "bad.html"
    bad.write_text((out / "report.html").read_text().replace("</body>", "<script>console.error('x')</script></body>"))
    assert console_messages(chromium_run(bad.resolve().as_uri(), tmp_path, "--dump-dom").stderr)
    dom = chromium_run(url + "#layout", tmp_path, "--dump-dom", "--virtual-time-budget=5000")
    assert dom.returncode == 0, dom.stderr[-2000:]
    assert console_messages(dom.stderr) == []
    title = re.search(r"<title>layout:(.*?)</title>", dom.stdout)
    assert title, dom.stdout[:500]
    rects = json.loads(title.group(1))
    assert len(rects) == 4
    width = 1300
    height = max(y + h for _, y, _, h in rects) + 20
    shot = tmp_path / "report.png"
    run = chromium_run(url + "#layout", tmp_path, f"--screenshot={shot}", f"--window-size={width},{height}")
    assert run.returncode == 0 and shot.is_file(), run.stderr[-2000:]
    assert console_messages(run.stderr) == []
    import numpy as np
    from matplotlib import image
    pixels = image.imread(str(shot))[..., :3]
    gray = pixels.mean(axis=2)
    for x, y, w, h in rects:
        assert w > 200 and h > 100, (x, y, w, h)
        region = gray[y:y + h, x:x + w]
        assert region.shape == (h, w), "the image lies outside the screenshot"
        # A drawn plot: its pixels vary (a blank or broken image is one colour) and a part of them
        # is ink (bars, lines, text), not paper.
        assert region.std() > 0.05 and (region < 0.8).mean() > 0.01, (x, y, w, h)
    shutil.copy(shot, out / "report_screenshot.png")


def test_names_must_match_the_files(hbc_cli, shared_data_dir, tmp_path):
    # A malformed command line (exit 1), found before any mesh is measured or anything written.
    f = str(shared_data_dir / MESHES[0][1])
    run = subprocess.run([hbc_cli, "compare", f, f, "-o", str(tmp_path / "o"), "--names", "a"],
                         capture_output=True, text=True)
    assert run.returncode == 1 and "--names gives 1 names for 2 files" in run.stderr
    assert not (tmp_path / "o").exists()


def test_cli_report_python(hbc_cli, shared_data_dir, tmp_path):
    """The Python the command draws report.html with (native/tools/locate.cpp): $HBC_PYTHON when it
    is set (a wrong one fails the report alone, saying so); else the Python the build tree was
    configured for, so that the report is drawn with no python3 on PATH at all."""
    f = str(shared_data_dir / MESHES[0][1])
    env = {k: v for k, v in os.environ.items() if k != "HBC_PYTHON"}
    env["PATH"] = str(tmp_path / "nothing-here")
    run = subprocess.run([hbc_cli, "compare", f, "-o", str(tmp_path / "a")], capture_output=True, text=True, env=env)
    assert run.returncode == 0, run.stderr
    assert (tmp_path / "a" / "report.html").is_file()
    env["HBC_PYTHON"] = str(tmp_path / "no-such-python")
    run = subprocess.run([hbc_cli, "compare", f, "-o", str(tmp_path / "b")], capture_output=True, text=True, env=env)
    assert run.returncode == 2 and "no Python to run hbc.report (set HBC_PYTHON)" in run.stderr, run.stderr
    assert (tmp_path / "b" / "metrics.json").is_file() and not (tmp_path / "b" / "report.html").exists()
