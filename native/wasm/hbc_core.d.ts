// hbc_core.js (+ hbc_core.wasm): the JavaScript binding of the hbc library (native/wasm/hbc_core.cpp).
// Names are those of the Python binding (native/python/hbc/_core.pyi); numpy arrays become typed
// arrays, each a copy owned by JS. nv, ne, nf, nc: the mesh's vertices, edges, faces, cells. Every CSR
// is <name>_offsets (rows + 1, Int32Array) with <name>_items (offsets[rows], Int32Array).
// Errors are thrown as JS Errors whose message is the CLI's ("file:line: expected ...").
// Embind objects (Mesh, Analysis) hold wasm memory: call .delete() when done.

export type Level = "complex" | "mesh";
export type SoupWhat = "cells" | "components" | "sheets" | "subsheets" | "sheet" | "sheet_non_hex" | "non_hex" | "boundary" | "hex";

export interface AnalyzeOptions {
  level?: Level;                       // default "complex"
  subsheet_rule?: "layers" | "fewest"; // default "layers"
  rho?: number;                        // the wireframes' colour-class threshold when wireframe() is given none, default 0.8
  sheets?: boolean; subsheets?: boolean; wireframe?: boolean;  // default true
}

export interface Mesh {
  readonly num_vertices: number; readonly num_edges: number; readonly num_faces: number; readonly num_cells: number;
  readonly source: string;                  // the name given to load
  readonly warnings: string[];              // what reading said (the CLI's "hbc: warning: FILE: TEXT" TEXTs)
  readonly points: Float32Array;            // (3 nv) x y z
  readonly points64: Float64Array;          // (3 nv)
  readonly edges: Int32Array;               // (2 ne) lower vertex first
  readonly face_vertices_offsets: Int32Array; readonly face_vertices_items: Int32Array;  // vertex loop per face
  readonly face_cells: Int32Array;          // (2 nf) second -1 on the boundary
  readonly cell_faces_offsets: Int32Array; readonly cell_faces_items: Int32Array;
  readonly cell_types: Uint8Array;          // (nc) 0 hex, 1 tet, 2 prism, 3 pyramid, 4 polyhedron
  readonly face_boundary: Uint8Array;       // (nf) 0/1
  info_json(): string;                      // `hbc info --json`, the same text: {"file","vertices","edges","faces","cells","hex_cells","hex_ratio","cell_types":{hex,tet,...},"boundary_faces","non_manifold_vertices","dropped_faces","dropped_edges"}
  analyze(options?: AnalyzeOptions): Analysis;
  delete(): void;
}

export interface Wireframe {
  count: number;                                          // polylines of the complete wireframe
  polylines_offsets: Int32Array; polylines_items: Int32Array;  // mesh vertices per polyline
  point_opacity: Float32Array;                            // aligned with polylines_items, in [floor, 1]
  kind: Uint8Array; shown: Uint8Array; color: Int32Array; color_class: Int32Array;  // (count)
  non_hex_offsets: Int32Array; non_hex_items: Int32Array; // non-hex kinds per polyline (docs/concepts.md)
  simplified_polylines_offsets: Int32Array; simplified_polylines_items: Int32Array;
  simplified_non_hex_offsets: Int32Array; simplified_non_hex_items: Int32Array;
}

export interface BlockSoup {
  positions: Float32Array;        // (3 np)
  point_vertex: Int32Array;       // (np) mesh vertex of each point
  face_vertices_offsets: Int32Array; face_vertices_items: Int32Array;  // point ids, loops outward
  face_owner: Int32Array;         // (nf') grouped by increasing owner
  face_source: Int32Array;        // (nf') mesh face ids
  face_cell: Int32Array;          // (nf') mesh cell on the owner's side
}

export interface SubsheetSet {
  sheet: number; count: number;
  subsheet_cells_offsets: Int32Array; subsheet_cells_items: Int32Array;
  subsheet_blocks_offsets: Int32Array; subsheet_blocks_items: Int32Array;
  subsheet_types: Uint8Array;     // (count) SHEET_TYPES index: 0 perfect, 1..3 type1..type3
  // each subsheet's highlights (rows: count), as the sheets' below
  subsheet_unmatched_vertices_offsets: Int32Array; subsheet_unmatched_vertices_items: Int32Array;
  subsheet_shared_vertices_offsets: Int32Array; subsheet_shared_vertices_items: Int32Array;
  subsheet_self_parallel_curves_offsets: Int32Array; subsheet_self_parallel_curves_items: Int32Array;
  subsheet_self_intersecting_components_offsets: Int32Array; subsheet_self_intersecting_components_items: Int32Array;
}

