"""Progress of a batch (hbc.gallery): a bar with rate and ETA on the terminal (rich, else tqdm,
else one plain line per step) and, for programs, one JSON object a line (``--json-progress``).

A JSON line: {"event": "start", "stage", "total"}, then {"event": "step", "stage", "done",
"total", "name", "ok", "error", "rate" (steps/s), "eta" (s)} per finished unit, then
{"event": "end", "stage", "done", "seconds"}.
"""

from __future__ import annotations

import json
import sys
import time


class Progress:
    """One stage of a batch ("measure", "thumbnails"): ``step(name, error)`` per finished unit.
    bar=False and json_lines=False: silent."""

    def __init__(self, stage: str, total: int, *, json_lines: bool = False, bar: bool = True, stream=None):
        self.stage, self.total, self.done = stage, total, 0
        self.json_lines = json_lines
        self.stream = stream or (sys.stdout if json_lines else sys.stderr)
        self.t0 = time.monotonic()
        self.quiet = not bar and not json_lines
        self._bar = _make_bar(stage, total) if bar and not json_lines and total else None
        self._emit({"event": "start", "stage": stage, "total": total})

    def step(self, name: str, error: str = "") -> None:
        self.done += 1
        elapsed = time.monotonic() - self.t0
        rate = self.done / elapsed if elapsed > 0 else None
        eta = (self.total - self.done) / rate if rate else None
        self._emit({"event": "step", "stage": self.stage, "done": self.done, "total": self.total, "name": name,
                    "ok": not error, "error": error, "rate": rate, "eta": eta})
        if self._bar:
            self._bar.advance(name)
        elif not self.json_lines and not self.quiet:
            what = f"FAILED: {error}" if error else "ok"
            print(f"hbc gallery: {self.stage} [{self.done}/{self.total}] {name}: {what}", file=self.stream)

    def close(self) -> None:
        if self._bar:
            self._bar.close()
        self._emit({"event": "end", "stage": self.stage, "done": self.done,
                    "seconds": round(time.monotonic() - self.t0, 3)})

    def _emit(self, obj: dict) -> None:
        if self.json_lines:
            self.stream.write(json.dumps(obj) + "\n")
            self.stream.flush()


def _make_bar(stage: str, total: int):
    """rich's bar (rate and ETA columns), else tqdm's (which shows both); None when neither is
    installed or stderr is no terminal (then one line per step)."""
    if not sys.stderr.isatty():
        return None
    try:
        return _RichBar(stage, total)
    except ImportError:
        pass
    try:
        return _TqdmBar(stage, total)
    except ImportError:
        return None


class _RichBar:
    def __init__(self, stage, total):
        from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn,
                                   TimeRemainingColumn)

        self._p = Progress(TextColumn(f"hbc gallery: {stage}"), BarColumn(), MofNCompleteColumn(),
                           TextColumn("{task.fields[rate]}"), TimeElapsedColumn(), TextColumn("ETA"),
                           TimeRemainingColumn(), TextColumn("{task.fields[name]}"), transient=False)
        self._p.start()
        self._task = self._p.add_task(stage, total=total, rate="", name="")
        self._t0 = time.monotonic()
        self._done = 0

    def advance(self, name):
        self._done += 1
        rate = self._done / max(time.monotonic() - self._t0, 1e-9)
        self._p.update(self._task, advance=1, rate=f"{rate:.2f} mesh/s", name=name)

    def close(self):
        self._p.stop()


class _TqdmBar:
    def __init__(self, stage, total):
        from tqdm import tqdm

        self._t = tqdm(total=total, desc=f"hbc gallery: {stage}", unit="mesh")

    def advance(self, name):
        self._t.set_postfix_str(name, refresh=False)
        self._t.update(1)

    def close(self):
        self._t.close()
