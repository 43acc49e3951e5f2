// The one place that knows how the WebAssembly module (scripts/build_wasm.sh, createHbcModule)
// spells things. The binding follows the Python names (native/python/hbc/_core.pyi); whether a
// name is a property or a method, and whether an array is a view into the wasm heap, is settled
// here, so the worker reads every array as a plain copy it may transfer.

/** The value of `name` on an embind object: a property, or a method without arguments. */
export function get(obj, name) {
  const v = obj[name];
  return typeof v === 'function' ? v.call(obj) : v;
}

/** A typed array copied out of the wasm heap: views die when the heap grows, and only a copy can
 *  be transferred to the page. Embind vectors (size/get) are read element by element. */
function copy(v) {
  if (v == null) return v;
  if (ArrayBuffer.isView(v)) return v.slice();
  if (Array.isArray(v)) return v;
  if (typeof v.size === 'function' && typeof v.get === 'function') {
    const n = v.size();
    const out = new Array(n);
    for (let i = 0; i < n; i++) out[i] = v.get(i);
    if (typeof v.delete === 'function') v.delete();
    return out;
  }
  return v;
}

/** The first of `names` the object has, copied; undefined when it has none. */
export function arr(obj, ...names) {
  for (const name of names) {
    if (obj != null && name in obj) return copy(get(obj, name));
  }
  return undefined;
}

/** A CSR as {offsets, items} from `<name>_offsets` and `<name>_items` (the first of `names` the
 *  object has); empty when it has none (a highlight an older core does not give). */
export function csr(obj, ...names) {
  for (const name of names) {
    const o = arr(obj, `${name}_offsets`);
    if (o !== undefined) return { offsets: Int32Array.from(o), items: Int32Array.from(arr(obj, `${name}_items`)) };
  }
  return { offsets: new Int32Array(1), items: new Int32Array(0) };
}

/** A face soup (block_soup, kept_surface_soup) as the worker's typed arrays; the embind object
 *  is freed once copied. */
function soupArrays(s) {
  const out = {
    positions: Float32Array.from(arr(s, 'positions')),
    offsets: Int32Array.from(arr(s, 'face_vertices_offsets')),
    items: Int32Array.from(arr(s, 'face_vertices_items')),
    owner: Int32Array.from(arr(s, 'face_owner')),
    cell: Int32Array.from(arr(s, 'face_cell')),
  };
  if (typeof s.delete === 'function') s.delete();
  return out;
}

/** The text of a thrown C++ InputError (or any error) as the CLI prints it: the binding turns every
 *  C++ exception into a JS Error carrying the CLI's message. */
export function errorText(M, e) {
  if (e && typeof e === 'object' && 'message' in e && e.message) return String(e.message);
  return String(e);
}

/** The path the core loads: the one file, or for several files (an OpenFOAM case) the owner file. */
function loadPath(files) {
  if (files.length === 1) return '/in/' + files[0].path;
  const owner = files.find((f) => /(^|\/)owner(\.gz)?$/.test(f.path));
  const foam = files.find((f) => /\.foam$/i.test(f.path));
  return '/in/' + (owner ?? foam ?? files[0]).path;
}

export class Core {
  constructor(M) { this.M = M; }

  /** The format extensions the readers take (the file picker's filter), longest first. */
  extensions() {
    const f = this.M.FORMATS ? copy(get(this.M, 'FORMATS')) : null;
    if (!f) return [];
    const list = (typeof f === 'string' ? JSON.parse(f) : f).flatMap((x) => x.extensions || [x.extension]).filter(Boolean);
    return list.sort((a, b) => b.length - a.length);
  }

  /** Table 1's columns from the module's schema, [{key, notation, meaning, kind, timing}], or null. */
  table1() {
    const M = this.M;
    const t = M.TABLE1_COLUMNS_json();
    if (!t) return null;
    const rows = typeof t === 'string' ? JSON.parse(t) : t;
    // The column's tooltip as the add-on's (planning.table1_columns): "label: meaning", times "(seconds)".
    const seconds = (timing) => (timing ? ' (seconds)' : '');
    return rows.map((r) => (Array.isArray(r)
      ? { key: r[0].key, notation: r[0].notation, meaning: `${r[0].label}: ${r[0].meaning}${seconds(r[1])}`, kind: r[0].kind, timing: !!r[1] }
      : { ...r, meaning: (r.label && !String(r.meaning).startsWith(r.label) ? `${r.label}: ${r.meaning}` : r.meaning) + seconds(r.timing), timing: !!r.timing }));
  }

