// Each layer's parts as the library requests them (hbc::layer_requests, native/include/hbc/layer_plan.hpp):
// which soup, polylines or dots the core makes for a part, with which options, and how they are
// coloured is decided there once, for the add-on too; web/build.mjs inlines the table
// (layer_requests_json) as REQUESTS. Here only the page's side: the core's calls for each kind of
// request, the buffers (geometry.js), and what the page does on its own (the cut of the direct
// view, the bound on all sheets at once, the names and flags scene.js and main.js read).
/* global __HBC_LAYER_REQUESTS__ */
import { arr, csr, get } from './core.js';
import { L, paletteColor, spreadColor, subsheetColor, componentColor, valenceColor, cellTypeColor, kindColor } from './colors.js';
import { soupPart, linesPart, dotsPart, opacityAlpha, row } from './geometry.js';

export const REQUESTS = __HBC_LAYER_REQUESTS__;

/** The parts of `layer`, in drawing order. */
export function requestsOf(layer) {
  return REQUESTS.filter((r) => r.layer === layer);
}

/** The faces of a soup whose owner is in `keep`, with only the points they use. */
export function selectOwners(soup, keep) {
  const offsets = [0];
  const items = [];
  const owner = [];
  const cell = [];
  const remap = new Map();
  const pos = [];
  for (let f = 0; f < soup.owner.length; f++) {
    if (!keep.has(soup.owner[f])) continue;
    for (let k = soup.offsets[f]; k < soup.offsets[f + 1]; k++) {
      const p = soup.items[k];
      let q = remap.get(p);
      if (q === undefined) {
        q = remap.size;
        remap.set(p, q);
        pos.push(soup.positions[3 * p], soup.positions[3 * p + 1], soup.positions[3 * p + 2]);
      }
      items.push(q);
    }
    offsets.push(items.length);
    owner.push(soup.owner[f]);
    cell.push(soup.cell[f]);
  }
  return { positions: Float32Array.from(pos), offsets: Int32Array.from(offsets), items: Int32Array.from(items), owner: Int32Array.from(owner), cell: Int32Array.from(cell) };
}

/** The request's colour rule as a function of a soup's owner or a polyline's row; `data` holds
 *  what the source read (the chains' valences, the wireframe's arrays). */
export const COLORS = {
  role: (r) => () => L.legend_colors[r.role],
  cell_type: (r, ctx) => (o) => cellTypeColor(ctx.S.cellTypes[o]),
  valence: (r, ctx, data) => (i) => valenceColor(data.valence[i]),
  component: (r, ctx) => (o) => componentColor(o, ctx.S.componentKind[o]),
  spread: () => (o) => spreadColor(o),
  sheet_shaded: (r, ctx, data) => {
    const color = spreadColor(data.sheet);
    return () => color;
  },
  subsheet: () => (o) => subsheetColor(o),
  wire: (r, ctx, data) => (data.kinds ? (i) => kindColor(row(data.kinds, i)) : (i) => paletteColor(data.color[i])),
};

/** Each owner (component) of the picked sheet a little lighter or darker, as the add-on shades it. */
function shadeOf(r) {
  return r.color === 'sheet_shaded' ? (o) => 0.8 + (0.2 * ((o * 7) % 3)) / 2 : null;
}

/** The page's names and flags of a part (scene.js and main.js read them), by layer/part. */
const PRESENT = {
  'direct/boundary': { name: 'boundary', anchorAtPoint: true, pickCell: true, flags: { boundary: true } },
  'direct/non_hex': { name: 'non-hex cells' },
  'graph/singularities': { name: 'singularities' },
  'graph/pseudo': { name: 'pseudo-singular' },
  'graph/non_manifold': { name: 'non-manifold' },
  'components/components': { name: 'components' },
  'sheets/sheets': { name: 'sheets' },
  'sheet/sheet': { name: 'picked sheet' },
  'sheet/unmatched': { name: 'unmatched' },
  'sheet/shared': { name: 'shared' },
  'sheet/self_parallel': { name: 'self-parallel' },
  // Drawn over the picked sheet whatever the cell-type filter hides.
  'sheet/self_intersecting': { name: 'self-intersecting', noCellTypes: true },
  'subsheets/subsheets': { name: 'subsheet {k}' },
  'subsheets/unmatched': { name: 'subsheet {k} unmatched' },
  'subsheets/wireframe': { name: 'wireframe {k}' },
  'wireframe/wireframe': { name: 'wireframe' },
};

function present(r, owner) {
  const p = PRESENT[`${r.layer}/${r.part}`] ?? { name: r.part };
  return { ...p, name: p.name.replace('{k}', String(owner)) };
}

