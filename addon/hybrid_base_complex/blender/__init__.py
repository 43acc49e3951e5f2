"""Blender data without UI: version differences (compat), bulk meshes, materials and
transactions (scene), one builder per layer (layers), the inspection's attributes, node group and
live surface (inspect), source paths (sources) and what the scene holds (context). Imports
``plan``, never ``ui``.
"""
