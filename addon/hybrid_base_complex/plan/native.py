"""The compiled hbc module: where it is imported from, and plain words when it is missing or was
built for another Python than this Blender's. No ``bpy`` here."""

from __future__ import annotations

import functools
import glob
import os
import re
import sys

#: The add-on package's folder; the release zip bundles the compiled hbc package in its hbc/.
PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class ModuleMismatch(ImportError):
    """The compiled hbc module is missing or was built for another Python than this Blender's."""


def _built_for(folder):
    """The Pythons (e.g. "CPython 3.11, linux x86_64") of the compiled modules in `folder`."""
    found = []
    for path in sorted(glob.glob(os.path.join(folder, "_core.*"))):
        m = re.match(r"_core\.cpython-(\d)(\d+)-([a-z0-9_]+)-([a-z]+)", os.path.basename(path))
        if m:
            found.append(f"CPython {m.group(1)}.{m.group(2)} ({m.group(4)} {m.group(3)})")
    return found


def mismatch_message() -> str:
    """Plain words for a Blender whose Python the add-on's compiled module was not built for."""
    here = f"{sys.version_info[0]}.{sys.version_info[1]}"
    built = _built_for(os.path.join(PACKAGE_DIR, "hbc"))
    have = f"built for {', '.join(built)}" if built else "not in this add-on"
    return (f"The compiled hbc module is {have}, but this Blender runs CPython {here} "
            f"({sys.platform}). Build it for this Python: `{sys.executable or 'python'} -m pip install .` "
            f"in the hbc source folder (or CMake with -DPython_EXECUTABLE=<this Python>), or install the "
            f"extension package that bundles a wheel for CPython {here}.")


def import_hbc():
    """The hbc module: the copy bundled in the add-on package (release zip), else one on sys.path
    (the extension's wheel, or a development checkout with PYTHONPATH=<build>/python). Raises
    ModuleMismatch, saying which Python the bundled module was built for and how to build it for
    this one, when neither imports."""
    # Imported here, not at the top: a module built for another Python must not stop the add-on
    # from registering (the panel and the operators then say why nothing can be analyzed).
    try:
        from .. import hbc  # type: ignore[attr-defined]
        return hbc
    except ImportError:
        pass
    try:
        import hbc  # type: ignore[no-redef]
        return hbc
    except ImportError:
        raise ModuleMismatch(mismatch_message()) from None


@functools.lru_cache(maxsize=1)
def module_problem():
    """None when the hbc module imports here, else the sentence mismatch_message() gives (asked
    once: the panel draws often, and a module does not appear while Blender runs)."""
    try:
        import_hbc()
    except ModuleMismatch as e:
        return str(e)
    return None
