// The gallery's index in Chromium (docs/gallery.md, "Speed and size"): the time from navigation to
// the rows drawn (body[data-state="ready"]) and to the load event, a sort and a filter's time, over
// RUNS fresh pages, from file://; with SHOT, a screenshot of the index (1000 x 560) there.
//   node scripts/bench/gallery_page.mjs SITE [RUNS] [SHOT.png]
// playwright-core from tests/web/node_modules (bash tests/web/setup.sh); HBC_CHROMIUM the browser.
import { createRequire } from 'node:module';
import { join, resolve, dirname } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const require = createRequire(join(ROOT, 'tests/web/package.json'));
const { chromium } = require('playwright-core');
const [site, runs = '5', shot] = process.argv.slice(2);
const url = pathToFileURL(join(resolve(site), 'index.html')).href;
const browser = await chromium.launch({ executablePath: process.env.HBC_CHROMIUM || '/usr/bin/chromium',
  args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader'] });
const times = [];
for (let i = 0; i < Number(runs); i++) {
  const page = await browser.newPage({ viewport: { width: 1000, height: 560 } });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(e.message));
  const t0 = Date.now();
  await page.goto(url, { waitUntil: 'load' });
  const loaded = Date.now() - t0;
  await page.waitForSelector('body[data-state="ready"]');
  const rows = await page.locator('#gallery tbody tr').count();
  const t1 = Date.now();
  await page.click('th[data-key="cells"]');
  await page.fill('#filter', 'grid');
  const interact = Date.now() - t1;
  times.push({ loaded, rows, interact, errors: errors.length });
  if (errors.length) console.error(errors);
  if (shot && i === 0) {
    await page.fill('#filter', '');
    await page.click('th[data-key="name"]');
    await page.$$eval('td.thumb img', (imgs) => imgs.forEach((im) => { im.loading = 'eager'; }));
    await page.waitForFunction(() => [...document.querySelectorAll('td.thumb img')].slice(0, 8).every((im) => im.complete));
    await page.screenshot({ path: shot });
  }
  await page.close();
}
await browser.close();
console.log(JSON.stringify(times));
