"""The panel's exports, read back: the analysis as VTU through the library's writer (hbc.load reads
the file again: the same cells; the block and sheet ids are cell arrays of it), and a built layer as
OBJ and PLY through Blender's exporters (as many faces as the layer's objects hold)."""
import re

import bpy
import pytest


def import_teapot(data_dir):
    path = data_dir / "hybrid-base-complex" / "teapot.hedra"
    assert bpy.ops.import_mesh.hbc(filepath=str(path)) == {"FINISHED"}
    (root,) = [c for c in bpy.data.collections if c.get("hbc_source") is not None]
    return root


def test_vtu_holds_every_cell_with_block_and_sheet_ids(clean_scene, data_dir, tmp_path):
    from hybrid_base_complex.plan.native import import_hbc

    hbc = import_hbc()
    root = import_teapot(data_dir)
    out = tmp_path / "teapot.vtu"
    assert bpy.ops.hbc.export_vtu(filepath=str(out)) == {"FINISHED"}
    assert hbc.load(str(out)).num_cells == root["hbc_cells"]
    text = out.read_text(errors="replace")
    for name in ("component", "sheet", "sheet_count"):
        assert f'Name="{name}"' in text
    assert (tmp_path / "teapot_graph.vtu").is_file()


def test_vtu_with_the_picked_sheet(clean_scene, data_dir, tmp_path):
    import_teapot(data_dir)
    assert bpy.ops.hbc.analyze() == {"FINISHED"}
    bpy.context.scene.hbc.sheet_index = 0
    out = tmp_path / "sheet.vtu"
    assert bpy.ops.hbc.export_vtu(filepath=str(out), picked_sheet=True) == {"FINISHED"}
    assert 'Name="in_sheet"' in out.read_text(errors="replace")


def layer_faces(root, layer):
    from hybrid_base_complex.blender import scene as S

    coll = S.find_layer(root, layer)
    deps = bpy.context.evaluated_depsgraph_get()
    return sum(len(ob.evaluated_get(deps).data.polygons) for ob in S.objects_in(coll)
               if ob.type == "MESH" and ob.visible_get())


def ply_faces(path) -> int:
    head = path.read_bytes().split(b"end_header", 1)[0].decode("ascii")
    return int(re.search(r"element face (\d+)", head).group(1))


def obj_faces(path) -> int:
    return sum(1 for line in path.read_text().splitlines() if line.startswith("f "))


@pytest.mark.parametrize("fmt, count", [("OBJ", obj_faces), ("PLY", ply_faces)])
def test_layer_as_obj_and_ply(clean_scene, data_dir, tmp_path, fmt, count):
    root = import_teapot(data_dir)
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    from hybrid_base_complex.blender import scene as S

    S.find_layer(root, "components").hide_viewport = True  # exported all the same, and left hidden
    bpy.context.view_layer.update()
    out = tmp_path / f"blocks.{fmt.lower()}"
    assert bpy.ops.hbc.export_layer(filepath=str(out), layer="components", format=fmt) == {"FINISHED"}
    assert S.find_layer(root, "components").hide_viewport
    S.find_layer(root, "components").hide_viewport = False
    bpy.context.view_layer.update()
    expected = layer_faces(root, "components")
    assert expected > 0 and count(out) == expected


def test_the_extension_follows_the_format(clean_scene, data_dir, tmp_path):
    """The file browser keeps the name typed for the first format: switched to PLY, blocks.obj is
    written as blocks.ply (a PLY file), not blocks.obj.ply; and back."""
    import_teapot(data_dir)
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    assert bpy.ops.hbc.export_layer(filepath=str(tmp_path / "blocks.obj"), layer="components", format="PLY") == {"FINISHED"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocks.ply"]
    assert (tmp_path / "blocks.ply").read_bytes().startswith(b"ply")
    assert bpy.ops.hbc.export_layer(filepath=str(tmp_path / "other.ply"), layer="components", format="OBJ") == {"FINISHED"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocks.ply", "other.obj"]


def test_unbuilt_layer_cancels(clean_scene, data_dir, tmp_path):
    import_teapot(data_dir)
    with pytest.raises(RuntimeError, match="not built"):
        bpy.ops.hbc.export_layer(filepath=str(tmp_path / "x.obj"), layer="sheets", format="OBJ")
    assert not (tmp_path / "x.obj").exists()
