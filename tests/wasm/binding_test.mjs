// The JavaScript binding under node: load teapot from bytes, compare info_json with `hbc info
// --json` (the same text), analyze, and compare stats_json with `hbc analyze --json` of the same
// file (every key but timings); then the arrays' sizes against the
// stats, a block soup, the wireframe, and a malformed file's error text against the CLI's; a file
// with invalid cells read with skip_invalid (JSON and warnings against the CLI's); the generator the
// viewer warms up with, and the warm-up itself (web/src/warmup.js); what web/src/core.js asks the
// module for.
//   node tests/wasm/binding_test.mjs HBC_CORE_JS HBC_CLI MESH_DIR
// HBC_CLI is the native hbc or `node .../hbc.js` run through a wrapper; prints "N passed, N failed".
import { execFileSync, spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { createRequire } from 'node:module';
import { basename, dirname, join } from 'node:path';
import { tmpdir } from 'node:os';
import { Core } from '../../web/src/core.js';
import { cylinderHedra, warmUpSteps, WARM_UP } from '../../web/src/warmup.js';

const [coreJs, cli, dataDir] = process.argv.slice(2);
const require = createRequire(import.meta.url);
const createHbcModule = require(coreJs);
let passed = 0, failed = 0;
function check(what, ok, detail = '') {
  if (ok) passed++; else { failed++; console.log(`FAIL ${what} ${detail}`); }
}
function noTimings(x) {
  if (Array.isArray(x)) return x.map(noTimings);
  if (x && typeof x === 'object')
    return Object.fromEntries(Object.entries(x).filter(([k]) => k !== 'timings').map(([k, v]) => [k, noTimings(v)]));
  return x;
}
function runCli(args) {
  try { return { out: execFileSync(cli, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] }), err: '' }; }
  catch (e) { return { out: '', err: String(e.stderr) }; }
}

const M = await createHbcModule();
const teapot = join(dataDir, 'hybrid-base-complex', 'teapot.hedra');
// The CLI runs in the file's folder on its bare name, the name the binding is given.
const cliStats = JSON.parse(execFileSync(cli, ['analyze', '--json', '--threads', '1', basename(teapot)],
                                         { cwd: dirname(teapot), encoding: 'utf8' }));
const mesh = M.load(readFileSync(teapot), basename(teapot), false);
// info_json is `hbc info --json`'s text, byte for byte (one writer in the library, hbc/report.hpp).
const cliInfo = execFileSync(cli, ['info', '--json', basename(teapot)], { cwd: dirname(teapot), encoding: 'utf8' });
check('info_json = hbc info --json, byte for byte', mesh.info_json() === cliInfo,
      `\n  js:  ${mesh.info_json()}\n  cli: ${cliInfo}`);
const a = mesh.analyze({ level: 'complex', subsheet_rule: 'layers' });
const stats = JSON.parse(a.stats_json());
check('stats equal to the CLI', JSON.stringify(noTimings(stats)) === JSON.stringify(noTimings(cliStats)),
      `\n  js:  ${JSON.stringify(noTimings(stats))}\n  cli: ${JSON.stringify(noTimings(cliStats))}`);
check('cells', mesh.num_cells === cliStats.cells);
check('points', mesh.points.length === 3 * mesh.num_vertices && mesh.points instanceof Float32Array);
check('cell_types', mesh.cell_types.length === mesh.num_cells && mesh.cell_types instanceof Uint8Array);
check('components', a.num_components === cliStats.components && a.cell_component.length === mesh.num_cells);
check('singularities', a.num_singularities === cliStats.singularities &&
      a.chain_vertices_offsets.length === cliStats.singularities + 1 && a.chain_valence.length === cliStats.singularities);
check('curves', a.num_curves === cliStats.curves && a.curve_vertices_offsets.length === cliStats.curves + 1);
check('sheets', a.num_sheets === cliStats.sheets && a.sheet_type.length === cliStats.sheets);
const w = a.wireframe();
check('wireframe', w.count === cliStats.wireframe_edges && w.point_opacity.length === w.polylines_items.length &&
      w.non_hex_offsets.length === w.count + 1);
const soup = a.block_soup('components', -1, 0.1);
check('block soup', soup.face_owner.length === soup.face_vertices_offsets.length - 1 &&
      soup.positions.length === 3 * soup.point_vertex.length && soup.face_owner.every((o) => o < a.num_components));
