// Colours and words of the library's layer plan (native/include/hbc/layer_plan.hpp), the add-on's
// source too: web/build.mjs asks the WebAssembly core for them (layer_plan_json) and inlines them,
// so the page holds no colour of its own.
/* global __HBC_LEGEND__ */
export const L = __HBC_LEGEND__;

const N = L.palette.length;

/** planning.palette_color: palette entry by index, the non-hex grey for a negative one. */
export function paletteColor(i) {
  return i < 0 ? L.non_hex_color : L.palette[((i % N) + N) % N];
}

/** planning.spread_ids then the palette: neighbouring ids get distant colours. */
export function spreadColor(id) {
  return L.palette[L.spread[id % L.spread.length]];
}

/** planning.subsheet_colors: the sheets' palette order walked from its other end, so that
 *  subsheet k never has sheet k's colour. */
export function subsheetColor(k) {
  return L.palette[L.subsheet_spread[k % L.subsheet_spread.length]];
}

/** planning.component_colors: palette by id, rings darker, non-hex components grey. */
export function componentColor(id, kind) {
  if (kind === 3) return L.non_hex_color;
  const c = spreadColor(id);
  return kind === 1 ? [c[0] * L.ring_darken, c[1] * L.ring_darken, c[2] * L.ring_darken, c[3]] : c;
}

export function valenceColor(v) {
  return L.valence_colors[String(v)] ?? L.legend_colors.valence_other;
}

export function cellTypeColor(t) {
  return L.cell_type_colors[t] ?? L.cell_type_colors[L.cell_type_colors.length - 1];
}

/** planning.chain_kind_colors for one chain's kind codes (code >> 16 is the cell type). */
export function kindColor(codes) {
  if (!codes.length) return L.wire_hex_color;
  const t = codes[0] >> 16;
  for (let i = 1; i < codes.length; i++) if (codes[i] >> 16 !== t) return L.wire_several_color;
  return t === 0 ? L.wire_hex_color : cellTypeColor(t);
}

/** A linear colour as CSS (sRGB) for a legend swatch. */
export function css(c) {
  const s = (x) => Math.round(255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055));
  const a = c.length > 3 ? c[3] : 1;
  return `rgba(${s(c[0])}, ${s(c[1])}, ${s(c[2])}, ${a})`;
}
