// The web viewer (build/web/viewer.html, made by scripts/build_web.sh) in a real browser: Debian's
// chromium driven by playwright-core. The page's contract: `viewer.html?mesh=URL` loads a mesh from
// its own origin, a page written by `hbc export-html` loads the mesh embedded in it; when the
// analysis is done, body[data-state] is "ready" and #hbc-results holds the keys and values of
// `hbc analyze --json` minus `timings`; a refused file gives state "error" and the CLI's message in
// #hbc-error; #plane-on / #plane-pos move a slicing plane. The numbers on screen are the open mesh's
// only, and as the CLI prints them. Every test also asserts that the page logged no console error
// and threw no uncaught error.
//
// Run: node tests/web/viewer.test.mjs (ctest's web_viewer does). Environment: HBC_CLI (the hbc
// binary), HBC_VIEWER (the page), HBC_DATA_DIR (the shared meshes), HBC_CHROMIUM (the browser),
// HBC_WEB_SHOTS (a folder that keeps the screenshots).
// Without the page the run is skipped (exit 77, which ctest reports as skipped) unless
// HBC_WEB_REQUIRED=1 (scripts/test.sh builds the page, so there it fails).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync, mkdirSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { dirname, join, resolve, sep } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { decodePng, nonBackgroundShare, changedShare } from './png.mjs';

const HERE = dirname(fileURLToPath(import.meta.url));
const ROOT = resolve(HERE, '../..');
const VIEWER = resolve(process.env.HBC_VIEWER || join(ROOT, 'build/web/viewer.html'));
const CLI = process.env.HBC_CLI || join(ROOT, 'build/bin/hbc');
const DATA = process.env.HBC_DATA_DIR || resolve(ROOT, '../shared/data');
const CHROMIUM = process.env.HBC_CHROMIUM || '/usr/bin/chromium';
const TEAPOT = join(DATA, 'hybrid-base-complex/teapot.hedra');
const LOAD_TIMEOUT = 120_000;

if (!existsSync(VIEWER)) {
  const why = `no viewer page at ${VIEWER}; build it with \`bash scripts/build_web.sh\``;
  if (process.env.HBC_WEB_REQUIRED === '1') {
    console.error(`web_viewer: FAILED: ${why} (HBC_WEB_REQUIRED=1)`);
    process.exit(1);
  }
  console.log(`web_viewer: SKIPPED: ${why}`);
  process.exit(77);
}
for (const [what, path] of [['hbc (HBC_CLI)', CLI], ['chromium (HBC_CHROMIUM)', CHROMIUM], ['teapot', TEAPOT]])
  if (!existsSync(path)) throw new Error(`${what} not found at ${path}`);
let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (e) {
  throw new Error(`playwright-core is not installed: run \`npm ci\` in tests/web (${e.message})`);
}

// -- fixtures: a folder served over HTTP, the meshes in it, the CLI's answers -------------------
const work = mkdtempSync(join(tmpdir(), 'hbc-webtest-'));
let server, origin, browser;

function hbc(args, options = {}) {
  return execFileSync(CLI, args, { cwd: work, encoding: 'utf8', ...options });
}

// `hbc analyze --json NAME` run in the served folder, so its file name is the page's; minus timings.
function expectedResults(name) {
  const json = JSON.parse(hbc(['analyze', '--json', name]));
  delete json.timings;
  return json;
}

// The CLI's message for a file it refuses, without its "hbc: error: " prefix.
function cliError(name) {
  const r = spawnSync(CLI, ['analyze', name], { cwd: work, encoding: 'utf8' });
  assert.equal(r.status, 2, `hbc analyze ${name} should refuse the file: ${r.stderr}`);
  return r.stderr.trim().replace(/^hbc: error: /, '');
}

function serve(root) {
  const types = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript' };
  return createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (path === '/favicon.ico') return res.writeHead(204).end();
    const file = resolve(root, '.' + path);
    if (!file.startsWith(root + sep) || !existsSync(file)) return res.writeHead(404).end();
    const ext = file.slice(file.lastIndexOf('.'));
    res.writeHead(200, { 'content-type': types[ext] ?? 'application/octet-stream' }).end(readFileSync(file));
  });
}

