"""The figure script's bpy-free modules (blender_scripts/figures/plan.py, compose.py) on sys.path."""

import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "blender_scripts"))
