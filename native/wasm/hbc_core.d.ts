// hbc_core.js (+ hbc_core.wasm): the JavaScript binding of the hbc library (native/wasm/hbc_core.cpp).
// Names are those of the Python binding (native/python/hbc/_core.pyi), both registered through one
// table in the library (hbc/exports.hpp; EXPORTS_json() below); numpy arrays become typed arrays,
// each a copy owned by JS, bool arrays Uint8Array 0/1. tests/wasm/binding_test.mjs checks this file
// and the module's objects against the table.
// Errors are thrown as JS Errors whose message is the CLI's ("file:line: expected ...").
// Embind objects (Mesh, Analysis) hold wasm memory: call .delete() when done.

export type Level = "complex" | "mesh";
export type SoupWhat = "cells" | "components" | "sheets" | "subsheets" | "sheet" | "sheet_non_hex" | "non_hex" | "boundary" | "hex";

// analyze's options (hbc/exports.hpp, the same as Python's Mesh.analyze(**options) and the CLI's):
// one per line, its type, then its default. An unknown key or a bad value throws an Error.
export interface AnalyzeOptions {
  rho?: number;                          // default 0.8: the wireframes' colour-class threshold when wireframe() is given none (presentation only)
  level?: Level;                         // default complex: level of the sheets and the wireframe
  sheets?: boolean;                      // default true: the sheet stage
  subsheets?: boolean;                   // default true: decompose every self-intersecting sheet
  wireframe?: boolean;                   // default true: the whole-mesh VSG wireframe
  threads?: number;                      // default none: the module runs on one thread whatever this says
  subsheet_rule?: "layers" | "fewest";   // default layers
  search_steps?: number;                 // default 100000: the fewest rule's exact search steps per sheet
}

// Array properties, one per line: name, typed array, then its shape in a comment, (rows) or
// (width rows) flattened, a CSR as <name>_offsets (rows + 1) and <name>_items (<name>_offsets[rows]);
// the rows are the dimensions of EXPORTS_json() (nv, ne, nf, nc: the mesh's vertices, edges, faces,
// cells; ns singularities, ncomp components, ...). Names marked @deprecated are the ones published
// before JavaScript took the Python names; they stay for old callers.

export interface Mesh {
  readonly num_vertices: number; readonly num_edges: number; readonly num_faces: number; readonly num_cells: number;
  readonly source: string;                  // the name given to load
  readonly warnings: string[];              // what reading said (the CLI's "hbc: warning: FILE: TEXT" TEXTs)
  readonly points: Float32Array;            // (3 nv) x y z
  readonly points64: Float64Array;          // (3 nv)
  readonly edges: Int32Array;               // (2 ne) lower vertex first
  readonly face_vertices_offsets: Int32Array;  // (nf + 1)
  readonly face_vertices_items: Int32Array;    // (face_vertices_offsets[nf]) vertex loop per face
  readonly face_cells: Int32Array;          // (2 nf) second -1 on the boundary
  readonly cell_faces_offsets: Int32Array;  // (nc + 1)
  readonly cell_faces_items: Int32Array;    // (cell_faces_offsets[nc])
  readonly cell_types: Uint8Array;          // (nc) 0 hex, 1 tet, 2 prism, 3 pyramid, 4 polyhedron
  readonly face_boundary: Uint8Array;       // (nf) 0/1
  info_json(): string;                      // `hbc info --json`, the same text: {"file","vertices","edges","faces","cells","hex_cells","hex_ratio","cell_types":{hex,tet,...},"boundary_faces","non_manifold_vertices","dropped_faces","dropped_edges"}
  analyze(options?: AnalyzeOptions): Analysis;
  delete(): void;
}

export interface Wireframe {
  count: number;                          // polylines of the complete wireframe
  polylines_offsets: Int32Array;          // (count + 1)
  polylines_items: Int32Array;            // (polylines_offsets[count]) mesh vertices per polyline
  point_opacity: Float32Array;            // (npp) aligned with polylines_items, in [floor, 1]
  kind: Uint8Array;                       // (count) 0 chain of VSG edges only, 1 other
  shown: Uint8Array;                      // (count) 0/1 on the simplified wireframe
  color: Int32Array;                      // (count) palette index
  color_class: Int32Array;                // (count)
  non_hex_offsets: Int32Array;            // (count + 1)
  non_hex_items: Int32Array;              // (non_hex_offsets[count]) non-hex kinds per polyline (docs/concepts.md)
  simplified_polylines_offsets: Int32Array;  // (nsimp + 1)
  simplified_polylines_items: Int32Array;    // (simplified_polylines_offsets[nsimp])
  simplified_non_hex_offsets: Int32Array;    // (nsimp + 1)
  simplified_non_hex_items: Int32Array;      // (simplified_non_hex_offsets[nsimp])
}

