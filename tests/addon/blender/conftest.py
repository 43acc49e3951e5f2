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


def render_from_above(tmp_path, tag, lo, hi, width, height, margin=1.05):
    """The scene rendered by Workbench with the add-on's Solid settings (colour type Attribute, the
    enum's "VERTEX"), flat light, from above the world box lo..hi (numpy (3,)), orthographic, its
    larger side times `margin` in view: (height, width, 4) pixels. The camera, "HBC test camera", is
    made once and stays (undo tests step over it)."""
    import numpy as np
    from hybrid_base_complex.blender import compat

    scene = bpy.context.scene
    cam = bpy.data.objects.get("HBC test camera")
    if cam is None:
        cam = bpy.data.objects.new("HBC test camera", bpy.data.cameras.new("HBC test camera"))
        scene.collection.objects.link(cam)
    cam.data.type = "ORTHO"
    cam.data.ortho_scale = float(max(hi[:2] - lo[:2])) * margin
    cam.location = (float(lo[0] + hi[0]) / 2, float(lo[1] + hi[1]) / 2, float(hi[2]) + 10.0)
    cam.rotation_euler = (0.0, 0.0, 0.0)
    scene.camera = cam
    scene.render.engine = "BLENDER_WORKBENCH"
    compat.solid_shading(scene.display.shading)
    scene.display.shading.light = "FLAT"
    scene.view_settings.view_transform = "Standard"
    scene.render.film_transparent = True
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = width, height, 100
    scene.render.image_settings.file_format = "PNG"
    scene.render.filepath = str(tmp_path / f"{tag}.png")
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(scene.render.filepath)
    try:
        px = np.empty(len(img.pixels), np.float32)
        img.pixels.foreach_get(px)
    finally:
        bpy.data.images.remove(img)
    return px.reshape(height, width, 4)