before(async () => {
  symlinkSync(VIEWER, join(work, 'viewer.html'));
  // build_web.sh writes the page twice, as viewer.html and index.html (a hosted folder's default).
  const index = join(dirname(VIEWER), 'index.html');
  symlinkSync(existsSync(index) ? index : VIEWER, join(work, 'index.html'));
  symlinkSync(TEAPOT, join(work, 'teapot.hedra'));
  symlinkSync(join(ROOT, 'tests/data/formats/foam/hex2_ascii'), join(work, 'hex2_ascii'));
  symlinkSync(join(ROOT, 'tests/data/formats/foam/hex2_gzip'), join(work, 'hex2_gzip'));
  // Five cells the readers refuse beside five good ones (docs/check.md): --skip-invalid drops them.
  symlinkSync(join(ROOT, 'tests/data/check/defects.HYBRID'), join(work, 'defects.HYBRID'));
  // A hex grid: every ratio of Table 1 is exactly 1.
  hbc(['generate', 'grid', '--size', '3', '3', '2', '-o', 'grid.mesh']);
  // A small mesh with pyramids among its hexahedra: the non-hex paths of every stage.
  hbc(['generate', 'split', '--size', '4', '3', '3', '--split', 'pyramids', '--random', '5', '--seed', '7',
       '-o', 'split.mesh']);
  // The same mesh with one vertex index of a cell spoiled: refused with its line.
  const lines = readFileSync(join(work, 'split.mesh'), 'utf8').split('\n');
  const at = lines.findIndex((l) => /^\s*Hexahedra\s*$/.test(l)) + 2;
  assert.ok(at > 1, 'split.mesh has a Hexahedra section');
  lines[at] = lines[at].replace(/^\s*\d+/, 'x');
  writeFileSync(join(work, 'broken.mesh'), lines.join('\n'));
  server = serve(work);
  await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
  origin = `http://127.0.0.1:${server.address().port}`;
  // SwiftShader: WebGL without a GPU, as on the test machines.
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist'],
  });
});

after(async () => {
  await browser?.close();
  server?.close();
  rmSync(work, { recursive: true, force: true });
});

// -- the page -----------------------------------------------------------------------------------
// A fresh page that records console errors and uncaught errors (the page's and its workers').
async function openPage(url) {
  const context = await browser.newContext({ viewport: { width: 1200, height: 800 } });
  const page = await context.newPage();
  const errors = [];
  const onConsole = (m) => { if (m.type() === 'error') errors.push(`console.error: ${m.text()}`); };
  page.on('console', onConsole);
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  page.on('worker', (w) => w.on('console', onConsole));
  await page.goto(url);
  return { page, errors, close: () => context.close() };
}

// Waits until the page is no longer loading; returns its state.
async function settled(page) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.state), null,
    { timeout: LOAD_TIMEOUT });
  return page.evaluate(() => document.body.dataset.state);
}

async function pageResults(page) {
  const text = await page.locator('#hbc-results').textContent();
  return JSON.parse(text);
}

// The page's results equal the CLI's, key order included.
function assertSameResults(got, want) {
  assert.deepStrictEqual(got, want);
  assert.deepStrictEqual(Object.keys(got), Object.keys(want));
}

// HBC_WEB_SHOTS=DIR keeps every screenshot there, to look at what the tests saw.
let shots = 0;
async function canvasShot(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const png = await page.locator('#hbc-canvas canvas').first().screenshot();
  if (process.env.HBC_WEB_SHOTS) writeFileSync(join(process.env.HBC_WEB_SHOTS, `shot-${String(shots++).padStart(3, '0')}.png`), png);
  return decodePng(png);
}

