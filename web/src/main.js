// The page: opening a mesh (picker, folder, drop, ?mesh=URL, the embedded mesh), the layers and
// their settings, the sheet list, the legend and Table 1, the state for tests (#hbc-results,
// body[data-state]) and the view in the URL fragment.
/* global __HBC_WORKER_SOURCE__ */
import { Viewer } from './scene.js';
import { L, css, spreadColor, subsheetColor } from './colors.js';
import { fixed } from './format.js';

const $ = (id) => document.getElementById(id);
const LAYERS = L.layers.map(([key]) => key);
const LAYER_TITLES = Object.fromEntries(L.layers);

const state = {
  layers: { direct: true, graph: true, components: false, sheets: false, sheet: false, subsheets: false, wireframe: false },
  shrink: 0.1,
  boundaryOpacity: 0.25,
  sheet: -1,
  sort: 'TYPE',
  wireScope: 'all',
  simplified: true,
  byKind: false,
  floor: L.wire_floor,
  spread: true,
  plane: { on: false, axis: 0, t: 0.5 },
  types: [true, true, true, true, true],
  skipInvalid: false, // the CLI's --skip-invalid for the files opened
};
let info = null; // the worker's summary of the open mesh
let results = null;
let timings = null;
let table1 = null;
let pendingView = null;
let firstFrame = null; // layers still to arrive before the page says "ready"
let embeddedWarnings = []; // what `hbc export-html` said when reading the embedded mesh's source
let lastName = ''; // the name of the last files given to the worker, which it can read again
let subsheetsShown = 0; // subsheets drawn side by side (0: none, or in place): the view frames them all
let framedSubsheets = ''; // which subsheets layout the view was last framed to (sheet, count)
let keepCameraFor = -1; // the subsheets request whose arrival must not move the camera (a view link's)
const requests = new Map(); // layer -> latest request id
let nextId = 1;

const viewer = new Viewer($('hbc-canvas'));
viewer.onView = () => saveFragment();

// -- the worker ------------------------------------------------------------------------------
const worker = new Worker(URL.createObjectURL(new Blob([__HBC_WORKER_SOURCE__], { type: 'text/javascript' })));
worker.onmessage = (ev) => {
  const m = ev.data;
  if (m.type === 'progress') showProgress(m.fraction, m.text);
  else if (m.type === 'ready') ready(m);
  else if (m.type === 'error') failed(m.message);
  else if (m.type === 'layer') layerArrived(m);
  else if (m.type === 'layer-error') layerFailed(m);
  else if (m.type === 'warm-up') warmUpState(m);
};
worker.onerror = (e) => failed(`The worker stopped: ${e.message || 'unknown error'}`);

function setState(s) {
  document.body.dataset.state = s;
  $('hbc-results').dataset.state = s;
}

/** body[data-warmup]: running, done, stopped (a file came first) or failed (docs/web.md). */
function warmUpState(m) {
  document.body.dataset.warmup = m.state;
  if (m.seconds != null) document.body.dataset.warmupSeconds = m.seconds.toFixed(3);
  if (m.message) document.body.dataset.warmupError = m.message;
}

function showProgress(fraction, text) {
  $('progress').hidden = false;
  $('progress-bar').value = fraction;
  $('status').textContent = text;
}

/** Opens files [{path, buffer}] named `name` (a file name, or a case folder's); without files, the
 *  last ones again (the worker still has them) with the present "skip invalid cells" choice.
 *  warnings: what was said when the files were made (hbc export-html's reading). */
function openFiles(name, files, warnings = []) {
  if (files) {
    embeddedWarnings = warnings;
    lastName = name;
  }
  firstFrame = null;
  state.sheet = -1; // a new mesh has other sheets (a view link sets it again once analysed)
  setState('loading');
  forgetMesh();
  $('hbc-error').hidden = true;
  $('hbc-error').textContent = '';
  $('mesh-name').textContent = name;
  document.title = `${name} — hbc viewer`;
  showProgress(0.02, 'Reading ' + name);
  if (!files) worker.postMessage({ type: 'reopen', skipInvalid: state.skipInvalid });
  else worker.postMessage({ type: 'open', name, files, skipInvalid: state.skipInvalid }, files.map((f) => f.buffer));
}

