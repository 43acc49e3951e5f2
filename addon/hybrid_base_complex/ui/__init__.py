"""What the user touches: settings (properties), operators, the sidebar (panels), the app
handlers (handlers), and the one place that registers them all (addon). Imports ``blender`` and
``plan``; nothing imports ``ui`` but the package's ``__init__``.
"""
