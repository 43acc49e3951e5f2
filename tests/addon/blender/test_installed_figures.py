"""*Figures* from the add-on as a new user installs it: a second Blender (this one's executable, or
this bpy module's Python) whose user folders are fresh temporary ones outside any source or build
tree installs the built package the way Preferences does (3.x: the legacy zip; 4.2+: the extension
zip), enables it, imports a small mesh and runs *Figures* (Workbench, tiny) to the end: every
default panel and the contact sheet must be written. Then the figure script is deleted from that
installed copy, and *Figures* must refuse at once, naming what is missing, before the file browser
(the folder and engine the user would pick) opens.

Environment: HBC_ADDON_ZIP (3.x), HBC_EXTENSION_ZIP (4.2+: scripts/wheels.sh packs it),
HBC_DATA_DIR.
"""

import json
import os
import pathlib
import subprocess
import sys

import pytest

bpy = pytest.importorskip("bpy")

EXTENSIONS = bpy.app.version >= (4, 2, 0)

# Runs in the second Blender: install, enable, import, Figures, then Figures without its script.
CHILD = r'''
import json, os, sys
import bpy

zip_path, mesh, out, extensions = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
if extensions == "1":
    module = "bl_ext.user_default.hybrid_base_complex"
    assert bpy.ops.extensions.package_install_files(filepath=zip_path, repo="user_default",
                                                    enable_on_install=True) == {"FINISHED"}
else:
    module = "hybrid_base_complex"
    assert bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True) == {"FINISHED"}
    assert bpy.ops.preferences.addon_enable(module=module) == {"FINISHED"}
installed = os.path.dirname(os.path.abspath(sys.modules[module].__file__))
assert bpy.ops.import_mesh.hbc(filepath=mesh) == {"FINISHED"}
result = bpy.ops.hbc.render_figures(directory=out, engine="workbench", width=64, height=48, wait=True)
os.remove(os.path.join(installed, "figures", "render_figures.py"))
try:
    bpy.ops.hbc.render_figures("INVOKE_DEFAULT")
    refused = ""
except RuntimeError as e:
    refused = str(e)
print("CHILD " + json.dumps({"installed": installed, "result": sorted(result), "refused": refused}), flush=True)
'''


def _file_from_env(name, hint):
    value = os.environ.get(name)
    if not value or not os.path.isfile(value):
        pytest.fail(f"{name}={value} is missing ({hint})")
    return value


def test_figures_from_the_installed_package(tmp_path):
    if EXTENSIONS:
        package = _file_from_env("HBC_EXTENSION_ZIP", "run scripts/wheels.sh, which packs it")
    else:
        package = _file_from_env("HBC_ADDON_ZIP", "build the addon_zip target")
    data = os.environ.get("HBC_DATA_DIR", "")
    mesh = pathlib.Path(data) / "hybrid-base-complex" / "twistcube_s.mesh"
    if not mesh.is_file():
        pytest.fail(f"HBC_DATA_DIR={data} has no hybrid-base-complex/twistcube_s.mesh")
    user, out = tmp_path / "user", tmp_path / "figures"
    script = tmp_path / "child.py"
    script.write_text(CHILD)
    # Nothing points the child at the build: its add-on is only the one it installs.
    env = {k: v for k, v in os.environ.items()
           if k not in ("HBC_ADDON_DIR", "HBC_FIGURES_SCRIPT", "HBC_RENDER_FIGURES", "PYTHONPATH")}
    env.update(BLENDER_USER_CONFIG=str(user / "config"), BLENDER_USER_SCRIPTS=str(user / "scripts"),
               BLENDER_USER_EXTENSIONS=str(user / "extensions"))
    args = [package, str(mesh), str(out), "1" if EXTENSIONS else "0"]
    if bpy.app.binary_path:
        cmd = [bpy.app.binary_path, "-b", "--factory-startup", "--python-exit-code", "1", "--python", str(script),
               "--", *args]
    else:
        cmd = [sys.executable, str(script), *args]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600, env=env)
    lines = [line for line in p.stdout.splitlines() if line.startswith("CHILD ")]
    assert p.returncode == 0 and lines, (p.stdout[-3000:], p.stderr[-3000:])
    child = json.loads(lines[-1][len("CHILD "):])
    assert pathlib.Path(child["installed"]).is_relative_to(user), child  # the installed copy ran
    assert child["result"] == ["FINISHED"], child
    pngs = sorted(q.name for q in out.glob("*.png"))
    # twistcube_s has self-intersecting sheets: every default panel (a-g) and the contact sheet.
    assert "twistcube_s_contact.png" in pngs and len(pngs) == 8, pngs
    assert all((out / name).stat().st_size > 0 for name in pngs)
    assert "figures/render_figures.py" in child["refused"] and "install the add-on again" in child["refused"], child
