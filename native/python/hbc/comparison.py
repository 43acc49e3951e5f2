"""``hbc.compare``: several meshes measured side by side in this process (docs/compare.md).

Each mesh is one work unit — load, analysis and metrics through the compiled module, which releases
the GIL — run on a ``concurrent.futures.Executor`` (a thread pool by default; any other: a process
pool, Dask's ``Client.get_executor()``, Ray's, mpi4py's ``MPIPoolExecutor``; submitit's, whose jobs
are polled) and collected as it finishes. metrics.json, metrics.csv and metrics.tex are written by the library's
writers (hbc/comparison.hpp), the text ``hbc compare`` writes; report.html by ``hbc.report``, here.
No ``hbc`` command runs: the one process chain left is CLI → ``python -m hbc.report`` → Blender.
"""

from __future__ import annotations

import concurrent.futures
import json
import os
import pathlib
import time
import warnings


class CompareError(RuntimeError):
    """With check=True: a mesh or the report failed."""


def _check_reading(format, threads) -> None:
    """Refuses what hbc.load would refuse, before any work is handed out."""
    if format is not None:
        from . import FORMATS

        # The library's rule (format_from_name): a name or alias of FORMATS, in any case.
        known = {f["name"] for f in FORMATS} | {f["alias"] for f in FORMATS if f["alias"]}
        if not isinstance(format, str) or format.lower() not in known:
            names = ", ".join(f["name"] for f in FORMATS)
            raise ValueError(f"unknown format {format!r} (expected {names})")
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int) or threads < 1):
        raise ValueError("threads must be a positive number or None")


def measure(file: str, format: str | None = None, threads: int | None = None, skip_invalid: bool = False) -> str:
    """The work unit: one mesh loaded and measured as ``hbc compare`` measures it (``hbc metrics``'s
    analysis and metrics, scaled Jacobian histograms per cell type); its JSON document as text.
    Raises hbc.MeshFormatError for a file that cannot be read."""
    from . import _core

    mesh = _core.load(file, format, threads=threads, skip_invalid=skip_invalid)
    return _core._comparison_measurement(mesh, file, threads)


def measure_or_error(file: str, format=None, threads=None, skip_invalid=False) -> tuple[str, str]:
    """What an executor runs: (measurement text, "") or ("", the error as ``hbc compare`` words it).
    The error is caught where it happens, so that no exception object has to cross a process or
    machine boundary."""
    try:
        return measure(file, format, threads, skip_invalid), ""
    except MemoryError:
        return "", "out of memory"
    except Exception as e:  # noqa: BLE001 -- any failure is this mesh's column, as in the CLI
        return "", str(e) or type(e).__name__


def _measure_all(files, executor, format, threads, skip_invalid):
    """Every file's (measurement, error) through `executor`, in file order, collected as they finish.
    A unit the executor itself loses (a worker process that died) fails its column alone."""
    measurements, errors = [""] * len(files), [""] * len(files)
    futures = {}
    for i, f in enumerate(files):
        try:
            futures[executor.submit(measure_or_error, f, format, threads, skip_invalid)] = i
        except concurrent.futures.BrokenExecutor as e:  # broken by an earlier unit
            errors[i] = _lost(e)
    for future in _as_completed(futures):
        i = futures[future]
        try:
            measurements[i], errors[i] = future.result()
        except Exception as e:  # noqa: BLE001
            errors[i] = _lost(e)
    return measurements, errors


def _as_completed(futures):
    """The futures as they finish: concurrent.futures' own, or, for an executor whose submit gives
    other objects with done() and result() (submitit's jobs), by polling them."""
    if all(isinstance(f, concurrent.futures.Future) for f in futures):
        yield from concurrent.futures.as_completed(futures)
        return
    pending = list(futures)
    while pending:
        finished = [f for f in pending if f.done()]
        pending = [f for f in pending if f not in finished]
        yield from finished
        if pending and not finished:
            time.sleep(0.2)


def _lost(e: BaseException) -> str:
    return f"the executor lost the measurement ({type(e).__name__}: {e})"


def compare(paths, out, names=None, figures: bool = False, jobs: int = 2, check: bool = False, *,
            format: str | None = None, threads: int | None = None, skip_invalid: bool = False,
            executor: concurrent.futures.Executor | None = None, report: bool = True) -> dict:
    """Measures the meshes at ``paths`` into the folder ``out`` (metrics.json, metrics.csv,
    metrics.tex: the text ``hbc compare`` writes, timings aside; then report.html) and returns
    metrics.json as a dict (``["errors"]`` names the meshes that failed; their values are None).

    executor: where each mesh is measured (work unit: one mesh; any concurrent.futures.Executor,
    used and left running); None: a ThreadPoolExecutor of ``jobs`` threads, which measure at once
    since the compiled module releases the GIL. A mesh that fails, or whose worker dies, gets its
    error in its column, as in the CLI. names: one column name per path (default: the file names).

    format, threads and skip_invalid read every mesh as ``hbc.load`` takes them (the command's
    ``--format``, ``--threads``, ``--skip-invalid``); a name or count hbc.load would refuse raises
    ValueError before anything runs, as do names that are not one per path.

    report: draw report.html (hbc.report, matplotlib) in this process; figures: with the Blender
    panels (hbc.locate says where Blender and the add-on are looked for). A report that cannot be
    drawn is a warning, its tables being complete. check=True raises CompareError instead, for a
    failed mesh too."""
    from . import _core

    _check_reading(format, threads)
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise ValueError("jobs must be a positive number")
    files = [os.fspath(p) for p in paths]
    given = [str(n) for n in names] if names else []
    _core._comparison_names(files, given)  # the names' count, checked before any work
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    if executor is None:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            measurements, errors = _measure_all(files, pool, format, threads, skip_invalid)
    else:
        measurements, errors = _measure_all(files, executor, format, threads, skip_invalid)
    tables = _core._comparison_tables(files, given, measurements, errors, skip_invalid)
    for name, text in zip(("metrics.json", "metrics.csv", "metrics.tex"), tables):
        (out / name).write_bytes(text)
    data = json.loads(tables[0])
    problems = [f"{n}: {e}" for n, e in data["errors"].items()]
    if report:
        from . import report as report_module

        try:
            report_module.write_report(out, figures=figures)
        except report_module.ReportError as e:
            problems.append(f"report.html not written: {e}")
            if not check:
                warnings.warn(f"hbc.compare: report.html not written: {e}", RuntimeWarning, stacklevel=2)
    if check and problems:
        raise CompareError("hbc.compare: " + "; ".join(problems))
    return data