/** Empties every view of the open mesh (layers, sheet and subsheet lists, legend, Table 1, the
 *  results, the reader's warnings): a file being opened, or refused, must not leave the previous
 *  mesh's numbers on screen beside its own name. */
function forgetMesh() {
  viewer.clearAll();
  requests.clear();
  info = null;
  results = null;
  timings = null;
  table1 = null;
  subsheetsShown = 0;
  framedSubsheets = '';
  $('hbc-results').textContent = '';
  delete $('hbc-results').dataset.openSeconds;
  $('sheet-count').textContent = '';
  showWarnings([]);
  sheetList();
  subsheetList([]);
  for (const layer of LAYERS) layerNote(layer, '');
  showTable1();
  legend();
  syncControls();
}

/** What reading said (cells dropped by "skip invalid cells", ...), in the CLI's words. */
function showWarnings(lines) {
  const el = $('hbc-warnings');
  el.textContent = lines.join('\n');
  el.hidden = !lines.length;
}

function ready(m) {
  info = m.info;
  timings = m.timings ?? null;
  results = m.results;
  table1 = m.table1;
  $('hbc-results').textContent = JSON.stringify(results, null, 2);
  // Beside the results, not in them (their keys are `hbc analyze --json`'s).
  $('hbc-results').dataset.openSeconds = m.seconds.toFixed(4);
  $('progress').hidden = true;
  $('status').textContent = `${info.cells} cells analysed`;
  showWarnings([...embeddedWarnings, ...(m.warnings ?? [])]);
  const keepCamera = pendingView ? applyFragment(pendingView) : false;
  if (!pendingView) viewer.frame(info.bbox);
  pendingView = null;
  sheetList();
  showTable1();
  syncControls();
  // "ready" once the first layers are drawn: a screenshot taken then shows the mesh.
  firstFrame = new Set(LAYERS.filter((l) => state.layers[l] && !((l === 'sheet' || l === 'subsheets') && state.sheet < 0)));
  rebuildAll();
  keepCameraFor = keepCamera ? requests.get('subsheets') ?? -1 : -1;
  settle();
}

/** Marks the page ready when no first layer is still on its way. */
function settle(layer) {
  if (!firstFrame) return;
  if (layer) firstFrame.delete(layer);
  if (firstFrame.size) return;
  firstFrame = null;
  viewer.renderNow();
  setState('ready');
}

function failed(message) {
  forgetMesh();
  $('progress').hidden = true;
  $('status').textContent = 'Could not open the mesh';
  let text = message;
  // The core's message names the CLI's option; on the page it is a tick box.
  if (!state.skipInvalid && message.includes('--skip-invalid')) text += '\n(On this page: tick "Skip invalid cells".)';
  else if (/expected an OpenFOAM case beside/.test(message)) text += '\n(On this page: pick the .foam file together with the files of constant/polyMesh, or open the case folder.)';
  $('hbc-error').textContent = text;
  $('hbc-error').hidden = false;
  setState('error');
}

// -- layers ----------------------------------------------------------------------------------
function layerParams(layer) {
  const p = { shrink: state.shrink };
  if (layer === 'direct') {
    p.shrink = 0;
    p.types = state.types;
    if (state.plane.on) p.plane = { axis: state.plane.axis, pos: planePos() };
  }
  if (layer === 'sheet' || layer === 'subsheets') p.sheet = state.sheet;
  if (layer === 'subsheets') Object.assign(p, { subsheetWires: true, floor: state.floor, simplified: state.simplified, byKind: state.byKind });
  if (layer === 'wireframe') {
    Object.assign(p, { floor: state.floor, simplified: state.simplified, byKind: state.byKind });
    p.sheet = state.wireScope === 'sheet' ? state.sheet : -1;
  }
  return p;
}