// Screenshots until `ok(image)` holds (the layers arrive from the worker after the analysis).
async function shotUntil(page, ok, what) {
  const end = Date.now() + 60_000;
  let img;
  do {
    img = await canvasShot(page);
    if (ok(img)) return img;
    await page.waitForTimeout(250);
  } while (Date.now() < end);
  assert.fail(`the canvas never showed ${what}`);
}

// A screenshot once the picture has stopped changing (the cut layer comes from the worker): two
// shots 400 ms apart equal.
async function stableShot(page) {
  let last = await canvasShot(page);
  for (let i = 0; i < 100; i++) {
    await page.waitForTimeout(400);
    const img = await canvasShot(page);
    if (changedShare(last, img) === 0) return img;
    last = img;
  }
  assert.fail('the canvas never settled');
}

// -- the tests ----------------------------------------------------------------------------------
test('teapot by index.html?mesh=: #hbc-results equals hbc analyze --json minus timings', { timeout: 180_000 }, async () => {
  const { page, errors, close } = await openPage(`${origin}/index.html?mesh=teapot.hedra`);
  assert.equal(await settled(page), 'ready', await page.locator('#hbc-error').textContent());
  assertSameResults(await pageResults(page), expectedResults('teapot.hedra'));
  assert.deepEqual(errors, []);
  await close();
});

test('a generated mesh with pyramids: #hbc-results equals hbc analyze --json', { timeout: 180_000 }, async () => {
  const want = expectedResults('split.mesh');
  assert.ok(JSON.stringify(want).length > 0);
  const info = JSON.parse(hbc(['info', '--json', 'split.mesh']));
  assert.ok(JSON.stringify(info).includes('pyramid'), 'the generated mesh holds pyramids');
  const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=split.mesh`);
  assert.equal(await settled(page), 'ready', await page.locator('#hbc-error').textContent());
  assertSameResults(await pageResults(page), want);
  assert.deepEqual(errors, []);
  await close();
});

test('the canvas shows the mesh, and moving the slicing plane changes the picture', { timeout: 180_000 }, async () => {
  const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=teapot.hedra`);
  assert.equal(await settled(page), 'ready');
  // Not blank: at least 2% of the pixels are not the background colour, in more than 16 colours.
  const drawn = (img) => { const s = nonBackgroundShare(img); return s.share > 0.02 && s.colours > 16; };
  await shotUntil(page, drawn, 'the mesh');
  await page.locator('#plane-on').check();
  const setPlane = (t) => page.evaluate((t) => {
    const input = document.getElementById('plane-pos');
    input.value = String(t);
    input.dispatchEvent(new Event('input', { bubbles: true }));
  }, t);
  await setPlane(0.7);
  const cutAt07 = await stableShot(page);
  assert.ok(drawn(cutAt07), 'the cut mesh is drawn');
  await setPlane(0.3);
  // Moved: more than 0.5% of the pixels change colour.
  await shotUntil(page, (img) => changedShare(cutAt07, img) > 0.005, 'a change after moving the plane');
  assert.deepEqual(errors, []);
  await close();
});

test('a page written by hbc export-html opens from file:// with the same #hbc-results', { timeout: 180_000 }, async () => {
  mkdirSync(join(work, 'exported'), { recursive: true });
  // The viewer found through HBC_VIEWER for one, --viewer for the others. An OpenFOAM case (a
  // folder) is embedded as one .ovm file: its results are the case's, under the embedded name.
  hbc(['export-html', 'teapot.hedra', '-o', 'exported/teapot.html'], { env: { ...process.env, HBC_VIEWER: VIEWER } });
  hbc(['export-html', 'split.mesh', '-o', 'exported/split.html', '--viewer', VIEWER]);
  hbc(['export-html', 'hex2_ascii', '-o', 'exported/foam.html', '--viewer', VIEWER]);
  const foam = { ...expectedResults('hex2_ascii'), file: 'hex2_ascii.ovm' };
  for (const [page_name, want] of [['teapot', expectedResults('teapot.hedra')], ['split', expectedResults('split.mesh')],
                                   ['foam', foam]]) {
    const { page, errors, close } = await openPage(pathToFileURL(join(work, 'exported', page_name + '.html')).href);
    assert.equal(await settled(page), 'ready', await page.locator('#hbc-error').textContent());
    assertSameResults(await pageResults(page), want);
    assert.deepEqual(errors, [], page_name);
    await close();
  }
});

