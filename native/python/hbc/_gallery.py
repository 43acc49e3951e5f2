"""``hbc.gallery``: a browsable static site of a whole collection of meshes (docs/gallery.md).

One work unit per mesh — load, the analysis of ``hbc analyze`` (Table 1), ``Analysis.metrics()``
and the thumbnail's input (the mesh's bytes, gzipped, for the site's viewer) — runs on any
``concurrent.futures.Executor`` (a thread pool by default; Dask's ``Client.get_executor()``, Ray's,
mpi4py's, submitit's), its result streamed back as it finishes and cached at once in the site
folder under the hash of the mesh's content and of what was asked (``cache/ID.json``): a re-run, an
interrupted run or a run with new meshes measures only what is not there. The thumbnails are made
afterwards on this machine, by the viewer page in headless Chromium (hbc._thumbnails). The site
(index.html, viewer.html, models/*.html) is written from the cache (hbc._gallery_site).

    python -m hbc._gallery DIR|FILES... -o SITE [--tags CSV] [-j N] [--dask ADDRESS] [--json-progress]
"""

from __future__ import annotations

import argparse
import concurrent.futures
import csv
import gzip
import hashlib
import json
import os
import pathlib
import sys
import time

from .comparison import _as_completed, _check_reading
from .progress import Progress

#: The folder layout tags are read from: SITE's input DIR/model/mesher/file.
TAG_LEVELS = ("model", "mesher")
#: Bumped when the work unit's result changes shape: older cache entries are measured again.
CACHE_FORMAT = 1
_EXCLUDED_FORMATS = {"exodus", "cgns", "med"}  # the page's core has not their libraries (docs/web.md)


class GalleryError(RuntimeError):
    """With check=True: a mesh failed; or nothing to show."""


# ---- the work unit -------------------------------------------------------------------------------

def measure_mesh(file: str, format=None, threads=None, skip_invalid=False, viewer_bytes=True) -> dict:
    """What an executor runs for one mesh: {"info", "stats" (Table 1 and the rest of ``hbc analyze
    --json``, with "timings"), "metrics" (``Analysis.metrics()``), "seconds", "viewer": {"name",
    "gzip"} or None} — or {"error": the words ``hbc analyze`` would print}. The error is caught
    here so that no exception object crosses a process or machine boundary."""
    try:
        return _measure(file, format, threads, skip_invalid, viewer_bytes)
    except MemoryError:
        return {"error": "out of memory"}
    except Exception as e:  # noqa: BLE001 -- any failure is this mesh's row
        return {"error": str(e) or type(e).__name__}


def _measure(file, format, threads, skip_invalid, viewer_bytes):
    from . import _core

    t0 = time.perf_counter()
    mesh = _core.load(file, format, threads=threads, skip_invalid=skip_invalid)
    t1 = time.perf_counter()
    analysis = mesh.analyze(threads=threads)
    t2 = time.perf_counter()
    metrics = analysis.metrics(threads=threads)
    t3 = time.perf_counter()
    return {"info": dict(mesh.info()), "stats": dict(analysis.stats), "metrics": metrics,
            "warnings": list(mesh.warnings),
            "seconds": {"load": t1 - t0, "analysis": t2 - t1, "metrics": t3 - t2},
            "viewer": _viewer_input(file, format, skip_invalid) if viewer_bytes else None}


def _viewer_input(file, format, skip_invalid):
    """The mesh as the site's viewer reads it: the file's own bytes, gzipped, under its own name,
    when it is one file the page's WebAssembly core reads; else None (the row says why)."""
    from . import FORMATS

    path = pathlib.Path(file)
    if not path.is_file() or skip_invalid or format:
        return None
    fmt = _format_of(path.name, FORMATS)
    if fmt is None or fmt in _EXCLUDED_FORMATS:
        return None
    return {"name": path.name, "gzip": gzip.compress(path.read_bytes(), compresslevel=6, mtime=0)}


