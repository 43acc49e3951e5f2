"""Hybrid Base Complex: import hex-dominant volume meshes and build their structure scene
(direct view, hybrid singularity graph, base complex components, sheets and subsheets with their
highlights, VSG wireframes) from the hbc analysis.

Blender 3.4 reads bl_info; 4.2+ reads blender_manifest.toml. The package is layered
ui -> blender -> plan: plan/ does not import bpy and is tested with plain pytest; blender/ makes
Blender data; ui/ is what the user touches, and ui/addon.py registers everything.
"""

# Preferences > Add-ons searches the name, author and category: "hex" finds the add-on by its name.
# Blender reads bl_info without running this file, so it holds literals only; doc_url and
# tracker_url are the add-on's own user guide (README.md), a file URL set when it registers.
bl_info = {
    "name": "Hex Structure: Hybrid Base Complex",
    "author": "hbc authors",
    "version": (0, 2, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > Hex-dominant Mesh; 3D View > Sidebar > Hex Structure",
    "description": "Structure of hex-dominant meshes: singularity graph, base complex, sheets, VSG wireframes",
    "doc_url": "",
    "tracker_url": "",
    "category": "Import-Export",
}

try:
    import bpy  # noqa: F401
except ImportError:  # plain Python (unit tests): only plan/ is usable
    bpy = None

if bpy is not None:
    from .ui.addon import register, unregister  # noqa: F401
