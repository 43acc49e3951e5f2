// The web page's colours and words after the layer plan moved into the library: the core's
// layer_plan_json (what web/build.mjs inlines as web/src/colors.js' L) against
// data/layer_plan_main.json, what the page was given before the move (main at 3ed11c3:
// scripts/export_legend.py, which evaluated the add-on's Python planning, run with the compiled
// module; its "source" and "table1" left out: the page asks the core's schema for Table 1). Every
// key, colour and word the same, and nothing more. The legend, which the page composed from that
// file's entries per fact, now comes per mesh from the core (legends_json): for arrays with known
// facts, each set of layers gives the entries the page composed from the old file. The one
// intended change since the capture, applied to the file by hand: docs/concepts.md's vocabulary
// (layer `blocks`/"Blocks" → `components`/"Components", `non_hex_block` → `non_hex_component`,
// "Hex component" → "Hex-cell component").
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
const G = ref.legend;  // the old entries per fact
delete ref.legend;

let passed = 0, failed = 0;
function check(what, ok, detail = '') {
  if (ok) passed++; else { failed++; console.log(`FAIL ${what} ${detail}`); }
}
check('the same keys', isDeepStrictEqual(Object.keys(plan).sort(), Object.keys(ref).sort()),
      `${Object.keys(plan).sort()} vs ${Object.keys(ref).sort()}`);
for (const key of Object.keys(ref)) {
  check(key, isDeepStrictEqual(plan[key], ref[key]), `\n  core: ${JSON.stringify(plan[key])}\n  main: ${JSON.stringify(ref[key])}`);
}
// A mesh of hexes, tets and pyramids (cell types 0, 1, 3); a pseudo-singular and a non-manifold
// edge (classes 2, 3); singularities of valence 5, 3, 4 and 3; a non-hex component (kind 3).
const { facts, legends } = JSON.parse(M.legends_json(Uint8Array.from([0, 1, 3, 0]), Uint8Array.from([0, 2, 3, 1]),
                                                     Int32Array.from([5, 3, 4, 3]), Uint8Array.from([0, 3])));
check('facts', isDeepStrictEqual(facts, { non_hex_types: [1, 3], valences: [3, 4, 5], has_pseudo: true,
                                          has_non_manifold: true, has_non_hex_blocks: true }), JSON.stringify(facts));
check('every set of the 7 layers, by class and by kind', Object.keys(legends).length === 2 * 127);
const expected = {
  // The page's composition of the old file (web/src/main.js before the move): legend by fact, then
  // each shown layer's palette entries once, the wireframe's only when coloured by class.
  'direct|0': [...G.direct, ...G.cell_type['1'], ...G.cell_type['3']],
  'graph|0': [...G.valence['3'], ...G.valence['4'], ...G.valence['5'], ...G.pseudo, ...G.non_manifold],
  'components|0': [...G.components, ...G.palette.components],
  'sheets|0': [...G.palette.sheets],
  'sheet,subsheets|0': [...G.highlights, ...G.palette.sheet, ...G.palette.subsheets],
  'wireframe|0': [...G.palette.wireframe],
  'wireframe|1': [...G.wire_kind_type['1'], ...G.wire_kind_type['3'], ...G.wire_kind_rest],
  'direct,subsheets,wireframe|1': [...G.direct, ...G.cell_type['1'], ...G.cell_type['3'], ...G.highlights,
                                   ...G.wire_kind_type['1'], ...G.wire_kind_type['3'], ...G.wire_kind_rest,
                                   ...G.palette.subsheets],
};
for (const [key, entries] of Object.entries(expected)) {
  check(`legend ${key}`, isDeepStrictEqual(legends[key], entries),
        `\n  core: ${JSON.stringify(legends[key])}\n  main: ${JSON.stringify(entries)}`);
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
