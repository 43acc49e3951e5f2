"""Screenshot of the add-on's sidebar panel in a real Blender window (docs/images/panel.png).

Blender runs with its user interface, under a virtual X server when there is no display. The script
enables the add-on from the build tree, imports a mesh (teapot by default) and analyzes it, builds
every overview layer (Build All), opens the 3D view's sidebar on the *Hex Structure* tab, takes a
screenshot of the whole window (`bpy.ops.screen.screenshot`) and writes it reduced as a small PNG.
Run from the repository's root:

    BLENDER_USER_CONFIG=$(mktemp -d) BLENDER_USER_SCRIPTS=$(mktemp -d) \
    xvfb-run -a -s "-screen 0 1280x1000x24" \
        blender --factory-startup --enable-event-simulate --python blender_scripts/panel_screenshot.py -- \
        [MESH] [--addon DIR] [--out PNG] [--width W] [--collapse PANEL,...]

Defaults: MESH ../shared/data/hybrid-base-complex/teapot.hedra; --addon $HBC_ADDON_DIR, else
build/addon/hybrid_base_complex (build the `addon` target first); --out docs/images/panel.png;
--width 960 (the height follows the window's aspect: 960x750 from 1280x1000, about 230 KB);
--collapse the add-on's panels shown closed so that the rest fits in the window (Look inside and
every layer's sub-panel, as a user may leave them: the add-on's own code is not changed). The
empty user folders keep the user's configuration out (Blender saves one on quit). Debian packages:
xvfb and xauth; made with Debian's Blender 3.4.1.

How: the default scene's objects are removed and the 3D view's floor grid and axes hidden;
`--enable-event-simulate` lets the script click down the sidebar's tab strip until the add-on's
tab is in front (Blender 3.4 has no Python setting for the sidebar's tab; the script knows by the
add-on's main panel being drawn) and makes Blender ignore the (virtual) mouse and keyboard. The
script quits Blender when done; on any failure it exits with status 1.
"""

import argparse
import os
import sys
import traceback

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TAB = "Hex Structure"


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="panel_screenshot.py")
    p.add_argument("mesh", nargs="?",
                   default=os.path.join(ROOT, "..", "shared", "data", "hybrid-base-complex", "teapot.hedra"))
    p.add_argument("--addon", default=os.environ.get("HBC_ADDON_DIR")
                   or os.path.join(ROOT, "build", "addon", "hybrid_base_complex"))
    p.add_argument("--out", default=os.path.join(ROOT, "docs", "images", "panel.png"))
    p.add_argument("--width", type=int, default=960)
    layers = ("direct", "graph", "components", "sheets", "sheet", "subsheets", "wireframe")
    p.add_argument("--collapse", default=",".join(["HBC_PT_inspect"] + [f"HBC_PT_layer_{x}" for x in layers]),
                   help="comma-separated ids of the add-on's panels to show closed")
    return p.parse_args(argv)


ARGS = parse_args()
STATE = {"step": 0}


def log(msg):
    print(f"panel_screenshot: {msg}", flush=True)


def fail(msg):
    log(f"error: {msg}")
    os._exit(1)  # noqa: SLF001 - leave at once, from inside a timer


def view3d(window):
    for area in window.screen.areas:
        if area.type == "VIEW_3D":
            region = next(r for r in area.regions if r.type == "WINDOW")
            sidebar = next(r for r in area.regions if r.type == "UI")
            return area, region, sidebar
    fail("no 3D view in the window")


def enable_addon():
    addon = os.path.abspath(ARGS.addon)
    if not os.path.isfile(os.path.join(addon, "__init__.py")):
        fail(f"no add-on at {addon} (build the `addon` target, or pass --addon)")
    sys.path.insert(0, os.path.dirname(addon))
    import addon_utils

    mod = addon_utils.enable(os.path.basename(addon), default_set=True)
    if mod is None:
        fail(f"could not enable the add-on {addon}")
    log(f"add-on enabled from {addon}")


