"""Speed of the Blender add-on, in background mode: import (load + analysis + direct view), every
layer of every given mesh, and the evaluation of the scene (geometry-nodes tubes), wall-clock
seconds, printed as a Markdown table.

    blender -b --factory-startup --python blender_scripts/bench_addon.py -- \
        --addon <build>/addon/hybrid_base_complex [--split-max N] MESH...

Targets (issue 7): every layer of teapot.hedra under 2 s; a generated 100k-cell mesh
(`hbc generate grid --size 50 40 50 -o x.mesh`, or a split grid as .ovm) under 20 s. The picked
sheet and subsheet layers use the largest self-intersecting sheet when there is one, else sheet 0.
Exit status 1 when a target is missed (--no-targets to only report).
"""

import argparse
import os
import sys
import time

import bpy


def parse():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser(prog="bench_addon.py")
    ap.add_argument("--addon", required=True, help="the add-on package folder (built tree)")
    ap.add_argument("--split-max", type=int, default=None, help="blocks up to this many as separate objects")
    ap.add_argument("--no-targets", action="store_true")
    ap.add_argument("meshes", nargs="+")
    return ap.parse_args(argv)


def main():
    args = parse()
    sys.path.insert(0, os.path.dirname(os.path.abspath(args.addon)))
    import hybrid_base_complex as addon
    from hybrid_base_complex import layers as L
    from hybrid_base_complex import session

    addon.register()
    rows = []
    failed = False
    for path in args.meshes:
        bpy.ops.wm.read_homefile(use_empty=True)
        st = bpy.context.scene.hbc
        if args.split_max is not None:
            st.split_max = args.split_max
        t = time.perf_counter()
        assert bpy.ops.import_mesh.hbc(filepath=path) == {"FINISHED"}
        t_import = time.perf_counter() - t
        root = L.find_root(st.active_mesh)
        s = session.get(root.name)
        times = {"import": t_import}
        a = s.analysis
        pick = int(a.largest_self_intersecting) if int(a.largest_self_intersecting) >= 0 else 0
        st.sheet_index = pick if s.num_sheets else 0
        layers = ["graph", "blocks", "sheets", "wireframe"]
        if s.num_sheets:
            layers.append("sheet")
            if int(s.sheet_types()[st.sheet_index]) == 3:
                layers.append("subsheets")
        for layer in layers:
            t = time.perf_counter()
            assert bpy.ops.hbc.build_layer(layer=layer) == {"FINISHED"}, layer
            times[layer] = time.perf_counter() - t
        # Tubes are made by geometry nodes when the scene is evaluated (drawn or rendered): time it.
        t = time.perf_counter()
        bpy.context.evaluated_depsgraph_get().update()
        times["evaluate"] = time.perf_counter() - t
        total = sum(times.values())
        rows.append((os.path.basename(path), s.num_cells, len(bpy.data.objects), times, total))
        cells = s.num_cells
        limit = 2.0 if cells < 20000 else 20.0
        if not args.no_targets and total > limit:
            failed = True
            print(f"bench_addon: {path}: {total:.2f} s is over the {limit:.0f} s target", flush=True)

    keys = ["import", "graph", "blocks", "sheets", "wireframe", "sheet", "subsheets", "evaluate"]
    print("\n| mesh | cells | objects | " + " | ".join(keys) + " | total (s) |")
    print("|---|---:|---:|" + "---:|" * len(keys) + "---:|")
    for name, cells, objects, times, total in rows:
        cols = " | ".join(f"{times[k]:.2f}" if k in times else "-" for k in keys)
        print(f"| {name} | {cells} | {objects} | {cols} | {total:.2f} |")
    sys.stdout.flush()
    addon.unregister()
    if failed:
        sys.exit(1)


main()
