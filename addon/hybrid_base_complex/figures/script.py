"""The figure script: the paper's pipeline panels of one mesh, or the comparison layout of two,
rendered in Blender's background mode with this add-on's own layer builders. Its command line is
`render_figures.py`'s (figures/plan.py parses it); run it through an entry file:

    blender -b --factory-startup --python-exit-code 1 --python <add-on>/figures/render_figures.py -- \
        MESH --out DIR [--engine cycles|eevee|workbench] [--samples N] [--resolution W H] [--sheet N]
    blender ... -- --compare A B --out DIR [...]

(or the repository's blender_scripts/render_figures.py, which finds the add-on first; with Blender as
a Python module, `python <entry> ARGS`).

One MESH: the paper's pipeline panels (Fig. 1), each a PNG `<name>_<letter>_<panel>.png` -
(a) the mesh (transparent boundary with its cell edges, non-hex cells coloured by type),
(b) the hybrid singularity graph, (c) the hybrid base complex (its components coloured, slight shrink),
(d) a sheet with its highlights (default: the largest self-intersecting sheet, else the largest
imperfect one, else the largest, within that class the largest with a non-empty VSG wireframe
first; --sheet N to choose), (e) its VSG, (f) its simplified VSG wireframe, (g) its largest
subsheets (self-intersecting sheets only), each above its wireframe - and `<name>_contact.png`,
all panels labelled. --compare A B: the paper's comparison layout, one column per mesh, rows mesh /
singularity graph / base complex / VSG wireframe / sheet, into `compare_<A>_<B>.png` (and the
panels). Every panel uses the same camera, framed on the mesh's bounding box. --legend adds under
each panel a strip of colour swatches with words (the add-on's legend for what the panel shows)
and writes `<name>_legend.json`. Each written file is printed as `wrote PATH`; any failure exits
non-zero.
"""

import os
import sys
import tempfile
import time
import traceback

import bpy

from . import animation
from . import animation_plan
from . import compose as C
from . import plan
from . import render as R


def wrote(path, written):
    written.append(path)
    print(f"wrote {path}", flush=True)


def stats_row(subject):
    P = subject.addon.P
    row = P.table1_row(subject.s.stats())
    head = "| mesh | " + " | ".join(label for label, _ in row) + " |"
    line = "|---|" + "---:|" * len(row)
    body = f"| {subject.name} | " + " | ".join(text for _, text in row) + " |"
    return "\n".join((head, line, body))


def sheet_caption(subject):
    if subject.sheet is None:
        return ""
    return f"sheet {subject.sheet}, {subject.addon.P.SHEET_TYPES[subject.sheet_type]}"


def start(args, path):
    """A fresh file with the studio set up around one analyzed mesh."""
    addon = R.Addon()
    scene = R.reset_file()
    w, h = args.resolution
    look = plan.LOOKS[args.look]
    R.setup_render(scene, args.engine, args.samples, w, h, addon.compat, args.denoise, look)
    R.setup_world(scene, args.engine, addon.compat, look)
    subject = R.Subject(addon, path, args, scene)
    R.add_camera(scene, subject.camera, subject.points)
    R.add_lights(scene, subject.camera, subject.points)
    return scene, subject


def render_panel(scene, subject, key, colls, path, written):
    subject.show(colls)
    t = R.render_to(scene, path)
    R.log(f"render_figures: {key}: {t:.1f} s")
    wrote(path, written)


def highlights_shown(colls, subsheets=None):
    """The sheet highlights (hbc_highlight) among the objects a panel renders; for panel g only
    those of the subsheets it shows."""
    return {ob["hbc_highlight"] for c in colls for ob in c.objects
            if ob.get("hbc_highlight") and (subsheets is None or ob.get("hbc_subsheet") in subsheets)}


def legend_of(subject, key, highlights=()):
    return plan.panel_legend(subject.addon.P, key, subject.s.legend_facts(), highlights,
                             subject.args.wire_colors == "kind")


