"""The panel's Metrics box and its worst-component / worst-sheet buttons, the panel's subsheet rule
on every path that analyzes (import, the layers, Export VTU, a mesh read again, Figures), and the
import's progress lines and closing report, in every Blender of the matrix."""

import base64
import json
import math
import os
import re
import subprocess
import zlib
from types import SimpleNamespace

import bpy
import numpy as np
import pytest

TWISTCUBE = ("hybrid-base-complex", "twistcube_s.mesh")  # 1301 cells; sheet 5 is self-intersecting
#: 493 cells, 221 components, 19 sheets; `hbc metrics` names block 220 and sheet 11 the worst.
CUBE_TWIST = ("hybrid-base-complex", "cube_twist-comp.obj.HYBRID")


def import_mesh(data_dir, parts=TWISTCUBE, **kwargs):
    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*parts)), **kwargs) == {"FINISHED"}
    return bpy.data.collections[bpy.context.scene.hbc.active_mesh]


def cli_metrics(path):
    cli = os.environ.get("HBC_CLI")
    if not cli or not os.path.isfile(cli):
        pytest.fail(f"HBC_CLI={cli} is not the hbc command (tests/addon/CMakeLists.txt sets it)")
    p = subprocess.run([cli, "metrics", str(path), "--json"], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


class _Words:
    """A stand-in UILayout recording, in drawing order, (kind, text) of each operator and label,
    and the operator's properties set (kind of hbc.show_worst)."""

    def __init__(self, log):
        object.__setattr__(self, "log", log)

    def _sub(self, *_, **__):
        return _Words(self.log)

    row = column = box = split = _sub

    def label(self, text="", **_):
        self.log.append(("label", text, None))

    def operator(self, idname, text="", **_):
        props = SimpleNamespace()
        self.log.append((idname, text, props))
        return props

    def __setattr__(self, name, value):
        pass


def drawn_rows(context):
    """{label: value text} of the Metrics box, and the hbc.show_worst buttons' kinds."""
    from hybrid_base_complex.ui import panels

    log = []
    panels.HBC_PT_metrics.draw(SimpleNamespace(layout=_Words(log)), context)
    rows = {}
    for (kind, text, _), nxt in zip(log, log[1:] + [("", "", None)]):
        if kind == "hbc.explain":
            assert nxt[0] == "label", (text, nxt)
            rows[text.strip()] = nxt[1]
    buttons = [props.kind for kind, _, props in log if kind == "hbc.show_worst"]
    return rows, buttons


def test_box_values_equal_hbc_metrics_json(clean_scene, data_dir):
    """Every value of the box is `hbc metrics --json`'s for the same file, written the box's way
    (counts whole, ratios with 3 decimals); the analysis' own metrics equal the command's (floats
    to 1e-12: JSON prints them rounded to 17 digits)."""
    from hybrid_base_complex.plan import metrics_box as MB
    from hybrid_base_complex.plan import session

    path = data_dir.joinpath(*TWISTCUBE)
    root = import_mesh(data_dir)
    want = cli_metrics(path)
    got = session.get(root.name).metrics()
    for group, key, _, _ in MB.ROWS:
        a, b = got[group][key], want[group][key]
        assert (a == b) if isinstance(b, int) else math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-12), (group, key)
    rows, buttons = drawn_rows(bpy.context)
    for group, key, label, _ in MB.ROWS:
        assert rows[label] == MB.value_text(want[group][key]), (label, rows[label], want[group][key])
    summary = want["summary"]
    assert rows["Score"] == f"{summary['score']:.3f}" == "5.056"
    for name, value in zip(summary["vector_keys"], summary["vector"]):
        assert rows[MB.VECTOR_ROWS[name][0]] == f"{value:.3f}", name
    # twistcube_s by hand: 1157 hexahedra of 1301 cells; 43 singularities; 20 sheets (1 perfect,
    # 16 type 1, 2 type 2, 1 type 3); 144 non-hex cells in 42 regions.
    assert (rows["Hex by count"], rows["Singularities"], rows["Sheets"]) == (f"{1157 / 1301:.3f}", "43", "20")
    assert [rows[k] for k in ("perfect", "type 1", "type 2", "type 3")] == ["1", "16", "2", "1"]
    assert (rows["Non-hex cells"], rows["regions"]) == ("144", "42")
    q = want["quality"]
    assert rows["component"] == f"{q['worst_component']} ({q['worst_component_sj']:.3f})"
    assert rows["sheet"] == f"{q['worst_sheet']} ({q['worst_sheet_sj']:.3f})"
    assert buttons == ["component", "sheet"]


