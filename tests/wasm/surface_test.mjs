// The JavaScript binding surface against its one description in the library (hbc/exports.hpp, the
// module's EXPORTS_json()): every array the module's objects hand out is in the table for
// JavaScript with its typed array and length, every JavaScript entry is handed out, hbc_core.d.ts
// says the same names, types, shapes and deprecations, and analyze() takes the table's options
// (the Python half: tests/python/test_exports.py).
//   node tests/wasm/surface_test.mjs HBC_CORE_JS MESH_DIR HBC_CORE_D_TS
// Prints "N passed, N failed".
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';

const [coreJs, dataDir, dtsPath] = process.argv.slice(2);
const require = createRequire(import.meta.url);
const M = await require(coreJs)();
let passed = 0, failed = 0;
function check(what, ok, detail = '') {
  if (ok) passed++; else { failed++; console.log(`FAIL ${what} ${detail}`); }
}

let table = null;
try { table = JSON.parse(M.EXPORTS_json()); } catch (e) { check('EXPORTS_json', false, String(e)); }
if (!table) { console.log(`${passed} passed, ${failed} failed`); process.exit(1); }
// JavaScript keeps the graph's and the base complex's arrays on Analysis (hbc/exports.hpp).
const jsHolder = (h) => (h === 'SingularityGraph' || h === 'BaseComplex' ? 'Analysis' : h);
const entries = (holder) => table.arrays.filter((a) => a.js && jsHolder(a.holder) === holder);
const halves = (e) => (e.csr ? [`${e.name}_offsets`, `${e.name}_items`] : [e.name]);
const TYPED = { bool: Uint8Array, uint8: Uint8Array, int32: Int32Array, float32: Float32Array, float64: Float64Array };

// teapot: its sheet 2 is self-intersecting, so every object has rows.
const mesh = M.load(readFileSync(join(dataDir, 'hybrid-base-complex', 'teapot.hedra')), 'teapot.hedra', false);
const a = mesh.analyze({});
const stats = JSON.parse(a.stats_json());
const w = a.wireframe();
const sub = a.subsheets(2);
const soup = a.block_soup('components', -1, 0.1);
const gen = M.generate_cylinder(2, 1);  // 42 vertices, 68 faces, 16 cells (binding_test.mjs derives them)
const dims = {
  nv: mesh.num_vertices, ne: mesh.num_edges, nf: mesh.num_faces, nc: mesh.num_cells,
  ns: a.num_singularities, ncomp: a.num_components, ncurve: a.num_curves, npatch: a.num_patches,
  num_sheets: a.num_sheets, npp: w.polylines_offsets[w.count], nsimp: stats.wireframe_edges_simplified,
  np: soup.point_vertex.length, nsf: soup.face_owner.length,
};
const objects = {
  Mesh: [mesh, dims], Analysis: [a, dims], Subsheets: [sub, { ...dims, count: sub.count }],
  Wireframe: [w, { ...dims, count: w.count }], BlockSoup: [soup, dims],
  GeneratedMesh: [gen, { nv: 42, nf: 68, nc: 16 }],
};

// The array properties an object hands out: an embind object's are on its prototype.
function arrayNames(obj) {
  const names = new Set(Object.keys(obj));
  const proto = Object.getPrototypeOf(obj);
  if (proto && proto !== Object.prototype) for (const n of Object.getOwnPropertyNames(proto)) names.add(n);
  return [...names].filter((n) => { try { return ArrayBuffer.isView(obj[n]); } catch (_) { return false; } });
}

for (const [holder, [obj, d]] of Object.entries(objects)) {
  const described = new Set();
  for (const e of entries(holder)) {
    for (const n of halves(e)) described.add(n);
    const rows = d[e.rows];
    if (e.csr) {
      const off = obj[`${e.name}_offsets`], items = obj[`${e.name}_items`];
      check(`${holder}.${e.name} (CSR)`, off instanceof Int32Array && items instanceof Int32Array &&
            off.length === rows + 1 && items.length === off[rows], `rows ${rows}`);
      continue;
    }
    const v = obj[e.name];
    const length = e.width ? e.width * rows : rows;
    check(`${holder}.${e.name}`, v instanceof TYPED[e.dtype] && (e.rows === 'k' || v.length === length),
          `${v && v.constructor.name} of ${v && v.length}, the table: ${e.dtype} (${e.width || ''} ${e.rows}) = ${length}`);
  }
  const handed = arrayNames(obj);
  const extra = handed.filter((n) => !described.has(n));
  const missing = [...described].filter((n) => !handed.includes(n));
  check(`${holder}: handed out = the table's`, extra.length === 0 && missing.length === 0,
        `not in the table: ${extra.join(', ')}; not handed out: ${missing.join(', ')}`);
}
// The deprecated names keep their old values: sheet_types is sheet_type; sheet_blocks holds the
// sheet domain's blocks, at level complex one per hex component, so as many per sheet as sheet_components.
const same = (x, y) => x.length === y.length && x.every((v, i) => v === y[i]);
check('sheet_types = sheet_type', same(a.sheet_types, a.sheet_type) && same(sub.subsheet_types, sub.subsheet_type));
check('sheet_blocks rows = sheet_components rows at level complex', same(a.sheet_blocks_offsets, a.sheet_components_offsets) &&
      same(sub.subsheet_blocks_offsets, sub.subsheet_components_offsets));