export interface BlockSoup {
  positions: Float32Array;                // (3 np)
  point_vertex: Int32Array;               // (np) mesh vertex of each point
  face_vertices_offsets: Int32Array;      // (nsf + 1)
  face_vertices_items: Int32Array;        // (face_vertices_offsets[nsf]) point ids, loops outward
  face_owner: Int32Array;                 // (nsf) grouped by increasing owner
  face_source: Int32Array;                // (nsf) mesh face ids
  face_cell: Int32Array;                  // (nsf) mesh cell on the owner's side
}

export interface Subsheets {
  sheet: number; count: number;
  subsheet_type: Uint8Array;              // (count) SHEET_TYPES index: 0 perfect, 1..3 type1..type3
  subsheet_components_offsets: Int32Array;  // (count + 1)
  subsheet_components_items: Int32Array;    // (subsheet_components_offsets[count]) base-complex components
  subsheet_cells_offsets: Int32Array;       // (count + 1)
  subsheet_cells_items: Int32Array;         // (subsheet_cells_offsets[count]) mesh hex cells
  // each subsheet's highlights, as the sheets' below
  subsheet_unmatched_vertices_offsets: Int32Array;      // (count + 1)
  subsheet_unmatched_vertices_items: Int32Array;        // (subsheet_unmatched_vertices_offsets[count])
  subsheet_shared_vertices_offsets: Int32Array;         // (count + 1)
  subsheet_shared_vertices_items: Int32Array;           // (subsheet_shared_vertices_offsets[count])
  subsheet_self_parallel_curves_offsets: Int32Array;    // (count + 1)
  subsheet_self_parallel_curves_items: Int32Array;      // (subsheet_self_parallel_curves_offsets[count])
  subsheet_self_intersecting_components_offsets: Int32Array;  // (count + 1)
  subsheet_self_intersecting_components_items: Int32Array;    // (subsheet_self_intersecting_components_offsets[count])
  /** @deprecated use subsheet_type (the same values) */ subsheet_types: Uint8Array;  // (count)
  /** @deprecated use subsheet_components (these are the sheet domain's block ids) */ subsheet_blocks_offsets: Int32Array;  // (count + 1)
  /** @deprecated use subsheet_components (these are the sheet domain's block ids) */ subsheet_blocks_items: Int32Array;  // (subsheet_blocks_offsets[count])
}
/** @deprecated the Python name: Subsheets */
export type SubsheetSet = Subsheets;

export interface Analysis {
  stats_json(): string;           // `hbc analyze --json` (same keys and values; "file" = the loaded name)
  // singularity graph (Python: Analysis.graph)
  readonly edge_class: Uint8Array;          // (ne) 0 regular, 1 singular, 2 pseudo-singular, 3 non-manifold
  readonly edge_chain: Int32Array;          // (ne) singularity of a singular edge, else -1
  readonly chain_vertices_offsets: Int32Array;  // (ns + 1)
  readonly chain_vertices_items: Int32Array;    // (chain_vertices_offsets[ns])
  readonly chain_edges_offsets: Int32Array;     // (ns + 1)
  readonly chain_edges_items: Int32Array;       // (chain_edges_offsets[ns])
  readonly chain_valence: Int32Array;       // (ns)
  readonly chain_boundary: Uint8Array;      // (ns)
  readonly chain_closed: Uint8Array;        // (ns)
  readonly singular_vertices: Int32Array;   // (k)
  readonly pseudo_singular_vertices: Int32Array;  // (k)
  readonly num_singularities: number;
  // base complex (Python: Analysis.complex)
  readonly cell_component: Int32Array;      // (nc)
  readonly component_kind: Uint8Array;      // (ncomp) 0 cube, 1 ring, 2 other, 3 non-hex
  readonly component_cells_offsets: Int32Array;  // (ncomp + 1)
  readonly component_cells_items: Int32Array;    // (component_cells_offsets[ncomp])
  readonly face_patch: Int32Array;          // (nf) patch of a separation face, else -1
  readonly curve_vertices_offsets: Int32Array;   // (ncurve + 1)
  readonly curve_vertices_items: Int32Array;     // (curve_vertices_offsets[ncurve])
  readonly curve_closed: Uint8Array;        // (ncurve)
  readonly corners: Int32Array;             // (k)
  readonly num_components: number; readonly num_curves: number; readonly num_patches: number;
  // sheets (throw when the analysis ran without them)
  readonly num_sheets: number;
  readonly sheet_type: Uint8Array;          // (num_sheets)
  readonly sheet_components_offsets: Int32Array;  // (num_sheets + 1)
  readonly sheet_components_items: Int32Array;    // (sheet_components_offsets[num_sheets]) base-complex components
  readonly sheet_cells_offsets: Int32Array;       // (num_sheets + 1)
  readonly sheet_cells_items: Int32Array;         // (sheet_cells_offsets[num_sheets]) mesh hex cells
  // The highlights of each sheet, as Analysis.sheet_* in _core.pyi: unmatched and shared mesh
  // vertices, curve ids of type 2 pairs, components holding type 3 pairs.
  readonly sheet_unmatched_vertices_offsets: Int32Array;      // (num_sheets + 1)
  readonly sheet_unmatched_vertices_items: Int32Array;        // (sheet_unmatched_vertices_offsets[num_sheets])
  readonly sheet_shared_vertices_offsets: Int32Array;         // (num_sheets + 1)
  readonly sheet_shared_vertices_items: Int32Array;           // (sheet_shared_vertices_offsets[num_sheets])
  readonly sheet_self_parallel_curves_offsets: Int32Array;    // (num_sheets + 1)
  readonly sheet_self_parallel_curves_items: Int32Array;      // (sheet_self_parallel_curves_offsets[num_sheets])
  readonly sheet_self_intersecting_components_offsets: Int32Array;  // (num_sheets + 1)
  readonly sheet_self_intersecting_components_items: Int32Array;    // (sheet_self_intersecting_components_offsets[num_sheets])
  /** @deprecated use sheet_type (the same values) */ readonly sheet_types: Uint8Array;  // (num_sheets)
  /** @deprecated use sheet_components (these are the sheet domain's block ids) */ readonly sheet_blocks_offsets: Int32Array;  // (num_sheets + 1)
  /** @deprecated use sheet_components (these are the sheet domain's block ids) */ readonly sheet_blocks_items: Int32Array;  // (sheet_blocks_offsets[num_sheets])
  subsheets(sheet: number): Subsheets | null;     // null: not self-intersecting
  wireframe(): Wireframe | null;                  // null: wireframe not run
  // The wireframe of a sheet's (or one of its subsheets') cells with their adjacent non-hex cells,
  // as Analysis.wireframe(sheet=, subsheet=); -1 for none (wireframe(-1, -1) is the whole mesh's).
  wireframe(sheet: number, subsheet: number): Wireframe | null;
  // The same styled at rho (colour classes, colours, opacity): a restyle, no analysis runs again.
  wireframe(sheet: number, subsheet: number, rho: number): Wireframe | null;
  block_soup(what: SoupWhat, sheet: number, shrink: number): BlockSoup;  // sheet -1: none
  delete(): void;
}

