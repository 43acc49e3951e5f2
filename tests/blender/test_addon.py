"""The add-on inside Blender (background mode): registration, import of every shared hex-dominant
mesh through the operator, every layer built with object/collection/material counts checked
against the analysis, rebuilds that replace, and failures that leave the file unchanged."""

import os
import zipfile

import bpy
import numpy as np
import pytest

from conftest import hbc_meshes
from fakes import FakeMesh


def roots():
    return [c for c in bpy.data.collections if c.get("hbc_source") is not None]


def layer_objects(root, layer):
    from hybrid_base_complex import scene as S

    coll = S.find_layer(root, layer)
    assert coll is not None, f"no {layer} layer under {root.name}"
    return list(coll.all_objects)


def has_analysis():
    from hybrid_base_complex.structure import import_hbc

    return hasattr(import_hbc().Mesh, "analyze")


def test_register_unregister_twice(addon):
    for _ in range(2):
        addon.unregister()
        assert not hasattr(bpy.types.Scene, "hbc")
        assert not hasattr(bpy.ops.import_mesh, "hbc") or "hbc" not in dir(bpy.ops.import_mesh)
        addon.register()
        assert hasattr(bpy.types.Scene, "hbc")
        assert "hbc" in dir(bpy.ops.import_mesh)


def test_addon_uses_bundled_hbc(addon):
    from hybrid_base_complex.structure import import_hbc

    hbc = import_hbc()
    assert hbc.__name__ == "hybrid_base_complex.hbc", hbc.__file__


def test_bad_file_leaves_scene_unchanged(clean_scene, tmp_path):
    from hybrid_base_complex import scene as S

    bad = tmp_path / "bad.mesh"
    bad.write_text("MeshVersionFormatted 1\nDimension 3\nVertices\n2\n0 0 0 0\n")
    before = S.datablock_names()
    with pytest.raises(RuntimeError):
        bpy.ops.import_mesh.hbc(filepath=str(bad))
    assert S.datablock_names() == before
    with pytest.raises(RuntimeError):
        bpy.ops.import_mesh.hbc(filepath=str(tmp_path / "missing.ovm"))
    assert S.datablock_names() == before


def test_failed_layer_build_leaves_scene_unchanged(clean_scene, monkeypatch, data_dir):
    from hybrid_base_complex import layers as L
    from hybrid_base_complex import scene as S

    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir / "openvolumemesh" / "Cylinder.ovm"),
                                   analyze=False) == {"FINISHED"}
    root = roots()[0]

    def explode(tx, coll, s, st, name):
        L.build_direct(tx, coll, s, st, name)  # makes objects, materials ... then fails
        raise RuntimeError("stage failed")

    bpy.data.materials.remove(bpy.data.materials[next(m.name for m in bpy.data.materials if "HBC" in m.name)])
    before = S.datablock_names()
    monkeypatch.setitem(L.BUILDERS, "direct", explode)
    with pytest.raises(RuntimeError, match="stage failed"):
        bpy.ops.hbc.build_layer(layer="direct")
    assert S.datablock_names() == before
    assert S.find_layer(root, "direct") is not None


@pytest.mark.parametrize("index", range(5))
def test_import_every_shared_mesh(clean_scene, data_dir, index):
    from hybrid_base_complex import session
    from hybrid_base_complex.structure import import_hbc

    path = hbc_meshes(data_dir)[index]
    analyze = has_analysis()
    assert bpy.ops.import_mesh.hbc(filepath=str(path), analyze=analyze) == {"FINISHED"}
    (root,) = roots()
    assert root.name in [c.name for c in bpy.context.scene.collection.children]
    mesh = import_hbc().load(str(path))
    s = session.get(root.name)
    assert s.num_cells == mesh.num_cells == root["hbc_cells"]
    direct = layer_objects(root, "direct")
    n_non_hex = int(np.sum(np.asarray(mesh.cell_types) != 0))
    assert len(direct) == 1 + (1 if n_non_hex else 0)
    boundary = next(o for o in direct if o.get("hbc_part") == "boundary")
    assert len(boundary.data.polygons) == int(np.sum(mesh.face_boundary))
    if n_non_hex:
        nh = next(o for o in direct if o.get("hbc_part") == "non_hex")
        owners = np.zeros(len(nh.data.polygons), np.int32)
        nh.data.attributes["owner"].data.foreach_get("value", owners)
        assert len(np.unique(owners)) == n_non_hex
    if analyze:
        st = bpy.context.scene.hbc
        assert len(st.sheets) == s.num_sheets
        build_every_layer_and_check(root, s)


