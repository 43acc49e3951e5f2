// The WebAssembly binding under node as the viewer's worker runs it: the module loaded once, the
// warm-up of web/src/warmup.js (unless --cold), then one mesh read through the viewer's load path
// (Core.open), analysed and written as `hbc analyze --json`, timed in-process. Prints one JSON line
// {warm_up_seconds, open_seconds}. Called by wasm_vs_native.py (one process per run).
//
//   node scripts/bench/wasm_warm.mjs BUILD_WASM/web/hbc_core.js MESH [--cold | --warmup R,L,N]
// (--warmup: the page's ?warmup=, another cylinder and number of rounds than warmup.js's)
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import { basename, resolve } from 'node:path';
import { performance } from 'node:perf_hooks';
import { Core } from '../../web/src/core.js';
import { warmUpSteps, WARM_UP } from '../../web/src/warmup.js';

const [coreJs, meshPath, flag, size] = process.argv.slice(2);
if (!coreJs || !meshPath) {
  console.error('usage: node wasm_warm.mjs HBC_CORE_JS MESH [--cold]');
  process.exit(2);
}
const createHbcModule = createRequire(import.meta.url)(resolve(coreJs));
const core = new Core(await createHbcModule({ print: () => {}, printErr: (t) => console.error(t) }));
let warm = 0;
if (flag !== '--cold') {
  const t = performance.now();
  const w = flag === '--warmup' ? size.split(',').map(Number) : null;
  for (const _ of warmUpSteps(core, w ? { radiusCells: w[0], layers: w[1], rounds: w[2] } : WARM_UP)) { /* every round */ }
  warm = (performance.now() - t) / 1000;
}
const name = basename(meshPath);
const bytes = readFileSync(meshPath);
const t0 = performance.now();
const mesh = core.open([{ path: name, buffer: bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length) }]);
const analysis = core.analyze(mesh);
const stats = JSON.parse(core.analysisJson(analysis));
const seconds = (performance.now() - t0) / 1000;
if (!(stats.cells > 0)) throw new Error(`${name}: no cells in the analysis`);
console.log(JSON.stringify({ warm_up_seconds: warm, open_seconds: seconds }));
core.free(analysis, mesh);