/** The boundary of the cells the plane and the type filter keep (the core's kept surface), when
 *  the page filters the direct view and the core can cut. */
function cutBoundary(ctx, p) {
  const filtered = p.plane || (p.types && p.types.some((on) => !on));
  if (!filtered || !ctx.core.hasCut()) return null;
  const { S } = ctx;
  const cen = ctx.centroids();
  const n = S.cellTypes.length;
  const kept = new Uint8Array(n);
  const ax = p.plane ? p.plane.axis : 0;
  for (let i = 0; i < n; i++) {
    kept[i] = (!p.types || p.types[S.cellTypes[i]]) && (!p.plane || cen[3 * i + ax] <= p.plane.pos) ? 1 : 0;
  }
  const boundary = ctx.core.keptSurface(S.mesh, kept, 0);
  return { ...soupPart(boundary, (o) => cellTypeColor(S.cellTypes[o]), { cellTypes: S.cellTypes, name: 'cut' }), cut: true };
}

/** Every sheet at once is large (a cell is in up to three sheets): bounded. */
function checkAllSheets(ctx, p, soup) {
  const sc = csr(ctx.S.analysis, 'sheet_cells');
  const total = sc.offsets[sc.offsets.length - 1];
  if (total > (p.maxCells ?? 6e6)) {
    throw new Error(`All sheets together hold ${total} cells, too many to draw at once here: pick a sheet instead.`);
  }
  if (soup && soup.owner.length > 4e6) {
    throw new Error(`All sheets together have ${soup.owner.length} faces, too many to draw at once here: pick a sheet instead.`);
  }
}

function soupOf(ctx, r, p, at) {
  const { core, S } = ctx;
  if (r.layer === 'direct' && r.part === 'boundary') {
    const cut = cutBoundary(ctx, p);
    if (cut) return [cut];
  }
  if (r.source === 'sheets') checkAllSheets(ctx, p, null);
  let keep = null;
  if (r.select) {
    keep = row(csr(S.analysis, r.select), at.sheet);
    if (!keep.length) return [];
  }
  // A soup of every owner is asked for once per layer and split here.
  const key = `${r.source}|${r.sheet ? at.sheet : -1}|${r.shrink}`;
  let soup = at.soups.get(key);
  if (!soup) {
    soup = core.blockSoup(S.mesh, S.analysis, r.source, r.sheet ? at.sheet : -1, r.shrink ? p.shrink ?? 0 : 0);
    at.soups.set(key, soup);
  }
  if (r.source === 'sheets') checkAllSheets(ctx, p, soup);
  if (keep) soup = selectOwners(soup, new Set(keep));
  if (r.split === 'owner') soup = selectOwners(soup, new Set([at.owner]));
  const look = present(r, at.owner);
  const colorOf = COLORS[r.color](r, ctx, { sheet: at.sheet });
  const part = soupPart(soup, colorOf, {
    cellTypes: look.noCellTypes ? null : S.cellTypes, shade: shadeOf(r), name: look.name,
    anchorAtPoint: !!look.anchorAtPoint, pickCell: !!look.pickCell,
  });
  return [{ ...part, ...look.flags }];
}

function dotsOf(ctx, r, p, at) {
  const holder = r.split === 'owner' ? at.subsheets() : ctx.S.analysis;
  const vertices = row(csr(holder, r.source), r.split === 'owner' ? at.owner : at.sheet);
  if (!vertices.length) return [];
  return [dotsPart(ctx.S.points, vertices, L.legend_colors[r.role], present(r, at.owner).name)];
}

/** Base-complex curves as polylines of mesh vertices. */
function curveRows(ctx, curves) {
  const offsets = [0];
  const items = [];
  const closed = [];
  if (!(ctx.S.levelMesh ?? false)) {
    const cx = ctx.core.complex(ctx.S.analysis);
    const cv = csr(cx, 'curve_vertices');
    const cc = arr(cx, 'curve_closed');
    for (const c of curves) {
      items.push(...row(cv, c));
      offsets.push(items.length);
      closed.push(!!cc[c]);
    }
  }
  return { offsets: Int32Array.from(offsets), items: Int32Array.from(items), closed };
}

