// hbc gallery's site in a real browser (Debian's chromium, playwright-core), opened from file:// as
// a reader opens a folder: `hbc gallery` makes the site of a small collection of the shared meshes
// laid out model/mesher/file (two meshes of one model, a broken file), thumbnails included (the
// viewer page in headless Chromium). The index shows one row per mesh with its thumbnail, sorts by
// a column, filters by text, tag and range; a row opens the mesh in the site's viewer (analysed:
// the same cells as the row); a model's page shows its meshes side by side. No page logs a console
// error or throws.
//
// Run: node tests/web/gallery.test.mjs (ctest web_gallery). Environment as viewer.test.mjs: HBC_CLI,
// HBC_VIEWER, HBC_DATA_DIR, HBC_CHROMIUM; HBC_GALLERY_SHOTS keeps a screenshot of the index there.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const HERE = dirname(fileURLToPath(import.meta.url));
const ROOT = resolve(HERE, '../..');
const VIEWER = resolve(process.env.HBC_VIEWER || join(ROOT, 'build/web/viewer.html'));
const CLI = process.env.HBC_CLI || join(ROOT, 'build/bin/hbc');
const DATA = process.env.HBC_DATA_DIR || resolve(ROOT, '../shared/data');
const CHROMIUM = process.env.HBC_CHROMIUM || '/usr/bin/chromium';
const TIMEOUT = 120_000;

if (!existsSync(VIEWER)) {
  const why = `no viewer page at ${VIEWER}; build it with \`bash scripts/build_web.sh\``;
  if (process.env.HBC_WEB_REQUIRED === '1') {
    console.error(`web_gallery: FAILED: ${why} (HBC_WEB_REQUIRED=1)`);
    process.exit(1);
  }
  console.log(`web_gallery: SKIPPED: ${why}`);
  process.exit(77);
}
const { chromium } = await import('playwright-core');

const work = mkdtempSync(join(tmpdir(), 'hbc-gallerytest-'));
const site = join(work, 'site');
const LAYOUT = {
  'Cylinder/ovm/Cylinder.ovm': 'openvolumemesh/Cylinder.ovm',
  'Cylinder/ovmb/Cylinder.ovmb': 'openvolumemesh/Cylinder.ovmb',
  'teapot/authors/teapot.hedra': 'hybrid-base-complex/teapot.hedra',
  'twistcube/authors/twistcube_s.mesh': 'hybrid-base-complex/twistcube_s.mesh',
};
let browser;

before(async () => {
  const col = join(work, 'collection');
  for (const [rel, src] of Object.entries(LAYOUT)) {
    mkdirSync(dirname(join(col, rel)), { recursive: true });
    symlinkSync(join(DATA, src), join(col, rel));
  }
  mkdirSync(join(col, 'broken/hand'), { recursive: true });
  writeFileSync(join(col, 'broken/hand/broken.mesh'), 'MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n');
  const r = spawnSync(CLI, ['gallery', col, '-o', site, '-j', '2'], {
    encoding: 'utf8', env: { ...process.env, HBC_VIEWER: VIEWER, HBC_CHROMIUM: CHROMIUM },
  });
  // Exit 1: the broken mesh failed, and its row says so; everything else was made.
  assert.equal(r.status, 1, r.stderr);
  assert.match(r.stderr, /5 mesh\(es\), 5 measured, 1 failed; 4 thumbnail\(s\) made in Chromium/);
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist'],
  });
});

after(async () => {
  await browser?.close();
  rmSync(work, { recursive: true, force: true });
});

/** A page whose console errors and uncaught exceptions are collected (asserted empty at the end). */
async function open(url) {
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(url);
  return { page, errors };
}

const indexUrl = pathToFileURL(join(site, 'index.html')).href;
const visibleNames = (page) => page.$$eval('#gallery tbody tr:not([hidden]) td.name', (tds) => tds.map((t) => t.textContent));
const columnValues = (page, key) => page.$$eval('#gallery tbody tr:not([hidden])', (trs, key) => {
  const i = [...document.querySelectorAll('#gallery thead tr:first-child th')].findIndex((th) => th.dataset.key === key);
  return trs.map((tr) => tr.children[i].textContent);
}, key);