function build(layer) {
  if (!info) return;
  if (!state.layers[layer] || ((layer === 'sheet' || layer === 'subsheets') && state.sheet < 0)) {
    viewer.clearLayer(layer);
    requests.delete(layer);
    if (layer === 'subsheets') {
      subsheetList([]);
      subsheetsShown = 0;
      framedSubsheets = ''; // switched on again: framed again
    }
    layerNote(layer, '');
    legend();
    return;
  }
  const id = nextId++;
  requests.set(layer, id);
  layerNote(layer, 'building…');
  worker.postMessage({ type: 'layer', id, layer, params: layerParams(layer) });
}

function rebuildAll() {
  for (const layer of LAYERS) build(layer);
  legend();
}

/** planning.spread_translation: subsheet k side by side along x (k steps of dx), each wireframe
 *  one row beneath (dz). */
function spreadStep() {
  const [lo, hi] = info.bbox;
  return { dx: (hi[0] - lo[0]) * (1 + L.spread_gap), dz: -(hi[2] - lo[2]) * (1 + L.spread_gap) };
}

/** The box the view frames: the mesh's, widened to every subsheet laid side by side when they show. */
function viewBox() {
  if (!subsheetsShown) return info.bbox;
  const [lo, hi] = info.bbox;
  const { dx, dz } = spreadStep();
  return [[lo[0], lo[1], lo[2] + dz], [hi[0] + dx * (subsheetsShown - 1), hi[1], hi[2]]];
}

function layerArrived(m) {
  if (requests.get(m.layer) !== m.id) return; // a newer request is on its way
  const style = { boundaryOpacity: state.boundaryOpacity };
  if (m.layer === 'subsheets' && state.spread && info) {
    const { dx, dz } = spreadStep();
    style.offset = (p) => (p.subsheet >= 0 ? [dx * p.subsheet, 0, p.below ? dz : 0] : [0, 0, 0]);
  }
  viewer.setLayer(m.layer, m.parts, style);
  const sub = m.parts.find((p) => p.subsheets !== undefined);
  let note = '';
  if (m.layer === 'subsheets') {
    const t = info.sheets[state.sheet]?.type;
    note = sub ? `${sub.subsheets.length} subsheets` : L.subsheets_unavailable?.[t] ?? 'only self-intersecting (type 3) sheets have subsheets';
    subsheetList(sub ? sub.subsheets : []);
    frameSubsheets(state.spread && sub ? sub.subsheets.length : 0, m.id);
  }
  layerNote(m.layer, note);
  legend();
  settle(m.layer);
}

/** Subsheets laid side by side reach beyond the mesh's box: the first time a layout shows (a sheet
 *  picked, the layer or the side-by-side choice switched on), the view frames all of them, unless
 *  the camera came with a view link. */
function frameSubsheets(count, id) {
  subsheetsShown = count;
  const key = count ? `${state.sheet}/${count}` : '';
  if (key && key !== framedSubsheets && id !== keepCameraFor) viewer.frame(viewBox());
  framedSubsheets = key;
}

/** The picked sheet's subsheets: class and cells, in the colours the layer draws them. */
function subsheetList(list) {
  const el = $('subsheet-list');
  el.textContent = '';
  list.forEach((s, k) => {
    const li = document.createElement('li');
    li.innerHTML = `<span class="sw" style="background:${css(subsheetColor(k))}"></span>`;
    li.appendChild(document.createTextNode(`subsheet ${k}: ${L.sheet_type_short[s.type]}, ${s.cells} cells`));
    el.appendChild(li);
  });
}

function layerFailed(m) {
  if (requests.get(m.layer) !== m.id) return;
  viewer.clearLayer(m.layer);
  layerNote(m.layer, m.message);
  settle(m.layer);
}

function layerNote(layer, text) {
  const el = document.querySelector(`[data-note="${layer}"]`);
  if (el) el.textContent = text;
}

