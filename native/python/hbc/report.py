"""The comparison report of several meshes: ``report.html``, one self-contained file (docs/compare.md).

``hbc.compare(paths, out)`` (hbc/comparison.py) and the ``hbc compare`` command write
``DIR/metrics.json``, ``metrics.csv`` and ``metrics.tex``; this module reads ``metrics.json`` only
and writes ``DIR/report.html``: the table, bar charts of the key metrics, histograms (singular edge
valences, component sizes, scaled Jacobian per cell type), every metric's definition, and with
``--figures`` the comparison panels rendered by Blender (the add-on's
``figures/render_figures.py --compare``; hbc.locate says where Blender and the add-on are looked
for). Images are inline (base64 PNG): nothing is fetched when the file is opened.

    python -m hbc.report DIR [--figures] [--blender CMD] [--addon DIR] [--engine E]

hbc.compare() calls ``write_report(out)`` in its own process; the command runs this module.
Plots need matplotlib, imported only when drawing.
"""

from __future__ import annotations

import argparse
import base64
import datetime
import html
import io
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

from . import locate

# The headings of docs/metrics.md's generated tables (scripts/metrics_doc.py), whose anchors the
# report links to; tests/python/test_compare.py checks that each heading is there.
GROUP_TITLES = {"census": "Census", "singular": "Singular structure", "complex": "Hybrid base complex",
                "sheets": "Sheets", "non_hex": "Non-hex clustering", "quality": "Quality beside structure",
                "summary": "Summary"}
# How a metric changes when every cell is split into 8 (the words of docs/metrics.md).
REFINEMENT = {"invariant": "unchanged", "x8": "× 8", "x2": "× 2", "x4": "× 4", "none": "no rule"}
# The bar charts: what a reader compares first (metric keys of metric_fields()).
KEY_METRICS = ["census.hex_ratio", "census.hex_volume_ratio", "singular.singularities", "singular.length",
               "complex.components", "complex.blocks", "sheets.sheets", "sheets.perfect_cell_share",
               "non_hex.regions", "quality.sj_min", "quality.sj_mean", "summary.score"]


def anchor(group: str) -> str:
    """GitHub's anchor of a docs/metrics.md heading: lower case, spaces to dashes."""
    title = GROUP_TITLES.get(group, group)
    return "".join(c for c in title.lower().replace(" ", "-") if c.isalnum() or c == "-")


class ReportError(Exception):
    """The report cannot be written (a missing dependency, an unreadable metrics.json)."""


# ---- plots ---------------------------------------------------------------------------------

def _pyplot():
    try:
        import matplotlib
    except ImportError as e:
        raise ReportError(
            f"matplotlib is not installed for {sys.executable} (Debian: apt-get install python3-matplotlib; "
            "else pip install matplotlib; the hbc command draws the report with $HBC_PYTHON, which can name a "
            "Python that has it)") from e
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plt.rcParams.update({"font.size": 9, "axes.spines.top": False, "axes.spines.right": False,
                         "axes.titlesize": 9, "axes.titleweight": "bold", "legend.fontsize": 8,
                         "svg.fonttype": "none"})
    return plt


def _png(fig) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight", facecolor="white")
    fig.clf()
    import matplotlib.pyplot as plt
    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def _colors(n: int):
    plt = _pyplot()
    cmap = plt.get_cmap("tab10" if n <= 10 else "tab20")
    return [cmap(i % cmap.N) for i in range(n)]


LEGEND_COLUMNS = 5
LEGEND_ROW_IN = 0.2  # inches per legend row


def _legend_rows(n: int) -> int:
    return math.ceil(n / LEGEND_COLUMNS)


def _legend_on_top(fig, colors, labels, height_in: float):
    """One legend of colour swatches above the panels, and the panels laid out under it."""
    import matplotlib.pyplot as plt
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in colors]
    fig.legend(handles, labels, loc="upper center", ncol=min(len(labels), LEGEND_COLUMNS), frameon=False,
               bbox_to_anchor=(0.5, 1.0))
    fig.tight_layout(rect=(0, 0, 1, 1 - (0.1 + LEGEND_ROW_IN * _legend_rows(len(labels))) / height_in))


