// The analysis runs here, off the page's thread: the WebAssembly core reads the file (every
// format the CLI reads; an OpenFOAM case's files when the core takes several), analyses it as
// `hbc analyze` does, and builds each layer's buffers, which go to the page by transfer.
/* global createHbcModule, __HBC_WASM_BASE64__ */
import { Core, arr, csr, errorText } from './core.js';
import { transferList } from './geometry.js';
import { buildLayer } from './parts.js';
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

/** What the layer builders (parts.js) read of the open mesh and the core. */
function context() {
  return { core, S, centroids };
}

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
      const parts = buildLayer(context(), msg.layer, msg.params || {});
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