def test_box_before_analysis_and_closed_at_first(clean_scene, data_dir):
    from hybrid_base_complex.ui import panels

    import_mesh(data_dir, analyze=False)
    log = []
    panels.HBC_PT_metrics.draw(SimpleNamespace(layout=_Words(log)), bpy.context)
    assert [text for _, text, _ in log] == ["Analyze first"]
    assert "DEFAULT_CLOSED" in panels.HBC_PT_metrics.bl_options


def test_worst_sheet_button_selects_that_sheet(clean_scene, data_dir):
    """cube_twist-comp's worst sheet is 11 (hbc metrics): the button picks it in the sheet list,
    builds the picked-sheet layer for it (its highlights), and selects and activates its objects."""
    from hybrid_base_complex.blender import scene as S

    want = cli_metrics(data_dir.joinpath(*CUBE_TWIST))["quality"]["worst_sheet"]
    assert want == 11
    root = import_mesh(data_dir, CUBE_TWIST)
    st = bpy.context.scene.hbc
    st.sheet_index = 3
    assert bpy.ops.hbc.show_worst(kind="sheet") == {"FINISHED"}
    assert st.sheet_index == want
    coll = S.find_layer(root, "sheet")
    objects = S.objects_in(coll)
    assert objects and {ob.get("hbc_sheet") for ob in objects} == {want}
    selected = set(bpy.context.selected_objects)
    assert selected and selected <= set(objects) and bpy.context.view_layer.objects.active in selected
    assert not coll.hide_viewport


@pytest.mark.parametrize("split_max", [1000, 0], ids=["objects", "merged"])
def test_worst_block_button_selects_that_component(clean_scene, data_dir, split_max):
    """The worst block (220 in cube_twist-comp): its object in the Blocks layer selected and active;
    with Blocks merged into one mesh (Max objects 0), that mesh in edit mode with exactly the
    component's faces selected."""
    from hybrid_base_complex.blender import scene as S

    want = cli_metrics(data_dir.joinpath(*CUBE_TWIST))["quality"]["worst_component"]
    assert want == 220
    root = import_mesh(data_dir, CUBE_TWIST)
    bpy.context.scene.hbc.split_max = split_max
    assert bpy.ops.hbc.show_worst(kind="component") == {"FINISHED"}
    active = bpy.context.view_layer.objects.active
    assert active in S.objects_in(S.find_layer(root, "components"))
    if split_max:
        assert active.get("hbc_component") == want and bpy.context.selected_objects == [active]
        return
    assert active.mode == "EDIT" and active.get("hbc_owner") == "component"
    bpy.ops.object.mode_set(mode="OBJECT")
    owner = np.zeros(len(active.data.polygons), np.int32)
    active.data.attributes[S.OWNER_ATTR].data.foreach_get("value", owner)
    picked = np.zeros(len(active.data.polygons), bool)
    active.data.polygons.foreach_get("select", picked)
    assert picked.any() and np.array_equal(picked, owner == want)


# -- the subsheet rule -------------------------------------------------------------------------

def vtu_array(path, name):
    """A cell array of a VTU the library wrote (binary: base64 of a UInt64 block header, then
    base64 of the zlib-compressed blocks)."""
    text = path.read_text()
    m = re.search(rf'<DataArray type="(\w+)" Name="{name}" format="binary">\s*(\S+)\s*</DataArray>', text)
    assert m, name
    raw = m.group(2)
    nblocks = int(np.frombuffer(base64.b64decode(raw[:32]), np.uint64)[0])
    head_chars = 4 * math.ceil((3 + nblocks) * 8 / 3)
    header = np.frombuffer(base64.b64decode(raw[:head_chars]), np.uint64)
    data, pos = base64.b64decode(raw[head_chars:]), 0
    out = b""
    for size in header[3:3 + nblocks]:
        out += zlib.decompress(data[pos:pos + int(size)])
        pos += int(size)
    return np.frombuffer(out, {"Int32": np.int32, "UInt8": np.uint8}[m.group(1)])


