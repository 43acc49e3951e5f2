"""The gallery's static site, written from the cached results (hbc.gallery): ``index.html`` (one
row per mesh: thumbnail, tags, cell kinds, Table 1, the report's key metrics; sorting, text, tag
and range filters in the page's script, ``gallery_index.js``), ``viewer.html`` (the web viewer,
once, loading ``meshes/ID.js`` beside it) and ``models/NAME.html`` (the meshes of one model side by
side). Every page works from file:// and on any static host: the data is inline, the meshes are
script files (a page opened from file:// may load a script, not fetch a file).

Why one shared viewer and not one ``hbc export-html`` page per mesh: the viewer page holds the
WebAssembly core and three.js (megabytes); one copy per mesh would make a site of 200 meshes
hundreds of megabytes beyond the meshes, one shared copy keeps it to one.
"""

from __future__ import annotations

import html
import json
import pathlib
import re
import shutil

from . import locate

_ASSETS = pathlib.Path(__file__).resolve().parent / "gallery_assets"
#: What viewer.html has after the viewer page's own script: ?m=ID loads meshes/ID.js, whose call
#: hands the gzipped bytes to the page (window.hbcViewer.load), named as the file was.
_VIEWER_BOOT = """<script>
(function () {
  var id = new URLSearchParams(location.search).get('m');
  if (!id || !/^[0-9a-f]+$/.test(id)) return;
  var back = document.createElement('a');
  back.href = 'index.html'; back.textContent = '\\u2190 gallery'; back.id = 'hbc-gallery-back';
  back.style.cssText = 'position:fixed;left:8px;bottom:8px;z-index:10;font:13px sans-serif;background:#fff;padding:2px 6px;border-radius:4px';
  document.body.appendChild(back);
  window.hbcGalleryMesh = function (name, b64) {
    var bin = atob(b64), bytes = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
    new Response(stream).arrayBuffer().then(function (buf) {
      document.title = name + ' \\u2014 hbc gallery';
      (function go() { if (window.hbcViewer) window.hbcViewer.load(name, buf); else setTimeout(go, 20); })();
    });
  };
  var s = document.createElement('script');
  s.src = 'meshes/' + id + '.js';
  s.onerror = function () { document.getElementById('status').textContent = 'meshes/' + id + '.js is missing'; };
  document.body.appendChild(s);
})();
</script>
"""


def write_viewer(out: pathlib.Path) -> bool:
    """viewer.html of the site (the built viewer page with _VIEWER_BOOT); False when there is no
    viewer page (hbc.locate.viewer_page), then the rows link no viewer."""
    try:
        page = locate.viewer_page().read_text(encoding="utf-8")
    except (locate.LocateError, OSError):
        return False
    # The page's policy lets no script file in; the site's copy lets in its meshes/*.js beside it
    # ('self' on a host; file: from disk, where a page has no origin of its own).
    page = page.replace("script-src 'unsafe-inline'", "script-src 'self' file: 'unsafe-inline'", 1)
    at = page.rfind("</body>")
    page = page[:at] + _VIEWER_BOOT + page[at:] if at >= 0 else page + _VIEWER_BOOT
    target = out / "viewer.html"
    if not target.exists() or target.read_text(encoding="utf-8") != page:
        target.write_text(page, encoding="utf-8")
    return True


# ---- the columns -------------------------------------------------------------------------------

def columns() -> list[dict]:
    """The index's columns after the thumbnail and the name: tags, cell kinds, Table 1 (the
    library's TABLE1_COLUMNS, headed by the paper's notation), the report's key metrics (headed by
    their labels). Each {"key", "label", "title", "kind": tag|num, "format": int|ratio|s}."""
    from . import METRIC_FIELDS, TABLE1_COLUMNS
    from .report import KEY_METRICS

    cols = [{"key": "model", "label": "model", "title": "the model (folder model/mesher/file, or --tags)", "kind": "tag"},
            {"key": "mesher", "label": "mesher", "title": "the mesher (folder model/mesher/file, or --tags)", "kind": "tag"},
            {"key": "cell_kinds", "label": "cell types", "title": "the cell types of the mesh", "kind": "tag"}]
    for field, timing in TABLE1_COLUMNS:
        key = ("timings." if timing else "") + field.key
        fmt = "s" if timing else ("ratio" if field.unit == "ratio" else "int")
        cols.append({"key": key, "label": field.notation or field.label, "title": f"{field.label}: {field.meaning}",
                     "kind": "num", "format": fmt})
    by_key = {f"{f.group}.{f.key}": f for f in METRIC_FIELDS}
    for key in KEY_METRICS:
        f = by_key.get(key)
        if f is None or key in ("census.hex_ratio",):  # Table 1's |H|/|C| already
            continue
        # "int": counts (a value that is not whole shows 4 significant digits).
        cols.append({"key": key, "label": f.label, "title": f"{f.label}: {f.meaning}", "kind": "num",
                     "format": "ratio" if f.unit == "ratio" else "int"})
    return cols


def _value(result: dict, key: str):
    if key.startswith("timings."):
        return (result.get("stats", {}).get("timings") or {}).get(key[8:])
    if "." in key:
        group, name = key.split(".", 1)
        return (result.get("metrics", {}).get(group) or {}).get(name)
    return result.get("stats", {}).get(key)


def _cell_kinds(result: dict) -> str:
    types = (result.get("info") or {}).get("cell_types") or {}
    return " ".join(t for t, n in types.items() if n)