def add_legends(items, args, name, written):
    """--legend: every panel of `items` ([(key, path, entries)]) with entries gets its strip under it,
    all strips of the run one height (the most rows any panel needs), so panels stay the same size;
    the PNG is rewritten and `<name>_legend.json` lists each panel's entries, colours (display
    sRGB) and where their swatches and words are."""
    import json

    m = plan.LegendMetrics.for_panel(args.resolution[1])
    texts = sorted({words for _, _, entries in items for _, words, _ in entries})
    if not texts:
        R.log("render_figures: --legend: no panel shows colours a legend names")
        return
    tmp = tempfile.mkdtemp(prefix="hbc_fig_")
    width = 20 * m.row  # room for the longest words (planning.LEGEND_MAX characters)
    images = R.render_labels(texts, width, m.row, tmp)
    os.rmdir(tmp)
    words = {}
    for text, img in zip(texts, images):
        ink = C.ink_columns(img)
        if ink is None or ink[1] >= width:
            raise RuntimeError(f"legend: the words {text!r} rendered as nothing or cut off")
        words[text] = img[:, ink[0]:ink[1]]
    panels = []
    loaded = {path: R.load_png(path) for _, path, entries in items if entries}
    layouts = {path: plan.legend_layout([words[w].shape[1] for _, w, _ in entries], loaded[path].shape[1], m)
               for _, path, entries in items if entries}
    rows = max(layout.rows for layout in layouts.values())
    height = plan.strip_height(m, rows)
    for key, path, entries in items:
        if not entries:
            continue
        img = loaded[path]
        layout = plan.legend_layout([words[w].shape[1] for _, w, _ in entries], img.shape[1], m, rows)
        strip = C.legend_strip(img.shape[1], height, [c for _, _, c in entries], [words[w] for _, w, _ in entries],
                               layout)
        R.save_png(C.stack(img, strip), path)
        h0 = img.shape[0]
        panels.append({
            "file": os.path.basename(path), "panel": key, "height_without_strip": h0,
            "entries": [{"key": k, "words": w, "srgb": [round(float(v), 4) for v in C.linear_to_srgb(c[:3])],
                         "swatch": [x, h0 + y, side], "words_at": [wx, h0 + wy, int(words[w].shape[1]), m.row]}
                        for (k, w, c), (x, y, side), (wx, wy) in zip(entries, layout.swatches, layout.words)]})
        R.log(f"render_figures: legend under {os.path.basename(path)}: {len(entries)} entries, "
              f"{layout.rows} row(s) of {layout.columns}")
    path = os.path.abspath(os.path.join(args.out, f"{name}_legend.json"))
    with open(path, "w") as f:
        json.dump({"strip_height": height, "row": m.row, "panels": panels}, f, indent=1)
    wrote(path, written)


def same_height(tiles):
    """Tiles padded below to the tallest (panels with and without a legend strip)."""
    h = max(t.shape[0] for t in tiles if t is not None)
    return [C.pad_to_height(t, h) if t is not None else None for t in tiles]


def render_subsheets(scene, subject, args, path, written):
    """Panel g: the largest subsheets side by side, each above its VSG wireframe, each tile the
    same view of the whole mesh (framed for the tile's shape)."""
    built = subject.subsheet_tiles()
    if built is None:
        R.log(f"render_figures: panel g skipped: {sheet_caption(subject) or 'no sheets'} "
              f"(only self-intersecting sheets have subsheets)")
        return None
    coll, picked, count = built
    w, h = args.resolution
    gw = 2 * w + C.PAD  # two contact-sheet columns wide
    (tw, th), cols = plan.tile_grid(len(picked), gw, h)
    cam = plan.frame(plan.framing_points(subject.points), subject.direction, args.up, tw, th)
    R.place_camera(scene.camera, cam)
    scene.render.resolution_x, scene.render.resolution_y = tw, th
    shell = subject.shell()
    tiles, where = [], []
    tmp = tempfile.mkdtemp(prefix="hbc_fig_")
    try:
        for k, (top, bottom) in zip(picked, cols):
            for wire, pos in ((False, top), (True, bottom)):
                for ob in coll.objects:
                    mine = ob.get("hbc_subsheet") == k
                    is_wire = bool(ob.get("hbc_wireframe", False))
                    ob.hide_render = not (mine and is_wire == wire)
                subject.show([coll] + shell)
                tile = os.path.join(tmp, f"tile_{k}_{int(wire)}.png")
                R.render_to(scene, tile)
                tiles.append(R.load_png(tile))
                where.append(pos)
                os.remove(tile)
    finally:
        os.rmdir(tmp) if os.path.isdir(tmp) and not os.listdir(tmp) else None
        R.place_camera(scene.camera, subject.camera)
        scene.render.resolution_x, scene.render.resolution_y = w, h
    g = subject.look.background
    bg = (g, g, g, 1.0)
    img = C.tiles_panel(tiles, where, gw, h, bg)
    R.save_png(img, path)
    wrote(path, written)
    R.log(f"render_figures: subsheets {picked} of {count} shown")
    subject.subsheets_shown = (picked, count)
    subject.subsheets_highlights = highlights_shown([coll], set(picked))
    return path


def panel_label(subject, key):
    t = f"({plan.PANEL_LETTER[key]}) {plan.PANEL_TITLE[key]}"
    if subject.sheet is None:
        return t
    name = subject.addon.P.SHEET_TYPES[subject.sheet_type]
    if key == "sheet":
        return f"{t} {subject.sheet} ({name})"
    if key in ("vsg", "wireframe"):
        return f"{t} of sheet {subject.sheet}"
    if key == "subsheets":
        picked, count = getattr(subject, "subsheets_shown", ((), 0))
        more = f", the {len(picked)} largest of {count}" if len(picked) < count else ""
        return f"{t} of sheet {subject.sheet}{more}, each above its VSG wireframe"
    return t