// An idle page warms the core up (web/src/warmup.js). A file picked while the warm-up runs stops
// it and opens with the CLI's results; on a fresh page, a file picked after the warm-up opens
// likewise. The page reports how long the worker took from the file's bytes to the counts.
test('the idle page warms the core up; a file picked during or after it opens with the CLI results', { timeout: 180_000 }, async () => {
  const want = expectedResults('split.mesh');
  const during = await openPage(`${origin}/viewer.html`);
  assert.equal(await during.page.evaluate(() => document.body.dataset.state), 'idle');
  await during.page.locator('#file').setInputFiles(join(work, 'split.mesh'));
  assert.equal(await settled(during.page), 'ready', await during.page.locator('#hbc-error').textContent());
  assertSameResults(await pageResults(during.page), want);
  // Picked at once, the file stopped the warm-up (or came just after its end); either way the
  // warm-up said so before the file was opened.
  const warm = await during.page.evaluate(() => document.body.dataset.warmup);
  assert.ok(['stopped', 'done'].includes(warm), `data-warmup is ${warm}`);
  assert.deepEqual(during.errors, []);
  await during.close();

  const after = await openPage(`${origin}/viewer.html`);
  await after.page.waitForFunction(() => ['done', 'failed'].includes(document.body.dataset.warmup), null, { timeout: LOAD_TIMEOUT });
  const body = await after.page.evaluate(() => ({ ...document.body.dataset }));
  assert.equal(body.warmup, 'done', body.warmupError);
  assert.ok(Number(body.warmupSeconds) > 0, `data-warmup-seconds ${body.warmupSeconds}`);
  assert.equal(body.state, 'idle', 'the warm-up leaves the page idle');
  await after.page.locator('#file').setInputFiles(join(work, 'split.mesh'));
  assert.equal(await settled(after.page), 'ready', await after.page.locator('#hbc-error').textContent());
  assertSameResults(await pageResults(after.page), want);
  const seconds = Number(await after.page.locator('#hbc-results').getAttribute('data-open-seconds'));
  assert.ok(seconds > 0 && seconds < LOAD_TIMEOUT / 1000, `data-open-seconds ${seconds}`);
  assert.deepEqual(after.errors, []);
  await after.close();
});

test('a broken file shows the CLI error text with file and line; then a good file opens', { timeout: 180_000 }, async () => {
  const message = cliError('broken.mesh');
  assert.match(message, /^broken\.mesh:\d+/, 'the CLI names file and line');
  const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=broken.mesh`);
  assert.equal(await settled(page), 'error');
  const shown = await page.locator('#hbc-error').textContent();
  assert.ok(shown.includes(message), `#hbc-error says\n  ${shown}\nthe CLI says\n  ${message}`);
  assert.equal(await page.locator('#hbc-error').isVisible(), true);
  // The page keeps working: a good file through the file picker.
  await page.locator('#file').setInputFiles(TEAPOT);
  await page.waitForFunction(() => document.body.dataset.state !== 'error', null, { timeout: LOAD_TIMEOUT });
  assert.equal(await settled(page), 'ready', await page.locator('#hbc-error').textContent());
  assertSameResults(await pageResults(page), expectedResults('teapot.hedra'));
  assert.equal(await page.locator('#hbc-error').isVisible(), false);
  assert.deepEqual(errors, []);
  await close();
});

// -- the numbers on screen (issue 62) -------------------------------------------------------------
// The rows of the sheet list, the legend's entries, Table 1's rows, the subsheet list.
async function shownCounts(page) {
  return page.evaluate(() => ({
    sheetRows: document.querySelectorAll('#sheet-rows tr').length,
    sheetCount: document.getElementById('sheet-count').textContent,
    legend: document.querySelectorAll('#legend li').length,
    table1: document.querySelectorAll('#table1 tr').length,
    subsheets: document.querySelectorAll('#subsheet-list li').length,
    results: document.getElementById('hbc-results').textContent,
  }));
}