def _format_of(name: str, formats) -> str | None:
    lower = name.lower()
    best = None
    for f in formats:
        for ext in f["extensions"]:
            if lower.endswith(ext.lower()) and (best is None or len(ext) > best[1]):
                best = (f["name"], len(ext))
    return best[0] if best else None


# ---- the collection ------------------------------------------------------------------------------

def collect(paths) -> list[dict]:
    """The meshes of ``paths``: each file itself; each folder's files (recursively, sorted) whose
    extension names a format hbc reads. Each as {"file", "rel"}: rel is the path below the folder
    given (the tags are read from it), or the file's name."""
    from . import FORMATS

    found = []
    for p in paths:
        p = pathlib.Path(p)
        if p.is_dir():
            for f in sorted(p.rglob("*")):
                if f.is_file() and _format_of(f.name, FORMATS) and not f.name.startswith("."):
                    found.append({"file": str(f), "rel": f.relative_to(p).as_posix()})
        elif p.exists():
            found.append({"file": str(p), "rel": p.name})
        else:
            raise FileNotFoundError(f"{p}: no such file or folder")
    return found


def folder_tags(rel: str) -> dict:
    """Tags from the layout ``model/mesher/file`` below the folder given: a file two folders down
    has both; one folder down, that folder is its mesher and the model is the file's name up to its
    first dot; at the top, the model only."""
    parts = rel.split("/")
    stem = parts[-1].split(".")[0]
    if len(parts) >= 3:
        return {"model": parts[-3], "mesher": parts[-2]}
    if len(parts) == 2:
        return {"model": stem, "mesher": parts[0]}
    return {"model": stem, "mesher": ""}


