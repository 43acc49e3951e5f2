// The web page's colours and words after the layer plan moved into the library: the core's
// layer_plan_json (what web/build.mjs inlines as web/src/colors.js' L) against
// data/layer_plan_main.json, what the page was given before the move (main at 3ed11c3:
// scripts/export_legend.py, which evaluated the add-on's Python planning, run with the compiled
// module; its "source" and "table1" left out: the page asks the core's schema for Table 1). Every
// key, colour and word the same, and nothing more.
//   node tests/wasm/layer_plan_test.mjs HBC_CORE_JS
// prints "N passed, N failed".
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { isDeepStrictEqual } from 'node:util';

const [coreJs] = process.argv.slice(2);
const here = dirname(fileURLToPath(import.meta.url));
const M = await createRequire(import.meta.url)(resolve(coreJs))();
const plan = JSON.parse(M.layer_plan_json());
const ref = JSON.parse(readFileSync(join(here, 'data', 'layer_plan_main.json'), 'utf8'));
delete ref.source;
delete ref.table1;

let passed = 0, failed = 0;
function check(what, ok, detail = '') {
  if (ok) passed++; else { failed++; console.log(`FAIL ${what} ${detail}`); }
}
check('the same keys', isDeepStrictEqual(Object.keys(plan).sort(), Object.keys(ref).sort()),
      `${Object.keys(plan).sort()} vs ${Object.keys(ref).sort()}`);
for (const key of Object.keys(ref)) {
  check(key, isDeepStrictEqual(plan[key], ref[key]), `\n  core: ${JSON.stringify(plan[key])}\n  main: ${JSON.stringify(ref[key])}`);
}
// The legend per fact in the order the legend lists it: valence 4 (no colour of its own) the
// "other" swatch, each cell type its own.
check('valence 4 is other', plan.legend.valence['4'][0][0] === 'valence_other');
check('tet cells', isDeepStrictEqual(plan.legend.cell_type['1'], [['tet', 'Tet cells']]));
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
