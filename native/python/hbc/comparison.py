"""``hbc.compare``: the ``hbc compare`` command from Python (docs/compare.md).

Runs the command, which measures the meshes (one child process each), writes metrics.json,
metrics.csv, metrics.tex and, through ``python -m hbc.report``, report.html; returns metrics.json.
Imports nothing beyond the standard library, so ``import hbc`` stays as light as before.
"""

from __future__ import annotations

import json
import os
import pathlib
import shutil
import subprocess
import sys


class CompareError(RuntimeError):
    """hbc compare could not run, or (with check=True) a mesh or the report failed."""


def find_cli() -> str:
    """The ``hbc`` command: $HBC_CLI, else BUILD/bin/hbc beside this package's build folder, else PATH."""
    env = os.environ.get("HBC_CLI")
    if env:
        return env
    beside = pathlib.Path(__file__).resolve().parent.parent.parent / "bin" / "hbc"
    if beside.is_file():
        return str(beside)
    found = shutil.which("hbc")
    if found:
        return found
    raise CompareError("the hbc command is not found (set HBC_CLI to its path)")


def _reading_args(format, threads, skip_invalid) -> list:
    """The command's reading options for hbc.load's keywords, checked as hbc.load checks them."""
    args = []
    if format is not None:
        from . import FORMATS  # the compiled module, loaded already by ``import hbc``

        # The library's rule (format_from_name): a name or alias of FORMATS, in any case.
        known = {f["name"] for f in FORMATS} | {f["alias"] for f in FORMATS if f["alias"]}
        if not isinstance(format, str) or format.lower() not in known:
            names = ", ".join(f["name"] for f in FORMATS)
            raise ValueError(f"unknown format {format!r} (expected {names})")
        args += ["--format", format]
    if threads is not None:
        if isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
            raise ValueError("threads must be a positive number or None")
        args += ["--threads", str(threads)]
    if skip_invalid:
        args.append("--skip-invalid")
    return args


def compare(paths, out, names=None, figures: bool = False, jobs: int = 2, check: bool = False, *,
            format: str | None = None, threads: int | None = None, skip_invalid: bool = False) -> dict:
    """Runs ``hbc compare`` on ``paths`` into the folder ``out`` and returns its metrics.json as a
    dict (``["errors"]`` names the meshes that failed; their values are None). The report is drawn
    by this interpreter unless HBC_PYTHON says otherwise. With check=True a failed mesh or report
    raises CompareError; otherwise the outputs are returned as they are.

    format, threads and skip_invalid read every mesh as ``hbc.load`` takes them (the command's
    ``--format``, ``--threads``, ``--skip-invalid``): a format name of hbc.FORMATS or None for by
    extension; threads per mesh or None for HBC_THREADS, else every core; skip_invalid drops the
    cells that cannot be volumes (``["meshes"][i]["dropped"]`` says which) instead of failing the
    column. Raises ValueError for a format name or thread count hbc.load would refuse."""
    cmd = [find_cli(), "compare", *map(str, paths), "-o", str(out), "-j", str(jobs)]
    if names:
        cmd += ["--names", ",".join(names)]
    if figures:
        cmd.append("--figures")
    cmd += _reading_args(format, threads, skip_invalid)
    env = dict(os.environ)
    env.setdefault("HBC_PYTHON", sys.executable)
    run = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if run.returncode not in (0, 2) or (check and run.returncode != 0):
        raise CompareError(f"hbc compare failed (exit status {run.returncode}):\n{run.stderr}")
    p = pathlib.Path(out) / "metrics.json"
    if not p.is_file():
        raise CompareError(f"hbc compare wrote no metrics.json:\n{run.stderr}")
    return json.loads(p.read_text(encoding="utf-8"))