def build_every_layer_and_check(root, s):
    """Builds every layer through the operators and checks counts against the analysis."""
    from hybrid_base_complex import planning as P

    st = bpy.context.scene.hbc
    assert bpy.ops.hbc.build_all() == {"FINISHED"}
    # Singularity graph: one object per valence present plus pseudo-singular / non-manifold.
    g = s.analysis.graph
    cls = np.asarray(g.edge_class)
    expected = len(np.unique(g.chain_valence)) + int(np.any(cls == 2)) + int(np.any(cls == 3))
    assert len(layer_objects(root, "graph")) == expected
    # Blocks: one object per component (or one merged mesh with an owner per face).
    blocks = layer_objects(root, "blocks")
    if s.num_components <= st.split_max:
        assert len(blocks) == s.num_components
        assert sorted(o["hbc_component"] for o in blocks) == list(range(s.num_components))
    else:
        (ob,) = blocks
        owners = np.zeros(len(ob.data.polygons), np.int32)
        ob.data.attributes["owner"].data.foreach_get("value", owners)
        assert len(np.unique(owners)) == s.num_components
    sheets = layer_objects(root, "sheets")
    assert len(sheets) == (s.num_sheets if s.num_sheets <= st.split_max else (1 if s.num_sheets else 0))
    wire = layer_objects(root, "wireframe")
    assert len(wire) <= 1
    # The picked sheet with its highlights, for each sheet type present.
    types = s.sheet_types()
    for t in sorted(set(types.tolist())):
        st.sheet_index = int(np.nonzero(types == t)[0][0])
        assert bpy.ops.hbc.build_layer(layer="sheet") == {"FINISHED"}
        objs = layer_objects(root, "sheet")
        hl = {o.get("hbc_highlight") for o in objs}
        if t in (1, 2, 3):
            assert "unmatched" in hl or "shared" in hl or "self_intersecting" in hl, (t, hl)
        if t == 3:
            assert "self_intersecting" in hl
            assert bpy.ops.hbc.build_layer(layer="subsheets") == {"FINISHED"}
            sub = s.subsheets(st.sheet_index)
            blocks = [o for o in layer_objects(root, "subsheets") if o.get("hbc_owner") == "subsheet"]
            assert len(blocks) == int(sub.count)
    # Rebuilding replaces: same counts, one collection per layer.
    n_objects = len(bpy.data.objects)
    n_collections = len(bpy.data.collections)
    n_materials = len(bpy.data.materials)
    assert bpy.ops.hbc.build_layer(layer="blocks") == {"FINISHED"}
    assert (len(bpy.data.objects), len(bpy.data.collections), len(bpy.data.materials)) == \
        (n_objects, n_collections, n_materials)
    assert sorted(c["hbc_layer"] for c in root.children) == sorted(
        {k for k, _ in P.LAYERS} - ({"subsheets"} if 3 not in types else set()))
    assert all(m.name.startswith("HBC ") for m in bpy.data.materials)


def test_every_layer_on_fake_analysis(clean_scene, addon):
    """Every builder on a stand-in analysis (grid with a non-hex cell), through the operators."""
    from hybrid_base_complex import layers as L
    from hybrid_base_complex import planning as P
    from hybrid_base_complex import scene as S
    from hybrid_base_complex import session
    from hybrid_base_complex.operators import fill_sheet_list
    from hybrid_base_complex.structure import Structure

    m = FakeMesh(4, 2, 2, non_hex_last=True)
    s = Structure(m, m.analyze())
    with S.Transaction() as tx:
        root = tx.collection("fake")
        root["hbc_source"] = "<fake>"
        root["hbc_cells"] = s.num_cells
        bpy.context.scene.collection.children.link(root)
    session.put(root.name, s)
    st = bpy.context.scene.hbc
    st.active_mesh = root.name
    fill_sheet_list(st, s)
    assert [it.type for it in st.sheets] == [0, 3, 2]
    build_every_layer_and_check(root, s)
    # Lines carry per-point opacity and the tube modifier renders them.
    (wire,) = layer_objects(root, "wireframe")
    col = np.zeros(4 * len(wire.data.vertices), np.float32)
    wire.data.color_attributes["hbc_color"].data.foreach_get("color", col)
    alpha = col[3::4]
    assert alpha.min() == pytest.approx(st.opacity_floor) and st.opacity_floor < alpha.max() <= 1.0
    dg = bpy.context.evaluated_depsgraph_get()
    ev = wire.evaluated_get(dg)
    assert len(ev.data.polygons) > 0 and "hbc_color" in ev.data.attributes
    # Picking another sheet in the list shows it at once (the picked-sheet layer exists).
    st.sheet_index = 2
    assert {o["hbc_sheet"] for o in layer_objects(root, "sheet")} == {2}
    st.sheet_index = 0
    assert {o["hbc_sheet"] for o in layer_objects(root, "sheet")} == {0}
    # Merged blocks when over the split limit; the face owner tells the block.
    st.split_max = 0
    assert bpy.ops.hbc.build_layer(layer="blocks") == {"FINISHED"}
    (merged,) = layer_objects(root, "blocks")
    assert merged["hbc_owner"] == "component"
    # The panel's picking: per-block object and merged mesh in edit mode.
    from hybrid_base_complex.panels import picked_block

    bpy.context.view_layer.objects.active = merged
    bpy.ops.object.mode_set(mode="EDIT")
    import bmesh

    bm = bmesh.from_edit_mesh(merged.data)
    bm.faces.ensure_lookup_table()
    bm.faces.active = bm.faces[len(bm.faces) - 1]
    owner, kind, _ = picked_block(bpy.context)
    bpy.ops.object.mode_set(mode="OBJECT")
    assert kind == "component" and owner == s.num_components - 1
    # Clearing removes the layer.
    assert bpy.ops.hbc.clear_layer(layer="blocks") == {"FINISHED"}
    assert S.find_layer(root, "blocks") is None
    assert P.layer_collection_name(root.name, "sheets") in bpy.data.collections