def prepare(window):
    """Empty scene, add-on, mesh, analysis, every overview layer, sidebar open."""
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob)
    enable_addon()
    area, region, _sidebar = view3d(window)
    with bpy.context.temp_override(window=window, area=area, region=region):
        r = bpy.ops.import_mesh.hbc(filepath=os.path.abspath(ARGS.mesh), analyze=True)
        if r != {"FINISHED"}:
            fail(f"import of {ARGS.mesh} returned {r}")
        r = bpy.ops.hbc.build_all()
        if r != {"FINISHED"}:
            fail(f"Build All returned {r}")
    space = area.spaces.active
    space.show_region_ui = True
    space.show_region_toolbar = False
    space.overlay.show_floor = False
    space.overlay.show_axis_x = False
    space.overlay.show_axis_y = False
    watch_panel()
    for name in ARGS.collapse.split(",") if ARGS.collapse else []:
        collapse_by_default(name)
    log(f"imported {ARGS.mesh} and built its layers")


def watch_panel():
    """Notes each draw of the add-on's main panel: Blender draws only the panels of the sidebar's
    active tab, so a draw after a tab change says the tab is the add-on's."""
    cls = bpy.types.HBC_PT_main
    draw = cls.draw

    def watched(self, context):
        STATE["drawn"] = True
        draw(self, context)

    cls.draw = watched


def collapse_by_default(name):
    """Registers the add-on's panel `name` again as closed by default (a collapsed panel, as a user
    would leave it): the picture then has room for the panels below it."""
    cls = getattr(bpy.types, name)
    bpy.utils.unregister_class(cls)
    cls.bl_options = set(getattr(cls, "bl_options", set())) | {"DEFAULT_CLOSED"}
    bpy.utils.register_class(cls)


def click_tab(window, k):
    """A left click on the sidebar's tab strip, the k-th 20-pixel step from its top: the tabs are
    drawn down the sidebar's right edge, and a click on one brings it forward."""
    _area, _region, sidebar = view3d(window)
    x = sidebar.x + sidebar.width - 10
    y = sidebar.y + sidebar.height - 20 - 20 * k
    if y < sidebar.y:
        fail(f"the sidebar never showed the {TAB} tab")
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    window.event_simulate(type="LEFTMOUSE", value="PRESS", x=x, y=y)
    window.event_simulate(type="LEFTMOUSE", value="RELEASE", x=x, y=y)


def shoot(window):
    full = os.path.abspath(ARGS.out) + ".full.png"
    area, region, _ = view3d(window)
    with bpy.context.temp_override(window=window, area=area, region=region):
        r = bpy.ops.screen.screenshot(filepath=full)
    if r != {"FINISHED"} or not os.path.isfile(full):
        fail(f"screenshot returned {r}")
    img = bpy.data.images.load(full)
    w, h = img.size
    img.scale(ARGS.width, round(h * ARGS.width / w))
    scene = bpy.context.scene
    settings = scene.render.image_settings
    settings.file_format = "PNG"
    settings.color_mode = "RGB"
    settings.color_depth = "8"
    settings.compression = 100
    img.save_render(os.path.abspath(ARGS.out), scene=scene)
    os.remove(full)
    log(f"wrote {ARGS.out} ({img.size[0]}x{img.size[1]}, {os.path.getsize(ARGS.out)} bytes; window {w}x{h})")


def tick():
    """One step per timer call, so Blender redraws the window between steps."""
    try:
        window = bpy.context.window_manager.windows[0]
        step = STATE["step"]
        STATE["step"] += 1
        if step == 0:
            prepare(window)
        elif not STATE.get("drawn"):
            click_tab(window, step - 1)
        elif not STATE.get("settled"):
            STATE["settled"] = True  # one more redraw with the tab in front
        else:
            shoot(window)
            bpy.ops.wm.quit_blender()
            return None
        return 0.5
    except Exception:  # noqa: BLE001 - any failure ends Blender with status 1
        traceback.print_exc()
        fail("unexpected exception")


if bpy.app.background:
    fail("needs Blender's window: run without -b (under xvfb-run when there is no display)")
bpy.context.preferences.view.show_splash = False
os.makedirs(os.path.dirname(os.path.abspath(ARGS.out)), exist_ok=True)
bpy.app.timers.register(tick, first_interval=2.0)