def _slugs(meshes) -> dict:
    """A file name per model, unique whatever the models' names hold."""
    slugs, used = {}, set()
    for m in meshes:
        model = m["tags"].get("model") or "(none)"
        if model in slugs:
            continue
        base = re.sub(r"[^A-Za-z0-9_-]+", "_", model).strip("_")[:60] or "model"
        slug, n = base, 2
        while slug.lower() in used:
            slug, n = f"{base}-{n}", n + 1
        used.add(slug.lower())
        slugs[model] = slug
    return slugs


def _rows(out, meshes, cols, slugs) -> list[dict]:
    rows = []
    for m in meshes:
        r = m["result"]
        values = {c["key"]: (m["tags"].get(c["key"], "") if c["kind"] == "tag" else _value(r, c["key"]))
                  for c in cols}
        values["cell_kinds"] = _cell_kinds(r)
        extra = {k: v for k, v in m["tags"].items() if k not in ("model", "mesher")}
        thumb = out / "thumbs" / f"{m['id']}.jpg"
        rows.append({"id": m["id"], "name": m["rel"], "file": m["file"], "values": values, "tags": extra,
                     "viewer": bool(r.get("viewer")) and (out / "meshes" / f"{m['id']}.js").exists(),
                     "thumb": thumb.exists(), "model_page": f"models/{slugs[m['tags'].get('model') or '(none)']}.html",
                     "error": r.get("error", "")})
    return rows


# ---- the pages -----------------------------------------------------------------------------------

def _json_script(obj, element_id: str) -> str:
    text = json.dumps(obj, separators=(",", ":")).replace("</", "<\\/")
    return f'<script type="application/json" id="{element_id}">{text}</script>'


def write(out: pathlib.Path, meshes) -> pathlib.Path:
    """index.html, the model pages and gallery.json (the index's data, for programs); returns the
    index's path."""
    from . import __version__

    has_viewer = write_viewer(out)
    cols = columns()
    slugs = _slugs(meshes)
    rows = _rows(out, meshes, cols, slugs)
    if not has_viewer:
        for r in rows:
            r["viewer"] = False
    tag_keys = sorted({k for r in rows for k in r["tags"]})
    cols = cols[:2] + [{"key": k, "label": k, "title": f"tag {k} (--tags)", "kind": "tag"} for k in tag_keys] + cols[2:]
    for r in rows:
        r["values"].update({k: r["tags"].get(k, "") for k in tag_keys})
        del r["tags"]
    data = {"hbc_version": __version__, "columns": cols, "rows": rows,
            "viewer": has_viewer, "note": "" if has_viewer else "no viewer page: build it (scripts/build_web.sh) or set HBC_VIEWER"}
    (out / "gallery.json").write_text(json.dumps(data, indent=1), encoding="utf-8")
    shutil.copyfile(_ASSETS / "gallery.css", out / "gallery.css")
    shutil.copyfile(_ASSETS / "gallery_index.js", out / "gallery_index.js")
    index = out / "index.html"
    index.write_text(_page("hbc gallery", f"""
<header><h1>hbc gallery</h1><span id="count"></span>
<input id="filter" type="search" placeholder="filter: name, tag, error…" aria-label="text filter">
<span id="tag-filters"></span><button id="clear">clear filters</button></header>
<p class="note" id="note">{html.escape(data['note'])}</p>
<table id="gallery"><thead></thead><tbody></tbody></table>
{_json_script(data, 'gallery-data')}
<script src="gallery_index.js"></script>""", "gallery.css"), encoding="utf-8")
    by_model: dict[str, list] = {}
    for r in rows:
        by_model.setdefault(r["values"].get("model") or "(none)", []).append(r)
    for model, members in by_model.items():
        (out / "models" / f"{slugs[model]}.html").write_text(_model_page(model, members, cols), encoding="utf-8")
    return index


def _page(title: str, body: str, css: str) -> str:
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f'<meta name="viewport" content="width=device-width"><link rel="stylesheet" href="{css}"></head>'
            f'<body data-state="loading">{body}</body></html>\n')


def _fmt(v, fmt) -> str:
    if v is None:
        return "–"
    if isinstance(v, str):
        return html.escape(v)
    if fmt == "int" and float(v).is_integer():
        return f"{int(v):,}".replace(",", "\u2009")
    return f"{v:.4f}" if fmt in ("ratio", "s") else f"{v:.4g}"


def _model_page(model: str, rows: list, cols: list) -> str:
    """The meshes of one model side by side: a column each (thumbnail, viewer link), a row per
    index column (Table 1, the key metrics, the tags)."""
    head = ['<th></th>']
    for r in rows:
        img = (f'<img src="../thumbs/{r["id"]}.jpg" alt="" width="240" height="180">' if r["thumb"]
               else '<div class="nothumb">no thumbnail</div>')
        name = html.escape(r["name"])
        link = f'<a href="../viewer.html?m={r["id"]}">{name}</a>' if r["viewer"] else name
        err = f'<div class="error">{html.escape(r["error"])}</div>' if r["error"] else ""
        head.append(f'<th class="mesh">{img}<div>{link}</div>{err}</th>')
    body = []
    for c in cols:
        if c["key"] == "model":
            continue
        cells = "".join(f'<td class="{c["kind"]}">{_fmt(r["values"].get(c["key"]), c.get("format"))}</td>' for r in rows)
        body.append(f'<tr><th title="{html.escape(c["title"])}">{html.escape(c["label"])}</th>{cells}</tr>')
    return _page(f"{model} — hbc gallery", f"""
<header><a href="../index.html">← gallery</a><h1>model {html.escape(model)}</h1><span>{len(rows)} mesh(es)</span></header>
<table id="side-by-side"><thead><tr>{''.join(head)}</tr></thead><tbody>{''.join(body)}</tbody></table>
<script>document.body.dataset.state = 'ready';</script>""", "../gallery.css")
