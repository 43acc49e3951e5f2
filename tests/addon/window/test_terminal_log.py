"""The add-on in a Blender window (Debian's blender with its user interface, under a virtual X server:
xvfb-run), as a user runs it from a terminal: the user guide (addon/hybrid_base_complex/README.md,
"Reporting a problem") promises every step of an import as a line starting with `hbc:` on that
terminal, not only in the status bar. The window imports a mesh through the importer (from a timer,
once the window is up) and quits; its standard output must hold every step's line, the import's
closing report, and a refused file's error.

Run by ctest (addon_window@blender-<version>) with Debian's Python: HBC_BLENDER (the executable),
XVFB_RUN, HBC_ADDON_DIR (the built add-on), HBC_DATA_DIR.
"""

import os
import pathlib
import subprocess

import pytest

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[2]
DEFECTS = ROOT / "tests" / "data" / "check" / "defects.HYBRID"

# Runs inside the window: the add-on from the build, the imports once the window is drawn, then quit.
CHILD = r'''
import os, sys, traceback
import bpy

addon_dir, *meshes = sys.argv[sys.argv.index("--") + 1:]
sys.path.insert(0, os.path.dirname(addon_dir))
import hybrid_base_complex
hybrid_base_complex.register()


def run():
    try:
        window = bpy.context.window_manager.windows[0]
        print(f"WINDOW background={bpy.app.background}", flush=True)
        with bpy.context.temp_override(window=window, screen=window.screen):
            for mesh in meshes:
                try:
                    bpy.ops.import_mesh.hbc(filepath=mesh)
                except RuntimeError as e:
                    print(f"WINDOW refused {os.path.basename(mesh)}", flush=True)
        print("WINDOW done", flush=True)
        bpy.ops.wm.quit_blender()
    except BaseException:
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(3)


bpy.app.timers.register(run, first_interval=1.0)
'''


def env_path(name, hint):
    value = os.environ.get(name)
    if not value or not os.path.exists(value):
        pytest.fail(f"{name}={value} does not exist ({hint})")
    return value


def test_every_import_step_is_printed_from_the_window(tmp_path):
    blender = env_path("HBC_BLENDER", "Debian's blender")
    xvfb = env_path("XVFB_RUN", "install xvfb: bash scripts/env/deps.sh")
    addon = env_path("HBC_ADDON_DIR", "build the addon target")
    mesh = pathlib.Path(env_path("HBC_DATA_DIR", "the shared meshes")) / "hybrid-base-complex" / "twistcube_s.mesh"
    script = tmp_path / "window.py"
    script.write_text(CHILD)
    # TMPDIR: Blender saves its session (quit.blend) there on quitting.
    env = dict(os.environ, BLENDER_USER_CONFIG=str(tmp_path / "config"), BLENDER_USER_SCRIPTS=str(tmp_path / "scripts"),
               TMPDIR=str(tmp_path))
    cmd = [xvfb, "-a", "-s", "-screen 0 1280x1000x24", blender, "--factory-startup", "--python", str(script),
           "--", addon, str(mesh), str(DEFECTS)]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, env=env)
    lines = p.stdout.splitlines()
    assert "WINDOW background=False" in lines and "WINDOW done" in lines, (p.stdout[-3000:], p.stderr[-3000:])
    steps = [line for line in lines if line.startswith("hbc: [")]
    for words in ("loading twistcube_s.mesh", "loaded 1301 cells", "analyzing 1301 cells",
                  "analyzed: 1301 components, 20 sheets", "building Direct view", "built Direct view"):
        assert any(line.endswith(words) for line in steps), (words, steps)
    assert any(line.startswith("hbc: loaded ") and "twistcube_s.mesh: 1301 cells" in line for line in lines), lines
    assert any(line.startswith("hbc: Imported twistcube_s") for line in lines), lines
    # The refused file: the loading step, then the reader's message naming the file and the option.
    assert any(line.endswith("loading defects.HYBRID") for line in steps), steps
    assert "WINDOW refused defects.HYBRID" in lines
    failed = [line for line in lines if line.startswith("hbc: failed: ")]
    assert len(failed) == 1 and "defects.HYBRID" in failed[0] and "Skip invalid cells" in failed[0], failed
