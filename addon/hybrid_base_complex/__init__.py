"""Hybrid Base Complex: import hex-dominant volume meshes and build their structure scene
(direct view, hybrid singularity graph, base complex blocks, sheets and subsheets with their
highlights, VSG wireframes) from the hbc analysis.

Blender 3.4 reads bl_info; 4.2+ reads blender_manifest.toml. The planning modules (planning,
structure, session) do not import bpy and are tested with plain pytest.
"""

bl_info = {
    "name": "Hybrid Base Complex",
    "author": "hbc authors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > Hex-dominant mesh; 3D View > Sidebar > Hex Structure",
    "description": "Structure of hex-dominant meshes: singularity graph, base complex, sheets, VSG wireframes",
    "category": "Import-Export",
}

try:
    import bpy  # noqa: F401
except ImportError:  # plain Python (unit tests): only the bpy-free modules are usable
    bpy = None

if bpy is not None:
    from . import handlers, inspect, operators, panels, properties

    _MODULES = (properties, operators, panels, inspect)

    def register():
        for module in _MODULES:
            for cls in module.classes:
                bpy.utils.register_class(cls)
        properties.register_props()
        inspect.register_props()
        operators.register_menus()
        handlers.register()
        from .structure import module_problem

        # Registered either way (menus and panel stay usable); the panel and every operator say why
        # nothing can be analyzed, and so does the console.
        problem = module_problem()
        if problem:
            print(f"Hybrid Base Complex: {problem}", flush=True)

    def unregister():
        handlers.unregister()
        operators.unregister_menus()
        properties.unregister_props()
        inspect.unregister_props()
        for module in reversed(_MODULES):
            for cls in reversed(module.classes):
                bpy.utils.unregister_class(cls)
        from . import session

        session.clear()
