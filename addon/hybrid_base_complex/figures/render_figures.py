"""The entry file of the add-on's figure script (figures/script.py says what it renders):

    blender -b --factory-startup --python-exit-code 1 --python <add-on>/figures/render_figures.py -- ARGS
    python <add-on>/figures/render_figures.py ARGS      (a Python with Blender as its bpy module)

Blender runs this file as a plain script, outside any package. It imports the add-on package that
holds it, from the folder above, and runs that package's figures: wherever the add-on was installed
(legacy zip, extension, build tree), the figures run with the very builders they were shipped with,
and no source or build tree is needed. The panel's *Figures* runs it in a second Blender; the
repository's blender_scripts/render_figures.py finds an add-on and runs its copy of this file.
"""

import importlib
import os
import sys

PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def figure_script():
    """The module figures/script of the add-on package holding this file (not of another add-on of
    the same name that an earlier sys.path entry would give)."""
    parent, name = os.path.split(PACKAGE_DIR)
    if parent in sys.path:
        sys.path.remove(parent)
    sys.path.insert(0, parent)
    package = importlib.import_module(name)
    found = os.path.dirname(os.path.abspath(package.__file__))
    if os.path.normcase(os.path.realpath(found)) != os.path.normcase(os.path.realpath(PACKAGE_DIR)):
        sys.exit(f"render_figures: the package {name} was already imported from {found}, not from {PACKAGE_DIR}")
    return importlib.import_module(name + ".figures.script")


if __name__ == "__main__":
    figure_script().run(sys.argv)
