"""Publication figures of a hex-dominant mesh, rendered in Blender's background mode.

    blender -b --factory-startup --python-exit-code 1 --python blender_scripts/render_figures.py -- \
        MESH --out DIR [--engine cycles|eevee|workbench] [--samples N] [--resolution W H] [--sheet N]
    blender ... -- --compare A B --out DIR [...]
    python blender_scripts/render_figures.py MESH --out DIR [...]   (a Python with Blender's bpy module)

The figure code ships inside the Blender add-on (hybrid_base_complex/figures/: what each panel
shows, the options, the outputs; `--help` lists the options). This file only finds the add-on and
runs the add-on's own entry, figures/render_figures.py, with the same arguments: the add-on is
taken from --addon, else $HBC_ADDON_DIR, else <repo>/build/addon/hybrid_base_complex (the build's
`addon` target, with the compiled hbc module inside). Each written file is printed as `wrote PATH`;
any failure exits non-zero.
"""

import os
import runpy
import sys

ENTRY = os.path.join("figures", "render_figures.py")


def script_args(argv):
    """The arguments after Blender's '--', else (a Python with bpy runs this file) after its name."""
    if "--" in argv:
        return argv[argv.index("--") + 1:]
    return argv[1:] if argv and argv[0].endswith(".py") else []


def addon_dir(args, env=os.environ):
    """--addon DIR (or --addon=DIR), else $HBC_ADDON_DIR, else the build tree's add-on."""
    for k, arg in enumerate(args):
        if arg == "--addon" and k + 1 < len(args):
            return args[k + 1]
        if arg.startswith("--addon="):
            return arg[len("--addon="):]
    if env.get("HBC_ADDON_DIR"):
        return env["HBC_ADDON_DIR"]
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    return os.path.join(repo, "build", "addon", "hybrid_base_complex")


def main():
    folder = os.path.abspath(addon_dir(script_args(sys.argv)))
    entry = os.path.join(folder, ENTRY)
    if not os.path.isfile(entry):
        sys.exit(f"render_figures.py: no add-on with figures at {folder} ({ENTRY} is missing): build the "
                 "'addon' target, or pass --addon DIR or set HBC_ADDON_DIR")
    runpy.run_path(entry, run_name="__main__")


if __name__ == "__main__":
    main()
