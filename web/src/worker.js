// The analysis runs here, off the page's thread: the WebAssembly core reads the file (every
// format the CLI reads; an OpenFOAM case's files when the core takes several), analyses it as
// `hbc analyze` does, and builds each layer's buffers, which go to the page by transfer.
/* global createHbcModule, __HBC_WASM_BASE64__ */
import { Core, arr, csr, get, errorText } from './core.js';
import { L, paletteColor, spreadColor, subsheetColor, componentColor, valenceColor, cellTypeColor, kindColor } from './colors.js';
import { soupPart, linesPart, dotsPart, opacityAlpha, transferList, row } from './geometry.js';
import { warmUpSteps, WARM_UP } from './warmup.js';

let core = null;
let instantiating = null; // the module's instantiation, started as the worker starts
let warming = null; // the warm-up (warmup.js) while it runs
let stopWarming = false; // a user's file has arrived: the warm-up ends after its current round
let S = null; // the open mesh: {name, mesh, analysis, points, cellTypes, centroids, ...}
let last = null; // the last files given, {name, files: [{path}]}: still in the core's file system, to
                 // be read again when the page's "skip invalid cells" choice changes

function post(msg, transfer = []) {
  self.postMessage(msg, transfer);
}

function progress(fraction, text) {
  post({ type: 'progress', fraction, text });
}

function module() {
  instantiating ??= instantiate();
  return instantiating;
}

async function instantiate() {
  if (typeof createHbcModule !== 'function') {
    throw new Error('The WebAssembly core is not in this page: build it with scripts/build_wasm.sh, then scripts/build_web.sh.');
  }
  const opts = { print: () => {}, printErr: (t) => console.warn(t) };
  if (typeof __HBC_WASM_BASE64__ === 'string' && __HBC_WASM_BASE64__) {
    const bin = atob(__HBC_WASM_BASE64__);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    opts.wasmBinary = bytes.buffer;
  }
  core = new Core(await createHbcModule(opts));
  return core;
}

function closeMesh() {
  if (!S) return;
  core.free(S.analysis, S.mesh);
  S = null;
}

/** Warms the core up while the page is idle (warmup.js): rounds on a small generated mesh, giving
 *  way to the event loop between rounds so that a user's file stops it. */
async function warmUp(size) {
  const c = await module();
  const t0 = performance.now();
  let rounds = 0;
  post({ type: 'warm-up', state: 'running' });
  const steps = warmUpSteps(c, size ?? WARM_UP);
  try {
    while (!stopWarming && !steps.next().done) {
      rounds++;
      await new Promise((resolve) => setTimeout(resolve, 0)); // a file's message may come in here
    }
    steps.return();
  } catch (e) {
    // A core without the generator: the page works as before, only colder.
    post({ type: 'warm-up', state: 'failed', message: errorText(c.M, e) });
    return;
  }
  post({ type: 'warm-up', state: stopWarming ? 'stopped' : 'done', rounds, seconds: (performance.now() - t0) / 1000 });
}

async function open({ name, files, skipInvalid, again }, t0) {
  progress(0.05, 'Starting the WebAssembly core');
  const c = await module();
  closeMesh();
  if (again) {
    if (!last) throw new Error('No file to read again: open one.');
    ({ name, files } = last);
  } else {
    last = { name, files: files.map((f) => ({ path: f.path })) };
  }
  progress(0.1, 'Reading ' + name);
  let mesh;
  let analysis;
  try {
    mesh = c.open(files, { skipInvalid: !!skipInvalid, written: !!again });
  } catch (e) {
    // The core names the file by its path in the in-memory file system: name it as the user did.
    throw new Error(errorText(c.M, e).split('/in/').join(''));
  }
  try {
    progress(0.4, 'Analysing (singularity graph, base complex, sheets, subsheets, wireframe)');
    analysis = c.analyze(mesh);
  } catch (e) {
    core.free(mesh);
    throw new Error(errorText(c.M, e).split('/in/').join(''));
  }
  progress(0.85, 'Preparing the layers');
  const results = JSON.parse(c.analysisJson(analysis));
  // The core names the file by its path in its in-memory file system (/in/...): name it as the
  // user did, in the same place of the JSON.
  if ('file' in results) results.file = name;
  const timings = results.timings ?? null; // Table 1's times; not part of the compared counts
  delete results.timings;
  S = { name, mesh, analysis, cache: new Map() };
  S.points = Float32Array.from(arr(mesh, 'points'));
  S.cellTypes = Uint8Array.from(arr(mesh, 'cell_types'));
  const cx = c.complex(analysis);
  S.componentKind = Uint8Array.from(arr(cx, 'component_kind'));
  S.sheetType = Uint8Array.from(arr(analysis, 'sheet_type') ?? []);
  const sc = csr(analysis, 'sheet_cells');
  const sp = csr(analysis, 'sheet_components');
  const sheets = [];
  for (let i = 0; i < S.sheetType.length; i++) {
    sheets.push({ id: i, type: S.sheetType[i], cells: sc.offsets[i + 1] - sc.offsets[i], blocks: sp.offsets[i + 1] - sp.offsets[i] });
  }
  const info = summary(c, analysis, sheets);
  // What reading said, as the CLI says it on stderr ("hbc: warning: FILE: TEXT"), cells dropped first.
  const warnings = (arr(mesh, 'warnings') ?? []).map((w) => `${name}: ${w}`);
  // What the user waited for: from the file's bytes reaching the worker to the counts.
  const seconds = (performance.now() - t0) / 1000;
  post({ type: 'ready', name, results, timings, info, warnings, table1: c.table1(), seconds });
}

