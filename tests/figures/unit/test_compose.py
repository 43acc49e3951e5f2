"""Contact sheets and the comparison grid in numpy."""

import numpy as np
import pytest

from hybrid_base_complex.figures import compose as C


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
    tw, th, gap = 20, 10, 4
    cells = [[tile(tw, th, 0.2), tile(tw, th, 0.4)], [None, tile(tw, th, 0.6)]]
    row_labels = [tile(15, 6, 0.1), tile(15, 6, 0.3)]
    col_labels = [tile(tw, 5, 0.5), tile(tw, 5, 0.7)]
    out = C.table(cells, row_labels, col_labels, gap=gap)
    x0, y0 = C.PAD + 15 + gap, C.PAD + 5 + gap  # the first cell's corner: after the labels
    assert out.shape == (y0 + 2 * (th + C.PAD), x0 + 2 * (tw + C.PAD), 4)
    for r, row in enumerate(cells):
        for c, cell in enumerate(row):
            x, y = x0 + c * (tw + C.PAD), y0 + r * (th + C.PAD)
            inside = out[y + 1:y + th - 1, x + 1:x + tw - 1, :3]  # within the tile's one-pixel frame
            expected = 1.0 if cell is None else cell[0, 0, 0]  # an empty cell shows the background
            assert np.allclose(inside, expected), (r, c)
            assert np.allclose(out[y + th:y + th + C.PAD, x:x + tw, :3], 1.0)  # the gap below it
    for r, label in enumerate(row_labels):  # left of its row, centred on the row's height
        y = y0 + r * (th + C.PAD) + (th - 6) // 2
        assert np.allclose(out[y:y + 6, C.PAD:C.PAD + 15, :3], label[0, 0, 0]), r
    for c, label in enumerate(col_labels):  # above its column
        x = x0 + c * (tw + C.PAD)
        assert np.allclose(out[C.PAD:C.PAD + 5, x:x + tw, :3], label[0, 0, 0]), c


def test_tiles_panel_and_measures():
    p = C.tiles_panel([tile(10, 10, 0.0), None], [(0, 0), (10, 0)], 20, 10)
    assert C.pixel_std(p) > 0.3 and C.pixel_std(C.canvas(5, 5)) == 0.0
    assert C.foreground_bbox(p, bg=(1, 1, 1)) == (0, 0, 10, 10)
    assert C.foreground_bbox(C.canvas(5, 5)) is None
    assert C.differs(p, C.canvas(20, 10)) and not C.differs(p, p.copy())
    assert C.resize_nearest(C.canvas(8, 6), 4, 3).shape == (3, 4, 4)


def test_linear_to_srgb():
    assert np.allclose(C.linear_to_srgb([0.0, 1.0, 0.0031308]), [0.0, 1.0, 0.04045], atol=1e-5)
    assert np.allclose(C.linear_to_srgb([0.214041]), [0.5], atol=1e-4)
    assert np.allclose(C.linear_to_srgb([-1.0, 2.0]), [0.0, 1.0])


def test_legend_strip_draws_framed_swatches_and_words():
    from hybrid_base_complex.figures import plan

    m = plan.LegendMetrics(row=20, swatch=12, gap=5, column_gap=22, margin=8)
    words = [tile(30, 20, 0.1), tile(50, 20, 0.2)]
    for w in words:
        w[:4, :, 3] = 0.0  # words come with transparent space around the ink
    layout = plan.legend_layout([w.shape[1] for w in words], 200, m)
    colors = [(1.0, 0.0, 0.0, 1.0), (0.214041, 0.214041, 0.214041, 1.0)]
    strip = C.legend_strip(200, plan.strip_height(m, layout.rows), colors, words, layout)
    assert strip.shape == (plan.strip_height(m, 1), 200, 4)
    for (x, y, side), color, (wx, wy), w in zip(layout.swatches, colors, layout.words, words):
        inner = strip[y + 1:y + side - 1, x + 1:x + side - 1, :3]
        assert np.allclose(inner, C.linear_to_srgb(color[:3]), atol=1e-4)  # display values
        assert np.allclose(strip[y, x:x + side, :3], C.SWATCH_EDGE[:3])  # framed
        assert np.allclose(strip[wy + 10, wx:wx + w.shape[1], :3], w[10, 0, 0])  # the words' ink
        assert np.allclose(strip[wy + 1, wx, :3], 1.0)  # their transparent part shows the background
    assert np.allclose(strip[0, :, :3], 1.0) and np.allclose(strip[-1, :, :3], 1.0)


def test_stack_pad_and_frame():
    panel, strip = tile(10, 6, 0.5), tile(10, 3, 1.0)
    both = C.stack(panel, strip)
    assert both.shape == (9, 10, 4) and np.allclose(both[:6], panel) and np.allclose(both[6:], strip)
    with pytest.raises(ValueError):
        C.stack(panel, tile(9, 3, 1.0))
    padded = C.pad_to_height(panel, 9)
    assert padded.shape == (9, 10, 4) and C.content_height(padded) == 6 and C.pad_to_height(padded, 5) is padded
    framed = C.framed(padded)
    assert np.allclose(framed[5, 5, :3], 0.75) and np.allclose(framed[0, 5, :3], 0.75)  # frame around the panel
    assert np.allclose(framed[6:, :, :3], 1.0)  # the padding below stays background, unframed