def bar_charts(data: dict, ok: list[int]) -> str:
    plt = _pyplot()
    fields = {f["key"]: f for f in data["fields"]}
    keys = [k for k in KEY_METRICS if k in fields]
    colors = _colors(len(data["meshes"]))
    # Panels wide enough for their bars; as many a row as fit in about 11 inches.
    panel_w = max(2.5, 0.22 * len(ok) + 0.8)
    cols = max(1, min(4, int(11 // panel_w)))
    rows = math.ceil(len(keys) / cols)
    height = 2.2 * rows + 0.1 + LEGEND_ROW_IN * _legend_rows(len(ok))
    fig, axes = plt.subplots(rows, cols, figsize=(cols * panel_w, height), squeeze=False)
    for ax, key in zip(axes.flat, keys):
        vals = [data["values"][key][i] for i in ok]
        f = fields[key]
        bars = ax.bar(range(len(ok)), [v if v is not None else 0.0 for v in vals], color=[colors[i] for i in ok])
        # The value over each bar (undefined: a dash at 0), so the chart reads without the table.
        for b, v in zip(bars, vals):
            text = "–" if v is None else _fmt(v, f["unit"]).replace("\u2009", "")
            y = b.get_height()
            ax.annotate(text, (b.get_x() + b.get_width() / 2, y), xytext=(0, 2 if y >= 0 else -2),
                        textcoords="offset points", ha="center", va="bottom" if y >= 0 else "top",
                        fontsize=7 if len(ok) <= 10 else 6, rotation=0 if len(ok) <= 10 else 90)
        unit = "" if f["unit"] == "ratio" else f" ({f['unit']})"
        ax.set_title(f["label"] + unit)
        ax.set_xticks([])
        ax.axhline(0, color="0.3", linewidth=0.8)
        ax.margins(y=0.15 if len(ok) <= 10 else 0.3)
        ax.grid(axis="y", alpha=0.3)
    for ax in list(axes.flat)[len(keys):]:
        ax.set_visible(False)
    _legend_on_top(fig, [colors[i] for i in ok], [data["meshes"][i]["name"] for i in ok], height)
    return _png(fig)


def _grouped_bars(ax, series: list[dict], names, colors, xlabel):
    xs = sorted({int(k) for s in series for k in s})
    if not xs:
        ax.text(0.5, 0.5, "none", ha="center", va="center", transform=ax.transAxes, color="0.5")
        ax.set_xticks([])
        return
    n = max(1, len(series))
    w = 0.8 / n
    for j, s in enumerate(series):
        ax.bar([x + (j - (n - 1) / 2) * w for x in range(len(xs))], [s.get(str(v), 0) for v in xs], w,
               color=colors[j], label=names[j])
    ax.set_xticks(range(len(xs)))
    ax.set_xticklabels([str(v) for v in xs])
    ax.set_xlabel(xlabel)
    ax.set_ylabel("edges")
    ax.grid(axis="y", alpha=0.3)


def valence_histograms(data: dict, ok: list[int]) -> str:
    plt = _pyplot()
    colors = _colors(len(data["meshes"]))
    names = [data["meshes"][i]["name"] for i in ok]
    height = 2.8 + LEGEND_ROW_IN * _legend_rows(len(ok))
    fig, axes = plt.subplots(1, 2, figsize=(10, height))
    for ax, key, title in ((axes[0], "valence_interior", "Interior singular edges by valence"),
                           (axes[1], "valence_boundary", "Boundary singular edges by valence")):
        series = [data["metrics"][i]["singular"][key] for i in ok]
        _grouped_bars(ax, series, names, [colors[i] for i in ok], "valence (hexahedra around the edge)")
        ax.set_title(title)
    _legend_on_top(fig, [colors[i] for i in ok], names, height)
    return _png(fig)


def component_histogram(data: dict, ok: list[int]) -> str:
    plt = _pyplot()
    colors = _colors(len(data["meshes"]))
    sizes = [data["metrics"][i]["complex"]["component_cells"] for i in ok]
    top = max([max(s) for s in sizes if s] + [1])
    edges = [2 ** k for k in range(0, max(1, math.ceil(math.log2(top + 1))) + 1)]
    height = 2.8 + LEGEND_ROW_IN * _legend_rows(len(ok))
    fig, ax = plt.subplots(figsize=(10, height))
    # Shares of each mesh's components, so meshes of 10^3 and 10^5 cells read on one axis.
    for j, (i, s) in enumerate(zip(ok, sizes)):
        counts = [0] * (len(edges) - 1)
        for v in s:
            b = min(len(counts) - 1, max(0, int(math.floor(math.log2(max(v, 1))))))
            counts[b] += 1
        w = 0.8 / len(ok)
        ax.bar([x + (j - (len(ok) - 1) / 2) * w for x in range(len(counts))], [c / max(1, len(s)) for c in counts],
               w, color=colors[i])
    ax.set_xticks(range(len(edges) - 1))
    ax.set_xticklabels([f"{edges[k]}-{edges[k + 1] - 1}" if edges[k + 1] - 1 > edges[k] else str(edges[k])
                        for k in range(len(edges) - 1)], rotation=30, ha="right", fontsize=7)
    ax.set_xlabel("cells per component of hexahedra (base complex)")
    ax.set_ylabel("share of the components")
    ax.set_title("Component sizes")
    ax.grid(axis="y", alpha=0.3)
    _legend_on_top(fig, [colors[i] for i in ok],
                   [f"{data['meshes'][i]['name']} ({len(s)})" for i, s in zip(ok, sizes)], height)
    return _png(fig)


def jacobian_histograms(data: dict, ok: list[int]) -> str:
    plt = _pyplot()
    colors = _colors(len(data["meshes"]))
    sj = data["scaled_jacobian_histograms"]
    edges = sj["bin_edges"]
    # cell_type_name()'s names, in the census' order.
    types = {"hex": "hexahedra", "prism": "prisms", "pyramid": "pyramids", "tet": "tetrahedra",
             "polyhedron": "polyhedra"}
    present = [t for t in types if any(t in (sj["by_type"][i] or {}) for i in ok)]
    cols = min(3, max(1, len(present)))
    rows = max(1, math.ceil(len(present) / cols))
    # Up to 6 meshes a legend per panel with each mesh's cells of that type; more, one on top.
    many = len(ok) > 6
    height = 2.9 * rows + (LEGEND_ROW_IN * _legend_rows(len(ok)) if many else 0)
    fig, axes = plt.subplots(rows, cols, figsize=(max(5.0, 3.4 * cols), height), squeeze=False)
    for ax in list(axes.flat)[len(present):]:
        ax.set_visible(False)
    for ax, t in zip(axes.flat, present):
        for i in ok:
            counts = (sj["by_type"][i] or {}).get(t)
            if not counts:
                continue
            total = sum(counts)
            ax.stairs([c / total for c in counts], edges, color=colors[i], linewidth=1.6,
                      label=f"{data['meshes'][i]['name']} ({total})")
        ax.set_title(f"Scaled Jacobian, {types[t]}")
        ax.set_xlim(-1, 1)
        ax.axvline(0, color="0.6", linewidth=0.8, linestyle=":")
        ax.set_xlabel("scaled Jacobian")
        ax.set_ylabel("share of the type's cells")
        if not many:
            ax.legend(loc="upper left", frameon=False, fontsize=7)
    if many:
        _legend_on_top(fig, [colors[i] for i in ok], [data["meshes"][i]["name"] for i in ok], height)
    else:
        fig.tight_layout()
    return _png(fig)


# ---- Blender panels ------------------------------------------------------------------------

def render_panels(data: dict, ok: list[int], out: pathlib.Path, args) -> list[tuple[str, str]]:
    """Renders the paper's comparison layout (render_figures.py --compare) for the meshes two by two
    (an odd last one beside the first); returns (caption, base64 PNG) per figure."""
    try:
        addon = pathlib.Path(args.addon) if args.addon else locate.addon_dir()
        script = locate.figures_script(addon)
        blender = args.blender or locate.blender()
    except locate.LocateError as e:
        raise ReportError(f"--figures: {e}") from e
    figdir = out / "figures"
    figdir.mkdir(exist_ok=True)
    pairs = [ok[k:k + 2] for k in range(0, len(ok), 2)]
    if len(pairs[-1]) == 1 and len(ok) > 1:
        pairs[-1] = [pairs[-1][0], ok[0]]
    figures = []
    # The add-on's entry renders with its own package; HBC_ADDON_DIR tells a deprecated
    # HBC_RENDER_FIGURES script (blender_scripts/render_figures.py) the same add-on.
    env = dict(os.environ, HBC_ADDON_DIR=str(addon))
    cfg = tempfile.mkdtemp(prefix="hbc-report-blender-")
    env.update(BLENDER_USER_CONFIG=cfg + "/config", BLENDER_USER_SCRIPTS=cfg + "/scripts")
    for pair in pairs:
        if len(pair) < 2:
            continue
        files = [data["meshes"][i]["file"] for i in pair]
        cmd = [blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", str(script), "--",
               "--compare", *files, "--out", str(figdir), "--engine", args.engine,
               "--resolution", "360", "270", "--legend"]
        print(f"hbc.report: rendering {' / '.join(data['meshes'][i]['name'] for i in pair)} in Blender",
              file=sys.stderr, flush=True)
        run = subprocess.run(cmd, env=env, capture_output=True, text=True)
        wrote = [ln[6:].strip() for ln in run.stdout.splitlines() if ln.startswith("wrote ")]
        compare_png = [p for p in wrote if os.path.basename(p).startswith("compare_") and p.endswith(".png")]
        if run.returncode != 0 or not compare_png:
            tail = "\n".join((run.stdout + run.stderr).splitlines()[-15:])
            raise ReportError(f"--figures: Blender failed on {files}:\n{tail}")
        caption = ", ".join(f"({chr(97 + k)}) {data['meshes'][i]['name']}" for k, i in enumerate(pair))
        figures.append((caption, base64.b64encode(pathlib.Path(compare_png[-1]).read_bytes()).decode("ascii")))
    shutil.rmtree(cfg, ignore_errors=True)
    return figures


# ---- HTML ----------------------------------------------------------------------------------

CSS = """
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:2em auto;max-width:1200px;
color:#222;padding:0 1em;line-height:1.4}
h1{font-size:1.5em;margin-bottom:.2em} h2{font-size:1.2em;margin-top:2em;border-bottom:1px solid #ddd}
.meta{color:#666;font-size:.9em} table{border-collapse:collapse;font-size:.85em}
th,td{padding:2px 8px} thead th{border-bottom:2px solid #444;text-align:right;position:sticky;top:0;background:#fff}
thead th:first-child,thead th:nth-child(2){text-align:left}
td.num{text-align:right;font-variant-numeric:tabular-nums} tr.group td{font-weight:bold;font-style:italic;
padding-top:.8em;border-bottom:1px solid #ccc} tbody tr:hover{background:#f4f6fa}
td.failed{color:#b00;text-align:center} .errors{background:#fff3f3;border:1px solid #e0b0b0;padding:.5em 1em}
.swatch{display:inline-block;width:.8em;height:.8em;margin-right:.3em;vertical-align:baseline}
figure{margin:1em 0} figure img{max-width:100%;border:1px solid #eee} figcaption{color:#555;font-size:.9em}
.scroll{overflow-x:auto;max-width:100%} #metrics td:first-child,#metrics td:nth-child(2){white-space:nowrap}
#metrics thead th{white-space:nowrap} table.defs td{vertical-align:top;border-bottom:1px solid #eee} table.defs th{text-align:left} code{font-size:.9em}
"""


def _fmt(v, unit):
    if v is None:
        return "–"
    if isinstance(v, float) and (math.isnan(v) or math.isinf(v)):
        return "–"
    if unit == "ratio" or (isinstance(v, float) and v != int(v)):
        return f"{v:.3f}"
    return f"{int(v):,}".replace(",", "\u2009")


def _hex(c):
    return "#%02x%02x%02x" % tuple(int(255 * x) for x in c[:3])


def metrics_table(data: dict, docs: str) -> str:
    e = html.escape
    meshes = data["meshes"]
    colors = [_hex(c) for c in _colors(len(meshes))]
    head = "".join(f'<th><span class="swatch" style="background:{colors[i]}"></span>{e(m["name"])}</th>'
                   for i, m in enumerate(meshes))
    rows, group = [], None
    for f in data["fields"]:
        if f["group"] != group:
            group = f["group"]
            rows.append(f'<tr class="group"><td colspan="{2 + len(meshes)}">'
                        f'<a href="{e(docs)}#{anchor(group)}">{e(GROUP_TITLES.get(group, group))}</a></td></tr>')
        cells = []
        for i, m in enumerate(meshes):
            if m["error"]:
                cells.append('<td class="failed">failed</td>')
            else:
                cells.append(f'<td class="num">{_fmt(data["values"][f["key"]][i], f["unit"])}</td>')
        unit = "" if f["unit"] == "ratio" else f["unit"]
        rows.append(f'<tr><td title="{e(f["meaning"])}">{e(f["label"])}</td><td>{e(unit)}</td>{"".join(cells)}</tr>')
    # Many meshes make a wide table: it scrolls on its own, the page does not.
    return (f'<div class="scroll"><table id="metrics"><thead><tr><th>metric</th><th>unit</th>{head}</tr></thead>'
            f'<tbody>{"".join(rows)}</tbody></table></div>')


def definitions(data: dict, docs: str) -> str:
    e = html.escape
    rows = "".join(
        f'<tr><td><a href="{e(docs)}#{anchor(f["group"])}"><code>{e(f["key"])}</code></a></td><td>{e(f["label"])}</td>'
        f'<td>{e(f["unit"])}</td><td>{REFINEMENT.get(f["refinement"], e(f["refinement"]))}</td>'
        f'<td>{e(f["meaning"])}</td></tr>'
        for f in data["fields"])
    return ('<table class="defs"><thead><tr><th>metric</th><th>label</th><th>unit</th>'
            '<th>under uniform refinement</th><th>meaning</th></tr></thead>'
            f"<tbody>{rows}</tbody></table>")


def _img(b64: str, alt: str, caption: str) -> str:
    return (f'<figure><img class="plot" alt="{html.escape(alt)}" src="data:image/png;base64,{b64}">'
            f"<figcaption>{caption}</figcaption></figure>")


# Reports the layout of the images (for the browser test) when opened as report.html#layout: the
# title becomes their bounding boxes, which `chromium --dump-dom` prints.
LAYOUT_SCRIPT = """<script>
if (location.hash === "#layout") {
  window.addEventListener("load", () => {
    const r = [...document.querySelectorAll("img.plot")].map(i => {
      const b = i.getBoundingClientRect();
      return [Math.round(b.left + scrollX), Math.round(b.top + scrollY), Math.round(b.width), Math.round(b.height)];
    });
    document.title = "layout:" + JSON.stringify(r);
  });
}
</script>"""


def build_html(data: dict, plots: list[tuple[str, str, str]], panels: list[tuple[str, str]], docs: str) -> str:
    e = html.escape
    meshes = data["meshes"]
    errors = data.get("errors") or {}
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    files = "".join(f"<li><b>{e(m['name'])}</b>: <code>{e(m['file'])}</code></li>" for m in meshes)
    err = ""
    if errors:
        err = ('<div class="errors"><b>Failed meshes</b> (their columns are empty):<ul>'
               + "".join(f"<li><b>{e(k)}</b>: <code>{e(v)}</code></li>" for k, v in errors.items()) + "</ul></div>")
    parts = [f"<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\">"
             f"<title>hbc compare: {e(', '.join(m['name'] for m in meshes))}</title><style>{CSS}</style>"
             f"{LAYOUT_SCRIPT}</head><body>",
             f"<h1>Structure of {len(meshes)} hex-dominant meshes</h1>",
             f'<p class="meta">hbc {e(str(data.get("hbc_version", "")))} · {when} · metric definitions: '
             f'<a href="{e(docs)}">docs/metrics.md</a> (hover a label for its meaning)</p>',
             f"<details{' open' if len(meshes) <= 6 else ''} class=\"meta\"><summary>{len(meshes)} files</summary>"
             f"<ul>{files}</ul></details>", err,
             "<h2>Metrics</h2>", metrics_table(data, docs)]
    if plots:
        parts.append("<h2>Key metrics and distributions</h2>")
        parts += [_img(b64, alt, cap) for alt, b64, cap in plots]
    if panels:
        parts.append("<h2>Structure side by side (Blender)</h2>")
        parts += [_img(b64, cap, f"{e(cap)}; rows: the mesh, its singularity graph, base complex, VSG wireframe "
                                 "and a sheet (the add-on's figures/render_figures.py --compare)")
                  for cap, b64 in panels]
    parts += ["<h2>Definitions</h2>", definitions(data, docs), "</body></html>\n"]
    return "\n".join(parts)


def write_report(out, figures: bool = False, args=None) -> pathlib.Path:
    """Writes ``out/report.html`` from ``out/metrics.json``; returns its path."""
    out = pathlib.Path(out)
    args = args or parse_args([str(out)])
    try:
        data = json.loads((out / "metrics.json").read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        raise ReportError(f"cannot read {out / 'metrics.json'}: {e}") from e
    ok = [i for i, m in enumerate(data["meshes"]) if not m["error"]]
    plots = []
    if ok:
        plots = [("key metrics", bar_charts(data, ok), "Key metrics (definitions below)."),
                 ("singular edge valences", valence_histograms(data, ok),
                  "Singular edges by valence: interior (regular 4) and boundary (regular 2)."),
                 ("component sizes", component_histogram(data, ok),
                  "Components of hexahedra of the hybrid base complex by cell count (bins of powers of 2; share of "
                  "each mesh's components, their number in the legend)."),
                 ("scaled Jacobian per cell type", jacobian_histograms(data, ok),
                  "Scaled Jacobian per cell type (share of that type's cells per bin of 0.1; cell count in "
                  "the legend; below 0: inverted).")]
    panels = render_panels(data, ok, out, args) if figures and ok else []
    path = out / "report.html"
    path.write_text(build_html(data, plots, panels, locate.metrics_doc()), encoding="utf-8")
    return path


# ---- entry points --------------------------------------------------------------------------

def parse_args(argv):
    ap = argparse.ArgumentParser(prog="python -m hbc.report",
                                 description="Writes DIR/report.html from DIR/metrics.json (hbc compare).")
    ap.add_argument("dir")
    ap.add_argument("--figures", action="store_true", help="render the comparison panels in Blender")
    ap.add_argument("--blender", help="the Blender command (default: hbc.locate.blender(): $HBC_BLENDER, else blender)")
    ap.add_argument("--addon", help="the add-on package whose figures/render_figures.py renders (default: "
                                    "hbc.locate.addon_dir(): $HBC_ADDON_DIR, else the build's)")
    ap.add_argument("--engine", default="workbench", choices=["workbench", "eevee", "cycles"])
    return ap.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        path = write_report(args.dir, args.figures, args)
    except ReportError as e:
        print(f"hbc.report: error: {e}", file=sys.stderr)
        return 3
    print(f"hbc.report: wrote {path}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