def read_tags(csv_path) -> dict:
    """``--tags CSV``: a header row whose first column names the file (a path as given, a path below
    the folder given, or a file name), then one column per tag ("model", "mesher" or any other).
    Returns {file key: {tag: value}}."""
    with open(csv_path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows or len(rows[0]) < 2:
        raise ValueError(f"{csv_path}: line 1: expected a header: file,TAG[,TAG...]")
    header = [h.strip() for h in rows[0]]
    tags = {}
    for line, row in enumerate(rows[1:], start=2):
        if not row or not "".join(row).strip():
            continue
        if len(row) != len(header):
            raise ValueError(f"{csv_path}: line {line}: {len(row)} fields, the header has {len(header)}")
        tags[row[0].strip()] = {h: v.strip() for h, v in zip(header[1:], row[1:])}
    return tags


def _tags_for(mesh: dict, given: dict) -> dict:
    tags = folder_tags(mesh["rel"])
    for key in (mesh["file"], mesh["rel"], pathlib.Path(mesh["file"]).name):
        if key in given:
            tags.update({k: v for k, v in given[key].items() if v or k not in tags})
            break
    return tags


def content_key(file: str, options: dict) -> str:
    """The cache key: SHA-256 of the mesh's bytes (a folder's files, by name) and of what the
    result depends on (hbc's version, the reading options, the cache format)."""
    from . import __version__

    h = hashlib.sha256(json.dumps([__version__, CACHE_FORMAT, options], sort_keys=True).encode())
    path = pathlib.Path(file)
    files = sorted(f for f in path.rglob("*") if f.is_file()) if path.is_dir() else [path]
    for f in files:
        h.update(f.relative_to(path).as_posix().encode() if path.is_dir() else b"")
        with open(f, "rb") as data:
            for block in iter(lambda: data.read(1 << 20), b""):
                h.update(block)
    return h.hexdigest()


# ---- the run ---------------------------------------------------------------------------------------

def _entry_path(out: pathlib.Path, mesh: dict) -> pathlib.Path:
    return out / "cache" / f"{mesh['id']}.json"


def _write_atomic(path: pathlib.Path, data: bytes) -> None:
    """Written whole or not at all: an interrupted run leaves no half entry to be taken as done."""
    tmp = path.with_name(path.name + ".part")
    tmp.write_bytes(data)
    os.replace(tmp, path)


def _store(out: pathlib.Path, mesh: dict, result: dict) -> None:
    """One finished unit, kept at once: the viewer's copy of the mesh, then its cache entry (the
    entry last, so that an entry found means everything of it is there)."""
    viewer = result.pop("viewer", None)
    if viewer:
        import base64

        text = (f"hbcGalleryMesh({json.dumps(viewer['name'])},"
                f"\"{base64.b64encode(viewer['gzip']).decode('ascii')}\");\n")
        _write_atomic(out / "meshes" / f"{mesh['id']}.js", text.encode())
        result["viewer"] = viewer["name"]
    entry = {"key": mesh["key"], "file": mesh["file"], "result": result}
    _write_atomic(_entry_path(out, mesh), json.dumps(entry).encode())


def _cached(out: pathlib.Path, mesh: dict) -> dict | None:
    try:
        entry = json.loads(_entry_path(out, mesh).read_text())
    except (OSError, ValueError):
        return None
    return entry["result"] if entry.get("key") == mesh["key"] else None


def _measure_missing(out, todo, executor, reading, progress) -> dict:
    """Hands each mesh to `executor` and keeps each result as it comes back. A unit the executor
    itself loses (a worker that died, a lost machine) is that mesh's error in this run's row but is
    not kept: the next run measures it again. Returns {id: that error}."""
    futures, lost = {}, {}

    def lose(m, e):
        lost[m["id"]] = {"error": f"the executor lost the measurement ({type(e).__name__}: {e})"}
        progress.step(m["rel"], lost[m["id"]]["error"])

    for m in todo:
        try:
            futures[executor.submit(measure_mesh, m["file"], *reading)] = m
        except concurrent.futures.BrokenExecutor as e:  # broken by an earlier unit
            lose(m, e)
    for future in _as_completed(futures):
        m = futures[future]
        try:
            result = future.result()
        except Exception as e:  # noqa: BLE001
            lose(m, e)
            continue
        _store(out, m, result)
        progress.step(m["rel"], result.get("error", ""))
    return lost


def gallery(paths, out, *, executor: concurrent.futures.Executor | None = None, jobs: int = 2,
            tags=None, thumbnails: bool = True, format: str | None = None, threads: int | None = None,
            skip_invalid: bool = False, progress: bool = True, json_progress: bool = False,
            check: bool = False) -> dict:
    """Makes (or brings up to date) the static site of the meshes at ``paths`` (files, or folders
    searched for every format hbc reads) in the folder ``out``; returns a summary: {"meshes",
    "measured" (the ones not in the cache), "failed" ({file: error}), "thumbnails" (what was made,
    or why none), "index" (index.html's path)}.

    executor: where each mesh is measured (work unit: one mesh; any concurrent.futures.Executor,
    used and left running); None: a ThreadPoolExecutor of ``jobs`` threads. tags: a CSV file of
    tags per mesh (read_tags), over those of the folder layout model/mesher/file. thumbnails:
    make the missing ones in headless Chromium (hbc._thumbnails; its absence is said in the
    summary, not an error). format, threads, skip_invalid: as hbc.load takes them. progress: a bar
    on stderr; json_progress: JSON lines on stdout instead (hbc.progress). check=True raises
    GalleryError when a mesh failed."""
    from . import _gallery_site, _thumbnails

    _check_reading(format, threads)
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise ValueError("jobs must be a positive number")
    meshes = collect(paths)
    if not meshes:
        raise GalleryError(f"no mesh found in {', '.join(map(str, paths))}")
    given = read_tags(tags) if tags else {}
    out = pathlib.Path(out)
    for sub in ("cache", "meshes", "thumbs", "models"):
        (out / sub).mkdir(parents=True, exist_ok=True)
    for m in meshes:
        m["key"] = content_key(m["file"], {"format": format, "skip_invalid": skip_invalid})
        m["id"] = m["key"][:20]
        m["tags"] = _tags_for(m, given)
    todo = [m for m in meshes if _cached(out, m) is None]
    unit_threads = threads if threads is not None or executor is not None else max(1, (os.cpu_count() or 1) // jobs)
    reading = (format, unit_threads, skip_invalid)
    bar = Progress("measure", len(todo), json_lines=json_progress, bar=progress)
    if executor is None:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            lost = _measure_missing(out, todo, pool, reading, bar)
    else:
        lost = _measure_missing(out, todo, executor, reading, bar)
    bar.close()
    for m in meshes:
        m["result"] = _cached(out, m) or lost.get(m["id"]) or {"error": "no result was kept"}
    made = (_thumbnails.make(out, meshes, jobs=jobs, json_progress=json_progress, progress=progress)
            if thumbnails else "thumbnails not asked for")
    index = _gallery_site.write(out, meshes)
    failed = {m["file"]: m["result"]["error"] for m in meshes if "error" in m["result"]}
    summary = {"meshes": len(meshes), "measured": len(todo), "failed": failed, "thumbnails": made,
               "index": str(index)}
    if check and failed:
        raise GalleryError("hbc.gallery: " + "; ".join(f"{f}: {e}" for f, e in failed.items()))
    return summary


# ---- the command -----------------------------------------------------------------------------------

def _dask_executor(address: str):
    """Dask's executor on the scheduler at `address` (its workers need this hbc package); the client
    is closed with the process."""
    try:
        from distributed import Client
    except ImportError as e:
        raise GalleryError(f"--dask needs Dask's distributed package in this Python ({e})") from e
    return Client(address).get_executor()


def main(argv=None) -> int:
    """``hbc gallery`` (the command runs ``python -m hbc._gallery``): exit 0 when every mesh was
    measured, 1 when some failed (their rows say why), 2 for bad arguments or no mesh."""
    ap = argparse.ArgumentParser(prog="hbc gallery", description="a browsable static site of a collection of "
                                 "meshes: index.html, a viewer, one side-by-side page per model (docs/gallery.md)")
    ap.add_argument("paths", nargs="+", metavar="DIR|FILE", help="mesh files, or folders searched for them")
    ap.add_argument("-o", "--out", required=True, help="the site's folder (created; its cache makes re-runs incremental)")
    ap.add_argument("--tags", help="CSV: file,TAG,... (model, mesher or any tag) over the folder layout model/mesher/file")
    ap.add_argument("-j", "--jobs", type=int, default=2, help="meshes measured at once (default 2)")
    ap.add_argument("--dask", metavar="SCHEDULER_ADDRESS", help="measure on this Dask cluster (tcp://host:8786)")
    ap.add_argument("--no-thumbnails", action="store_true", help="make no thumbnails (no Chromium started)")
    ap.add_argument("--json-progress", action="store_true", help="progress as JSON lines on stdout, no bar")
    ap.add_argument("--format", help="read every mesh as this format")
    ap.add_argument("--threads", type=int, help="threads of each mesh's analysis")
    ap.add_argument("--skip-invalid", action="store_true", help="drop the cells that cannot be volumes")
    args = ap.parse_args(argv)
    try:
        executor = _dask_executor(args.dask) if args.dask else None
        summary = gallery(args.paths, args.out, executor=executor, jobs=args.jobs, tags=args.tags,
                          thumbnails=not args.no_thumbnails, format=args.format, threads=args.threads,
                          skip_invalid=args.skip_invalid, json_progress=args.json_progress)
    except (GalleryError, ValueError, OSError) as e:
        print(f"hbc gallery: error: {e}", file=sys.stderr)
        return 2
    print(f"hbc gallery: {summary['meshes']} mesh(es), {summary['measured']} measured, "
          f"{len(summary['failed'])} failed; {summary['thumbnails']}; wrote {summary['index']}", file=sys.stderr)
    if args.json_progress:
        print(json.dumps({"event": "summary", **summary}), flush=True)
    return 1 if summary["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