def single(args):
    scene, subject = start(args, args.mesh)
    print(stats_row(subject), flush=True)
    R.log(f"render_figures: {subject.name}: {subject.s.num_cells} cells, analyzed in {subject.t_analysis:.2f} s; "
          f"panels d-g: {sheet_caption(subject) or 'no sheets'}")
    os.makedirs(args.out, exist_ok=True)
    written, shown, legends = [], [], []
    for key in args.panels:
        letter = plan.PANEL_LETTER[key]
        path = os.path.abspath(os.path.join(args.out, f"{subject.name}_{letter}_{key}.png"))
        if key == "subsheets":
            if render_subsheets(scene, subject, args, path, written):
                shown.append((key, path))
                legends.append((key, path, legend_of(subject, key, subject.subsheets_highlights)))
            continue
        colls = getattr(subject, f"panel_{key}")()
        if colls is None:
            R.log(f"render_figures: panel {letter} ({key}) skipped: nothing to show for "
                  f"{sheet_caption(subject) or 'this mesh'}")
            continue
        render_panel(scene, subject, key, colls, path, written)
        shown.append((key, path))
        legends.append((key, path, legend_of(subject, key, highlights_shown(colls))))
    if args.legend:
        add_legends(legends, args, subject.name, written)
    if args.blend:
        blend = os.path.abspath(os.path.join(args.out, f"{subject.name}_figures.blend"))
        bpy.ops.wm.save_as_mainfile(filepath=blend, check_existing=False)
        wrote(blend, written)
    if not shown:
        raise RuntimeError("no panel rendered")
    # Contact sheet: panel g spans two columns.
    w, h = args.resolution
    label_h = max(14, round(h * 0.07))
    spans = [2 if key == "subsheets" else 1 for key, _ in shown]
    texts = [panel_label(subject, key) for key, _ in shown]
    tmp = tempfile.mkdtemp(prefix="hbc_fig_")
    labels = [R.render_labels([t], span * w + (span - 1) * C.PAD, label_h, tmp)[0] for t, span in zip(texts, spans)]
    os.rmdir(tmp)
    tiles = same_height([R.load_png(p) for _, p in shown])
    sheet = C.contact_sheet(tiles, labels, C.contact_columns(spans), spans)
    path = os.path.abspath(os.path.join(args.out, f"{subject.name}_contact.png"))
    R.save_png(sheet, path)
    wrote(path, written)
    return written


def compare(args):
    written = []
    columns, names = [], []
    os.makedirs(args.out, exist_ok=True)
    legends = []
    for mesh in args.compare:
        scene, subject = start(args, mesh)
        print(stats_row(subject), flush=True)
        names.append(subject.name)
        col = []
        for key, title in plan.COMPARE_ROWS:
            path = os.path.abspath(os.path.join(args.out, f"{subject.name}_{key}.png"))
            colls = getattr(subject, f"panel_{key}")()
            if colls is None:
                R.log(f"render_figures: {subject.name}: {title} skipped: nothing to show")
                col.append(None)
                continue
            render_panel(scene, subject, key, colls, path, written)
            col.append(path)
            legends.append((key, path, legend_of(subject, key, highlights_shown(colls))))
        columns.append(col)
    if args.legend:
        add_legends(legends, args, "compare_" + "_".join(names), written)
    w, h = args.resolution
    label_h = max(14, round(h * 0.07))
    tmp = tempfile.mkdtemp(prefix="hbc_fig_")
    heads = R.render_labels([f"({chr(97 + i)}) {n}" for i, n in enumerate(names)], w, label_h, tmp, align="CENTER")
    row_w = max(120, round(w * 0.4))
    rows = R.render_labels([title for _, title in plan.COMPARE_ROWS], row_w, label_h, tmp)
    os.rmdir(tmp)
    n = len(plan.COMPARE_ROWS)
    flat = same_height([R.load_png(columns[c][r]) if columns[c][r] else None for r in range(n) for c in range(len(columns))])
    cells = [flat[r * len(columns):(r + 1) * len(columns)] for r in range(n)]
    if all(t is None for r in cells for t in r):
        raise RuntimeError("no panel rendered")
    img = C.table(cells, rows, heads)
    a, b = names
    path = os.path.abspath(os.path.join(args.out, f"compare_{a}_{b}.png"))
    R.save_png(img, path)
    wrote(path, written)
    return written


def main(argv):
    args = plan.parse(plan.script_args(argv), (animation_plan,))
    t = time.perf_counter()
    if args.animate:
        written = animation.animate(args, start, wrote)
    else:
        written = compare(args) if args.compare else single(args)
    R.log(f"render_figures: {len(written)} files in {time.perf_counter() - t:.1f} s")


def run(argv):
    """main(argv), exiting non-zero with the traceback on any failure (an entry file's whole job)."""
    try:
        main(argv)
    except SystemExit:
        raise
    except BaseException:  # noqa: BLE001 - report and exit non-zero whatever went wrong
        traceback.print_exc()
        sys.stdout.flush()
        sys.exit(1)
