"""Builds in steps (plan/steps.py, the modal operators of ui/operators.py), driven here as the
modal operator's timer drives them in a window: the operator's job stepped by a `Stepper` with
its C++ work in worker threads, the main thread's share cut into the shortest steps (budget 0).

- Cancelled half-way (Build All over layers already built, so some are being rebuilt in place, and
  an import), the file is exactly as before: every object, mesh (geometry, attributes, materials),
  collection and their properties, the panel's settings; where this Blender has an undo stack, the
  undo history too (the last step is still the one pushed before, and redo has nothing).
- Completed, a stepped build gives exactly the objects and geometry of the direct build (the
  operator run at once, as a script or background mode runs it)."""

import bpy
import numpy as np
import pytest

TWISTCUBE = ("hybrid-base-complex", "twistcube_s.mesh")


def _plain(value):
    """An ID property as a plain value; a datablock it points to by its name (the state outlives
    the file it was read from)."""
    if isinstance(value, bpy.types.ID):
        return ("ID", value.name)
    return value.to_dict() if hasattr(value, "to_dict") else value.to_list() if hasattr(value, "to_list") else value


def file_state():
    """Everything a build may touch, as plain comparable values."""
    from hybrid_base_complex.blender import scene as S

    objects = {}
    for ob in bpy.data.objects:
        entry = {"props": {k: _plain(ob[k]) for k in ob.keys()}, "color": tuple(ob.color),
                 "hidden": (ob.hide_viewport, ob.hide_render, ob.hide_select),
                 "matrix": [tuple(r) for r in ob.matrix_basis], "data": ob.data.name if ob.data else None,
                 "collections": sorted(c.name for c in ob.users_collection),
                 "modifiers": [(m.name, getattr(m, "node_group", None) and m.node_group.name) for m in ob.modifiers]}
        objects[ob.name] = entry
    meshes = {}
    for me in bpy.data.meshes:
        m = S._MeshState(me)
        meshes[me.name] = (m.co.tobytes(), m.edges.tobytes(), m.loops.tobytes(), m.starts.tobytes(),
                           [(n, t, d, v.tobytes()) for n, t, d, _, v in m.attrs], m.active,
                           [x.name for x in m.materials], {k: _plain(me[k]) for k in me.keys()})
    colls = {c.name: (sorted(ch.name for ch in c.children), sorted(o.name for o in c.objects),
                      {k: _plain(c[k]) for k in c.keys()}, c.hide_viewport, c.hide_render)
             for c in bpy.data.collections}
    st = bpy.context.scene.hbc
    settings = (st.active_mesh, st.sheet_index, [(i.index, i.type, i.cells, i.components) for i in st.sheets])
    top = sorted(c.name for c in bpy.context.scene.collection.children)
    return {"objects": objects, "meshes": meshes, "collections": colls, "settings": settings, "top": top,
            "datablocks": S.datablock_names()}


def assert_same_state(got, want):
    for key in want:
        if key in ("objects", "meshes", "collections"):
            assert sorted(got[key]) == sorted(want[key]), key
            for name in want[key]:
                assert got[key][name] == want[key][name], (key, name)
        else:
            assert got[key] == want[key], key


def undo_works():
    """Whether this Blender keeps an undo stack here (as test_undo.py's fixture probes it)."""
    if not bpy.ops.ed.undo_push.poll():
        return False
    bpy.ops.ed.undo_push(message="probe base")
    bpy.context.scene["hbc_probe"] = 1
    bpy.ops.ed.undo_push(message="probe")
    try:
        ok = bpy.ops.ed.undo() == {"FINISHED"} and "hbc_probe" not in bpy.context.scene
        ok = ok and bpy.ops.ed.redo() == {"FINISHED"} and "hbc_probe" in bpy.context.scene
    except RuntimeError:
        return False
    del bpy.context.scene["hbc_probe"]
    return ok


def stepper(job, plan):
    from hybrid_base_complex.plan import steps

    return steps.Stepper(job, plan, threads=True)


def step_to(st, fraction):
    """Steps the job (main-thread steps one at a time, waiting for its worker) until the overall
    progress reaches `fraction`; returns how many steps that took."""
    n = 0
    while st.fraction < fraction:
        assert not st.advance(0.0), "the job ended before it got there"
        if st.waiting():
            st._worker[0].join()
        n += 1
    return n


def active_root():
    return bpy.data.collections[bpy.context.scene.hbc.active_mesh]