def test_zip_installs_and_enables(addon, tmp_path):
    """The release zip installs through Preferences and enables (then is disabled again)."""
    zip_path = os.environ.get("HBC_ADDON_ZIP")
    if not zip_path or not os.path.isfile(zip_path):
        pytest.fail(f"HBC_ADDON_ZIP={zip_path} is missing (build the addon_zip target)")
    with zipfile.ZipFile(zip_path) as z:
        names = z.namelist()
    assert "hybrid_base_complex/__init__.py" in names
    assert any(n.startswith("hybrid_base_complex/hbc/_core") for n in names)
    # Installing copies into BLENDER_USER_SCRIPTS (a temporary folder in ctest); enabling the
    # installed copy would clash with the session's registered classes, so only the copy is checked.
    assert bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True) == {"FINISHED"}
    installed = os.path.join(bpy.utils.user_resource("SCRIPTS", path="addons"), "hybrid_base_complex", "__init__.py")
    assert os.path.isfile(installed)


class _Recorder:
    """A stand-in UILayout: accepts every call, records the texts, returns another recorder."""

    def __init__(self, log):
        self._log = log

    def __getattr__(self, name):
        def call(*args, **kwargs):
            if name == "prop":
                data, prop = args[0], args[1]
                assert hasattr(data, prop) or prop in data.bl_rna.properties, prop
            if "text" in kwargs:
                self._log.append(str(kwargs["text"]))
            return _Recorder(self._log)
        return call

    def __setattr__(self, name, value):
        object.__setattr__(self, name, value)


def test_panels_draw(clean_scene, data_dir):
    """Every panel's draw runs (against a recording layout) for an analyzed mesh and a picked block."""
    from types import SimpleNamespace

    from hybrid_base_complex import panels

    path = data_dir / "hybrid-base-complex" / "twistcube_s.mesh"
    assert bpy.ops.import_mesh.hbc(filepath=str(path), analyze=has_analysis()) == {"FINISHED"}
    texts = []
    for cls in (panels.HBC_PT_main, panels.HBC_PT_layers):
        assert not hasattr(cls, "poll") or cls.poll(bpy.context)
        cls.draw(SimpleNamespace(layout=_Recorder(texts)), bpy.context)
    assert "|C|" in texts and "Build" in texts
    if has_analysis():
        bpy.context.scene.hbc.split_max = 100000
        assert bpy.ops.hbc.build_layer(layer="blocks") == {"FINISHED"}
        root = roots()[0]
        ob = layer_objects(root, "blocks")[3]
        bpy.context.view_layer.objects.active = ob
        assert panels.HBC_PT_selection.poll(bpy.context)
        panels.HBC_PT_selection.draw(SimpleNamespace(layout=_Recorder(texts)), bpy.context)
        assert f"component: {ob['hbc_component']}" in texts
        assert any(t.startswith("kind: ") for t in texts) and any(t.startswith("sheets: ") for t in texts)
    item = SimpleNamespace(index=0, type=3, cells=10, components=2)
    panels.HBC_UL_sheets.draw_item(None, bpy.context, _Recorder(texts), None, item, 0, None, "")
    assert "type 3 (self-intersecting)" in texts