/** What the page shows beside the layers: counts, the box, the sheets, the legend's facts and entries. */
function summary(c, analysis, sheets) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  const p = S.points;
  for (let i = 0; i < p.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      if (p[i + k] < lo[k]) lo[k] = p[i + k];
      if (p[i + k] > hi[k]) hi[k] = p[i + k];
    }
  }
  const typeCounts = [0, 0, 0, 0, 0];
  for (const t of S.cellTypes) typeCounts[t]++;
  const g = c.graph(analysis);
  const { facts, legends } = c.legends(S.cellTypes, arr(g, 'edge_class'), arr(g, 'chain_valence'), S.componentKind);
  return {
    cells: S.cellTypes.length,
    typeCounts,
    bbox: [lo, hi],
    sheets,
    facts,  // the library's (hbc::legend_facts)
    legends,  // the library's legend per set of shown layers (hbc::legend, palette_legend)
  };
}

function centroids() {
  if (!S.centroids) S.centroids = core.centroids(S.mesh);
  return S.centroids;
}

function hasKept() {
  return core.hasCut();
}

/** The direct view: the boundary (of the cells kept by the plane and the type filter, when the
 *  core can cut) and the non-hex cells coloured by type. */
function buildDirect(p) {
  const parts = [];
  const filtered = p.plane || (p.types && p.types.some((on) => !on));
  let boundary;
  if (filtered && hasKept()) {
    const cen = centroids();
    const n = S.cellTypes.length;
    const kept = new Uint8Array(n);
    const ax = p.plane ? p.plane.axis : 0;
    for (let i = 0; i < n; i++) {
      kept[i] = (!p.types || p.types[S.cellTypes[i]]) && (!p.plane || cen[3 * i + ax] <= p.plane.pos) ? 1 : 0;
    }
    boundary = core.keptSurface(S.mesh, kept, 0);
    parts.push({ ...soupPart(boundary, (o) => cellTypeColor(S.cellTypes[o]), { cellTypes: S.cellTypes, name: 'cut' }), cut: true });
  } else {
    boundary = core.blockSoup(S.mesh, S.analysis, 'boundary', -1, 0);
    // Without the core's cut surface the see-through boundary is cut where the plane passes.
    parts.push({ ...soupPart(boundary, () => L.cell_type_colors[0], { cellTypes: S.cellTypes, name: 'boundary', anchorAtPoint: true, pickCell: true }), boundary: true });
  }
  if (S.cellTypes.some((t) => t !== 0)) {
    const soup = core.blockSoup(S.mesh, S.analysis, 'non_hex', -1, p.shrink ?? 0);
    parts.push(soupPart(soup, (o) => cellTypeColor(S.cellTypes[o]), { cellTypes: S.cellTypes, name: 'non-hex cells' }));
  }
  return parts;
}

/** The hybrid singularity graph: singularities by valence, pseudo-singular and non-manifold edges. */
function buildGraph() {
  const g = core.graph(S.analysis);
  const chains = csr(g, 'chain_vertices');
  const valence = arr(g, 'chain_valence');
  const closed = arr(g, 'chain_closed');
  const parts = [];
  const pos = core.polylines(S.mesh, chains.offsets, chains.items);
  parts.push(linesPart(pos, chains.offsets, { colorOf: (r) => valenceColor(valence[r]), closed: (r) => !!closed[r], name: 'singularities' }));
  const cls = arr(g, 'edge_class');
  const edges = arr(S.mesh, 'edges');
  for (const [value, color, name] of [[2, L.pseudo_color, 'pseudo-singular'], [3, L.non_manifold_color, 'non-manifold']]) {
    const sel = [];
    for (let e = 0; e < cls.length; e++) if (cls[e] === value) sel.push(edges[2 * e], edges[2 * e + 1]);
    if (!sel.length) continue;
    const items = Int32Array.from(sel);
    const offsets = new Int32Array(sel.length / 2 + 1).map((_, i) => 2 * i);
    parts.push(linesPart(core.polylines(S.mesh, offsets, items), offsets, { colorOf: () => color, name }));
  }
  return parts;
}