test('a refused file after teapot: teapot\'s sheets, legend and Table 1 row are gone', { timeout: 180_000 }, async () => {
  const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=teapot.hedra`);
  assert.equal(await settled(page), 'ready');
  const teapot = await shownCounts(page);
  assert.equal(teapot.sheetRows, 23, 'teapot has 23 sheets');
  assert.ok(teapot.legend > 0 && teapot.table1 === 2, JSON.stringify(teapot));
  await page.locator('#file').setInputFiles(join(work, 'broken.mesh'));
  await page.waitForFunction(() => document.body.dataset.state === 'error', null, { timeout: LOAD_TIMEOUT });
  assert.equal(await page.locator('#mesh-name').textContent(), 'broken.mesh');
  assert.ok((await page.locator('#hbc-error').textContent()).includes(cliError('broken.mesh')));
  assert.deepEqual(await shownCounts(page), { sheetRows: 0, sheetCount: '', legend: 0, table1: 0, subsheets: 0, results: '' });
  assert.deepEqual(errors, []);
  await close();
});

// Table 1 on the page against `hbc table --md` for the same file: every column but the times (the
// page's are in whole ms of its own run) reads the same, a ratio of exactly 1 as 1.0000.
test('Table 1 on the page prints counts and ratios as hbc table does', { timeout: 180_000 }, async () => {
  for (const name of ['grid.mesh', 'teapot.hedra']) {
    const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=${name}`);
    assert.equal(await settled(page), 'ready');
    const [head, row] = await page.evaluate(() => [...document.querySelectorAll('#table1 tr')]
      .map((tr) => [...tr.children].map((c) => c.textContent)));
    const md = hbc(['table', name, '--md']).trim().split('\n');
    const timing = row.map((t) => / ms$/.test(t));
    // The same columns in the same order (hbc table marks the times' heads " ms").
    assert.equal(md[0], `| mesh | ${head.map((h, i) => (timing[i] ? `${h} ms` : h)).join(' | ')} |`);
    const cli = md[2].replace(/^\| | \|$/g, '').split(' | ').slice(1);
    assert.equal(cli.length, row.length);
    const shown = row.filter((_, i) => !timing[i]);
    assert.deepEqual(shown, cli.filter((_, i) => !timing[i]), name);
    if (name === 'grid.mesh') assert.ok(shown.includes('1.0000'), `a ratio of 1 reads 1.0000: ${shown}`);
    assert.deepEqual(errors, [], name);
    await close();
  }
});

// An OpenFOAM case picked through "Open file…" (the .foam marker and the polyMesh files, or only the
// polyMesh files) or "Open folder…": the case's results, named after the case.
test('an OpenFOAM case picked as files or as a folder opens with the CLI results, named after the case', { timeout: 180_000 }, async () => {
  const cases = [
    ['#file', ['hex2_ascii/hex2_ascii.foam', ...['boundary', 'faces', 'neighbour', 'owner', 'points'].map((f) => `hex2_ascii/constant/polyMesh/${f}`)], 'hex2_ascii', 'hex2_ascii'],
    ['#file', ['boundary', 'faces', 'neighbour', 'owner', 'points'].map((f) => `hex2_gzip/constant/polyMesh/${f}.gz`), 'hex2_gzip', 'polyMesh'],
    // The folder itself (the work folder's link to it is not followed by the picker).
    ['#folder', join(ROOT, 'tests/data/formats/foam/hex2_ascii'), 'hex2_ascii', 'hex2_ascii'],
  ];
  const page0 = await openPage(`${origin}/viewer.html?warmup=0,0,0`);
  for (const [input, files, dir, name] of cases) {
    const { page } = page0;
    await page.locator(input).setInputFiles(Array.isArray(files) ? files.map((f) => join(work, f)) : files);
    // The name is set as the files go to the worker.
    await page.waitForFunction((n) => document.getElementById('mesh-name').textContent === n, name)
      .catch(async () => assert.fail(`${input} ${files}: the mesh is named "${await page.locator('#mesh-name').textContent()}", not "${name}"`));
    assert.equal(await settled(page), 'ready', `${input} ${files}: ${await page.locator('#hbc-error').textContent()}`);
    assertSameResults(await pageResults(page), { ...expectedResults(dir), file: name });
    assert.equal(await page.locator('#mesh-name').textContent(), name);
  }
  assert.deepEqual(page0.errors, []);
  await page0.close();
});

