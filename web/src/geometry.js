// Flat render buffers from the core's soups and polylines, built in the worker in one pass each:
// one geometry per layer part (positions, a triangle or segment index, 8-bit vertex colours), so
// the page makes one three.js BufferGeometry per part and no object per cell.

/** Linear RGB(A) floats to bytes (the page's vertex colours are linear, as three.js expects). */
function byte(x) {
  return Math.max(0, Math.min(255, Math.round(x * 255)));
}

/** Soup faces (CSR of point ids) as a triangle fan index; a face of k points gives k - 2 triangles. */
export function fanIndex(offsets) {
  const nf = offsets.length - 1;
  let nt = 0;
  for (let f = 0; f < nf; f++) nt += Math.max(0, offsets[f + 1] - offsets[f] - 2);
  return nt;
}

/**
 * A soup as a mesh part. colorOf(owner) gives an RGB(A) array; shade(owner) an optional factor.
 * Each point is coloured by the first face that uses it (a soup's points belong to one owner).
 * anchor: per point, the centroid of its owner (the slicing plane hides whole owners: cells,
 * blocks, sheets), or with anchorAtPoint the point itself (the plane cuts the surface); owner:
 * per point, what a click picks (the face's owner, or with pickCell its cell); ctype: per point, the cell type of its face's cell (the cell-type filter).
 */
export function soupPart(soup, colorOf, { cellTypes = null, shade = null, name = '', anchorAtPoint = false, pickCell = false } = {}) {
  const { positions, offsets, items, owner, cell } = soup;
  const np = positions.length / 3;
  const nf = owner.length;
  const index = new Uint32Array(3 * fanIndex(offsets));
  let t = 0;
  for (let f = 0; f < nf; f++) {
    const a = offsets[f];
    const b = offsets[f + 1];
    for (let k = a + 1; k + 1 < b; k++) {
      index[t++] = items[a];
      index[t++] = items[k];
      index[t++] = items[k + 1];
    }
  }
  // Owner centroids: mean of the face loops' points (every loop entry counts once).
  const ownerIds = new Map();
  const sums = [];
  for (let f = 0; f < nf; f++) {
    let o = ownerIds.get(owner[f]);
    if (o === undefined) {
      o = sums.length / 4;
      ownerIds.set(owner[f], o);
      sums.push(0, 0, 0, 0);
    }
    for (let k = offsets[f]; k < offsets[f + 1]; k++) {
      const p = items[k];
      sums[4 * o] += positions[3 * p];
      sums[4 * o + 1] += positions[3 * p + 1];
      sums[4 * o + 2] += positions[3 * p + 2];
      sums[4 * o + 3] += 1;
    }
  }
  const color = new Uint8Array(3 * np);
  const anchor = new Float32Array(3 * np);
  const ctype = new Uint8Array(np);
  const pointOwner = new Int32Array(np); // what a click on the point picks (sheet, block, cell)
  const seen = new Uint8Array(np);
  for (let f = 0; f < nf; f++) {
    const c = colorOf(owner[f]);
    const s = shade ? shade(owner[f]) : 1;
    const o = ownerIds.get(owner[f]);
    const w = sums[4 * o + 3] || 1;
    const type = cellTypes && cell[f] >= 0 ? cellTypes[cell[f]] : 0;
    for (let k = offsets[f]; k < offsets[f + 1]; k++) {
      const p = items[k];
      if (seen[p]) continue;
      seen[p] = 1;
      color[3 * p] = byte(c[0] * s);
      color[3 * p + 1] = byte(c[1] * s);
      color[3 * p + 2] = byte(c[2] * s);
      anchor[3 * p] = sums[4 * o] / w;
      anchor[3 * p + 1] = sums[4 * o + 1] / w;
      anchor[3 * p + 2] = sums[4 * o + 2] / w;
      ctype[p] = type;
      pointOwner[p] = pickCell ? cell[f] : owner[f];
    }
  }
  // A surface cut where it is (the boundary): each point is its own anchor.
  return { kind: 'mesh', name, position: positions, index, color, anchor: anchorAtPoint ? positions : anchor, ctype, owner: pointOwner };
}

/**
 * Polylines (positions one per CSR entry, as the core's polylines() gives them) as line segments.
 * colorOf(row) -> RGBA; alpha: optional per point; keep(row): optional filter; closed(row):
 * optional, joins a row's last point to its first (chains and curves do not repeat it).
 */
export function linesPart(positions, offsets, { colorOf, alpha = null, keep = null, closed = null, name = '' }) {
  const k = offsets.length - 1;
  let ns = 0;
  let npKept = 0;
  for (let r = 0; r < k; r++) {
    if (keep && !keep(r)) continue;
    const n = offsets[r + 1] - offsets[r];
    npKept += n;
    ns += Math.max(0, n - 1) + (closed && closed(r) && n > 2 ? 1 : 0);
  }
  const position = new Float32Array(3 * npKept);
  const color = new Uint8Array(4 * npKept);
  const index = new Uint32Array(2 * ns);
  let p = 0;
  let s = 0;
  for (let r = 0; r < k; r++) {
    if (keep && !keep(r)) continue;
    const a = offsets[r];
    const b = offsets[r + 1];
    const c = colorOf(r);
    const first = p;
    for (let i = a; i < b; i++, p++) {
      position[3 * p] = positions[3 * i];
      position[3 * p + 1] = positions[3 * i + 1];
      position[3 * p + 2] = positions[3 * i + 2];
      color[4 * p] = byte(c[0]);
      color[4 * p + 1] = byte(c[1]);
      color[4 * p + 2] = byte(c[2]);
      color[4 * p + 3] = byte(alpha ? alpha[i] : c[3] ?? 1);
      if (i > a) {
        index[s++] = p - 1;
        index[s++] = p;
      }
    }
    if (closed && closed(r) && b - a > 2) {
      index[s++] = p - 1;
      index[s++] = first;
    }
  }
  return { kind: 'lines', name, position, index, color };
}

/** Mesh vertices as dots of one colour. */
export function dotsPart(points, vertices, rgba, name = '') {
  const position = new Float32Array(3 * vertices.length);
  for (let i = 0; i < vertices.length; i++) {
    const v = vertices[i];
    position[3 * i] = points[3 * v];
    position[3 * i + 1] = points[3 * v + 1];
    position[3 * i + 2] = points[3 * v + 2];
  }
  return { kind: 'points', name, position, rgba };
}

/** planning.opacity_alpha: the per-point opacity's own range [min, 1] stretched onto [floor, 1]. */
export function opacityAlpha(opacity, floor) {
  const n = opacity.length;
  const out = new Float32Array(n);
  if (!n) return out;
  const f = Math.min(Math.max(floor, 0), 1);
  let lo = Infinity;
  for (let i = 0; i < n; i++) lo = Math.min(lo, Math.min(Math.max(opacity[i], 0), 1));
  if (lo >= 1) return out.fill(1);
  for (let i = 0; i < n; i++) {
    const o = Math.min(Math.max(opacity[i], 0), 1);
    out[i] = f + (1 - f) * (o - lo) / (1 - lo);
  }
  return out;
}

/** Every transferable buffer of some parts (the worker hands them over, never copies). */
export function transferList(parts) {
  const out = [];
  for (const p of parts) {
    for (const key of ['position', 'index', 'color', 'anchor', 'ctype', 'owner']) {
      if (p[key] && p[key].buffer && !out.includes(p[key].buffer)) out.push(p[key].buffer);
    }
  }
  return out;
}

/** One row of a CSR. */
export function row(c, r) {
  return c.items.subarray(c.offsets[r], c.offsets[r + 1]);
}