function buildBlocks(p) {
  const soup = core.blockSoup(S.mesh, S.analysis, 'components', -1, p.shrink);
  return [soupPart(soup, (o) => componentColor(o, S.componentKind[o]), { cellTypes: S.cellTypes, name: 'components' })];
}

/** Every sheet at once: large (a cell is in up to three sheets), so bounded. */
function buildSheets(p) {
  const sc = csr(S.analysis, 'sheet_cells');
  const total = sc.offsets[sc.offsets.length - 1];
  if (total > (p.maxCells ?? 6e6)) {
    throw new Error(`All sheets together hold ${total} cells, too many to draw at once here: pick a sheet instead.`);
  }
  const soup = core.blockSoup(S.mesh, S.analysis, 'sheets', -1, p.shrink);
  if (soup.owner.length > 4e6) {
    throw new Error(`All sheets together have ${soup.owner.length} faces, too many to draw at once here: pick a sheet instead.`);
  }
  return [soupPart(soup, (o) => spreadColor(o), { cellTypes: S.cellTypes, name: 'sheets' })];
}

/** The picked sheet: its blocks in the sheet's colour, each a little lighter or darker (as the
 *  add-on does), and its highlights. */
function buildSheet(p) {
  const i = p.sheet;
  if (!(i >= 0 && i < S.sheetType.length)) return [];
  const color = spreadColor(i);
  const soup = core.blockSoup(S.mesh, S.analysis, 'sheet', i, p.shrink);
  const parts = [soupPart(soup, () => color, { cellTypes: S.cellTypes, shade: (o) => 0.8 + (0.2 * ((o * 7) % 3)) / 2, name: 'picked sheet' })];
  const a = S.analysis;
  const unmatched = row(csr(a, 'sheet_unmatched_vertices'), i);
  if (unmatched.length) parts.push(dotsPart(S.points, unmatched, L.unmatched_color, 'unmatched'));
  const shared = row(csr(a, 'sheet_shared_vertices'), i);
  if (shared.length) parts.push(dotsPart(S.points, shared, L.shared_color, 'shared'));
  const curves = row(csr(a, 'sheet_self_parallel_curves'), i);
  if (curves.length) parts.push(curveLines(curves, L.self_parallel_color));
  const comps = row(csr(a, 'sheet_self_intersecting_components'), i);
  if (comps.length) {
    const blocks = core.blockSoup(S.mesh, S.analysis, 'components', -1, 0);
    parts.push(soupPart(selectOwners(blocks, new Set(comps)), () => L.self_intersecting_color, { name: 'self-intersecting' }));
  }
  return parts;
}

/** Base-complex curves (or, at level mesh, mesh edges) as lines of one colour. */
function curveLines(curves, color) {
  const level = S.levelMesh ?? false;
  const offsets = [0];
  const items = [];
  let closed = [];
  if (!level) {
    const cx = core.complex(S.analysis);
    const cv = csr(cx, 'curve_vertices');
    const cc = arr(cx, 'curve_closed');
    for (const c of curves) {
      items.push(...row(cv, c));
      offsets.push(items.length);
      closed.push(!!cc[c]);
    }
  }
  const off = Int32Array.from(offsets);
  const pos = core.polylines(S.mesh, off, Int32Array.from(items));
  return linesPart(pos, off, { colorOf: () => color, closed: (r) => closed[r], name: 'self-parallel' });
}

/** The faces of a soup whose owner is in `keep`, with only the points they use. */
function selectOwners(soup, keep) {
  const offsets = [0];
  const items = [];
  const owner = [];
  const cell = [];
  const remap = new Map();
  const pos = [];
  for (let f = 0; f < soup.owner.length; f++) {
    if (!keep.has(soup.owner[f])) continue;
    for (let k = soup.offsets[f]; k < soup.offsets[f + 1]; k++) {
      const p = soup.items[k];
      let q = remap.get(p);
      if (q === undefined) {
        q = remap.size;
        remap.set(p, q);
        pos.push(soup.positions[3 * p], soup.positions[3 * p + 1], soup.positions[3 * p + 2]);
      }
      items.push(q);
    }
    offsets.push(items.length);
    owner.push(soup.owner[f]);
    cell.push(soup.cell[f]);
  }
  return { positions: Float32Array.from(pos), offsets: Int32Array.from(offsets), items: Int32Array.from(items), owner: Int32Array.from(owner), cell: Int32Array.from(cell) };
}