def test_build_all_cancelled_half_way_leaves_file_and_undo_as_before(clean_scene, data_dir):
    """Import, the components and sheets layers built (Build All rebuilds them in place), the sheet
    list emptied (Build All fills it when it finishes); Build All stepped to half its progress,
    inside its layers, then cancelled."""
    from hybrid_base_complex.ui import operators as O

    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*TWISTCUBE))) == {"FINISHED"}
    for layer in ("components", "sheets"):
        assert bpy.ops.hbc.build_layer(layer=layer) == {"FINISHED"}
    bpy.context.scene.hbc.sheets.clear()
    undo = undo_works()
    if undo:
        bpy.ops.ed.undo_push(message="before the build")
        bpy.context.scene["hbc_marker"] = 7
        bpy.ops.ed.undo_push(message="marker")
    before = file_state()
    root = active_root()
    plan = O.steps.build_phases(O.BUILD_ALL, False)
    st = stepper(O.build_all_steps(bpy.context.scene, root, print), plan)
    assert step_to(st, 0.5) > 3
    assert st.phase in ("components", "sheets") and not st.done
    assert file_state() != before  # it did write into the file
    st.cancel()
    assert st.cancelled
    assert_same_state(file_state(), before)
    if not undo:
        pytest.skip(f"Blender {bpy.app.version_string}: no undo stack here; the file is as before")
    # The cancelled build left no step: one undo goes back over the marker, redo brings it back.
    assert bpy.ops.ed.undo() == {"FINISHED"} and "hbc_marker" not in bpy.context.scene
    assert bpy.ops.ed.redo() == {"FINISHED"} and bpy.context.scene.get("hbc_marker") == 7
    assert_same_state(file_state(), before)


def test_import_cancelled_while_building_leaves_file_as_before(clean_scene, data_dir):
    """An import with its layers, cancelled in its third layer: no collection, object, mesh or
    material of it stays, and the session keeps no mesh."""
    from hybrid_base_complex.plan import session
    from hybrid_base_complex.ui import operators as O

    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir / "openvolumemesh" / "Cylinder.ovm")) == {"FINISHED"}
    before, names = file_state(), session.names()
    layers = ["direct", "graph", "components", "wireframe"]
    st = stepper(O.import_steps(bpy.context.scene, str(data_dir.joinpath(*TWISTCUBE)), layers, print),
                 O.steps.import_phases(True, layers))
    while st.phase != "components":
        assert not st.advance(0.0)
        if st.waiting():
            st._worker[0].join()
    st.advance(0.0)  # its soup asked for
    assert st.phase == "components" and not st.done and file_state() != before
    st.cancel()
    assert_same_state(file_state(), before)
    assert session.names() == names


def layer_geometry():
    """{object: (mesh arrays, properties)} of every add-on object: what a build made."""
    state = file_state()
    return {name: (state["meshes"].get(entry["data"]), entry["props"], entry["collections"], entry["hidden"],
                   entry["modifiers"])
            for name, entry in state["objects"].items()}


@pytest.mark.parametrize("split_max", [10000, 1])
def test_stepped_build_all_equals_the_direct_build(clean_scene, data_dir, split_max):
    """Build All in steps (worker threads) and at once (the operator's execute) on the same file:
    the same objects with the same geometry, attributes, materials and properties; with each
    component and sheet its own object, and with one object per layer."""
    from hybrid_base_complex.ui import operators as O

    def imported():
        bpy.ops.wm.read_homefile(use_empty=True)
        bpy.context.scene.hbc.split_max = split_max
        assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*TWISTCUBE))) == {"FINISHED"}
        return active_root()

    imported()
    assert bpy.ops.hbc.build_all() == {"FINISHED"}
    direct = layer_geometry()
    root = imported()
    st = stepper(O.build_all_steps(bpy.context.scene, root, print), O.steps.build_phases(O.BUILD_ALL, False))
    steps_taken = 0
    while not st.advance(0.0):
        if st.waiting():
            st._worker[0].join()
        steps_taken += 1
    assert steps_taken > len(O.BUILD_ALL)
    bpy.context.view_layer.update()  # the scene evaluated, as after an operator (its handlers run)
    stepped = layer_geometry()
    assert sorted(stepped) == sorted(direct)
    for name in direct:
        assert stepped[name] == direct[name], name


def test_stepped_import_equals_the_direct_import(clean_scene, data_dir):
    from hybrid_base_complex.plan import session
    from hybrid_base_complex.ui import operators as O

    path = str(data_dir.joinpath(*TWISTCUBE))
    layers = ["direct", "graph", "components", "wireframe"]
    assert bpy.ops.import_mesh.hbc(filepath=path, build_layers=True) == {"FINISHED"}
    direct = layer_geometry()
    bpy.ops.wm.read_homefile(use_empty=True)
    session.clear()
    st = stepper(O.import_steps(bpy.context.scene, path, layers, print), O.steps.import_phases(True, layers))
    root, s = st.run()
    assert s.num_cells == 1301 and root.name in bpy.context.scene.collection.children
    assert set(st.times) == {"load", "analysis", *layers}
    session.put(root.name, s)  # as the operator finishes: the mesh in memory and active
    bpy.context.scene.hbc.active_mesh = root.name
    bpy.context.view_layer.update()
    stepped = layer_geometry()
    assert sorted(stepped) == sorted(direct)
    for name in direct:
        assert stepped[name] == direct[name], name
