"""The add-on's bpy-free modules are imported from the source tree (addon/) by plain Python."""

import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
for p in (ROOT / "addon", HERE):
    if str(p) not in sys.path:
        sys.path.insert(0, str(p))