// Teapot's sheet 2 (self-intersecting) has 4 subsheets; picked with the subsheets layer on, they
// lie side by side along x. Every point of every subsheet (and of its wireframe beneath) projects
// into the canvas: at first show, and after the camera moved and "Reset view" was clicked.
async function subsheetsInFrame(page) {
  return page.evaluate(() => {
    const v = window.hbcViewer.viewer;
    const cam = v.camera;
    cam.updateMatrixWorld();
    const group = v.layers.get('subsheets');
    let worst = 0;
    let parts = 0;
    group.traverse((o) => {
      if (!o.geometry) return;
      parts++;
      const p = o.geometry.getAttribute('position');
      const q = cam.position.clone();
      for (let i = 0; i < p.count; i++) {
        q.set(p.getX(i), p.getY(i), p.getZ(i)).add(o.position).project(cam);
        worst = Math.max(worst, Math.abs(q.x), Math.abs(q.y));
      }
    });
    return { worst, parts };
  });
}

async function teapotSubsheets(page) {
  await page.locator('#sheet-rows tr[data-sheet="2"]').click();
  await page.locator('input[data-layer="subsheets"]').check();
  await page.waitForFunction(() => document.querySelectorAll('#subsheet-list li').length === 4 &&
    window.hbcViewer.viewer.layers.has('subsheets'), null, { timeout: LOAD_TIMEOUT });
}

test('subsheets side by side are all in frame at first show and after Reset view', { timeout: 180_000 }, async () => {
  const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=teapot.hedra`);
  assert.equal(await settled(page), 'ready');
  assert.equal(await page.locator('#spread').isChecked(), true, 'side by side is the default');
  await teapotSubsheets(page);
  const first = await subsheetsInFrame(page);
  assert.ok(first.parts >= 8, `4 subsheets and their wireframes: ${first.parts} parts`);
  assert.ok(first.worst <= 1, `at first show a subsheet reaches ${first.worst} (1: the canvas edge)`);
  // Closer to the mesh's centre, then back.
  await page.evaluate(() => {
    const v = window.hbcViewer.viewer;
    const t = v.controls.target;
    v.setView([t.x, t.y, t.z + v.size * 0.3, t.x, t.y, t.z, 0, 1, 0]);
  });
  assert.ok((await subsheetsInFrame(page)).worst > 1, 'the moved camera leaves subsheets out');
  await page.locator('#reset-view').click();
  const reset = await subsheetsInFrame(page);
  assert.ok(reset.worst <= 1, `after Reset view a subsheet reaches ${reset.worst}`);
  assert.deepEqual(errors, []);
  await close();
});

// The colour each subsheet k is drawn in differs from sheet k's (the sheets layer's), and the
// subsheet list's swatches differ from the sheet list's.
test('subsheet k and sheet k are drawn in different colours', { timeout: 180_000 }, async () => {
  const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=teapot.hedra`);
  assert.equal(await settled(page), 'ready');
  await teapotSubsheets(page);
  await page.locator('input[data-layer="sheets"]').check();
  await page.waitForFunction(() => window.hbcViewer.viewer.layers.has('sheets'), null, { timeout: LOAD_TIMEOUT });
  const drawn = await page.evaluate(() => {
    const layers = window.hbcViewer.viewer.layers;
    const sheets = layers.get('sheets').children.find((o) => o.isMesh).userData.part;
    const out = [];
    for (let k = 0; k < 4; k++) {
      const sub = layers.get('subsheets').children.find((o) => o.name === `subsheet ${k}`).userData.part;
      const v = sheets.owner.indexOf(k);
      out.push({ sheet: [...sheets.color.slice(3 * v, 3 * v + 3)], subsheet: [...sub.color.slice(0, 3)] });
    }
    return out;
  });
  drawn.forEach((c, k) => assert.notDeepEqual(c.subsheet, c.sheet, `subsheet ${k} and sheet ${k}: ${JSON.stringify(c)}`));
  const swatch = (sel) => page.evaluate((sel) => [...document.querySelectorAll(sel)].map((e) => e.style.background), sel);
  const subs = await swatch('#subsheet-list .sw');
  for (let k = 0; k < subs.length; k++) {
    const sheet = await swatch(`#sheet-rows tr[data-sheet="${k}"] .sw`);
    assert.notEqual(subs[k], sheet[0], `swatches of subsheet ${k} and sheet ${k}`);
  }
  assert.deepEqual(errors, []);
  await close();
});

