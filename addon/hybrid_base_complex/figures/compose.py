"""Composition of rendered images in numpy (no ``bpy``, no PIL): contact sheets, the comparison
grid and panel g's tiles. Images are float32 (h, w, 4) RGBA arrays, row 0 at the top, values in
[0, 1] (display space: what the PNG holds). Blender's pixel buffers start at the bottom row:
`from_blender` / `to_blender` convert.
"""

from __future__ import annotations

import numpy as np

BACKGROUND = (1.0, 1.0, 1.0, 1.0)
PAD = 12  # gap between tiles (and around them)


def from_blender(flat, width, height):
    """Blender's flat bottom-up RGBA pixels -> (h, w, 4) top-down."""
    return np.asarray(flat, np.float32).reshape(height, width, 4)[::-1].copy()


def to_blender(img):
    """(h, w, 4) top-down -> flat bottom-up float32 for Image.pixels.foreach_set."""
    return np.ascontiguousarray(np.asarray(img, np.float32)[::-1]).ravel()


def canvas(width, height, color=BACKGROUND):
    out = np.empty((int(height), int(width), 4), np.float32)
    out[:] = np.asarray(color, np.float32)
    return out


def paste(dst, src, x, y):
    """Copies src into dst with its top-left corner at (x, y), alpha-blended over dst; clipped."""
    h, w = src.shape[:2]
    x0, y0 = max(x, 0), max(y, 0)
    x1, y1 = min(x + w, dst.shape[1]), min(y + h, dst.shape[0])
    if x1 <= x0 or y1 <= y0:
        return dst
    s = src[y0 - y: y1 - y, x0 - x: x1 - x]
    a = s[..., 3:4]
    d = dst[y0:y1, x0:x1]
    d[..., :3] = s[..., :3] * a + d[..., :3] * (1.0 - a)
    d[..., 3:4] = a + d[..., 3:4] * (1.0 - a)
    return dst


def flatten(img, color=BACKGROUND):
    """Composites an image over an opaque colour."""
    out = canvas(img.shape[1], img.shape[0], color)
    return paste(out, img, 0, 0)


def resize_nearest(img, width, height):
    """Box/nearest resampling (integer factors average, others pick): for thumbnails only."""
    h, w = img.shape[:2]
    if (w, h) == (width, height):
        return img
    if w % width == 0 and h % height == 0:
        fx, fy = w // width, h // height
        return img.reshape(height, fy, width, fx, 4).mean(axis=(1, 3)).astype(np.float32)
    ys = (np.arange(height) * h / height).astype(np.int64)
    xs = (np.arange(width) * w / width).astype(np.int64)
    return img[ys][:, xs]


def border(img, width=1, color=(0.75, 0.75, 0.75, 1.0)):
    """A thin frame drawn inside the image's edge."""
    out = img.copy()
    c = np.asarray(color, np.float32)
    out[:width] = c
    out[-width:] = c
    out[:, :width] = c
    out[:, -width:] = c
    return out


def layout(spans, cols):
    """Greedy rows: [(row, col)] slot of each item given its span (in columns); an item that
    does not fit in the rest of a row starts the next one."""
    out, r, c = [], 0, 0
    for span in spans:
        span = min(max(int(span), 1), cols)
        if c + span > cols:
            r, c = r + 1, 0
        out.append((r, c))
        c += span
    return out


def contact_columns(spans):
    """Columns of a contact sheet for these spans: 4 for 7 or more slots (two rows), 3 for 5-6,
    else one row."""
    total = sum(spans)
    if total >= 7:
        return 4
    if total >= 5:
        return 3
    return max(total, 1)


