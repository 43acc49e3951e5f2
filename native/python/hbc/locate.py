"""Where the Python side of hbc looks for the pieces it runs: each piece in one order, with at most
one environment variable (docs/development.md, "Where hbc looks for its pieces"). The ``hbc``
command looks for its own (the Python that draws the report, the web viewer page) in
native/tools/locate.cpp.

=================  =====================================================================
piece              looked for, in this order
=================  =====================================================================
hbc command        ``$HBC_CLI``; ``BUILD/bin/hbc`` when this package is a build tree's
                   (``BUILD/python/hbc``); ``hbc`` on ``PATH``
Blender            ``$HBC_BLENDER``; ``blender`` on ``PATH``
the add-on         ``$HBC_ADDON_DIR``; ``BUILD/addon/hybrid_base_complex``
figures script     the add-on's own ``figures/render_figures.py`` (no variable of its own;
                   ``$HBC_RENDER_FIGURES`` is read as a deprecated alias)
viewer page        ``$HBC_VIEWER``; ``BUILD/web/viewer.html`` (scripts/build_web.sh) of this
                   package's build tree (the gallery's viewer.html)
Chromium           ``$HBC_CHROMIUM``; ``chromium``, ``chromium-browser``, ``google-chrome`` on
                   ``PATH`` (the gallery's thumbnails)
metrics.md         the source tree's ``docs/metrics.md`` (above this package, or the build
                   tree's source folder) as a file URL; else the relative link
=================  =====================================================================

The report is drawn by the Python that imports this package (``sys.executable``); nothing here
starts the ``hbc`` command (hbc.compare measures in this process), which the tests and other
programs may still want.
"""

from __future__ import annotations

import os
import pathlib
import shutil
import warnings

#: The add-on package's folder name, in a build tree and where Blender installs it.
ADDON_NAME = "hybrid_base_complex"
#: The figures script inside the add-on package.
FIGURES_SCRIPT = pathlib.Path("figures") / "render_figures.py"


class LocateError(LookupError):
    """A piece is not where it is looked for; the message says where it looked and which variable
    names it."""


def build_dir() -> pathlib.Path | None:
    """The build tree this package was built into (``BUILD/python/hbc``, beside ``BUILD/CMakeCache.txt``),
    or None for an installed package."""
    build = pathlib.Path(__file__).resolve().parent.parent.parent
    return build if (build / "CMakeCache.txt").is_file() else None


def _from_env(name: str) -> str | None:
    value = os.environ.get(name)
    return value if value else None


def hbc_command() -> str:
    """The ``hbc`` command: $HBC_CLI, else BUILD/bin/hbc of this package's build tree, else ``hbc``
    on PATH."""
    env = _from_env("HBC_CLI")
    if env:
        return env
    build = build_dir()
    if build and (build / "bin" / "hbc").is_file():
        return str(build / "bin" / "hbc")
    found = shutil.which("hbc")
    if found:
        return found
    raise LocateError("the hbc command is not found (set HBC_CLI to its path)")


def blender() -> str:
    """Blender's executable: $HBC_BLENDER, else ``blender`` on PATH."""
    env = _from_env("HBC_BLENDER")
    if env:
        return env
    found = shutil.which("blender")
    if found:
        return found
    raise LocateError("Blender is not found (set HBC_BLENDER to its executable, or put blender on PATH)")


def addon_dir() -> pathlib.Path:
    """The Blender add-on package (the folder holding ``__init__.py`` and ``figures/``):
    $HBC_ADDON_DIR, else BUILD/addon/hybrid_base_complex of this package's build tree."""
    env = _from_env("HBC_ADDON_DIR")
    if env:
        return pathlib.Path(env)
    build = build_dir()
    if build and (build / "addon" / ADDON_NAME / "__init__.py").is_file():
        return build / "addon" / ADDON_NAME
    raise LocateError("the Blender add-on is not found (set HBC_ADDON_DIR to its package folder, "
                      f".../{ADDON_NAME}; a build tree makes one with its 'addon' target)")


def figures_script(addon: os.PathLike | str | None = None) -> pathlib.Path:
    """The figures script Blender runs: the add-on's own ``figures/render_figures.py`` (of ``addon``,
    else of addon_dir()). $HBC_RENDER_FIGURES, which named a script before the figures shipped in the
    add-on, is still taken, with a FutureWarning (the category Python shows to users)."""
    old = _from_env("HBC_RENDER_FIGURES")
    if old:
        warnings.warn("HBC_RENDER_FIGURES is deprecated: the figures script is found through the add-on "
                      "(HBC_ADDON_DIR)", FutureWarning, stacklevel=2)
        return pathlib.Path(old)
    folder = pathlib.Path(addon) if addon is not None else addon_dir()
    script = folder / FIGURES_SCRIPT
    if not script.is_file():
        raise LocateError(f"{folder} is not an add-on with figures ({FIGURES_SCRIPT} is missing)")
    return script


def viewer_page() -> pathlib.Path:
    """The web viewer page (scripts/build_web.sh) the gallery's viewer.html is made of: $HBC_VIEWER,
    else BUILD/web/viewer.html of this package's build tree."""
    env = _from_env("HBC_VIEWER")
    if env:
        return pathlib.Path(env)
    build = build_dir()
    if build and (build / "web" / "viewer.html").is_file():
        return build / "web" / "viewer.html"
    raise LocateError("the web viewer page is not found (set HBC_VIEWER to viewer.html; "
                      "a build tree makes one with scripts/build_web.sh)")


def chromium() -> str:
    """Chromium (or Chrome) for headless pages: $HBC_CHROMIUM, else chromium, chromium-browser or
    google-chrome on PATH."""
    env = _from_env("HBC_CHROMIUM")
    if env:
        return env
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    raise LocateError("Chromium is not found (set HBC_CHROMIUM to its executable, or put chromium on PATH; "
                      "Debian: apt-get install chromium)")


def metrics_doc() -> str:
    """docs/metrics.md as a file:// URL when the source tree is found (a folder above this package
    holding it, or the source folder of this package's build tree), else the relative link."""
    here = pathlib.Path(__file__).resolve()
    roots = list(here.parents)
    build = build_dir()
    if build:
        for line in (build / "CMakeCache.txt").read_text(errors="replace").splitlines():
            if line.startswith("CMAKE_HOME_DIRECTORY:"):
                roots.append(pathlib.Path(line.split("=", 1)[1]))
    for root in roots:
        doc = root / "docs" / "metrics.md"
        if doc.is_file():
            return doc.resolve().as_uri()
    return "docs/metrics.md"
