// The worker's buffer builders (web/src/geometry.js) on cases small enough to derive by hand.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { soupPart, linesPart, opacityAlpha, dotsPart } from '../src/geometry.js';

test('a quad and a triangle of two owners: fan triangles, colours and owner centres per point', () => {
  // Quad 0-1-2-3 (unit square at z = 0, owner 5), triangle 4-5-6 (owner 9, at z = 3).
  const soup = {
    positions: Float32Array.from([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 3, 3, 0, 3, 0, 3, 3]),
    offsets: Int32Array.from([0, 4, 7]),
    items: Int32Array.from([0, 1, 2, 3, 4, 5, 6]),
    owner: Int32Array.from([5, 9]),
    cell: Int32Array.from([0, 1]),
  };
  const colors = { 5: [1, 0, 0], 9: [0, 0, 1] };
  const p = soupPart(soup, (o) => colors[o], { cellTypes: Uint8Array.from([0, 2]) });
  // A face of k points is a fan of k - 2 triangles from its first point.
  assert.deepEqual([...p.index], [0, 1, 2, 0, 2, 3, 4, 5, 6]);
  assert.deepEqual([...p.color], [255, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0, 0, 0, 0, 255, 0, 0, 255, 0, 0, 255]);
  // Quad centre (0.5, 0.5, 0); triangle centre (1, 1, 3).
  assert.deepEqual([...p.anchor.subarray(0, 3)], [0.5, 0.5, 0]);
  assert.deepEqual([...p.anchor.subarray(12, 15)], [1, 1, 3]);
  // The cell type of each point's face's cell: hex for the quad's, prism (2) for the triangle's.
  assert.deepEqual([...p.ctype], [0, 0, 0, 0, 2, 2, 2]);
  // A click picks the owner, or with pickCell the face's cell.
  assert.deepEqual([...p.owner], [5, 5, 5, 5, 9, 9, 9]);
  const byCell = soupPart(soup, (o) => colors[o], { pickCell: true });
  assert.deepEqual([...byCell.owner], [0, 0, 0, 0, 1, 1, 1]);
});

test('polylines: segments between consecutive points, a closed one joined back, a filtered one dropped', () => {
  // Rows [0,1,2] (dropped), [3,4] (open), [5,6,7] (closed): kept points renumber 0..4.
  const positions = new Float32Array(3 * 8).map((_, i) => i);
  const offsets = Int32Array.from([0, 3, 5, 8]);
  const p = linesPart(positions, offsets, {
    colorOf: (r) => [r / 2, 0, 0, 1],
    keep: (r) => r > 0,
    closed: (r) => r === 2,
  });
  assert.equal(p.position.length, 3 * 5);
  assert.deepEqual([...p.position.subarray(0, 3)], [9, 10, 11]); // entry 3
  assert.deepEqual([...p.index], [0, 1, 2, 3, 3, 4, 4, 2]);
  // Row 1's colour 0.5 -> 128, row 2's 1 -> 255; alpha 255.
  assert.deepEqual([...p.color.subarray(0, 4)], [128, 0, 0, 255]);
  assert.deepEqual([...p.color.subarray(16, 20)], [255, 0, 0, 255]);
});

test('opacity: the range [min, 1] stretched onto [floor, 1], as planning.opacity_alpha', () => {
  // min 0.5: 0.5 -> floor 0.2, 1 -> 1, 0.75 -> 0.2 + 0.8 * 0.5 = 0.6.
  const a = opacityAlpha(Float32Array.from([0.5, 1, 0.75]), 0.2);
  assert.deepEqual([...a].map((x) => +x.toFixed(6)), [0.2, 1, 0.6]);
  assert.deepEqual([...opacityAlpha(Float32Array.from([1, 1]), 0.2)], [1, 1]);
});

test('dots at mesh vertices', () => {
  const points = Float32Array.from([0, 0, 0, 1, 2, 3, 4, 5, 6]);
  const p = dotsPart(points, Int32Array.from([2, 1]), [1, 0, 0, 1]);
  assert.deepEqual([...p.position], [4, 5, 6, 1, 2, 3]);
});
