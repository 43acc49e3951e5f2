"""Publication figures of a hex-dominant mesh, rendered in Blender's background mode.

    blender -b --factory-startup --python-exit-code 1 --python blender_scripts/render_figures.py -- \
        MESH --out DIR [--engine cycles|eevee|workbench] [--samples N] [--resolution W H] [--sheet N]
    blender ... -- --compare A B --out DIR [...]

One MESH: the paper's pipeline panels (Fig. 1), each a PNG `<name>_<letter>_<panel>.png` -
(a) the mesh (transparent boundary with its cell edges, non-hex cells coloured by type),
(b) the hybrid singularity graph, (c) the hybrid base complex (coloured blocks, slight shrink),
(d) a sheet with its highlights (default: the largest self-intersecting sheet, else the largest
imperfect one, else the largest, within that class the largest with a non-empty VSG wireframe
first; --sheet N to choose), (e) its VSG, (f) its simplified VSG wireframe, (g) its largest
subsheets (self-intersecting sheets only), each above its wireframe - and `<name>_contact.png`,
all panels labelled. --compare A B: the paper's comparison layout, one column per mesh, rows mesh /
singularity graph / base complex / VSG wireframe / sheet, into `compare_<A>_<B>.png` (and the
panels). Every panel uses the same camera, framed on the mesh's bounding box. Each written file is printed as `wrote PATH`; any failure exits non-zero.

The add-on is taken from --addon, else $HBC_ADDON_DIR, else <repo>/build/addon/hybrid_base_complex
(the build's `addon` target, with the compiled hbc module inside).
"""

import os
import sys
import tempfile
import time
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bpy  # noqa: E402

from figures import compose as C  # noqa: E402
from figures import plan  # noqa: E402
from figures import render as R  # noqa: E402


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
    return f"sheet {subject.sheet}, {plan.SHEET_TYPE_NAMES[subject.sheet_type]}"


def start(args, path):
    """A fresh file with the studio set up around one analyzed mesh."""
    scene = R.reset_file()
    w, h = args.resolution
    R.setup_render(scene, args.engine, args.samples, w, h, ADDON.compat, args.denoise)
    R.setup_world(scene, args.engine, ADDON.compat)
    subject = R.Subject(ADDON, path, args, scene)
    R.add_camera(scene, subject.camera, subject.points)
    R.add_lights(scene, subject.camera, subject.points)
    return scene, subject


def render_panel(scene, subject, key, colls, path, written):
    subject.show(colls)
    t = R.render_to(scene, path)
    R.log(f"render_figures: {key}: {t:.1f} s")
    wrote(path, written)


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
    bg = (R.BG_DISPLAY, R.BG_DISPLAY, R.BG_DISPLAY, 1.0)
    img = C.tiles_panel(tiles, where, gw, h, bg)
    R.save_png(img, path)
    wrote(path, written)
    R.log(f"render_figures: subsheets {picked} of {count} shown")
    subject.subsheets_shown = (picked, count)
    return path


def panel_label(subject, key):
    t = f"({plan.PANEL_LETTER[key]}) {plan.PANEL_TITLE[key]}"
    if subject.sheet is None:
        return t
    name = plan.SHEET_TYPE_NAMES[subject.sheet_type]
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
    written, shown = [], []
    for key in args.panels:
        letter = plan.PANEL_LETTER[key]
        path = os.path.abspath(os.path.join(args.out, f"{subject.name}_{letter}_{key}.png"))
        if key == "subsheets":
            if render_subsheets(scene, subject, args, path, written):
                shown.append((key, path))
            continue
        colls = getattr(subject, f"panel_{key}")()
        if colls is None:
            R.log(f"render_figures: panel {letter} ({key}) skipped: nothing to show for "
                  f"{sheet_caption(subject) or 'this mesh'}")
            continue
        render_panel(scene, subject, key, colls, path, written)
        shown.append((key, path))
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
    tiles = [R.load_png(p) for _, p in shown]
    sheet = C.contact_sheet(tiles, labels, C.contact_columns(spans), spans)
    path = os.path.abspath(os.path.join(args.out, f"{subject.name}_contact.png"))
    R.save_png(sheet, path)
    wrote(path, written)
    return written


def compare(args):
    written = []
    columns, names = [], []
    os.makedirs(args.out, exist_ok=True)
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
        columns.append(col)
    w, h = args.resolution
    label_h = max(14, round(h * 0.07))
    tmp = tempfile.mkdtemp(prefix="hbc_fig_")
    heads = R.render_labels([f"({chr(97 + i)}) {n}" for i, n in enumerate(names)], w, label_h, tmp, align="CENTER")
    row_w = max(120, round(w * 0.4))
    rows = R.render_labels([title for _, title in plan.COMPARE_ROWS], row_w, label_h, tmp)
    os.rmdir(tmp)
    cells = [[R.load_png(columns[c][r]) if columns[c][r] else None for c in range(len(columns))]
             for r in range(len(plan.COMPARE_ROWS))]
    if all(t is None for r in cells for t in r):
        raise RuntimeError("no panel rendered")
    img = C.table(cells, rows, heads)
    a, b = names
    path = os.path.abspath(os.path.join(args.out, f"compare_{a}_{b}.png"))
    R.save_png(img, path)
    wrote(path, written)
    return written


def main():
    global ADDON
    args = plan.parse(plan.script_args(sys.argv))
    t = time.perf_counter()
    ADDON = R.Addon(args.addon or R.default_addon_dir())
    written = compare(args) if args.compare else single(args)
    R.log(f"render_figures: {len(written)} files in {time.perf_counter() - t:.1f} s")


ADDON = None

if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except BaseException:  # noqa: BLE001 - report and exit non-zero whatever went wrong
        traceback.print_exc()
        sys.stdout.flush()
        sys.exit(1)
