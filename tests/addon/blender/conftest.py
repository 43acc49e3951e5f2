"""Fixtures of the add-on tests inside Blender (run by tests/run_pytest_in_blender.py).

HBC_ADDON_DIR: the add-on package assembled by the build (<build>/addon/hybrid_base_complex, with
the compiled hbc inside); HBC_DATA_DIR: the shared meshes. A missing variable fails the tests.
"""

import os
import pathlib
import sys

import pytest

bpy = pytest.importorskip("bpy")

HERE = pathlib.Path(__file__).resolve().parent

MESH_SUFFIXES = (".ovm", ".ovmb", ".mesh", ".hybrid", ".hedra")


def addon_dir():
    value = os.environ.get("HBC_ADDON_DIR")
    return pathlib.Path(value) if value else None


@pytest.fixture(scope="session")
def addon():
    d = addon_dir()
    if d is None or not (d / "__init__.py").is_file():
        pytest.fail(f"HBC_ADDON_DIR={d} does not hold the built add-on (build the 'addon' target)")
    if str(d.parent) not in sys.path:
        sys.path.insert(0, str(d.parent))
    import hybrid_base_complex

    hybrid_base_complex.register()
    yield hybrid_base_complex
    hybrid_base_complex.unregister()


@pytest.fixture
def clean_scene(addon):
    """An empty file (factory settings keep the add-on's classes registered)."""
    bpy.ops.wm.read_homefile(use_empty=True)
    # read_homefile resets data; make sure nothing of ours lingers.
    yield bpy.context.scene


@pytest.fixture(scope="session")
def data_dir():
    value = os.environ.get("HBC_DATA_DIR")
    if not value or not os.path.isdir(value):
        pytest.fail(f"HBC_DATA_DIR={value} is not a folder")
    return pathlib.Path(value)


def hbc_meshes(root):
    """The four meshes of the paper's data plus one OpenVolumeMesh file."""
    root = pathlib.Path(root)
    files = sorted((root / "hybrid-base-complex").iterdir())
    files = [p for p in files if p.suffix.lower() in MESH_SUFFIXES]
    files.append(root / "openvolumemesh" / "Cylinder.ovm")
    return files