export interface Analysis {
  stats_json(): string;           // `hbc analyze --json` (same keys and values; "file" = the loaded name)
  // singularity graph
  readonly edge_class: Uint8Array;        // (ne) 0 regular, 1 singular, 2 pseudo-singular, 3 non-manifold
  readonly edge_chain: Int32Array;        // (ne) singularity of a singular edge, else -1
  readonly chain_vertices_offsets: Int32Array; readonly chain_vertices_items: Int32Array;
  readonly chain_edges_offsets: Int32Array; readonly chain_edges_items: Int32Array;
  readonly chain_valence: Int32Array; readonly chain_boundary: Uint8Array; readonly chain_closed: Uint8Array;  // (ns)
  readonly singular_vertices: Int32Array; readonly pseudo_singular_vertices: Int32Array;
  readonly num_singularities: number;
  // base complex
  readonly cell_component: Int32Array;    // (nc)
  readonly component_kind: Uint8Array;    // (ncomp) 0 cube, 1 ring, 2 other, 3 non-hex
  readonly component_cells_offsets: Int32Array; readonly component_cells_items: Int32Array;
  readonly face_patch: Int32Array;        // (nf) patch of a separation face, else -1
  readonly curve_vertices_offsets: Int32Array; readonly curve_vertices_items: Int32Array;
  readonly curve_closed: Uint8Array; readonly corners: Int32Array;
  readonly num_components: number; readonly num_curves: number; readonly num_patches: number;
  // sheets (throw when the analysis ran without them)
  readonly num_sheets: number;
  readonly sheet_cells_offsets: Int32Array; readonly sheet_cells_items: Int32Array;
  readonly sheet_blocks_offsets: Int32Array; readonly sheet_blocks_items: Int32Array;
  readonly sheet_types: Uint8Array;       // (num_sheets)
  // The highlights of each sheet (rows: num_sheets), as Analysis.sheet_* in _core.pyi:
  // unmatched and shared mesh vertices, curve ids of type 2 pairs, components holding type 3 pairs.
  readonly sheet_unmatched_vertices_offsets: Int32Array; readonly sheet_unmatched_vertices_items: Int32Array;
  readonly sheet_shared_vertices_offsets: Int32Array; readonly sheet_shared_vertices_items: Int32Array;
  readonly sheet_self_parallel_curves_offsets: Int32Array; readonly sheet_self_parallel_curves_items: Int32Array;
  readonly sheet_self_intersecting_components_offsets: Int32Array;
  readonly sheet_self_intersecting_components_items: Int32Array;
  subsheets(sheet: number): SubsheetSet | null;   // null: not self-intersecting
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
  faces_items: Int32Array;     // vertex loops, 0-based
  cells_offsets: Int32Array;   // (nc + 1)
  cells_items: Int32Array;     // 2 face + flip
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
  // The layer plan (hbc/layer_plan.hpp, native/wasm/layer_plan_json.cpp): JSON of the layers
  // [[key, title]], every colour by its role (linear RGBA), the legend's colours by key,
  // sheet_type_short, subsheets_unavailable[t], wire_floor, spread_gap: web/src/colors.js' L.
  layer_plan_json(): string;
  // A mesh's legend: JSON {facts: {non_hex_types, valences, has_pseudo, has_non_manifold,
  // has_non_hex_blocks}, legends: {"<shown layer keys in order, comma-joined>|<1: wireframes by
  // non-hex kind, else 0>": [[colour key, words]]}} for every non-empty set of layers.
  legends_json(cell_types: Uint8Array, edge_class: Uint8Array, chain_valence: Int32Array,
               component_kind: Uint8Array): string;
  FS: any;                                    // emscripten's in-memory file system (for load_path)
  version(): string;
}
export default function createHbcModule(overrides?: object): Promise<HbcModule>;