// A file with invalid cells: refused, then opened once "Skip invalid cells" is ticked, with the
// results of `hbc analyze --skip-invalid --json` and the CLI's warnings (how many cells were
// dropped). A page written by `hbc export-html --skip-invalid` says the same.
test('skip invalid cells: the tick box, and a page made by hbc export-html --skip-invalid, say what was dropped', { timeout: 180_000 }, async () => {
  const name = 'defects.HYBRID';
  const refused = spawnSync(CLI, ['analyze', name], { cwd: work, encoding: 'utf8' });
  assert.equal(refused.status, 2);
  const r = spawnSync(CLI, ['analyze', '--skip-invalid', '--json', name], { cwd: work, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const want = JSON.parse(r.stdout);
  delete want.timings;
  assert.ok(want.dropped.count > 0);
  // The CLI's warnings, without "hbc: warning: ".
  const warnings = r.stderr.trim().split('\n').map((l) => l.replace(/^hbc: warning: /, ''));
  assert.ok(warnings.some((w) => w.startsWith(`${name}: ${want.dropped.count} cell(s) dropped (`)), r.stderr);

  const { page, errors, close } = await openPage(`${origin}/viewer.html?mesh=${name}`);
  assert.equal(await settled(page), 'error');
  assert.ok((await page.locator('#hbc-error').textContent()).includes(cliError(name)));
  await page.locator('#skip-invalid').check();
  await page.waitForFunction(() => document.body.dataset.state !== 'error', null, { timeout: LOAD_TIMEOUT });
  assert.equal(await settled(page), 'ready', await page.locator('#hbc-error').textContent());
  assertSameResults(await pageResults(page), want);
  assert.equal(await page.locator('#hbc-warnings').textContent(), warnings.join('\n'));
  assert.equal(await page.locator('#hbc-warnings').isVisible(), true);
  // Unticked: the file is refused again, and nothing of the dropped run stays.
  await page.locator('#skip-invalid').uncheck();
  assert.equal(await settled(page), 'error');
  assert.equal(await page.locator('#hbc-warnings').isVisible(), false);
  assert.deepEqual(errors, []);
  await close();

  mkdirSync(join(work, 'exported'), { recursive: true });
  hbc(['export-html', name, '--skip-invalid', '-o', 'exported/defects.html', '--viewer', VIEWER], { stdio: 'pipe' });
  const exported = await openPage(pathToFileURL(join(work, 'exported', 'defects.html')).href);
  assert.equal(await settled(exported.page), 'ready', await exported.page.locator('#hbc-error').textContent());
  // The page reads the kept cells (written as .ovm): the analysis of --skip-invalid, no dropped key.
  const { dropped, ...kept } = want;
  assertSameResults(await pageResults(exported.page), { ...kept, file: 'defects.ovm' });
  assert.equal(await exported.page.locator('#hbc-warnings').textContent(), warnings.join('\n'));
  assert.deepEqual(exported.errors, []);
  await exported.close();
});
