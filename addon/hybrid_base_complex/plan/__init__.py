"""What the add-on decides without Blender: the plain data the scene builders take (planning),
which hbc arrays each layer shows (structure), the loaded meshes (session), the compiled module
(native) and the inspection's per-cell decisions (inspection). Nothing here imports ``bpy``, so
plain pytest tests it (tests/addon/unit); tests/addon/unit/test_import_graph.py keeps it so.
"""
