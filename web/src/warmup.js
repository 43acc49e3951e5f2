// The core's warm-up (docs/web.md, "Why the page warms the core up"). V8 runs a WebAssembly
// function's first calls in its baseline compiler (Liftoff) and compiles it with its optimizing
// compiler (TurboFan) only once it has run for a while, in the background; a mesh analysed right
// after the module is instantiated therefore runs mostly baseline code, 2-5x slower. The worker
// spends the page's idle time after instantiation analysing a small generated mesh, which tiers
// the hot functions up before the user's file arrives. Shared by the worker and the benchmark
// (scripts/bench/wasm_warm.mjs), so that both warm up alike.
import { arr, csr, get } from './core.js';

/** The warm-up mesh, `hbc generate cylinder --radius-cells R --layers L` (hexes and a ring of
 *  prism columns: the hex and the non-hex paths) as .hedra text, so that it is read the way a
 *  user's text file is read. */
export function cylinderHedra(M, radiusCells, layers) {
  const g = M.generate_cylinder(radiusCells, layers);
  const p = g.points;
  const fo = g.faces_offsets;
  const fi = g.faces_items;
  const co = g.cells_offsets;
  const ci = g.cells_items;
  const nf = fo.length - 1;
  const nc = co.length - 1;
  const lines = [`${p.length / 3} ${nf} ${nc}`];
  for (let v = 0; v < p.length; v += 3) lines.push(`${p[v]} ${p[v + 1]} ${p[v + 2]}`);
  for (let f = 0; f < nf; f++) {
    const loop = [fo[f + 1] - fo[f]];
    for (let k = fo[f]; k < fo[f + 1]; k++) loop.push(fi[k] + 1); // 1-based
    lines.push(loop.join(' '));
  }
  for (let c = 0; c < nc; c++) {
    const row = [co[c + 1] - co[c]];
    // 2 face + flip -> the 1-based face id, negative when the cell sees the loop reversed.
    for (let k = co[c]; k < co[c + 1]; k++) row.push(ci[k] & 1 ? -((ci[k] >> 1) + 1) : (ci[k] >> 1) + 1);
    lines.push(row.join(' '));
  }
  return lines.join('\n') + '\n';
}

/** The default warm-up: 8 rounds of the whole path on a cylinder of radius 6 cells, 10 layers
 *  (1 200 hexes, 120 prisms). Fewer cells left armadillo's first analysis in Chromium and node
 *  partly in baseline code; a round takes tens of milliseconds once warm, which bounds the wait
 *  of a file picked during the warm-up. */
export const WARM_UP = { radiusCells: 6, layers: 10, rounds: 8 };

/**
 * The core calls the viewer makes for a mesh, on the warm-up mesh, `rounds` times: reading through
 * core.open (the user's load path), the analysis, `hbc analyze --json`, the arrays the summary
 * reads, every soup, the cut surface, the wireframes and polylines. A generator: it yields after
 * each round so that the caller can give way (a user's file waits at most one round); leaving it
 * early frees what it holds.
 */
export function* warmUpSteps(core, { radiusCells, layers, rounds } = WARM_UP) {
  if (!(rounds > 0)) return;
  const name = 'warm-up.hedra';
  const buffer = new TextEncoder().encode(cylinderHedra(core.M, radiusCells, layers)).buffer;
  for (let r = 0; r < rounds; r++) {
    let mesh = null;
    let analysis = null;
    try {
      mesh = core.open([{ path: name, buffer: buffer.slice(0) }]);
      analysis = core.analyze(mesh);
      JSON.parse(core.analysisJson(analysis));
      touch(core, mesh, analysis);
    } finally {
      core.free(analysis, mesh);
    }
    yield r + 1;
  }
}

/** Everything the worker reads of an analysed mesh to show it, once. */
function touch(core, mesh, analysis) {
  arr(mesh, 'points');
  const types = arr(mesh, 'cell_types');
  arr(core.complex(analysis), 'component_kind');
  const sheetTypes = arr(analysis, 'sheet_type') ?? [];
  csr(analysis, 'sheet_cells');
  csr(analysis, 'sheet_components');
  for (const name of ['sheet_unmatched_vertices', 'sheet_shared_vertices', 'sheet_self_parallel_curves',
    'sheet_self_intersecting_components']) csr(analysis, name);
  const g = core.graph(analysis);
  arr(g, 'edge_class');
  arr(g, 'chain_valence');
  const chains = csr(g, 'chain_vertices');
  core.polylines(mesh, chains.offsets, chains.items);
  for (const what of ['boundary', 'non_hex', 'components', 'sheets']) core.blockSoup(mesh, analysis, what, -1, 0.1);
  if (sheetTypes.length) core.blockSoup(mesh, analysis, 'sheet', 0, 0.1);
  const self = Array.prototype.indexOf.call(sheetTypes, 3);
  if (self >= 0) {
    core.blockSoup(mesh, analysis, 'subsheets', self, 0.1);
    core.free(core.subsheets(analysis, self));
  }
  if (core.hasCut()) {
    const cen = core.centroids(mesh);
    const kept = new Uint8Array(types.length).map((_, c) => (cen[3 * c] <= 0 ? 1 : 0));
    core.keptSurface(mesh, kept, 0);
  }
  for (const sheet of sheetTypes.length ? [-1, 0] : [-1]) {
    const w = core.wireframe(analysis, sheet, -1);
    if (!w) continue;
    const poly = csr(w, 'polylines');
    core.polylines(mesh, poly.offsets, poly.items);
    get(w, 'count');
    core.free(w);
  }
}