def contact_sheet(tiles, labels, cols, spans=None, pad=PAD, label_gap=4, bg=BACKGROUND):
    """Tiles in a grid of `cols` columns of the first tile's size, each with its label image above
    (labels[i] may be None). spans[i] (default 1) columns per tile: a tile spanning s columns is
    s * w + (s - 1) * pad wide at most (centred in its slot). Returns the sheet."""
    if not tiles:
        raise ValueError("contact sheet: no tiles")
    spans = list(spans) if spans is not None else [1] * len(tiles)
    th, tw = tiles[0].shape[:2]
    for t, s in zip(tiles, spans):
        if t.shape[0] != th or t.shape[1] > s * tw + (s - 1) * pad:
            raise ValueError("contact sheet: a tile does not fit its slot")
    lh = max((lab.shape[0] for lab in labels if lab is not None), default=0)
    cols = max(1, int(cols))
    slots = layout(spans, cols)
    rows = max(r for r, _ in slots) + 1
    used_cols = max(c + min(s, cols) for (_, c), s in zip(slots, spans))
    cell_h = lh + (label_gap if lh else 0) + th
    W = pad + used_cols * (tw + pad)
    H = pad + rows * (cell_h + pad)
    out = canvas(W, H, bg)
    for i, tile in enumerate(tiles):
        r, c = slots[i]
        slot_w = spans[i] * tw + (spans[i] - 1) * pad
        x = pad + c * (tw + pad)
        y = pad + r * (cell_h + pad)
        lab = labels[i] if i < len(labels) else None
        if lab is not None:
            paste(out, lab[:, :slot_w], x, y)
        paste(out, framed(tile), x + (slot_w - tile.shape[1]) // 2, y + cell_h - th)
    return out


def content_height(img):
    """Rows from the top down to the last one holding anything opaque (tiles padded below by
    pad_to_height end in transparent rows)."""
    rows = np.nonzero((np.asarray(img)[..., 3] > 0.0).any(axis=1))[0]
    return int(rows[-1]) + 1 if len(rows) else 0


def framed(tile, bg=BACKGROUND):
    """The tile flattened onto bg with a thin frame around its content; transparent padding below
    the content stays unframed background."""
    h = content_height(tile)
    out = flatten(tile, bg)
    if h:
        out[:h] = border(out[:h])
    return out


def sheet_size(spans, cols, tile_w, tile_h, label_h, pad=PAD, label_gap=4):
    """(width, height) contact_sheet gives for these spans and sizes."""
    slots = layout(spans, cols)
    rows = max(r for r, _ in slots) + 1
    used_cols = max(c + min(s, cols) for (_, c), s in zip(slots, spans))
    cell_h = label_h + (label_gap if label_h else 0) + tile_h
    return pad + used_cols * (tile_w + pad), pad + rows * (cell_h + pad)


def table(cells, row_labels, col_labels, pad=PAD, gap=4, bg=BACKGROUND):
    """The comparison layout: cells[r][c] tiles (same size, None for an empty cell), a label image
    left of every row (row_labels, same heights as tiles or smaller, centred) and above every
    column (col_labels)."""
    rows = len(cells)
    cols = max(len(r) for r in cells)
    sample = next(t for r in cells for t in r if t is not None)
    th, tw = sample.shape[:2]
    rw = max((lab.shape[1] for lab in row_labels if lab is not None), default=0)
    ch = max((lab.shape[0] for lab in col_labels if lab is not None), default=0)
    x0 = pad + (rw + gap if rw else 0)
    y0 = pad + (ch + gap if ch else 0)
    W = x0 + cols * (tw + pad)
    H = y0 + rows * (th + pad)
    out = canvas(W, H, bg)
    for c, lab in enumerate(col_labels):
        if lab is not None:
            paste(out, lab[:, :tw], x0 + c * (tw + pad) + (tw - min(tw, lab.shape[1])) // 2, pad)
    for r in range(rows):
        y = y0 + r * (th + pad)
        lab = row_labels[r] if r < len(row_labels) else None
        if lab is not None:
            paste(out, lab[:th], pad, y + (th - min(th, lab.shape[0])) // 2)
        for c, tile in enumerate(cells[r]):
            if tile is not None:
                paste(out, framed(tile), x0 + c * (tw + pad), y)
    return out


def tiles_panel(tiles, positions, width, height, bg=BACKGROUND):
    """Panel g: tiles pasted at their (x, y) into one width x height image."""
    out = canvas(width, height, bg)
    for tile, (x, y) in zip(tiles, positions):
        if tile is not None:
            paste(out, flatten(tile, bg), x, y)
    return out


def pixel_std(img):
    """Standard deviation of the RGB values (a blank image gives ~0)."""
    return float(np.asarray(img, np.float32)[..., :3].std())


def differs(a, b, threshold=1e-3):
    """Mean absolute RGB difference above threshold (different sizes differ)."""
    if a.shape != b.shape:
        return True
    return float(np.abs(a[..., :3] - b[..., :3]).mean()) > threshold


def foreground_bbox(img, bg=None, tol=0.02):
    """(x0, y0, x1, y1) of the pixels that differ from the background (the corner pixel by
    default), or None for a blank image."""
    rgb = np.asarray(img, np.float32)[..., :3]
    ref = rgb[0, 0] if bg is None else np.asarray(bg, np.float32)[:3]
    mask = np.abs(rgb - ref).max(axis=2) > tol
    if not mask.any():
        return None
    ys, xs = np.nonzero(mask)
    return int(xs.min()), int(ys.min()), int(xs.max()) + 1, int(ys.max()) + 1


# ---------------------------------------------------------------------------------------------
# Legend strip

SWATCH_EDGE = (0.25, 0.25, 0.27, 1.0)  # a thin dark frame: light swatches (yellow, grey) on white


def linear_to_srgb(rgb):
    """Scene-linear colour values (what Blender's colours and the add-on's palette hold) to the
    display values a PNG holds (the figures' view transform is Standard: plain sRGB)."""
    c = np.clip(np.asarray(rgb, np.float64), 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1.0 / 2.4) - 0.055)


def ink_columns(img, threshold=0.02):
    """(x0, x1) of the columns of a label image holding any ink (alpha above threshold), or None."""
    cols = np.nonzero((np.asarray(img)[..., 3] > threshold).any(axis=0))[0]
    return (int(cols[0]), int(cols[-1]) + 1) if len(cols) else None


def legend_strip(width, height, colors, words, layout, bg=BACKGROUND):
    """A strip `width` x `height`: for each entry a square swatch of its linear colour (shown in
    display values, framed thinly) at layout.swatches[i] and its words (a label image cut to its
    ink) at layout.words[i]."""
    out = canvas(width, height, bg)
    edge = np.asarray(SWATCH_EDGE, np.float32)
    for color, word, (x, y, side), (wx, wy) in zip(colors, words, layout.swatches, layout.words):
        sw = np.empty((side, side, 4), np.float32)
        sw[:] = edge
        sw[1:-1, 1:-1, :3] = linear_to_srgb(color[:3])
        paste(out, sw, x, y)
        paste(out, word, wx, wy)
    return out


def stack(top, bottom, bg=BACKGROUND):
    """`bottom` under `top` (a panel and its strip), both flattened onto bg; widths must agree."""
    if top.shape[1] != bottom.shape[1]:
        raise ValueError("stack: widths differ")
    return np.concatenate([flatten(top, bg), flatten(bottom, bg)], axis=0)


def pad_to_height(img, height):
    """The image with transparent rows added below it up to `height` (tiles of one contact sheet
    or comparison table must share a height: panels without a legend strip)."""
    h = img.shape[0]
    if h >= height:
        return img
    return np.concatenate([img, np.zeros((height - h,) + img.shape[1:], np.float32)], axis=0)
