"""The figure script's bpy-free modules (addon/hybrid_base_complex/figures/plan.py, compose.py) and
the add-on's bpy-free planning module (plan/planning.py: the legend's colours and words, which the
figures take from there), imported from the source tree by plain Python."""

import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "addon"))
