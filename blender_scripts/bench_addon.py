"""Speed of the Blender add-on, in background mode: import (load + analysis + direct view), every
layer of every given mesh, and the evaluation of the scene (geometry-nodes tubes), wall-clock
seconds, printed as a Markdown table.

    blender -b --factory-startup --python blender_scripts/bench_addon.py -- \
        --addon <build>/addon/hybrid_base_complex [--split-max N] MESH...

Targets: every layer of teapot.hedra under 2 s; a generated 100k-cell mesh
(`hbc generate grid --size 50 40 50 -o x.mesh`, or a split grid as .ovm) under 20 s. The picked
sheet and subsheet layers use the largest self-intersecting sheet when there is one, else sheet 0.
Exit status 1 when a target is missed (--no-targets to only report).

Rebuilds (a rebuild costs no more than a first build): after the first build of the
blocks (column `blocks`, a fresh file), --rebuilds N times the blocks layer is cleared and built
again (a first build) and then rebuilt with another shrink, so that every block's geometry is
written anew, as when a user changes a setting and rebuilds. Column `rebuild blocks` and a second
table give the medians of those N first builds and N rebuilds, measured in the same run, and their
ratio. Use --split-max 100000 to make every block of a mesh its own object.

--inspect adds the direct view's cells (column `cells`: every cell with the filter
modifier, or above the add-on's live-surface threshold the surface of the kept cells) and times
one update of the sliced direct view: the slicing plane (an Empty through the mesh centre) is
moved and the scene evaluated, which rebuilds the live surface, median of --repeat moves (column
`slice`; target 0.2 s at 10^6 cells). --no-analysis imports without analysing (the
direct view needs none), e.g. for `hbc generate grid --size 100 100 100 -o grid100.ovm`.

A layer's column is the whole operator as a user waits for it: the layer's builder (what the
layer's own log line reports, "built ... in N s") and then the evaluation of the scene that
`bpy.ops` runs after every operator (the depsgraph: Blender 3.4 copies every new mesh there, and
an object's modifiers run). A second table splits each layer's time into these two.

Column `metrics` times the Metrics box's first drawing (Analysis.metrics()); `cpu` is the
process's CPU seconds for the mesh (all threads: on a busy machine it says more than the
wall-clock columns); `peak MB` is the process's peak resident memory after the mesh (it never goes
down, so with several meshes each row is the peak so far); the import's own report (printed)
splits its time into load, analysis and scene. --layers names the layers timed (default all; e.g.
`blocks,sheets` for a 10^6-cell mesh, whose wireframe and subsheets take long);
--rebuilds 0 skips the rebuild timing.

--stepped N times Build All in steps against Build All at once (both rebuilding every layer in
place), N pairs alternating, medians: the stepped one is the job the window's modal operator runs
(plan/steps.Stepper: the C++ work in worker threads, the main thread's share in chunks of
stepping.BUDGET seconds), driven here without redraws in between, so the difference is what the
stepping itself costs (threads, chunks, polling at the window's timer interval: the driver sleeps
stepping.TICK while it waits for a worker, as the window's timer does).
"""

import argparse
import os
import resource
import sys
import time

import bpy


def parse():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser(prog="bench_addon.py")
    ap.add_argument("--addon", required=True, help="the add-on package folder (built tree)")
    ap.add_argument("--split-max", type=int, default=None, help="blocks up to this many as separate objects")
    ap.add_argument("--no-targets", action="store_true")
    ap.add_argument("--inspect", action="store_true", help="time the sliced direct view")
    ap.add_argument("--no-analysis", action="store_true", help="import without analysing")
    ap.add_argument("--repeat", type=int, default=3, help="plane moves timed for --inspect")
    ap.add_argument("--rebuilds", type=int, default=3,
                    help="first builds and rebuilds of the blocks layer timed for the rebuild table (medians)")
    ap.add_argument("--surface-above", type=int, default=None,
                    help="the add-on's live-surface threshold (cells) for --inspect; a large value times "
                         "the geometry-nodes filter on every cell instead")
    ap.add_argument("--layers", default=None,
                    help="comma-separated layers to time after the import (default: every one that applies)")
    ap.add_argument("--stepped", type=int, default=0,
                    help="pairs of Build All at once and in steps timed for the stepping table (medians)")
    ap.add_argument("meshes", nargs="+")
    return ap.parse_args(argv)