function planePos() {
  const [lo, hi] = info ? info.bbox : [[0, 0, 0], [1, 1, 1]];
  const a = state.plane.axis;
  // Just beyond the ends so that 0 hides everything and 1 nothing.
  const span = hi[a] - lo[a] || 1;
  return lo[a] - 1e-6 * span + state.plane.t * span * (1 + 2e-6);
}

let directTimer = null;
function planeChanged() {
  viewer.setClip(state.plane.on, state.plane.axis, planePos());
  viewer.setTypeMask(state.types);
  clearTimeout(directTimer);
  directTimer = setTimeout(() => build('direct'), 120); // the cut surface, recomputed by the core
  saveFragment();
}

// -- sheet list ------------------------------------------------------------------------------
/** planning.sheet_order: by type then size (largest first), by size, or by index. */
function sheetOrder(sheets, by) {
  const s = [...sheets];
  if (by === 'TYPE') s.sort((a, b) => a.type - b.type || b.cells - a.cells || a.id - b.id);
  else if (by === 'SIZE') s.sort((a, b) => b.cells - a.cells || a.id - b.id);
  return s;
}

function sheetList() {
  const body = $('sheet-rows');
  body.textContent = '';
  if (!info) return;
  const rows = sheetOrder(info.sheets, state.sort).slice(0, 5000);
  const frag = document.createDocumentFragment();
  for (const s of rows) {
    const tr = document.createElement('tr');
    tr.dataset.sheet = s.id;
    if (s.id === state.sheet) tr.className = 'picked';
    const sw = `<span class="sw" style="background:${css(spreadColor(s.id))}"></span>`;
    tr.innerHTML = `<td>${sw}${s.id}</td><td>${L.sheet_type_short[s.type]}</td><td>${s.cells}</td><td>${s.blocks}</td>`;
    frag.appendChild(tr);
  }
  body.appendChild(frag);
  $('sheet-count').textContent = `${info.sheets.length} sheets`;
}

function pickSheet(id) {
  state.sheet = id;
  state.layers.sheet = true;
  sheetList();
  syncControls();
  build('sheet');
  build('subsheets');
  if (state.wireScope === 'sheet') build('wireframe');
  saveFragment();
}

// -- legend and Table 1 ------------------------------------------------------------------------
/** The library's legend for the layers shown (hbc::legend, then palette_legend, as the add-on's
 *  planning.legend and palette_legend): the worker asked the core for every set of shown layers. */
function legendEntries() {
  const shown = LAYERS.filter((l) => state.layers[l] && viewer.layers.has(l));
  if (!info || !shown.length) return [];
  return info.legends[`${shown.join(',')}|${state.byKind ? 1 : 0}`];
}

function legend() {
  const el = $('legend');
  el.textContent = '';
  for (const [key, words] of legendEntries()) {
    const c = L.legend_colors[key];
    const li = document.createElement('li');
    li.innerHTML = `<span class="sw" style="background:${css(c)}"></span>`;
    li.appendChild(document.createTextNode(words));
    el.appendChild(li);
  }
}

/** Table 1 as planning.table1_row: counts as integers, times in ms, missing as '-'; ratios with the
 *  4 decimals of `hbc table` (a ratio of exactly 1 is 1.0000, not 1). */
function showTable1() {
  const t = $('table1');
  t.textContent = '';
  if (!results) return;
  if (!table1) {
    // The columns come from the library's schema: the build had no compiled hbc module and the
    // WebAssembly core gives none.
    t.innerHTML = '<tr><td>Table 1\'s columns are not in this build (see web/README.md).</td></tr>';
    return;
  }
  const stats = { ...results };
  if (!('hex_component_ratio' in stats) && stats.components) stats.hex_component_ratio = (stats.hex_components ?? 0) / stats.components;
  const head = document.createElement('tr');
  const row = document.createElement('tr');
  for (const c of table1) {
    const th = document.createElement('th');
    th.textContent = c.notation;
    th.title = c.meaning;
    head.appendChild(th);
    const v = (c.timing ? timings ?? {} : stats)[c.key];
    let text;
    if (v == null || (Number.isInteger(v) && v < 0)) text = '-';
    else if (c.timing) text = `${Math.round(1000 * v)} ms`;
    else if (c.kind ? c.kind === 'count' : Number.isInteger(v)) text = String(v);
    else text = fixed(v, 4);
    const td = document.createElement('td');
    td.textContent = text;
    row.appendChild(td);
  }
  t.append(head, row);
}

