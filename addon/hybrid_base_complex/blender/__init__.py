"""Blender data without UI: version differences (compat), bulk meshes, materials and
transactions (scene), one builder per layer (layers), the inspection's attributes, node group and
live surface (inspect), source paths (sources), what the scene holds (context) and the upgrade
of files saved by an older add-on (upgrade). Imports
``plan``, never ``ui``.
"""