def time_slice(root, s, repeat):
    """{'cells': build of the direct view with every cell, 'slice': median seconds of one plane
    move + evaluation of the sliced direct view}."""
    import statistics

    from hybrid_base_complex.blender import inspect as I

    t = time.perf_counter()
    bpy.context.scene.hbc_inspect.direct_cells = True  # rebuilds the direct view with its cells
    dg = bpy.context.evaluated_depsgraph_get()
    dg.update()
    out = {"cells": time.perf_counter() - t}
    cells = next(o for o in root.all_objects if o.get("hbc_part") == "cells")
    lo, hi = s.points.min(axis=0), s.points.max(axis=0)
    plane = I.add_plane(bpy.context, tuple(float(x) for x in (lo + hi) / 2), (1.0, 0.3, 0.2))
    dg.update()
    spans = []
    for i in range(repeat):
        plane.location.x = float(lo[0] + (hi[0] - lo[0]) * (0.4 + 0.2 * i / max(repeat - 1, 1)))
        t = time.perf_counter()
        dg.update()
        faces = len(cells.evaluated_get(dg).data.polygons)
        spans.append(time.perf_counter() - t)
        print(f"bench_addon: slice update {spans[-1]:.3f} s ({faces} faces shown)", flush=True)
    out["slice"] = statistics.median(spans)
    return out


def time_rebuilds(st, n):
    """(median first build, median rebuild) of the blocks layer over n pairs, each pair in the same
    conditions: the layer cleared and built again, then rebuilt with another shrink."""
    import statistics

    first, again = [], []
    shrink = st.shrink
    for i in range(n):
        assert bpy.ops.hbc.clear_layer(layer="components") == {"FINISHED"}
        st.shrink = shrink
        t = time.perf_counter()
        assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
        first.append(time.perf_counter() - t)
        st.shrink = shrink + 0.05
        t = time.perf_counter()
        assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
        again.append(time.perf_counter() - t)
    st.shrink = shrink
    return statistics.median(first), statistics.median(again)


def time_stepped(root, n):
    """(median Build All at once, median Build All in steps, median steps) over n pairs."""
    import statistics

    from hybrid_base_complex.blender import stepping
    from hybrid_base_complex.plan import steps
    from hybrid_base_complex.ui import operators as O

    direct, stepped, counts = [], [], []
    for _ in range(n):
        t = time.perf_counter()
        assert bpy.ops.hbc.build_all() == {"FINISHED"}
        direct.append(time.perf_counter() - t)
        t = time.perf_counter()
        st = steps.Stepper(O.build_all_steps(bpy.context.scene, root, lambda _m: None),
                           steps.build_phases(O.BUILD_ALL, False))
        count = 0
        while not st.advance(stepping.BUDGET):
            count += 1
            if st.waiting():
                time.sleep(stepping.TICK)
        bpy.context.view_layer.update()  # the operator's evaluation after it, as bpy.ops runs it
        stepped.append(time.perf_counter() - t)
        counts.append(count)
    return statistics.median(direct), statistics.median(stepped), statistics.median(counts)


