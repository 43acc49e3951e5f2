"""render_figures.py --wire-colors kind: the sheet's wireframe panel (f) coloured by the non-hex kinds
of its chains, with a legend strip naming each colour (the add-on's legend), beside today's colour
classes, which stay the default."""

import json
import os
import sys

import numpy as np
import pytest

pytest.importorskip("bpy")

from test_render_figures import data, load, run  # noqa: E402
from hybrid_base_complex.figures import plan  # noqa: E402

W, H = 320, 240


def test_wireframe_panel_coloured_by_kind_with_its_legend(tmp_path):
    import importlib

    renders = {}
    for colors in ("class", "kind"):
        out = tmp_path / colors
        p = run([data("twistcube_s.mesh"), "--out", out, "--engine", "workbench", "--resolution", W, H,
                 "--panels", "wireframe", "--legend", "--wire-colors", colors])
        assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
        renders[colors] = out
    name = "twistcube_s_f_wireframe.png"
    by_class, by_kind = load(renders["class"] / name), load(renders["kind"] / name)
    # Class colours name nothing: no strip; by kind the panel grew by one.
    assert by_class.shape[0] == H and by_kind.shape[0] > H
    assert np.abs(by_kind[:H, :, :3] - by_class[..., :3]).max() > 0.1  # other colours
    info = json.loads((renders["kind"] / "twistcube_s_legend.json").read_text())
    (panel,) = info["panels"]
    assert panel["panel"] == "wireframe"
    # The entries: the add-on's legend of a wireframe coloured by kind, for this mesh's cell types.
    addon = os.environ["HBC_ADDON_DIR"]
    sys.path.insert(0, os.path.dirname(addon))
    P = importlib.import_module(os.path.basename(addon) + ".plan.planning")
    hbc = importlib.import_module(os.path.basename(addon) + ".plan.native").import_hbc()
    types = sorted({int(t) for t in np.unique(hbc.load(data("twistcube_s.mesh")).cell_types) if t})
    assert types == [1, 2, 3, 4]
    want = P.wire_kind_legend(types)
    assert [(e["key"], e["words"]) for e in panel["entries"]] == want
    for e in panel["entries"]:
        y, x, side = e["swatch"][1], e["swatch"][0], e["swatch"][2]
        inner = by_kind[y + 1:y + side - 1, x + 1:x + side - 1, :3]
        assert np.abs(inner - np.asarray(e["srgb"])).max() < 1.5 / 255, e["key"]