test('the index: a row per mesh with its thumbnail, the failure in its row', async () => {
  const { page, errors } = await open(indexUrl);
  await page.waitForSelector('body[data-state="ready"]', { timeout: TIMEOUT });
  assert.deepEqual((await visibleNames(page)).sort(), [...Object.keys(LAYOUT), 'broken/hand/broken.mesh'].sort());
  assert.equal(await page.textContent('#count'), '5 of 5 meshes');
  // Every thumbnail drawn by the viewer, loaded (lazy images: scrolled into view first).
  await page.$$eval('td.thumb img', (imgs) => imgs.forEach((i) => { i.loading = 'eager'; }));
  await page.waitForFunction(() => [...document.querySelectorAll('td.thumb img')].every((i) => i.complete && i.naturalWidth > 0),
    null, { timeout: TIMEOUT });
  assert.equal(await page.locator('td.thumb img').count(), 4);
  assert.match(await page.textContent('tr.failed td.error'), /broken\.mesh/);
  if (process.env.HBC_GALLERY_SHOTS) await page.screenshot({ path: join(process.env.HBC_GALLERY_SHOTS, 'gallery-index.png') });
  assert.deepEqual(errors, []);
});

test('sort by a column both ways, filter by text, tag and range', async () => {
  const { page, errors } = await open(indexUrl);
  await page.waitForSelector('body[data-state="ready"]');
  const cells = (await page.$eval('#gallery-data', (e) => JSON.parse(e.textContent).rows))
    .filter((r) => r.values.cells !== null).map((r) => r.values.cells);
  const asNumbers = (texts) => texts.filter((t) => t !== '–').map((t) => Number(t.replace(/\u2009/g, '')));
  await page.click('th[data-key="cells"]');
  assert.deepEqual(asNumbers(await columnValues(page, 'cells')), [...cells].sort((a, b) => a - b));
  assert.equal((await columnValues(page, 'cells')).at(-1), '–', 'the failed mesh last');
  await page.click('th[data-key="cells"]');
  assert.deepEqual(asNumbers(await columnValues(page, 'cells')), [...cells].sort((a, b) => b - a));
  await page.fill('#filter', 'cylinder');
  assert.deepEqual((await visibleNames(page)).sort(), ['Cylinder/ovm/Cylinder.ovm', 'Cylinder/ovmb/Cylinder.ovmb']);
  await page.fill('#filter', '');
  await page.selectOption('select[data-tag="model"]', 'teapot');
  assert.deepEqual(await visibleNames(page), ['teapot/authors/teapot.hedra']);
  await page.click('#clear');
  const lo = Math.min(...cells);
  await page.fill('input[data-range="cells"]', `>${lo + 1}`);
  assert.equal((await visibleNames(page)).length, cells.filter((c) => c > lo + 1).length);
  await page.fill('input[data-range="cells"]', `..${lo}`);
  assert.equal((await visibleNames(page)).length, cells.filter((c) => c <= lo).length);
  assert.deepEqual(errors, []);
});

test('a row opens its mesh in the viewer, analysed', async () => {
  const { page, errors } = await open(indexUrl);
  await page.waitForSelector('body[data-state="ready"]');
  const row = await page.$eval('#gallery-data', (e) => JSON.parse(e.textContent).rows.find((r) => r.name.endsWith('teapot.hedra')));
  await page.click(`tr[data-id="${row.id}"] a.open`);
  await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.state) && window.hbcViewer?.results,
    null, { timeout: TIMEOUT });
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready');
  const results = JSON.parse(await page.textContent('#hbc-results'));
  assert.equal(results.cells, row.values.cells);
  assert.equal(results.sheets, row.values.sheets);
  assert.equal(await page.textContent('#mesh-name'), 'teapot.hedra');
  assert.deepEqual(errors, []);
});

test("a model's page shows its meshes side by side", async () => {
  const { page, errors } = await open(indexUrl);
  await page.waitForSelector('body[data-state="ready"]');
  await page.selectOption('select[data-tag="model"]', 'Cylinder');
  await page.click('#gallery tbody tr:not([hidden]) a.model');
  await page.waitForSelector('body[data-state="ready"]');
  assert.match(await page.textContent('h1'), /Cylinder/);
  const heads = await page.$$eval('th.mesh a', (as) => as.map((a) => a.textContent));
  assert.deepEqual(heads.sort(), ['Cylinder/ovm/Cylinder.ovm', 'Cylinder/ovmb/Cylinder.ovmb']);
  const cellsRow = await page.$$eval('#side-by-side tbody tr', (trs) => trs.find((tr) => tr.querySelector('th').textContent === '|C|')
    ?.querySelectorAll('td').length);
  assert.equal(cellsRow, 2);
  assert.equal(await page.locator('th.mesh img').count(), 2);
  assert.deepEqual(errors, []);
  assert.ok(readdirSync(join(site, 'models')).length >= 4);
});