/** The subsheets of the picked self-intersecting sheet, each its own colour (optionally side by
 *  side, as the add-on lays them out), with their unmatched vertices and their wireframes. */
function buildSubsheets(p) {
  const i = p.sheet;
  if (!(i >= 0 && i < S.sheetType.length) || S.sheetType[i] !== 3) return [];
  const sub = core.subsheets(S.analysis, i);
  const count = Number(get(sub, 'count'));
  const soup = core.blockSoup(S.mesh, S.analysis, 'subsheets', i, p.shrink);
  const un = csr(sub, 'subsheet_unmatched_vertices');
  const types = arr(sub, 'subsheet_type');
  const cells = csr(sub, 'subsheet_cells').offsets;
  const list = Array.from({ length: count }, (_, k) => ({ type: types[k], cells: cells[k + 1] - cells[k] }));
  const parts = [];
  let wiresOk = true;
  // One part per subsheet, so that the page can lay them out side by side.
  for (let k = 0; k < count; k++) {
    const one = selectOwners(soup, new Set([k]));
    parts.push({ ...soupPart(one, () => subsheetColor(k), { cellTypes: S.cellTypes, name: `subsheet ${k}` }), subsheet: k });
    const dots = row(un, k);
    if (dots.length) parts.push({ ...dotsPart(S.points, dots, L.unmatched_color, `subsheet ${k} unmatched`), subsheet: k });
    if (p.subsheetWires && wiresOk) {
      try {
        parts.push(...buildWireframe({ ...p, sheet: i, subsheet: k }).map((w) => ({ ...w, below: true })));
      } catch (e) {
        wiresOk = false; // a core without per-subsheet wireframes: the subsheets still draw
      }
    }
  }
  core.free(sub);
  return parts.map((q) => ({ ...q, subsheets: list }));
}

/** A VSG wireframe (of the mesh, a sheet or a subsheet): colour class or non-hex kind, per-point
 *  alpha from its opacity, the simplified one by default. */
function buildWireframe(p) {
  const w = core.wireframe(S.analysis, p.sheet ?? -1, p.subsheet ?? -1);
  const poly = csr(w, 'polylines');
  const opacity = Float32Array.from(arr(w, 'point_opacity'));
  const color = arr(w, 'color');
  const shown = arr(w, 'shown');
  const kinds = p.byKind ? csr(w, 'non_hex') : null;
  const pos = core.polylines(S.mesh, poly.offsets, poly.items);
  const part = linesPart(pos, poly.offsets, {
    colorOf: kinds ? (r) => kindColor(row(kinds, r)) : (r) => paletteColor(color[r]),
    alpha: opacityAlpha(opacity, p.floor ?? L.wire_floor ?? 0.15),
    keep: p.simplified === false ? null : (r) => !!shown[r],
    name: p.subsheet >= 0 ? `wireframe ${p.subsheet}` : 'wireframe',
  });
  core.free(w);
  return [{ ...part, subsheet: p.subsheet ?? -1 }];
}

const BUILDERS = { direct: buildDirect, graph: buildGraph, components: buildBlocks, sheets: buildSheets, sheet: buildSheet, subsheets: buildSubsheets, wireframe: buildWireframe };

self.onmessage = async (ev) => {
  const msg = ev.data;
  const t0 = performance.now();
  try {
    if (msg.type === 'warm') {
      warming ??= warmUp(msg.size).catch(() => {}); // an instantiation error shows when a file is opened
    } else if (msg.type === 'open' || msg.type === 'reopen') {
      stopWarming = true;
      if (warming) await warming;
      await open({ ...msg, again: msg.type === 'reopen' }, t0);
    } else if (msg.type === 'layer') {
      if (!S) return;
      const parts = BUILDERS[msg.layer](msg.params || {});
      post({ type: 'layer', id: msg.id, layer: msg.layer, parts }, transferList(parts));
    }
  } catch (e) {
    const text = e instanceof Error ? e.message : errorText(core?.M ?? {}, e);
    if (msg.type === 'open' || msg.type === 'reopen') {
      closeMesh();
      post({ type: 'error', message: text });
    } else {
      post({ type: 'layer-error', id: msg.id, layer: msg.layer, message: text });
    }
  }
};

// Instantiated at once: a file opened later does not wait for it.
module().catch(() => {});