const pl = M.polylines(mesh, w.polylines_offsets, w.polylines_items);
check('polylines', pl.length === 3 * w.polylines_items.length);
const nBoundary = mesh.face_boundary.reduce((n, b) => n + b, 0);
const kept = M.kept_surface_soup(mesh, new Uint8Array(mesh.num_cells).fill(1), 0);
check('kept surface of every cell is the boundary', kept.face_owner.length === nBoundary);
check('cell centroids', M.cell_centroids(mesh).length === 3 * mesh.num_cells);
check('formats', JSON.parse(M.FORMATS()).some((f) => f.extension === '.hedra'));
const table1 = JSON.parse(M.TABLE1_COLUMNS_json());
check('Table 1 columns', table1.length > 0 && table1.every((c) => 'key' in c && 'notation' in c && 'timing' in c));
// The picked sheet's highlights and a sheet's own wireframe, against `hbc sheets --json` and
// `hbc wireframe --sheet 2 --json` (teapot's sheet 2 is self-intersecting: every highlight occurs).
const cliSheets = JSON.parse(execFileSync(cli, ['sheets', '--json', '--threads', '1', basename(teapot)],
                                          { cwd: dirname(teapot), maxBuffer: 1 << 28 }).toString()).sheets;
const rowLength = (offsets, i) => offsets[i + 1] - offsets[i];
const highlights = [['unmatched_vertices', 'unmatched_vertices'], ['shared_vertices', 'shared_vertices'],
                    ['self_parallel_curves', 'self_parallel_curves'],
                    ['self_intersecting_components', 'self_intersecting_blocks']];
for (const [name, key] of highlights) {
  const offsets = a[`sheet_${name}_offsets`];
  check(`sheet_${name}`, offsets.length === a.num_sheets + 1 && a[`sheet_${name}_items`].length === offsets[a.num_sheets] &&
        Object.entries(cliSheets).every(([i, s]) => rowLength(offsets, Number(i)) === s[key]));
}
const sub = a.subsheets(2);
check('subsheet highlights', Object.entries(cliSheets['2'].subsheets).every(([k, s]) =>
      rowLength(sub.subsheet_unmatched_vertices_offsets, Number(k)) === s.unmatched_vertices &&
      rowLength(sub.subsheet_shared_vertices_offsets, Number(k)) === s.shared_vertices));
const cliWire = JSON.parse(execFileSync(cli, ['wireframe', '--sheet', '2', '--json', '--threads', '1', basename(teapot)],
                                        { cwd: dirname(teapot), maxBuffer: 1 << 28 }).toString());
const sheetWire = a.wireframe(2, -1);
check('wireframe of a sheet', sheetWire.count === cliWire.wireframe_edges && sheetWire.count !== w.count);
check('wireframe(-1, -1) is the whole mesh', a.wireframe(-1, -1).count === w.count);
const subWire = a.wireframe(2, 0);
check('wireframe of a subsheet', subWire.count > 0 && subWire.count < sheetWire.count);
a.delete();
mesh.delete();
// load_path: a file in the module's file system, as the CLI reads a path.
M.FS.writeFile('/teapot.hedra', readFileSync(teapot));
const byPath = M.load_path('/teapot.hedra');
check('load_path', byPath.num_cells === cliStats.cells);
byPath.delete();
// load_path(path, true): --skip-invalid. A file with refused cells (tests/data/check): the JSON
// (its "dropped" key included) and the warnings are the CLI's.
const defects = join(dirname(new URL(import.meta.url).pathname), '..', 'data', 'check', 'defects.HYBRID');
M.FS.writeFile('/defects.HYBRID', readFileSync(defects));
let refused = '';
try { M.load_path('/defects.HYBRID'); } catch (e) { refused = String(e.message); }
check('load_path refuses invalid cells', refused.includes('--skip-invalid'), refused);
// Exodus II and CGNS are listed (the picker takes them) but the core has neither library: the
// message says they need the desktop tool.
const formats = JSON.parse(M.FORMATS());
check('FORMATS lists Exodus II and CGNS', ['.exo', '.e', '.g', '.cgns'].every((x) => formats.some((f) => f.extension === x)));
for (const name of ['/slab.exo', '/slab.cgns']) {
  M.FS.writeFile(name, readFileSync(join(dirname(new URL(import.meta.url).pathname), '..', 'data', 'formats', 'real',
                                         name === '/slab.exo' ? 'slab_hdf5.exo' : 'slab.cgns')));
  let why = '';
  try { M.load_path(name); } catch (e) { why = String(e.message); }
  check(`${name} needs the desktop tool`, why.includes('need the desktop tool'), why);
}
const skipped = M.load_path('/defects.HYBRID', true);
const skippedStats = JSON.parse(skipped.analyze({}).stats_json());
const cliSkip = JSON.parse(execFileSync(cli, ['analyze', '--json', '--skip-invalid', 'defects.HYBRID'],
                                        { cwd: dirname(defects), encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }));
check('load_path skip_invalid: stats_json as hbc analyze --skip-invalid --json',
      JSON.stringify(noTimings({ ...skippedStats, file: 'defects.HYBRID' })) === JSON.stringify(noTimings(cliSkip)));
