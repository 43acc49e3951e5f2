"""Contact sheets and the comparison grid in numpy."""

import numpy as np
import pytest

from figures import compose as C


def tile(w, h, value):
    t = np.zeros((h, w, 4), np.float32)
    t[..., :3] = value
    t[..., 3] = 1.0
    return t


def test_blender_round_trip_flips_rows():
    img = np.random.default_rng(0).random((3, 5, 4)).astype(np.float32)
    flat = C.to_blender(img)
    assert np.allclose(flat.reshape(3, 5, 4)[0], img[-1])
    assert np.allclose(C.from_blender(flat, 5, 3), img)


def test_paste_blends_and_clips():
    dst = C.canvas(4, 4, (1, 1, 1, 1))
    src = tile(3, 3, 0.0)
    src[..., 3] = 0.5
    C.paste(dst, src, 2, 2)
    assert np.allclose(dst[3, 3, :3], 0.5) and np.allclose(dst[0, 0, :3], 1.0)


def test_layout_and_columns():
    assert C.layout([1, 1, 1, 1, 1, 1, 2], 4) == [(0, 0), (0, 1), (0, 2), (0, 3), (1, 0), (1, 1), (1, 2)]
    assert C.layout([1, 1, 1, 2], 4) == [(0, 0), (0, 1), (0, 2), (1, 0)]
    assert C.contact_columns([1] * 6 + [2]) == 4
    assert C.contact_columns([1] * 5) == 3
    assert C.contact_columns([1, 1]) == 2


def test_contact_sheet_size_and_content():
    w, h, lh = 40, 30, 8
    tiles = [tile(w, h, 0.1 * i) for i in range(6)] + [tile(2 * w + C.PAD, h, 0.9)]
    labels = [tile(w, lh, 0.0)] * 6 + [tile(2 * w + C.PAD, lh, 0.0)]
    spans = [1] * 6 + [2]
    sheet = C.contact_sheet(tiles, labels, 4, spans)
    assert sheet.shape[:2][::-1] == C.sheet_size(spans, 4, w, h, lh)
    # the wide tile's centre (row 2, slots 2-3)
    y = C.PAD + (lh + 4 + h + C.PAD) + lh + 4 + h // 2
    x = C.PAD + 2 * (w + C.PAD) + w
    assert np.allclose(sheet[y, x, :3], 0.9)
    with pytest.raises(ValueError):
        C.contact_sheet([tile(w, h, 0), tile(w + 1, h, 0)], [None, None], 2)


def test_table_places_rows_and_columns():
    cells = [[tile(20, 10, 0.2), tile(20, 10, 0.4)], [None, tile(20, 10, 0.6)]]
    out = C.table(cells, [tile(15, 6, 0.0)] * 2, [tile(20, 5, 0.0)] * 2)
    assert out.shape == (C.PAD + 5 + 4 + 2 * (10 + C.PAD), C.PAD + 15 + 4 + 2 * (20 + C.PAD), 4)


def test_tiles_panel_and_measures():
    p = C.tiles_panel([tile(10, 10, 0.0), None], [(0, 0), (10, 0)], 20, 10)
    assert C.pixel_std(p) > 0.3 and C.pixel_std(C.canvas(5, 5)) == 0.0
    assert C.foreground_bbox(p, bg=(1, 1, 1)) == (0, 0, 10, 10)
    assert C.foreground_bbox(C.canvas(5, 5)) is None
    assert C.differs(p, C.canvas(20, 10)) and not C.differs(p, p.copy())
    assert C.resize_nearest(C.canvas(8, 6), 4, 3).shape == (3, 4, 4)
