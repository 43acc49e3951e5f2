"""The add-on as a user installs it, in a Blender whose user folders are empty (ctest points them at
a fresh folder per Blender version): Blender 4.2+ installs the extension zip (manifest + hbc
wheels, one per Python) the way its command line and Preferences do; 3.x installs the legacy zip
(bl_info, hbc bundled). Then the add-on is enabled, teapot.hedra imported through File > Import's
operator, every layer built (Build All, then the picked sheet and its subsheets), and the add-on
disabled again.

Runs in its own pytest session (ctest entry extension@...): the add-on must not be registered
from the build tree as well.

Environment: HBC_EXTENSION_ZIP (scripts/wheels.sh packs it), HBC_ADDON_ZIP, HBC_DATA_DIR.
"""

import os
import pathlib
import sys

import pytest

bpy = pytest.importorskip("bpy")
import addon_utils  # noqa: E402  (Blender's own module, importable once bpy is)

EXTENSIONS = bpy.app.version >= (4, 2, 0)
REPO = "user_default"
MODULE = f"bl_ext.{REPO}.hybrid_base_complex" if EXTENSIONS else "hybrid_base_complex"


def _env_file(name, hint):
    value = os.environ.get(name)
    if not value or not os.path.isfile(value):
        pytest.fail(f"{name}={value} is missing ({hint})")
    return value


@pytest.fixture(scope="module")
def installed():
    if EXTENSIONS:
        zip_path = _env_file("HBC_EXTENSION_ZIP", "run scripts/wheels.sh, which packs it")
        # What "Install from Disk" and `blender --command extension install-file` do.
        result = bpy.ops.extensions.package_install_files(filepath=zip_path, repo=REPO, enable_on_install=True)
    else:
        zip_path = _env_file("HBC_ADDON_ZIP", "build the addon_zip target")
        assert bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True) == {"FINISHED"}
        result = bpy.ops.preferences.addon_enable(module=MODULE)
    assert result == {"FINISHED"}, result
    yield MODULE
    bpy.ops.preferences.addon_disable(module=MODULE)


def test_enabled_from_a_clean_user_folder(installed):
    loaded, enabled = addon_utils.check(installed)
    assert loaded and enabled
    assert "hbc" in dir(bpy.ops.import_mesh)
    # Installed into this test's own user folder (ctest sets BLENDER_USER_EXTENSIONS / _SCRIPTS).
    folder = os.environ.get("BLENDER_USER_EXTENSIONS" if EXTENSIONS else "BLENDER_USER_SCRIPTS")
    assert folder, "ctest sets the user folders"
    mod = pathlib.Path(sys.modules[installed].__file__).resolve()
    assert mod.is_relative_to(pathlib.Path(folder).resolve()), (mod, folder)


def test_hbc_comes_from_the_package(installed):
    """4.2+: the module of the extension's wheel for this Python; 3.x: the copy inside the zip."""
    from importlib import import_module

    hbc = import_module(f"{installed}.plan.native").import_hbc()
    where = pathlib.Path(hbc.__file__).resolve()
    tag = f"cpython-{sys.version_info[0]}{sys.version_info[1]}"
    assert any(p.name.startswith("_core.") and tag in p.name for p in where.parent.iterdir()), where
    if EXTENSIONS:
        assert hbc.__name__ == "hbc" and "site-packages" in where.parts, where
    else:
        assert hbc.__name__ == f"{installed}.hbc", where


def test_import_teapot_and_build_every_layer(installed):
    """Build All's five overview layers, then the picked sheet (the largest self-intersecting one)
    and its subsheets: every layer of planning.LAYERS, each holding what it shows."""
    from importlib import import_module

    data = os.environ.get("HBC_DATA_DIR")
    teapot = pathlib.Path(data or "") / "hybrid-base-complex" / "teapot.hedra"
    if not teapot.is_file():
        pytest.fail(f"HBC_DATA_DIR={data} has no hybrid-base-complex/teapot.hedra")
    bpy.ops.wm.read_homefile(use_empty=True)
    assert bpy.ops.import_mesh.hbc(filepath=str(teapot), build_layers=False) == {"FINISHED"}
    roots = [c for c in bpy.data.collections if c.get("hbc_source") is not None]
    assert [c.name for c in roots] == ["teapot"]
    root = roots[0]
    assert bpy.ops.hbc.build_all() == {"FINISHED"}
    st = bpy.context.scene.hbc
    self_intersecting = [it for it in st.sheets if it.type == 3]
    assert self_intersecting, "teapot.hedra has self-intersecting sheets"
    sheet = max(self_intersecting, key=lambda it: it.cells).index
    st.sheet_index = sheet
    assert bpy.ops.hbc.build_layer(layer="sheet") == {"FINISHED"}
    assert bpy.ops.hbc.build_layer(layer="subsheets") == {"FINISHED"}

    layers = {c.get("hbc_layer"): list(c.all_objects) for c in root.children}
    every = [key for key, _ in import_module(f"{installed}.plan.planning").LAYERS]
    assert sorted(layers) == sorted(every), layers.keys()
    empty = [key for key, objects in layers.items() if not objects]
    assert not empty, empty
    # The picked sheet: its blocks and highlights, all of that sheet.
    assert {ob.get("hbc_sheet") for ob in layers["sheet"]} == {sheet}
    assert any(ob.get("hbc_highlight") is None for ob in layers["sheet"])
    # The subsheets: one block object per subsheet of the analysis, each with its wireframe.
    s = import_module(f"{installed}.plan.session").get(root.name)
    count = int(s.subsheets(sheet).count)
    assert count >= 2
    blocks = [ob for ob in layers["subsheets"] if ob.get("hbc_owner") == "subsheet"]
    assert sorted(ob["hbc_subsheet"] for ob in blocks) == list(range(count))
    assert {ob.get("hbc_sheet") for ob in layers["subsheets"]} == {sheet}
    assert any(ob.get("hbc_wireframe") for ob in layers["subsheets"])


def test_disable_removes_everything(installed):
    bpy.ops.preferences.addon_disable(module=installed)
    assert "hbc" not in dir(bpy.ops.import_mesh)
    assert not hasattr(bpy.types.Scene, "hbc")
    bpy.ops.preferences.addon_enable(module=installed)  # the fixture disables it at the end
    assert "hbc" in dir(bpy.ops.import_mesh)