// -- controls ------------------------------------------------------------------------------
function syncControls() {
  for (const layer of LAYERS) {
    const box = document.querySelector(`input[data-layer="${layer}"]`);
    if (box) box.checked = !!state.layers[layer];
  }
  $('shrink').value = state.shrink;
  $('boundary-opacity').value = state.boundaryOpacity;
  $('plane-on').checked = state.plane.on;
  $('plane-axis').value = String(state.plane.axis);
  $('plane-pos').value = state.plane.t;
  $('wire-scope').value = state.wireScope;
  $('wire-simplified').checked = state.simplified;
  $('wire-kind').value = state.byKind ? 'KIND' : 'CLASS';
  $('wire-floor').value = state.floor;
  $('spread').checked = state.spread;
  $('sheet-sort').value = state.sort;
  $('skip-invalid').checked = state.skipInvalid;
  document.querySelectorAll('input[data-type]').forEach((b) => { b.checked = state.types[+b.dataset.type]; });
  const t = info && state.sheet >= 0 ? info.sheets[state.sheet] : null;
  $('picked').textContent = t ? `Sheet ${t.id}: ${L.sheet_type_short[t.type]}, ${t.cells} cells, ${t.blocks} blocks` : 'No sheet picked';
  viewer.setClip(state.plane.on, state.plane.axis, planePos());
  viewer.setTypeMask(state.types);
}

function buildControls() {
  const list = $('layers');
  for (const layer of LAYERS) {
    const li = document.createElement('li');
    li.innerHTML = `<label><input type="checkbox" data-layer="${layer}"> ${LAYER_TITLES[layer]}</label> <span class="note" data-note="${layer}"></span>`;
    list.appendChild(li);
  }
  list.addEventListener('change', (e) => {
    const layer = e.target.dataset.layer;
    if (!layer) return;
    state.layers[layer] = e.target.checked;
    build(layer);
    saveFragment();
  });
  const types = $('types');
  L.cell_type_names.forEach((name, t) => {
    const label = document.createElement('label');
    label.innerHTML = `<input type="checkbox" data-type="${t}" checked> <span class="sw" style="background:${css(L.cell_type_colors[t])}"></span>${name}`;
    types.appendChild(label);
  });
  types.addEventListener('change', (e) => {
    if (e.target.dataset.type === undefined) return;
    state.types[+e.target.dataset.type] = e.target.checked;
    planeChanged();
  });
  $('shrink').addEventListener('change', (e) => {
    state.shrink = +e.target.value;
    for (const l of ['components', 'sheets', 'sheet', 'subsheets']) build(l);
    saveFragment();
  });
  $('boundary-opacity').addEventListener('input', (e) => {
    state.boundaryOpacity = +e.target.value;
    viewer.setBoundaryOpacity(state.boundaryOpacity);
    saveFragment();
  });
  $('plane-on').addEventListener('change', (e) => { state.plane.on = e.target.checked; planeChanged(); });
  $('plane-axis').addEventListener('change', (e) => { state.plane.axis = +e.target.value; planeChanged(); });
  $('plane-pos').addEventListener('input', (e) => { state.plane.t = +e.target.value; planeChanged(); });
  const wire = () => { build('wireframe'); build('subsheets'); saveFragment(); };
  $('wire-scope').addEventListener('change', (e) => { state.wireScope = e.target.value; wire(); });
  $('wire-simplified').addEventListener('change', (e) => { state.simplified = e.target.checked; wire(); });
  $('wire-kind').addEventListener('change', (e) => { state.byKind = e.target.value === 'KIND'; wire(); });
  $('wire-floor').addEventListener('change', (e) => { state.floor = +e.target.value; wire(); });
  $('spread').addEventListener('change', (e) => { state.spread = e.target.checked; build('subsheets'); saveFragment(); });
  $('sheet-sort').addEventListener('change', (e) => { state.sort = e.target.value; sheetList(); });
  $('sheet-rows').addEventListener('click', (e) => {
    const tr = e.target.closest('tr');
    if (tr) pickSheet(+tr.dataset.sheet);
  });
  $('snapshot').addEventListener('click', snapshot);
  $('reset-view').addEventListener('click', () => info && viewer.frame(viewBox()));
  $('skip-invalid').addEventListener('change', (e) => {
    state.skipInvalid = e.target.checked;
    // The open (or refused) file again, read the other way.
    if (['ready', 'error'].includes(document.body.dataset.state) && lastName) openFiles(lastName, null);
  });
}

