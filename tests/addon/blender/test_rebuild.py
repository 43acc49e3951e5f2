"""Rebuilding a layer in place: a rebuild refills the layer's objects instead of
removing and making them again, and must give exactly what a first build with the same settings
gives (names, geometry, attributes, materials, modifiers and their inputs, properties, colours,
visibility), remove what the new build no longer makes, and, when it fails, put the layer back as
it was. How long it takes is measured by blender_scripts/bench_addon.py, not here."""

import bpy
import numpy as np
import pytest

TWISTCUBE = ("hybrid-base-complex", "twistcube_s.mesh")  # 1301 cells, 20 sheets of all four types


def import_twistcube(data_dir):
    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*TWISTCUBE))) == {"FINISHED"}
    return bpy.data.collections[bpy.context.scene.hbc.active_mesh]


def layer(root, key):
    from hybrid_base_complex.blender import scene as S

    coll = S.find_layer(root, key)
    assert coll is not None, f"no {key} layer"
    return coll


#: foreach_get property, components and dtype per attribute type (the add-on's meshes use these).
ATTR_IO = {"FLOAT": ("value", 1, np.float32), "INT": ("value", 1, np.int32), "BOOLEAN": ("value", 1, bool),
           "FLOAT_VECTOR": ("vector", 3, np.float32), "FLOAT_COLOR": ("color", 4, np.float32)}


def read(collection, prop, width, dtype):
    out = np.empty(len(collection) * width, dtype)
    collection.foreach_get(prop, out)
    return out


def group_inputs(mod):
    """{input name: value} of a geometry-nodes modifier (objects by name)."""
    from hybrid_base_complex.blender import compat

    ng = mod.node_group
    if hasattr(ng, "interface"):
        names = [s.name for s in ng.interface.items_tree
                 if getattr(s, "item_type", "SOCKET") == "SOCKET" and s.in_out == "INPUT"]
    else:
        names = [s.name for s in ng.inputs]
    out = {}
    for name in names:
        if name == "Geometry":
            continue
        v = compat.get_modifier_input(mod, name)
        out[name] = getattr(v, "name", v) if not isinstance(v, (int, float, bool)) else v
    return out


def object_state(ob):
    me = ob.data
    sizes = {"POINT": len(me.vertices), "EDGE": len(me.edges), "FACE": len(me.polygons), "CORNER": len(me.loops)}
    attrs = {}
    for a in me.attributes:
        if a.name.startswith(".") or a.name == "position" or a.data_type not in ATTR_IO:
            continue
        key, width, dtype = ATTR_IO[a.data_type]
        values = np.empty(sizes[a.domain] * width, dtype)
        a.data.foreach_get(key, values)
        attrs[a.name] = (a.domain, a.data_type, values)
    active = me.color_attributes.active_color
    return {
        "type": ob.type,
        "mesh": me.name,
        "co": read(me.vertices, "co", 3, np.float32),
        "edges": read(me.edges, "vertices", 2, np.int32),
        "corners": read(me.loops, "vertex_index", 1, np.int32),
        "starts": read(me.polygons, "loop_start", 1, np.int32),
        "attrs": attrs,
        "active_color": active.name if active is not None else None,
        "materials": [m.name if m else None for m in me.materials],
        "modifiers": [(m.name, m.type, m.node_group.name, group_inputs(m), m.show_viewport) for m in ob.modifiers],
        "props": {k: (v.to_list() if hasattr(v, "to_list") else v) for k, v in ob.items() if k.startswith("hbc_")},
        "color": tuple(round(c, 6) for c in ob.color),
        "hidden": (ob.hide_viewport, ob.hide_render),
        "matrix": tuple(tuple(r) for r in ob.matrix_basis),
    }


def layer_state(root, key):
    coll = layer(root, key)
    state = {ob.name: object_state(ob) for ob in coll.objects}
    state["<collection>"] = (coll.name, coll.hide_viewport, coll.hide_render, len(coll.children))
    return state


def assert_same(a, b):
    assert sorted(a) == sorted(b)
    for name in a:
        x, y = a[name], b[name]
        if not isinstance(x, dict):
            assert x == y, name
            continue
        assert sorted(x) == sorted(y), name
        for k in x:
            if k == "attrs":
                assert sorted(x[k]) == sorted(y[k]), (name, k)
                for attr, (dom, kind, values) in x[k].items():
                    assert (dom, kind) == y[k][attr][:2], (name, attr)
                    assert np.array_equal(values, y[k][attr][2]), (name, attr)
            elif isinstance(x[k], np.ndarray):
                assert np.array_equal(x[k], y[k]), (name, k)
            else:
                assert x[k] == y[k], (name, k)


def pointers(root, key):
    return {ob.name: ob.as_pointer() for ob in layer(root, key).objects}


