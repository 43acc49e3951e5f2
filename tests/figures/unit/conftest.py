"""The figure script's bpy-free modules (blender_scripts/figures/plan.py, compose.py) on sys.path, and
the add-on's bpy-free planning module (addon/hybrid_base_complex/plan/planning.py: the legend's colours
and words, which the figures take from there)."""

import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "blender_scripts"))
sys.path.insert(0, str(ROOT / "addon"))