const cliWarnings = (() => {
  const r = spawnSync(cli, ['analyze', '--skip-invalid', 'defects.HYBRID'], { cwd: dirname(defects), encoding: 'utf8' });
  return r.stderr.trim().split('\n').map((l) => l.replace(/^hbc: warning: defects\.HYBRID: /, ''));
})();
check('warnings as the CLI says them', JSON.stringify(skipped.warnings) === JSON.stringify(cliWarnings),
      `${JSON.stringify(skipped.warnings)} against ${JSON.stringify(cliWarnings)}`);
skipped.delete();

// generate_cylinder(2, 1): a = ceil(2 / 2) = 1, so a 2x2 quad core (9 vertices, 8 on its boundary)
// and one ring of 4 round(2 pi 2 / 4) = 12 vertices: 8 quads on the core's 8 edges and 12 - 8 = 4
// triangles; one layer: 12 hexes + 4 prisms, 2 (9 + 12) = 42 vertices; 2D edges 21 + 16 - 1 = 36
// (Euler), faces 16 * 2 + 36 = 68; cell rows hold 2 + 4 faces per hex, 2 + 3 per prism: 92.
const g = M.generate_cylinder(2, 1);
check('generate_cylinder arrays', g.points.length === 3 * 42 && g.faces_offsets.length === 69 &&
      g.cells_offsets.length === 17 && g.cells_items.length === 92 && g.faces_items.length === g.faces_offsets[68]);
// Written as .hedra and read back: the mesh `hbc generate cylinder` writes, as `hbc info` sees it.
const cyl = M.load(Buffer.from(cylinderHedra(M, 2, 1)), 'cylinder.hedra', false);
const cylInfo = JSON.parse(cyl.info_json());
const cylDir = mkdtempSync(join(tmpdir(), 'hbc-js-'));
execFileSync(cli, ['generate', 'cylinder', '--radius-cells', '2', '--layers', '1', '-o', 'cylinder.mesh'], { cwd: cylDir, stdio: 'pipe' });
const cliCyl = JSON.parse(execFileSync(cli, ['info', '--json', 'cylinder.mesh'], { cwd: cylDir, encoding: 'utf8' }));
delete cylInfo.file;
delete cliCyl.file;
// The mesh the viewer warms up with is the one `hbc generate cylinder` writes: every count equal.
check('cylinder as .hedra = hbc generate cylinder', JSON.stringify(cylInfo) === JSON.stringify(cliCyl) &&
      cylInfo.cells === 16 && cylInfo.cell_types.hex === 12 && cylInfo.cell_types.prism === 4,
      `\n  js:  ${JSON.stringify(cylInfo)}\n  cli: ${JSON.stringify(cliCyl)}`);
cyl.delete();
// web/src/core.js asks the module only for what it exports, and each function once (it probed for
// load_case, analysis_json, analyze_json, block_soup and lastError, none of which the core has ever
// exported, and for stats_json twice).
const coreSrc = readFileSync(new URL('../../web/src/core.js', import.meta.url), 'utf8');
const moduleNames = new Set([...coreSrc.matchAll(/\bM\.([A-Za-z_]\w*)/g)].map((x) => x[1]));
const notExported = [...moduleNames].filter((n) => !(n in M));
check('core.js names only what the module exports', notExported.length === 0, notExported.join(', '));
const probes = [...coreSrc.matchAll(/typeof\s+([\w.]+)\s*===\s*'function'/g)].map((x) => x[1]);
check('core.js probes each function once', new Set(probes).size === probes.length, probes.join(', '));
const rounds = [...warmUpSteps(new Core(M))];
check('warm-up: every round', WARM_UP.rounds > 0 && rounds.length === WARM_UP.rounds && rounds.at(-1) === WARM_UP.rounds, JSON.stringify(rounds));
check('no warm-up at 0 rounds', [...warmUpSteps(new Core(M), { radiusCells: 0, layers: 0, rounds: 0 })].length === 0);

// A malformed file: the same message as the CLI's (run in the file's folder on the same name).
const dir = mkdtempSync(join(tmpdir(), 'hbc-js-'));
const bad = 'MeshVersionFormatted 1\nDimension 3\nVertices\n2\n0 0 0 0\n1 x 0 0\nEnd\n';
writeFileSync(join(dir, 'bad.mesh'), bad);
const cliErr = (() => { try { execFileSync(cli, ['info', 'bad.mesh'], { cwd: dir, stdio: 'pipe' }); return ''; }
                        catch (e) { return String(e.stderr).trim(); } })();
let jsErr = '';
try { M.load(Buffer.from(bad), 'bad.mesh', false).delete(); } catch (e) { jsErr = e.message; }
check('error text', jsErr !== '' && cliErr.includes(jsErr), `\n  js:  ${jsErr}\n  cli: ${cliErr}`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
