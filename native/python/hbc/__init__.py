"""hbc: structure analysis of hex-dominant volume meshes.

The work is done by the compiled module ``hbc._core``; this package re-exports its public names
so that user code never imports ``_core`` directly.

    >>> import hbc
    >>> mesh = hbc.load("model.mesh")
    >>> mesh.info()["hex_ratio"]
"""

from ._core import Mesh, MeshFormatError, __version__, load

__all__ = ["Mesh", "MeshFormatError", "load", "__version__"]