check('sheet_components are component ids', a.sheet_components_items.every((c) => c >= 0 && c < a.num_components &&
      a.component_kind[c] !== 3));

// hbc_core.d.ts: per interface, each typed-array property with its shape comment, deprecated or not.
const dts = readFileSync(dtsPath, 'utf8');
const interfaces = Object.fromEntries([...dts.matchAll(/export interface (\w+) \{([\s\S]*?)\n\}/g)].map((m) => [m[1], m[2]]));
const propRe = /^\s*(\/\*\*\s*@deprecated[^*]*\*\/\s*)?(?:readonly\s+)?(\w+): (Int32Array|Uint8Array|Float32Array|Float64Array);\s*\/\/\s*\(([^)]*)\)/gm;
for (const holder of Object.keys(objects)) {
  const body = interfaces[holder] ?? '';
  check(`d.ts interface ${holder}`, body !== '');
  const props = Object.fromEntries([...body.matchAll(propRe)].map((m) => [m[2], { deprecated: !!m[1], type: m[3], shape: m[4] }]));
  const want = {};
  for (const e of entries(holder)) {
    for (const n of halves(e)) {
      const half = n.slice(e.name.length);
      const shape = half === '_offsets' ? `${e.rows} + 1` : half === '_items' ? `${e.name}_offsets[${e.rows}]`
        : e.width ? `${e.width} ${e.rows}` : e.rows;
      want[n] = { deprecated: e.deprecated !== '', type: half ? 'Int32Array' : TYPED[e.dtype].name, shape };
    }
  }
  const names = (o) => Object.keys(o).sort().join(', ');
  check(`d.ts ${holder}: the table's arrays`, names(props) === names(want), `\n  d.ts:  ${names(props)}\n  table: ${names(want)}`);
  for (const [n, p] of Object.entries(want)) {
    const got = props[n];
    check(`d.ts ${holder}.${n}`, got && got.type === p.type && got.shape === p.shape && got.deprecated === p.deprecated,
          `d.ts ${JSON.stringify(got)}, the table ${JSON.stringify(p)}`);
  }
}
check('d.ts: SubsheetSet is the deprecated old name of Subsheets',
      /\/\*\*\s*@deprecated[^*]*\*\/\s*export type SubsheetSet = Subsheets;/.test(dts));

// analyze's options: d.ts's AnalyzeOptions lists the table's, with its types and defaults.
const aliases = Object.fromEntries([...dts.matchAll(/export type (\w+) = ([^;]+);/g)].map((m) => [m[1], m[2].trim()]));
const optRe = /^\s*(\w+)\?: ([^;]+);\s*\/\/\s*default (\S+?)(?::|$)/gm;
const opts = Object.fromEntries([...(interfaces.AnalyzeOptions ?? '').matchAll(optRe)].map((m) => [m[1], { type: m[2].trim(), def: m[3] }]));
check('d.ts AnalyzeOptions: the table\'s keys', Object.keys(opts).join() === table.options.map((o) => o.key).join(),
      `${Object.keys(opts)} against ${table.options.map((o) => o.key)}`);
for (const o of table.options) {
  const got = opts[o.key];
  const type = got && (aliases[got.type] ?? got.type);
  const want = o.type === 'bool' ? 'boolean' : o.type === 'choice' ? o.choices.map((c) => `"${c}"`).join(' | ') : 'number';
  check(`d.ts AnalyzeOptions.${o.key}`, got && type === want && got.def === o.default, `${JSON.stringify(got)}: ${want}, default ${o.default}`);
}
// ... and analyze reads them with the library's reader: its errors, and the options JavaScript
// did not take before (search_steps).
const message = (options) => { try { mesh.analyze(options).delete(); return ''; } catch (e) { return String(e.message); } };
check('unknown option', message({ colour: 'red' }).includes("'colour'"), message({ colour: 'red' }));
check('bad choice', message({ level: 'fine' }) === "level must be one of 'complex', 'mesh', not 'fine'", message({ level: 'fine' }));
check('bad range', message({ rho: 2 }) === 'rho must be in [0, 1], not 2', message({ rho: 2 }));
check('bad type', message({ sheets: 'yes' }) === "sheets must be true or false, not 'yes'", message({ sheets: 'yes' }));
const fewest = mesh.analyze({ subsheet_rule: 'fewest', search_steps: 50, wireframe: false, rho: undefined });
check('search_steps and subsheet_rule taken', fewest.wireframe() === null && fewest.subsheets(2) !== null);
fewest.delete();

a.delete();
mesh.delete();
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