def test_fewest_reaches_import_export_and_a_mesh_read_again(clean_scene, data_dir, tmp_path):
    """With Subsheets = Fewest, the import analyzes by it; Export VTU of the self-intersecting
    sheet writes its fewest subsheets (not the authors' 9); a mesh read again (a reopened file:
    the session is empty) and a cached analysis by the other rule are analyzed by the setting."""
    from hybrid_base_complex.blender.context import structure_of
    from hybrid_base_complex.plan import session
    from hybrid_base_complex.plan.native import import_hbc

    st = bpy.context.scene.hbc
    st.subsheet_rule = "fewest"
    root = import_mesh(data_dir)
    s = session.get(root.name)
    big = s.analysis.largest_self_intersecting
    fewest = s.analysis.subsheets(big)
    assert s.subsheet_rule == "fewest" and fewest.rule == "fewest" and fewest.count < 9
    st.sheet_index = big
    session.clear()  # as after reopening the file
    out = tmp_path / "fewest.vtu"
    assert bpy.ops.hbc.export_vtu(filepath=str(out), picked_sheet=True) == {"FINISHED"}
    # The subsheet arrays are those of the fewest rule's analysis, not of the authors' rule.
    hbc = import_hbc()
    mesh = hbc.load(str(data_dir.joinpath(*TWISTCUBE)))
    for rule, same in (("fewest", True), ("layers", False)):
        ref = tmp_path / f"{rule}.ref.vtu"
        mesh.analyze(subsheet_rule=rule).to_vtu(str(ref), sheet=big)
        assert np.array_equal(vtu_array(out, "subsheet"), vtu_array(ref, "subsheet")) == same, rule
    assert session.get(root.name).analysis.subsheets(big).rule == "fewest"
    st.subsheet_rule = "layers"  # the cached analysis is by the other rule: analyzed again
    s = structure_of(root, True, print)
    assert s.analysis.subsheets(big).rule == "layers" and s.analysis.subsheets(big).count == 9


def test_subsheets_layer_of_the_other_rule_is_stale(clean_scene, data_dir):
    """A subsheets layer built by the authors' rule (9 subsheets of sheet 5) is marked stale and
    hidden once the mesh is analyzed by the fewest rule; rebuilt, it shows the fewest subsheets."""
    from hybrid_base_complex.blender import scene as S
    from hybrid_base_complex.plan import session

    root = import_mesh(data_dir)
    st = bpy.context.scene.hbc
    big = session.get(root.name).analysis.largest_self_intersecting
    st.sheet_index = big
    assert bpy.ops.hbc.build_layer(layer="subsheets") == {"FINISHED"}
    coll = S.find_layer(root, "subsheets")

    def subsheets():
        return {ob["hbc_subsheet"] for ob in S.objects_in(S.find_layer(root, "subsheets")) if "hbc_subsheet" in ob}

    assert subsheets() == set(range(9)) and not coll.get("hbc_stale")
    st.subsheet_rule = "fewest"
    assert bpy.ops.hbc.analyze() == {"FINISHED"}
    coll = S.find_layer(root, "subsheets")
    assert coll.get("hbc_stale") and coll.hide_viewport
    assert bpy.ops.hbc.build_layer(layer="subsheets") == {"FINISHED"}
    coll = S.find_layer(root, "subsheets")
    count = session.get(root.name).analysis.subsheets(big).count
    assert not coll.get("hbc_stale") and subsheets() == set(range(count)) and count < 9


def test_figures_run_with_the_panel_rule(clean_scene, data_dir, tmp_path, monkeypatch):
    """Figures starts its child Blender with the panel's rule (--subsheet-rule)."""
    from hybrid_base_complex.plan import figures_job

    import_mesh(data_dir, analyze=False)
    bpy.context.scene.hbc.subsheet_rule = "fewest"
    seen = []

    class FakeJob:
        def __init__(self, cmd, expected_files=0, env=None):
            seen.append(cmd)
            self.written, self.tail, self.last, self.cancelled = [], [], "", False

        def poll(self):
            return 0

    monkeypatch.setattr(figures_job, "Job", FakeJob)
    assert bpy.ops.hbc.render_figures(directory=str(tmp_path), wait=True) == {"FINISHED"}
    (cmd,) = seen
    assert cmd[cmd.index("--subsheet-rule") + 1] == "fewest"


def test_import_says_each_step_and_reports_counts_and_times(clean_scene, data_dir, capsys):
    """Background mode prints the progress of the load, the analysis and the scene (each step
    named before it runs and when done), and the closing report has the counts and the times."""
    root = import_mesh(data_dir)
    out = capsys.readouterr().out
    steps = [line for line in out.splitlines() if line.startswith("hbc: [")]
    assert steps[0].endswith("loading twistcube_s.mesh") and "  0%]" in steps[0], steps
    for word in ("loaded 1301 cells", "analyzing 1301 cells", "analyzed: 1301 components, 20 sheets",
                 "building Direct view", "built Direct view"):
        assert any(line.endswith(word) for line in steps), (word, steps)
    assert steps[-1].startswith("hbc: [100%]")
    report = re.search(r"Imported (\S+): 1301 cells, 1301 components, 20 sheets, (\d+) objects? in [\d.]+ s "
                       r"\(load [\d.]+ s, analysis [\d.]+ s, scene [\d.]+ s\)", out)
    assert report and report.group(1) == root.name, out[-800:]
