// Bundles the viewer into one self-contained HTML file: the page's JS (three.js included), the
// worker (the WebAssembly core's JS and, unless it is already inside, its wasm as base64), the
// layer plan (colours, legend words, layers: hbc/layer_plan.hpp, asked of that same core under
// node), and the CSS, all inline.
// usage: node build.mjs --out DIR --wasm DIR (with hbc_core.js + hbc_core.wasm)
import * as esbuild from 'esbuild';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const args = Object.fromEntries(process.argv.slice(2).reduce((acc, a, i, all) => (a.startsWith('--') ? [...acc, [a.slice(2), all[i + 1]]] : acc), []));
const out = path.resolve(args.out ?? path.join(here, '..', 'build', 'web'));
const wasmDir = args.wasm ? path.resolve(args.wasm) : null;

function read(file) {
  return fs.existsSync(file) ? fs.readFileSync(file) : null;
}

const coreJs = wasmDir ? read(path.join(wasmDir, 'hbc_core.js')) : null;
const coreWasm = wasmDir ? read(path.join(wasmDir, 'hbc_core.wasm')) : null;
if (!coreJs) throw new Error(`build.mjs: no hbc_core.js in ${wasmDir}: the page's colours and words come from the core`);

/** The core's layer plan (web/src/colors.js' L): the colours and words the add-on draws with; and
 *  the parts of every layer it requests. */
async function layerPlan() {
  const createHbcModule = createRequire(import.meta.url)(path.join(wasmDir, 'hbc_core.js'));
  const M = await createHbcModule();
  return { legend: JSON.stringify(JSON.parse(M.layer_plan_json())), requests: JSON.stringify(JSON.parse(M.layer_requests_json())) };
}
// What each layer draws (hbc::layer_requests: web/src/parts.js' REQUESTS), from the same core.
const { legend, requests } = await layerPlan();

async function bundle(entry, define) {
  const r = await esbuild.build({
    entryPoints: [path.join(here, 'src', entry)],
    bundle: true,
    format: 'iife',
    minify: true,
    target: ['es2020'],
    write: false,
    legalComments: 'none',
    define: { __HBC_LEGEND__: legend, __HBC_LAYER_REQUESTS__: requests, ...define },
    logLevel: 'warning',
  });
  return r.outputFiles[0].text;
}

/** A JS string literal safe inside an inline <script>: no "</" (it could close the element). */
function literal(text) {
  return JSON.stringify(text).replace(/<\//g, '<\\/').replace(/<!--/g, '<\\!--');
}

const workerJs = await bundle('worker.js', {
  __HBC_WASM_BASE64__: coreWasm ? JSON.stringify(coreWasm.toString('base64')) : '""',
});
const workerSource = (coreJs ? coreJs.toString('utf8') + '\n' : '') + workerJs;
let mainJs = await bundle('main.js', { __HBC_WORKER_SOURCE__: 'HBC_WORKER_SOURCE_PLACEHOLDER' });
if (mainJs.split('HBC_WORKER_SOURCE_PLACEHOLDER').length !== 2) throw new Error('worker placeholder not found exactly once');
if (/<\/script|<!--/i.test(mainJs)) throw new Error('the page bundle holds "</script" or "<!--": it cannot be inlined');
mainJs = mainJs.split('HBC_WORKER_SOURCE_PLACEHOLDER').join(literal(workerSource));

const css = fs.readFileSync(path.join(here, 'src', 'style.css'), 'utf8');
let html = fs.readFileSync(path.join(here, 'src', 'index.html'), 'utf8');
html = html.split('/*HBC_CSS*/').join(css).split('/*HBC_JS*/').join(mainJs);
fs.mkdirSync(out, { recursive: true });
fs.writeFileSync(path.join(out, 'viewer.html'), html);
fs.writeFileSync(path.join(out, 'index.html'), html);
console.log(`${path.join(out, 'viewer.html')}: ${(html.length / 1e6).toFixed(2)} MB${coreJs ? '' : ' (without the WebAssembly core)'}`);
