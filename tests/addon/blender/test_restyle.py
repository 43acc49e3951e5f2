"""ρ is presentation: a new ρ in the panel restyles the wireframe layers from the analysis in memory
and runs no analysis (issue 59, item 4). The wireframe's colour classes are the render layer's step
(native/include/hbc/wireframe_style.hpp), computed per wireframe, never part of hbc.Analysis."""

import bpy
import numpy as np
import pytest

from test_rebuild import assert_same, layer, layer_state

#: 493 cells; its whole-mesh wireframe joins colour classes at ρ = 0 that stay apart at 0.8, on
#: chains the simplified wireframe shows (teapot's and twistcube_s's do not change).
TWIST_CUBE = ("hybrid-base-complex", "cube_twist-comp.obj.HYBRID")


def import_twist_cube(data_dir):
    assert bpy.ops.import_mesh.hbc(filepath=str(data_dir.joinpath(*TWIST_CUBE))) == {"FINISHED"}
    return bpy.data.collections[bpy.context.scene.hbc.active_mesh]


def wire_colors(root):
    """(points, 4) RGBA of the wireframe layer's one object (its hbc_color point attribute)."""
    (wire,) = layer(root, "wireframe").objects
    col = np.zeros(4 * len(wire.data.vertices), np.float32)
    wire.data.color_attributes["hbc_color"].data.foreach_get("color", col)
    return col.reshape(-1, 4)


def test_a_new_rho_restyles_the_wireframe_and_runs_no_analysis(clean_scene, data_dir):
    from hybrid_base_complex.plan import session

    root = import_twist_cube(data_dir)
    st = bpy.context.scene.hbc
    assert st.rho == pytest.approx(0.8)
    assert bpy.ops.hbc.build_layer(layer="wireframe") == {"FINISHED"}
    s = session.get(root.name)
    analysis, runs = s.analysis, getattr(s, "analyses", None)
    before = wire_colors(root)

    st.rho = 0.0  # the panel's ρ: every chain pair with a parallel edge joins one colour class

    # No analysis ran: the structure in memory keeps the same hbc.Analysis object (and its count
    # of analyses).
    assert session.get(root.name) is s and s.analysis is analysis
    assert getattr(s, "analyses", None) == runs
    # The layer was restyled: other colours, the same opacities (which do not depend on ρ) ...
    after = wire_colors(root)
    assert after.shape == before.shape
    assert not np.array_equal(after[:, :3], before[:, :3]), "the wireframe's colours did not change with ρ"
    assert np.array_equal(after[:, 3], before[:, 3])
    assert root["hbc_rho"] == pytest.approx(0.0)  # the mesh records the ρ it is drawn at
    # ... exactly as a first build at the new ρ gives it, still on the same analysis.
    restyled = layer_state(root, "wireframe")
    assert bpy.ops.hbc.clear_layer(layer="wireframe") == {"FINISHED"}
    assert bpy.ops.hbc.build_layer(layer="wireframe") == {"FINISHED"}
    assert_same(restyled, layer_state(root, "wireframe"))
    assert s.analysis is analysis
    # What changed is the colour classes: the binding's style at ρ = 0 joins classes of 0.8.
    w0, w8 = analysis.wireframe(rho=0.0), analysis.wireframe(rho=0.8)
    assert len(np.unique(w0.color_class)) < len(np.unique(w8.color_class))