  writeFiles(files) {
    const FS = this.M.FS;
    for (const f of files) {
      const parts = f.path.split('/').filter(Boolean);
      let dir = '';
      for (const p of parts.slice(0, -1)) {
        dir += '/' + p;
        try { FS.mkdir(dir); } catch (_) { /* exists */ }
      }
      FS.writeFile('/' + parts.join('/'), new Uint8Array(f.buffer));
    }
  }

  removeTree(path) {
    const FS = this.M.FS;
    let st;
    try { st = FS.stat(path); } catch (_) { return; }
    if (FS.isDir(st.mode)) {
      for (const n of FS.readdir(path)) if (n !== '.' && n !== '..') this.removeTree(`${path}/${n}`);
      FS.rmdir(path);
    } else FS.unlink(path);
  }

  /** The mesh of some files [{path, buffer}]: one mesh file, or an OpenFOAM case's files. The
   *  binding reads bytes with a name (the name's extension picks the reader), or paths in its
   *  file system when it exports one. skipInvalid: the CLI's --skip-invalid. written: the files
   *  are in the file system already (the same files read again; their buffers are not needed). */
  open(files, { skipInvalid = false, written = false } = {}) {
    const M = this.M;
    if (M.FS && typeof M.load_path === 'function') {
      if (!written) {
        this.removeTree('/in');
        M.FS.mkdir('/in');
        this.writeFiles(files.map((f) => ({ path: 'in/' + f.path, buffer: f.buffer })));
      }
      // Only a core that takes the choice is asked with it (embind checks the argument count).
      return skipInvalid ? M.load_path(loadPath(files), true) : M.load_path(loadPath(files));
    }
    if (written) throw new Error('This WebAssembly core keeps no file: open the file again.');
    if (files.length > 1) {
      throw new Error('An OpenFOAM case (several files) needs a newer WebAssembly core: this one reads one file at a time.');
    }
    return M.load(new Uint8Array(files[0].buffer), files[0].path, !!skipInvalid);
  }

  analyze(mesh) {
    return mesh.analyze({});
  }

  /** `hbc analyze FILE --json` as text, from the library's own JSON writer ("file" is the name
   *  the mesh was loaded with). */
  analysisJson(analysis) {
    return analysis.stats_json();
  }

  // The graph's and the base complex's arrays: on their own objects (Python) or on the analysis.
  graph(a) { return 'graph' in a ? get(a, 'graph') : a; }
  complex(a) { return 'complex' in a ? get(a, 'complex') : a; }

  blockSoup(mesh, analysis, what, sheet, shrink) {
    const id = sheet == null ? -1 : sheet;
    return soupArrays(analysis.block_soup(what, id, shrink));
  }

  keptSurface(mesh, kept, shrink) {
    const s = this.M.kept_surface_soup(mesh, kept, shrink);
    return soupArrays(s);
  }

  polylines(mesh, offsets, items) {
    return Float32Array.from(copy(this.M.polylines(mesh, offsets, items)));
  }

  centroids(mesh) {
    return Float32Array.from(copy(this.M.cell_centroids(mesh)));
  }

  subsheets(a, sheet) { return a.subsheets(sheet); }

  wireframe(a, sheet, subsheet) {
    const s = sheet == null ? -1 : sheet;
    const k = subsheet == null ? -1 : subsheet;
    try {
      return a.wireframe(s, k);
    } catch (e) {
      if (!/argument|parameter/i.test(String(e && e.message))) throw e;
    }
    if (s >= 0) throw new Error("This build of the core draws the whole mesh's wireframe only.");
    return a.wireframe();
  }

  /** The library's legend of this mesh for every set of shown layers, and its facts
   *  (layer_plan_json.cpp's legends_json): { facts, legends: { "direct,graph|0": [[key, words]] } }. */
  legends(cellTypes, edgeClass, chainValence, componentKind) {
    return JSON.parse(this.M.legends_json(cellTypes, edgeClass, chainValence, componentKind));
  }

  hasCut() {
    return typeof this.M.kept_surface_soup === 'function' && typeof this.M.cell_centroids === 'function';
  }

  free(...objs) {
    for (const o of objs) if (o && typeof o.delete === 'function') { try { o.delete(); } catch (_) { /* freed */ } }
  }
}
