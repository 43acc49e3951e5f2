// What a user of the web viewer waits for, in Debian's chromium driven by playwright-core (as
// tests/web run it, the built page served over HTTP the same way). One request per stdin line,
// one JSON line back, so that wasm_vs_native.py can interleave it with the native runs:
//
//   warm PATH   a fresh page (its own browser context), idle until the worker's warm-up is over
//               (body[data-warmup]), then PATH through the file picker (#file)
//   cold PATH   a fresh page opening PATH by ?mesh= at start: no warm-up
//   warm@R,L,N PATH   as warm, with the page's ?warmup=R,L,N (another warm-up mesh and rounds)
//
// Answer: {open_seconds, warm_up_seconds}; open_seconds is what the page reports in
// #hbc-results[data-open-seconds]: from the file's bytes reaching the worker to the counts.
//
//   node scripts/bench/wasm_page.mjs VIEWER_HTML      (HBC_CHROMIUM: the browser, /usr/bin/chromium)
import { createInterface } from 'node:readline';
import { createServer } from 'node:http';
import { createReadStream, existsSync, mkdtempSync, rmSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { basename, dirname, join, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const VIEWER = resolve(process.argv[2] ?? join(ROOT, 'build/web/viewer.html'));
const CHROMIUM = process.env.HBC_CHROMIUM || '/usr/bin/chromium';
const TIMEOUT = 600_000;
if (!existsSync(VIEWER)) throw new Error(`no viewer page at ${VIEWER}: bash scripts/build_web.sh`);
let chromium;
try {
  ({ chromium } = await import(join(ROOT, 'tests/web/node_modules/playwright-core/index.mjs')));
} catch (e) {
  throw new Error(`playwright-core is not installed: bash tests/web/setup.sh (${e.message})`);
}

// A folder served over HTTP as tests/web/viewer.test.mjs serves it: the page and links to meshes.
const work = mkdtempSync(join(tmpdir(), 'hbc-page-bench-'));
symlinkSync(VIEWER, join(work, 'viewer.html'));
const server = createServer((req, res) => {
  const file = resolve(work, '.' + decodeURIComponent(new URL(req.url, 'http://x').pathname));
  if (!file.startsWith(work + sep) || !existsSync(file)) return res.writeHead(404).end();
  res.writeHead(200, { 'content-type': file.endsWith('.html') ? 'text/html; charset=utf-8' : 'application/octet-stream' });
  createReadStream(file).pipe(res);
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const origin = `http://127.0.0.1:${server.address().port}`;
const browser = await chromium.launch({
  executablePath: CHROMIUM,
  args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist'],
});

async function measure(request, path) {
  const [mode, warmup] = request.split('@');
  const context = await browser.newContext({ viewport: { width: 1200, height: 800 } });
  try {
    const page = await context.newPage();
    let warmUp = null;
    if (mode === 'warm') {
      await page.goto(`${origin}/viewer.html${warmup ? '?warmup=' + warmup : ''}`);
      await page.waitForFunction(() => ['done', 'failed'].includes(document.body.dataset.warmup), null, { timeout: TIMEOUT });
      const w = await page.evaluate(() => ({ ...document.body.dataset }));
      if (w.warmup !== 'done') throw new Error(`the warm-up failed: ${w.warmupError}`);
      warmUp = Number(w.warmupSeconds);
      // HBC_PICK_DELAY_MS: a pause before the pick, as a user's (default none: picked at once).
      await page.waitForTimeout(Number(process.env.HBC_PICK_DELAY_MS || 0));
      await page.locator('#file').setInputFiles(path);
    } else {
      const name = `m${Date.now()}_${basename(path)}`;
      symlinkSync(path, join(work, name));
      await page.goto(`${origin}/viewer.html?mesh=${encodeURIComponent(name)}`);
    }
    // The counts are there (the layers are still being drawn, which is not timed), or an error.
    await page.waitForFunction(() => document.querySelector('#hbc-results').dataset.openSeconds || document.body.dataset.state === 'error',
      null, { timeout: TIMEOUT, polling: 50 });
    const state = await page.evaluate(() => document.body.dataset.state);
    if (state === 'error') throw new Error(`${path}: ${await page.locator('#hbc-error').textContent()}`);
    const seconds = Number(await page.locator('#hbc-results').getAttribute('data-open-seconds'));
    return { open_seconds: seconds, warm_up_seconds: warmUp };
  } finally {
    await context.close();
  }
}

const lines = createInterface({ input: process.stdin });
for await (const line of lines) {
  const [mode, ...rest] = line.trim().split(' ');
  if (!mode) continue;
  try {
    console.log(JSON.stringify(await measure(mode, resolve(rest.join(' ')))));
  } catch (e) {
    console.log(JSON.stringify({ error: String(e.message ?? e) }));
  }
}
await browser.close();
server.close();
rmSync(work, { recursive: true, force: true });
