"""Where an imported mesh's source file is, stored the Blender way: relative to the .blend ("//")
when the .blend's place is known, resolved with bpy.path.abspath on use, and found again beside a
moved .blend (the mesh moved with it) when the stored path no longer exists. The save handlers
(ui/handlers.py) call `store_for_save` and `store_relative`."""

from __future__ import annotations

import os

import bpy


class SourceMissing(Exception):
    """The mesh's source file is gone; the message says which file and how to point at it again."""


def stored(path: str, blend_path: str | None = None) -> str:
    """`path` as it is kept on the mesh: relative to the .blend at `blend_path` (default: the open
    file, when saved), else absolute."""
    path = os.path.abspath(bpy.path.abspath(path))
    blend = blend_path if blend_path is not None else (bpy.data.filepath if bpy.data.is_saved else "")
    if not blend:
        return path
    try:
        return bpy.path.relpath(path, start=os.path.dirname(os.path.abspath(blend)))
    except ValueError:  # another drive (Windows): no relative path exists
        return path


def _beside_blend(path: str):
    """The file at the stored path's tail below the .blend's folder (the folder moved as a whole),
    longest tail first; None when none exists or the file is not saved."""
    if not bpy.data.is_saved:
        return None
    parts = os.path.normpath(path).split(os.sep)
    for k in range(len(parts) - 1, 0, -1):
        candidate = bpy.path.abspath("//" + "/".join(parts[-k:]))
        if os.path.isfile(candidate):
            return os.path.normpath(candidate)
    return None


def resolve(root) -> str:
    """The absolute path of the mesh's source file; SourceMissing when it is not there."""
    raw = root.get("hbc_source", "")
    path = os.path.normpath(bpy.path.abspath(raw)) if raw else ""
    if path and os.path.isfile(path):
        return path
    found = _beside_blend(path) if path else None
    if found is not None:
        return found
    raise SourceMissing(f"Source of '{root.name}' is missing: {path or '(none)'}. Set its path in "
                        "Hex Structure > Source; the layers are kept.")


def _roots():
    return [c for c in bpy.data.collections if c.get("hbc_source") is not None]


def _current(root) -> str:
    """The source's absolute path: where it was found, else where it was stored."""
    try:
        return resolve(root)
    except SourceMissing:
        return os.path.normpath(bpy.path.abspath(root["hbc_source"]))


def store_for_save(target: str | None):
    """Relative paths for the file being written. Blender versions that pass the target path to
    the save handler get paths relative to it (`target`); others (3.4 passes none: None) get
    absolute paths, always right whatever folder the .blend is saved into, and found again by
    `resolve` after a move."""
    for root in _roots():
        if root["hbc_source"]:
            path = _current(root)
            root["hbc_source"] = stored(path, target) if target else path


def store_relative():
    """Back to paths relative to the file just written (its place is known now)."""
    for root in _roots():
        if root["hbc_source"]:
            root["hbc_source"] = stored(_current(root))