export interface GeneratedMesh {
  points: Float64Array;        // (3 nv)
  faces_offsets: Int32Array;   // (nf + 1)
  faces_items: Int32Array;     // (faces_offsets[nf]) vertex loops, 0-based
  cells_offsets: Int32Array;   // (nc + 1)
  cells_items: Int32Array;     // (cells_offsets[nc]) 2 face + flip
}

export interface HbcModule {
  load(bytes: Uint8Array | ArrayBuffer, name: string, skip_invalid: boolean): Mesh;  // format from the name
  load_path(path: string, skip_invalid?: boolean): Mesh;  // a file or OpenFOAM case already in FS (the CLI's reading of a path)
  polylines(mesh: Mesh, offsets: Int32Array, items: Int32Array): Float32Array;       // (3 * items.length)
  kept_surface_soup(mesh: Mesh, kept: Uint8Array, shrink: number): BlockSoup;        // kept: (nc) 0/1; owner = cell
  cell_centroids(mesh: Mesh): Float64Array;   // (3 nc) mean of each cell's distinct vertices
  // `hbc generate cylinder --radius-cells R --layers L` before any reader (hex-dominant: hexes and
  // prisms); cells_items: 2 face + flip (flip 1: the cell sees the face's loop reversed).
  generate_cylinder(radius_cells: number, layers: number): GeneratedMesh;
  FORMATS(): string;                          // JSON [{name, alias, extension, title, writable}]
  TABLE1_COLUMNS_json(): string;              // JSON [{key, label, notation, meaning, kind, timing}] (kind: count|ratio|seconds) in Table 1's order
  EXPORTS_json(): string;                     // JSON {arrays: [{holder, name, dtype, csr, rows, width, python, js, deprecated, meaning}], dimensions: {symbol: meaning}, options: [{key, type, default, choices, min, max, meaning}]}: this file's arrays and options, described once (hbc/exports.hpp)
  // The layer plan (hbc/layer_plan.hpp, native/wasm/layer_plan_json.cpp): JSON of the layers
  // [[key, title]], every colour by its role (linear RGBA), the legend's colours by key,
  // sheet_type_short, subsheets_unavailable[t], wire_floor, spread_gap: web/src/colors.js' L.
  layer_plan_json(): string;
  // A mesh's legend: JSON {facts: {non_hex_types, valences, has_pseudo, has_non_manifold,
  // has_non_hex_blocks}, legends: {"<shown layer keys in order, comma-joined>|<1: wireframes by
  // non-hex kind, else 0>": [[colour key, words]]}} for every non-empty set of layers.
  // Every layer's parts as the front ends request them (hbc::layer_requests): JSON [{layer, part,
  // geometry, source, select, edge_class, sheet, shrink, color, role, split, when, default_on,
  // optional}], the fields of _core.pyi's PartRequest; web/build.mjs inlines it for the worker.
  layer_requests_json(): string;
  legends_json(cell_types: Uint8Array, edge_class: Uint8Array, chain_valence: Int32Array,
               component_kind: Uint8Array): string;
  FS: any;                                    // emscripten's in-memory file system (for load_path)
  version(): string;
}
export default function createHbcModule(overrides?: object): Promise<HbcModule>;
