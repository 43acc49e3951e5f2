// The web viewer draws each layer from the library's requests (hbc::layer_requests, the add-on's
// too: tests/addon/unit/test_layer_requests.py): web/src/parts.js, the worker's builders, given the
// core's layer_requests_json as web/build.mjs inlines it. Its dispatch knows every geometry, lines
// source and colour rule of the table and none of its own; every layer of the plan has parts; and
// on real meshes each layer gives the parts the worker's hand-written builders gave before the
// table (their names and order, derived here from the analysis' arrays), a highlight only where
// the sheet has one.
//   node tests/wasm/layer_requests_test.mjs HBC_CORE_JS HBC_CLI MESH_DIR
// prints "N passed, N failed".
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { basename, join, resolve } from 'node:path';
import { isDeepStrictEqual } from 'node:util';

const [coreJs, cli, dataDir] = process.argv.slice(2);
const M = await createRequire(import.meta.url)(resolve(coreJs))();
globalThis.__HBC_LEGEND__ = JSON.parse(M.layer_plan_json());
globalThis.__HBC_LAYER_REQUESTS__ = JSON.parse(M.layer_requests_json());
const { Core, arr, csr } = await import('../../web/src/core.js');
const { REQUESTS, COLORS, GEOMETRY, LINE_SOURCES, buildLayer } = await import('../../web/src/parts.js');

let passed = 0, failed = 0;
function check(what, ok, detail = '') {
  if (ok) passed++; else { failed++; console.log(`FAIL ${what} ${detail}`); }
}
const same = (a, b) => isDeepStrictEqual([...a].sort(), [...b].sort());

const table = JSON.parse(M.layer_requests_json());
const layers = JSON.parse(M.layer_plan_json()).layers.map(([k]) => k);
check('the worker draws the core\'s table', isDeepStrictEqual(REQUESTS, table));
check('every layer has parts, in the layers\' order',
      isDeepStrictEqual([...new Set(table.map((r) => r.layer))], layers), JSON.stringify(table.map((r) => r.layer)));
check('the colour rules are the table\'s', same(Object.keys(COLORS), new Set(table.map((r) => r.color))),
      `${Object.keys(COLORS)} vs ${[...new Set(table.map((r) => r.color))]}`);
check('the geometries are the table\'s', same(Object.keys(GEOMETRY), new Set(table.map((r) => r.geometry))));
check('the lines sources are the table\'s',
      same(LINE_SOURCES, new Set(table.filter((r) => r.geometry === 'lines').map((r) => r.source))));
check('every role has a legend colour', table.filter((r) => r.color === 'role').every((r) => r.role in __HBC_LEGEND__.legend_colors));

/** What the worker's open() keeps of a mesh (web/src/worker.js). */
function opened(core, path) {
  const mesh = M.load(readFileSync(path), basename(path), false);
  const analysis = core.analyze(mesh);
  const S = { mesh, analysis };
  S.points = Float32Array.from(arr(mesh, 'points'));
  S.cellTypes = Uint8Array.from(arr(mesh, 'cell_types'));
  S.componentKind = Uint8Array.from(arr(core.complex(analysis), 'component_kind'));
  S.sheetType = Uint8Array.from(arr(analysis, 'sheet_type') ?? []);
  return S;
}

const rowOf = (c, r) => c.offsets[r + 1] - c.offsets[r];

/** The parts' names the hand-written builders gave, from the arrays. */
function expected(S, layer, sheet) {
  const a = S.analysis;
  const cls = arr(core.graph(a), 'edge_class');
  switch (layer) {
    case 'direct': return ['boundary', ...(S.cellTypes.some((t) => t !== 0) ? ['non-hex cells'] : [])];
    case 'graph': return ['singularities', ...(cls.includes(2) ? ['pseudo-singular'] : []), ...(cls.includes(3) ? ['non-manifold'] : [])];
    case 'components': return ['components'];
    case 'sheets': return ['sheets'];
    case 'sheet': return ['picked sheet',
      ...[['sheet_unmatched_vertices', 'unmatched'], ['sheet_shared_vertices', 'shared'],
        ['sheet_self_parallel_curves', 'self-parallel'], ['sheet_self_intersecting_components', 'self-intersecting']]
        .filter(([name]) => rowOf(csr(a, name), sheet) > 0).map(([, part]) => part)];
    case 'subsheets': {
      if (S.sheetType[sheet] !== 3) return [];
      const sub = a.subsheets(sheet);
      const un = csr(sub, 'subsheet_unmatched_vertices');
      const out = [];
      for (let k = 0; k < Number(sub.count); k++) {
        out.push(`subsheet ${k}`, ...(rowOf(un, k) ? [`subsheet ${k} unmatched`] : []), `wireframe ${k}`);
      }
      core.free(sub);
      return out;
    }
    default: return ['wireframe'];
  }
}

const core = new Core(M);
const dir = mkdtempSync(join(tmpdir(), 'hbc-requests-'));
execFileSync(cli, ['generate', 'twisted-pair', '--section', '2', '--sections', '8', '-o', join(dir, 'twisted.mesh')], { stdio: 'pipe' });
for (const path of [join(dir, 'twisted.mesh'), join(dataDir, 'hybrid-base-complex', 'teapot.hedra')]) {
  const S = opened(core, path);
  const ctx = { core, S, centroids: () => Float32Array.from(M.cell_centroids(S.mesh)) };
  // The sheets with most highlights first: a self-intersecting one where there is one.
  const sheets = [...S.sheetType.keys()].sort((x, y) => S.sheetType[y] - S.sheetType[x]).slice(0, 3);
  for (const layer of layers) {
    for (const sheet of ['sheet', 'subsheets'].includes(layer) ? sheets : [-1]) {
      const p = { shrink: 0.1, sheet, floor: 0.15, simplified: true, byKind: false, subsheetWires: true };
      const parts = buildLayer(ctx, layer, p);
      const names = parts.map((q) => q.name);
      check(`${basename(path)} ${layer} ${sheet}`, isDeepStrictEqual(names, expected(S, layer, sheet)),
            `\n  parts: ${JSON.stringify(names)}\n  before: ${JSON.stringify(expected(S, layer, sheet))}`);
      if (layer === 'subsheets' && parts.length) {
        check(`${basename(path)} subsheets laid out`, parts.every((q) => q.subsheet >= 0 && q.subsheets.length > 0) &&
              parts.filter((q) => q.below).every((q) => q.kind === 'lines'));
      }
    }
  }
  // The direct view cut by the plane: the core's kept surface takes the boundary's place.
  const cut = buildLayer(ctx, 'direct', { shrink: 0, plane: { axis: 0, pos: 1e30 } });
  check(`${basename(path)} direct cut`, cut[0].name === 'cut' && cut[0].cut === true && !cut.some((q) => q.boundary));
  core.free(S.analysis, S.mesh);
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