# Each case: a layer, the setting changed before the rebuild (so that the rebuild writes other
# geometry, colours or modifier inputs than the layer holds) and its new value.
CASES = [
    ("components", "shrink", 0.25),
    ("sheets", "shrink", 0.25),
    ("sheet", "shrink", 0.25),
    ("graph", "line_radius", 0.01),
    ("wireframe", "opacity_floor", 0.5),
    ("direct", "direct_shrink", 0.3),
]


@pytest.mark.parametrize("key,setting,value", CASES, ids=[c[0] for c in CASES])
def test_rebuild_refills_in_place_and_equals_a_first_build(clean_scene, data_dir, key, setting, value):
    """The rebuild keeps the layer's collection and its objects (the same Blender objects, not new
    ones of the same names) and leaves exactly what clearing the layer and building it anew gives."""
    root = import_twistcube(data_dir)
    st = bpy.context.scene.hbc
    st.split_max = 100000
    st.sheet_index = 3
    assert bpy.ops.hbc.build_layer(layer=key) == {"FINISHED"}
    before = pointers(root, key)
    coll = layer(root, key).as_pointer()
    old = layer_state(root, key)
    setattr(st, setting, value)
    assert bpy.ops.hbc.build_layer(layer=key) == {"FINISHED"}
    assert pointers(root, key) == before and layer(root, key).as_pointer() == coll
    rebuilt = layer_state(root, key)
    assert bpy.ops.hbc.clear_layer(layer=key) == {"FINISHED"}
    assert bpy.ops.hbc.build_layer(layer=key) == {"FINISHED"}
    first = layer_state(root, key)
    assert_same(rebuilt, first)
    # The setting did change what the layer holds (else the comparison above proves little).
    with pytest.raises(AssertionError):
        assert_same(old, rebuilt)


def test_rebuild_removes_what_it_no_longer_makes(clean_scene, data_dir):
    """Blocks as 1301 objects, then merged into one (the 1301 objects and their meshes go, nothing
    is left behind), then split again: the first build's names come back."""
    root = import_twistcube(data_dir)
    st = bpy.context.scene.hbc
    st.split_max = 100000
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    split = sorted(ob.name for ob in layer(root, "components").objects)
    counts = (len(bpy.data.objects), len(bpy.data.meshes))
    assert len(split) == 1301
    st.split_max = 0
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    assert [ob.name for ob in layer(root, "components").objects] == [f"{root.name} components"]
    assert (len(bpy.data.objects), len(bpy.data.meshes)) == (counts[0] - 1300, counts[1] - 1300)
    assert not any(m.users == 0 for m in bpy.data.meshes)
    st.split_max = 100000
    assert bpy.ops.hbc.build_layer(layer="components") == {"FINISHED"}
    assert sorted(ob.name for ob in layer(root, "components").objects) == split
    assert (len(bpy.data.objects), len(bpy.data.meshes)) == counts


@pytest.mark.parametrize("key,setting,value", [CASES[0], CASES[3]], ids=["components", "graph"])
def test_failed_rebuild_puts_the_layer_back(clean_scene, data_dir, monkeypatch, key, setting, value):
    """A builder that refills every object with other settings and then fails: the layer is as it
    was (geometry, colours, modifier inputs, properties) and no datablock is left or lost."""
    from hybrid_base_complex.blender import layers as L
    from hybrid_base_complex.blender import scene as S

    root = import_twistcube(data_dir)
    st = bpy.context.scene.hbc
    st.split_max = 100000
    assert bpy.ops.hbc.build_layer(layer=key) == {"FINISHED"}
    before = layer_state(root, key)
    names = S.datablock_names()
    builder = L.BUILDERS[key]

    def fails(tx, coll, s, st_, name):
        made = yield from builder(tx, coll, s, st_, name)
        assert made and tx.kept  # it did refill the old objects
        raise RuntimeError("stage failed")

    monkeypatch.setitem(L.BUILDERS, key, fails)
    setattr(st, setting, value)
    with pytest.raises(RuntimeError, match="stage failed"):
        bpy.ops.hbc.build_layer(layer=key)
    assert S.datablock_names() == names
    assert_same(layer_state(root, key), before)


def test_every_layer_has_first_build_names(clean_scene, data_dir):
    """Every layer built, the picked sheet and its subsheets too, then every layer rebuilt: no
    object or mesh is named with a '.001'-style suffix (no two layers ask for one name)."""
    import re

    from hybrid_base_complex.plan import planning as P
    from hybrid_base_complex.plan import session

    root = import_twistcube(data_dir)
    st = bpy.context.scene.hbc
    s = session.get(root.name)
    st.sheet_index = int(s.analysis.largest_self_intersecting)
    assert bpy.ops.hbc.build_all() == {"FINISHED"}
    for key in ("sheet", "subsheets"):
        assert bpy.ops.hbc.build_layer(layer=key) == {"FINISHED"}
    for key, _ in P.LAYERS:
        assert bpy.ops.hbc.build_layer(layer=key) == {"FINISHED"}
    suffixed = [d.name for d in list(bpy.data.objects) + list(bpy.data.meshes) if re.search(r"\.\d{3}$", d.name)]
    assert suffixed == []
