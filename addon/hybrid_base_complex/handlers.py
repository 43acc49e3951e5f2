"""File and undo handlers: after undo, redo or loading a file the layers look as they did (their
colour attribute is the active and rendered one again), and the source paths are stored the
Blender way on save (sources.py)."""

from __future__ import annotations

import bpy
from bpy.app.handlers import persistent

from . import compat
from . import scene as S
from . import sources


def relink_colors() -> int:
    """Makes `hbc_color` the active and rendered colour attribute of every layer mesh (undo
    restores meshes without it, so Solid > Attribute drew them black); returns how many changed."""
    changed = 0
    for me in bpy.data.meshes:
        attr = me.color_attributes.get(S.COLOR_ATTR)
        if attr is None:
            continue
        active = me.color_attributes.active_color
        if active is None or active.name != attr.name:
            changed += 1
        compat.make_active_color(me, attr)
    return changed


@persistent
def _relink(*_args):
    relink_colors()


HANDLERS = ("undo_post", "redo_post", "load_post")


def register():
    for name in HANDLERS:
        getattr(bpy.app.handlers, name).append(_relink)
    sources.register()


def unregister():
    sources.unregister()
    for name in HANDLERS:
        handlers = getattr(bpy.app.handlers, name)
        if _relink in handlers:
            handlers.remove(_relink)