/** The polylines of a lines request: {offsets, items, closed(row), keep(row), alpha, data}. */
const LINES = {
  chains(ctx) {
    const g = ctx.core.graph(ctx.S.analysis);
    const chains = csr(g, 'chain_vertices');
    const closed = arr(g, 'chain_closed');
    return { ...chains, closed: (i) => !!closed[i], data: { valence: arr(g, 'chain_valence') } };
  },
  edges(ctx, r) {
    const cls = arr(ctx.core.graph(ctx.S.analysis), 'edge_class');
    const edges = arr(ctx.S.mesh, 'edges');
    const sel = [];
    for (let e = 0; e < cls.length; e++) if (cls[e] === r.edge_class) sel.push(edges[2 * e], edges[2 * e + 1]);
    return { items: Int32Array.from(sel), offsets: new Int32Array(sel.length / 2 + 1).map((_, i) => 2 * i), data: {} };
  },
  curves(ctx, r, p, at) {
    const c = curveRows(ctx, row(csr(ctx.S.analysis, r.select), at.sheet));
    return { ...c, closed: (i) => c.closed[i], data: {} };
  },
  wireframe(ctx, r, p, at) {
    const w = ctx.core.wireframe(ctx.S.analysis, p.sheet ?? -1, r.split === 'owner' ? at.owner : p.subsheet ?? -1);
    const poly = csr(w, 'polylines');
    const shown = arr(w, 'shown');
    const out = {
      ...poly,
      alpha: opacityAlpha(Float32Array.from(arr(w, 'point_opacity')), p.floor ?? L.wire_floor ?? 0.15),
      keep: p.simplified === false ? null : (i) => !!shown[i],
      data: { color: arr(w, 'color'), kinds: p.byKind ? csr(w, 'non_hex') : null },
    };
    ctx.core.free(w);
    return out;
  },
};

function linesOf(ctx, r, p, at) {
  const l = LINES[r.source](ctx, r, p, at);
  if (r.optional && l.offsets.length < 2) return [];
  const pos = ctx.core.polylines(ctx.S.mesh, l.offsets, l.items);
  const part = linesPart(pos, l.offsets, {
    colorOf: COLORS[r.color](r, ctx, { ...l.data, sheet: at.sheet }),
    alpha: l.alpha ?? null, keep: l.keep ?? null, closed: l.closed ?? null, name: present(r, at.owner).name,
  });
  return [r.source === 'wireframe' ? { ...part, subsheet: r.split === 'owner' ? at.owner : p.subsheet ?? -1 } : part];
}

/** The parts of one request, by its geometry. */
export const GEOMETRY = { soup: soupOf, dots: dotsOf, lines: linesOf };
/** The lines' sources; the soups' are the core's block_soup kinds, the dots' its CSRs. */
export const LINE_SOURCES = Object.keys(LINES);

function wanted(ctx, r) {
  if (r.when === 'non_hex_cells') return ctx.S.cellTypes.some((t) => t !== 0);
  if (r.when === 'setting') return r.default_on; // the page has none of the add-on's switches
  return true;
}

/** The subsheets of the picked self-intersecting sheet: each owner's parts together (optionally
 *  laid side by side by the page), the wireframes beneath; a core without per-subsheet wireframes
 *  still draws the subsheets. */
function perOwner(ctx, reqs, p, at) {
  if (ctx.S.sheetType[at.sheet] !== 3) return [];
  const sub = ctx.core.subsheets(ctx.S.analysis, at.sheet);
  at.subsheets = () => sub;
  const count = Number(get(sub, 'count'));
  const types = arr(sub, 'subsheet_type');
  const cells = csr(sub, 'subsheet_cells').offsets;
  const list = Array.from({ length: count }, (_, k) => ({ type: types[k], cells: cells[k + 1] - cells[k] }));
  const parts = [];
  let wiresOk = true;
  for (let k = 0; k < count; k++) {
    at.owner = k;
    for (const r of reqs) {
      if (r.source === 'wireframe') {
        if (!p.subsheetWires || !wiresOk) continue;
        try {
          parts.push(...linesOf(ctx, r, p, at).map((w) => ({ ...w, below: true })));
        } catch (e) {
          wiresOk = false;
        }
        continue;
      }
      parts.push(...GEOMETRY[r.geometry](ctx, r, p, at).map((q) => ({ ...q, subsheet: k })));
    }
  }
  ctx.core.free(sub);
  return parts.map((q) => ({ ...q, subsheets: list }));
}

/** A layer's parts: ctx = {core, S (the open mesh), centroids()}; p the page's settings
 *  (shrink, sheet, plane, types, floor, simplified, byKind, ...). */
export function buildLayer(ctx, layer, p) {
  const reqs = requestsOf(layer).filter((r) => wanted(ctx, r));
  const at = { sheet: p.sheet ?? -1, owner: -1, soups: new Map(), subsheets: null };
  if (reqs.some((r) => r.sheet) && !(at.sheet >= 0 && at.sheet < ctx.S.sheetType.length)) return [];
  if (reqs.some((r) => r.split === 'owner')) return perOwner(ctx, reqs, p, at);
  return reqs.flatMap((r) => GEOMETRY[r.geometry](ctx, r, p, at));
}