/** A click (not a drag) on the view: a sheet of the sheets layer is picked; a block, a cell or a
 *  subsheet is named in the status line. */
function setupPicking() {
  const el = $('hbc-canvas');
  let down = null;
  el.addEventListener('pointerdown', (e) => { down = [e.clientX, e.clientY]; });
  el.addEventListener('pointerup', (e) => {
    if (!down || !info || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    const r = el.getBoundingClientRect();
    const hit = viewer.pick(e.clientX - r.left, e.clientY - r.top, ['sheets', 'components', 'sheet', 'subsheets', 'direct']);
    if (!hit) return;
    if (hit.layer === 'sheets') {
      pickSheet(hit.owner);
      return;
    }
    const what = { components: 'component', sheet: 'component', subsheets: 'subsheet', direct: 'cell' }[hit.layer];
    $('status').textContent = `${LAYER_TITLES[hit.layer]}: ${what} ${hit.owner}`;
  });
}

function snapshot() {
  const a = document.createElement('a');
  a.href = viewer.snapshot();
  a.download = `${($('mesh-name').textContent || 'hbc').replace(/[^\w.-]+/g, '_')}.png`;
  document.body.appendChild(a);
  a.click();
  a.remove();
}

// -- the view in the URL fragment ------------------------------------------------------------
// Keys: cam (position, target, up: 9 numbers), layers (keys shown), sheet, shrink, opacity,
// plane (axis x|y|z and position 0..1, absent when off), types (5 digits 0/1 by cell type),
// wire (all|sheet), simplified (0|1), colors (class|kind), floor, spread (0|1).
let fragTimer = null;
function saveFragment() {
  if (!info) return;
  clearTimeout(fragTimer);
  fragTimer = setTimeout(() => {
    const q = new URLSearchParams();
    q.set('cam', viewer.getView().map((x) => +x.toPrecision(6)).join(','));
    q.set('layers', LAYERS.filter((l) => state.layers[l]).join(','));
    if (state.sheet >= 0) q.set('sheet', state.sheet);
    q.set('shrink', state.shrink);
    q.set('opacity', state.boundaryOpacity);
    if (state.plane.on) q.set('plane', `${'xyz'[state.plane.axis]},${state.plane.t}`);
    q.set('types', state.types.map((b) => (b ? 1 : 0)).join(''));
    q.set('wire', state.wireScope);
    q.set('simplified', state.simplified ? 1 : 0);
    q.set('colors', state.byKind ? 'kind' : 'class');
    q.set('floor', state.floor);
    q.set('spread', state.spread ? 1 : 0);
    history.replaceState(null, '', `${location.pathname}${location.search}#${q.toString().replace(/%2C/g, ',')}`);
  }, 200);
}

function applyFragment(text) {
  const q = new URLSearchParams(text);
  const num = (k, d) => (q.has(k) && Number.isFinite(+q.get(k)) ? +q.get(k) : d);
  if (q.has('layers')) {
    const on = new Set(q.get('layers').split(',').filter(Boolean));
    if (on.has('blocks')) on.add('components'); // the layer's old key (docs/concepts.md, retired words) in saved links
    for (const l of LAYERS) state.layers[l] = on.has(l);
  }
  state.sheet = info && num('sheet', -1) < info.sheets.length ? Math.trunc(num('sheet', -1)) : -1;
  state.shrink = num('shrink', state.shrink);
  state.boundaryOpacity = num('opacity', state.boundaryOpacity);
  if (q.has('plane')) {
    const [axis, t] = q.get('plane').split(',');
    state.plane = { on: true, axis: Math.max(0, 'xyz'.indexOf(axis)), t: Number.isFinite(+t) ? +t : 0.5 };
  } else state.plane.on = false;
  if (q.has('types')) state.types = [...q.get('types').padEnd(5, '1')].slice(0, 5).map((c) => c !== '0');
  if (q.has('wire')) state.wireScope = q.get('wire') === 'sheet' ? 'sheet' : 'all';
  state.simplified = num('simplified', 1) !== 0;
  state.byKind = q.get('colors') === 'kind';
  state.floor = num('floor', state.floor);
  state.spread = num('spread', 1) !== 0;
  viewer.frame(info.bbox);
  if (q.has('cam')) viewer.setView(q.get('cam').split(',').map(Number));
  return q.has('cam');
}

// -- opening -------------------------------------------------------------------------------
async function filesFromList(list) {
  const all = [...list].map((f) => ({ file: f, path: f.webkitRelativePath || f.name }));
  return keepMeshFiles(asCase(all));
}

// The files of an OpenFOAM case's constant/polyMesh folder (gzipped or not).
const POLY_MESH_FILE = /^(points|faces|owner|neighbour|boundary)(\.gz)?$/;

/** Files picked one by one (a file picker or a drop gives no folders) that are an OpenFOAM case's,
 *  the .foam marker and the polyMesh files, laid out as the case they come from: CASE/CASE.foam
 *  and CASE/constant/polyMesh/*, CASE the marker's name (else "polyMesh", the folder they are). */
function asCase(all) {
  if (all.length < 2 || all.some((f) => f.path.includes('/'))) return all;
  if (!all.some((f) => /^owner(\.gz)?$/.test(f.path))) return all;
  const foam = all.find((f) => /\.foam$/i.test(f.path));
  const name = foam ? foam.path.replace(/\.foam$/i, '') || 'case' : 'polyMesh';
  return all.filter((f) => f === foam || POLY_MESH_FILE.test(f.path))
    .map((f) => ({ ...f, path: f === foam ? `${name}/${f.path}` : `${name}/constant/polyMesh/${f.path}` }));
}

/** Of a folder's files, an OpenFOAM case's polyMesh (and .foam file) when there is one. */
async function keepMeshFiles(all) {
  let files = all;
  if (all.length > 1) {
    const poly = all.filter((f) => /(^|\/)polyMesh\/[^/]+$/.test(f.path) || /\.foam$/i.test(f.path));
    if (poly.length) files = poly;
  }
  return Promise.all(files.map(async (f) => ({ path: f.path, buffer: await f.file.arrayBuffer() })));
}

/** The mesh's name: the one file's, or an OpenFOAM case's (the folder holding constant/polyMesh). */
function nameOf(files) {
  if (files.length === 1) return files[0].path.split('/').pop();
  const poly = files.map((f) => f.path.match(/(?:^|\/)([^/]+)\/constant\/polyMesh\/[^/]+$/)).find(Boolean);
  if (poly) return poly[1];
  return files[0].path.split('/')[0] || 'case';
}

async function openList(list) {
  if (!list || !list.length) return;
  const files = await filesFromList(list);
  openFiles(nameOf(files), files);
}

/** Dropped entries, folders read recursively (an OpenFOAM case dropped as a folder). */
async function droppedFiles(items) {
  const out = [];
  const walk = async (entry, prefix) => {
    if (entry.isFile) {
      out.push({ file: await new Promise((res, rej) => entry.file(res, rej)), path: prefix + entry.name });
    } else if (entry.isDirectory) {
      const reader = entry.createReader();
      for (;;) {
        const batch = await new Promise((res, rej) => reader.readEntries(res, rej));
        if (!batch.length) break;
        for (const e of batch) await walk(e, prefix + entry.name + '/');
      }
    }
  };
  const entries = [...items].map((i) => (i.webkitGetAsEntry ? i.webkitGetAsEntry() : null)).filter(Boolean);
  for (const e of entries) await walk(e, '');
  return keepMeshFiles(asCase(out));
}

function setupOpening() {
  $('file').addEventListener('change', (e) => { openList(e.target.files); e.target.value = ''; });
  $('folder').addEventListener('change', (e) => { openList(e.target.files); e.target.value = ''; });
  const drop = $('drop');
  window.addEventListener('dragover', (e) => { e.preventDefault(); drop.hidden = false; });
  window.addEventListener('dragleave', (e) => { if (!e.relatedTarget) drop.hidden = true; });
  window.addEventListener('drop', async (e) => {
    e.preventDefault();
    drop.hidden = true;
    const files = e.dataTransfer.items ? await droppedFiles(e.dataTransfer.items) : await filesFromList(e.dataTransfer.files);
    if (files.length) openFiles(nameOf(files), files);
  });
}

function base64Bytes(text) {
  const bin = atob(text.replace(/\s+/g, ''));
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  return bytes;
}

async function start() {
  buildControls();
  setupOpening();
  setupPicking();
  syncControls();
  legend();
  if (location.hash.length > 1) pendingView = location.hash.slice(1);
  // A view link pasted into the open page: the same mesh, the new view.
  window.addEventListener('hashchange', () => {
    if (!info || location.hash.length < 2) return;
    const keepCamera = applyFragment(location.hash.slice(1));
    sheetList();
    syncControls();
    rebuildAll();
    keepCameraFor = keepCamera ? requests.get('subsheets') ?? -1 : -1;
  });
  const embedded = $('hbc-embedded-mesh');
  const params = new URLSearchParams(location.search);
  if (embedded && embedded.textContent.trim()) {
    const name = embedded.dataset.name || 'mesh';
    if (embedded.dataset.title) document.title = embedded.dataset.title;
    // What hbc export-html's reading said (cells dropped by --skip-invalid: the page reads the kept
    // ones only), as the CLI said it.
    const warnings = (embedded.dataset.warnings || '').split('\n').filter(Boolean);
    const bytes = base64Bytes(embedded.textContent);
    openFiles(name, [{ path: name, buffer: bytes.buffer }], warnings);
  } else if (params.has('mesh')) {
    const url = params.get('mesh');
    const name = params.get('name') || decodeURIComponent(url.split(/[?#]/)[0].split('/').pop() || 'mesh');
    setState('loading');
    showProgress(0.01, 'Fetching ' + url);
    try {
      const r = await fetch(url);
      if (!r.ok) throw new Error(`${url}: ${r.status} ${r.statusText}`);
      openFiles(name, [{ path: name, buffer: await r.arrayBuffer() }]);
    } catch (e) {
      failed(`${url}: could not be fetched (${e.message})`);
    }
  } else {
    setState('idle');
    $('status').textContent = 'Open a mesh: drop a file or folder here, or use the buttons.';
    // Nothing to open yet: the worker warms the core up meanwhile (web/src/warmup.js).
    // ?warmup=R,L,N: a cylinder of R cells' radius and L layers, N rounds (for measuring it).
    const w = (params.get('warmup') || '').split(',').map(Number);
    const size = w.length === 3 && w.every((x) => Number.isInteger(x) && x >= 0) ? { radiusCells: w[0], layers: w[1], rounds: w[2] } : null;
    worker.postMessage({ type: 'warm', size });
  }
}

window.hbcViewer = {
  load: (name, buffer) => openFiles(name, [{ path: name, buffer }]),
  get state() { return document.body.dataset.state; },
  get results() { return results; },
  viewer,
};

start();