def main():
    args = parse()
    sys.path.insert(0, os.path.dirname(os.path.abspath(args.addon)))
    import hybrid_base_complex as addon
    from hybrid_base_complex.blender.context import find_root
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.plan import session

    addon.register()
    from hybrid_base_complex.blender import layers as L

    builder = {"last": 0.0}
    build_layer_steps = L.build_layer_steps

    def timed_build_layer_steps(*a, **k):  # the builder alone, without the operator's scene evaluation
        t = time.perf_counter()
        try:
            return (yield from build_layer_steps(*a, **k))
        finally:
            builder["last"] = time.perf_counter() - t

    L.build_layer_steps = timed_build_layer_steps
    splits = []
    analyzed = not args.no_analysis
    rows = []
    rebuilds = []
    stepping_rows = []
    failed = False
    for path in args.meshes:
        bpy.ops.wm.read_homefile(use_empty=True)
        st = bpy.context.scene.hbc
        if args.split_max is not None:
            st.split_max = args.split_max
        cpu0 = time.process_time()
        t = time.perf_counter()
        assert bpy.ops.import_mesh.hbc(filepath=path, analyze=analyzed) == {"FINISHED"}
        t_import = time.perf_counter() - t
        root = find_root(st.active_mesh)
        s = session.get(root.name)
        times = {"import": t_import}
        layers = ["graph", "components", "sheets", "wireframe"] if analyzed else []
        if analyzed:
            a = s.analysis
            big = a.largest_self_intersecting
            st.sheet_index = big if big is not None else 0
        if analyzed and s.num_sheets:
            layers.append("sheet")
            if int(s.sheet_types()[st.sheet_index]) == 3:
                layers.append("subsheets")
        if analyzed:  # the Metrics box, the first time it is drawn open
            t = time.perf_counter()
            s.metrics()
            times["metrics"] = time.perf_counter() - t
        if args.layers is not None:
            wanted = args.layers.split(",")
            layers = [layer for layer in layers if layer in wanted]
        for layer in layers:
            t = time.perf_counter()
            assert bpy.ops.hbc.build_layer(layer=layer) == {"FINISHED"}, layer
            times[layer] = time.perf_counter() - t
            splits.append((os.path.basename(path), layer, times[layer], builder["last"]))
        if analyzed and args.stepped > 0:
            stepping_rows.append((os.path.basename(path), *time_stepped(root, args.stepped)))
        if "components" in layers and args.rebuilds > 0:
            first, again = time_rebuilds(st, max(args.rebuilds, 1))
            times["rebuild blocks"] = again
            rebuilds.append((os.path.basename(path), len(S.find_layer(root, "components").objects), first, again))
        # Tubes are made by geometry nodes when the scene is evaluated (drawn or rendered): time it.
        t = time.perf_counter()
        bpy.context.evaluated_depsgraph_get().update()
        times["evaluate"] = time.perf_counter() - t
        if args.inspect:
            if args.surface_above is not None:
                bpy.context.scene.hbc_inspect.surface_above = args.surface_above
            times.update(time_slice(root, s, args.repeat))
        total = sum(v for k, v in times.items() if k not in ("slice", "rebuild blocks", "cpu", "peak MB"))
        if args.inspect and not args.no_targets and s.num_cells >= 10 ** 6 and times["slice"] > 0.2:
            failed = True
            print(f"bench_addon: {path}: slice update {times['slice']:.2f} s is over the 0.2 s target", flush=True)
        times["cpu"] = time.process_time() - cpu0  # every thread of the process
        times["peak MB"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # kB on Linux
        rows.append((os.path.basename(path), s.num_cells, len(bpy.data.objects), times, total))
        cells = s.num_cells
        limit = 2.0 if cells < 20000 else 20.0
        if not args.no_targets and total > limit:
            failed = True
            print(f"bench_addon: {path}: {total:.2f} s is over the {limit:.0f} s target", flush=True)

    keys = ["import", "metrics", "graph", "components", "sheets", "wireframe", "sheet", "subsheets", "rebuild blocks", "evaluate"]
    if args.inspect:
        keys += ["cells", "slice"]
    keys += ["cpu", "peak MB"]
    print("\n| mesh | cells | objects | " + " | ".join(keys) + " | total (s) |")
    print("|---|---:|---:|" + "---:|" * len(keys) + "---:|")
    for name, cells, objects, times, total in rows:
        cols = " | ".join((f"{times[k]:.0f}" if k == "peak MB" else f"{times[k]:.2f}") if k in times else "-"
                          for k in keys)
        print(f"| {name} | {cells} | {objects} | {cols} | {total:.2f} |")
    if splits:
        print("\n| mesh | layer | operator (s) | builder (s) | scene evaluation after it (s) |")
        print("|---|---|---:|---:|---:|")
        for name, layer, whole, built in splits:
            print(f"| {name} | {layer} | {whole:.2f} | {built:.2f} | {whole - built:.2f} |")
    if rebuilds:
        n = max(args.rebuilds, 1)
        print(f"\n| mesh | block objects | first build (s, median of {n}) | rebuild (s, median of {n}) | rebuild / first |")
        print("|---|---:|---:|---:|---:|")
        for name, objects, first, again in rebuilds:
            print(f"| {name} | {objects} | {first:.2f} | {again:.2f} | {again / first:.2f} |")
    if stepping_rows:
        n = args.stepped
        print(f"\n| mesh | Build All at once (s, median of {n}) | in steps (s, median of {n}) | steps | in steps / at once |")
        print("|---|---:|---:|---:|---:|")
        for name, direct, stepped, count in stepping_rows:
            print(f"| {name} | {direct:.2f} | {stepped:.2f} | {count:.0f} | {stepped / direct:.2f} |")
    sys.stdout.flush()
    addon.unregister()
    if failed:
        sys.exit(1)


main()
