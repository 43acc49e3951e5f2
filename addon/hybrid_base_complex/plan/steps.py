"""Long builds in steps, without ``bpy``: a build is a generator (a *job*) that yields where the
scene is whole, so the same code runs blocking (background mode, scripts) or between the window's
redraws (a modal operator), and a cancel is a `close()` at one of those points (the job's
`scene.Transaction` then rolls back what it made).

A job yields:
- `Work(fn, *args)`: C++ work that touches no Blender data (reading, analysing, the soups); the
  result is sent back into the job. The stepper runs it in a worker thread (the module releases
  the GIL), the direct run inline.
- `Phase(key, message)`: the next phase of the job's plan starts (the overall progress and the
  status text follow the plan's weights, `phases`).
- a float in [0, 1]: the share of the current phase done (e.g. objects written of all).
- a str: the current phase is done, as the message says (e.g. "loaded 1301 cells").
- None: a point where the window may redraw.
"""

from __future__ import annotations

import threading
import time


class Work:
    """C++ work off the main thread: `fn(*args)` must not touch Blender data (nor write to objects
    the main thread reads: its result is applied by the job when sent back)."""

    __slots__ = ("fn", "args")

    def __init__(self, fn, *args):
        self.fn, self.args = fn, args

    def __call__(self):
        return self.fn(*self.args)


class Phase:
    __slots__ = ("key", "message")

    def __init__(self, key: str, message: str):
        self.key, self.message = key, message


def run_direct(job):
    """Runs a job to its end on this thread (Work inline) and returns its return value."""
    send, value = job.send, None
    try:
        while True:
            item = send(value)
            send, value = job.send, None
            if isinstance(item, Work):
                try:
                    value = item()
                except Exception as e:  # noqa: BLE001 - into the job, whose transaction rolls back
                    send, value = job.throw, e
    except StopIteration as stop:
        return stop.value


# What each phase costs, relative to the others (measured on the 988k-cell cylinder in Blender 3.4:
# docs/performance.md); a phase not listed weighs 1.
WEIGHTS = {"load": 2.0, "analysis": 6.0, "direct": 1.0, "graph": 0.3, "components": 2.0, "sheets": 2.0,
           "wireframe": 1.0, "sheet": 0.5, "subsheets": 1.0}


def phases(keys, weights=None) -> list:
    """[(key, start, end)]: each phase's share of the whole job, from 0 to 1, in order."""
    weights = WEIGHTS if weights is None else weights
    w = [max(float(weights.get(k, 1.0)), 1e-6) for k in keys]
    total, out, at = sum(w), [], 0.0
    for k, x in zip(keys, w):
        out.append((k, at / total, (at + x) / total))
        at += x
    return out


def import_phases(analyze: bool, layers) -> list:
    """The phases of an import: the file read, its analysis, then the layers it builds."""
    return phases(["load"] + (["analysis"] if analyze else []) + list(layers))


def build_phases(layers, analysis: bool) -> list:
    """The phases of a build of `layers` (one, or Build All's), after an analysis when the mesh
    needs one first."""
    return phases((["analysis"] if analysis else []) + list(layers))


class Stepper:
    """Drives a job between redraws: `advance(budget)` runs the job's main-thread steps for about
    `budget` seconds (at least one) and returns; a `Work` runs in a worker thread meanwhile and its
    result is sent back at the first `advance` after it ends. `fraction` and `message` say where
    the job is (by the plan `phases`); `done` and `result` once it returned. An exception of the job
    or of its work propagates out of `advance` (the job has then ended: its transaction rolled
    back). `threads=False` runs Work inline (tests step through a job deterministically)."""

    def __init__(self, job, plan, threads: bool = True, report=None, clock=time.perf_counter):
        self.job, self.threads, self.clock = job, threads, clock
        self.report = report or (lambda fraction, message: None)  # called at each Phase and message
        self.spans = {k: (a, b) for k, a, b in plan}
        self.fraction, self.message = 0.0, ""
        self.phase = None
        self.done, self.result, self.cancelled = False, None, False
        self.times: dict[str, float] = {}  # seconds per phase, wall clock
        self._phase_t = None
        self._worker = None  # (thread, box) of the running Work

    def _enter(self, item: Phase):
        self._close_phase()
        self.phase, self.message = item.key, item.message
        self._phase_t = self.clock()
        self.fraction = self.spans.get(item.key, (self.fraction, self.fraction))[0]
        self.report(self.fraction, self.message)

    def _close_phase(self):
        if self.phase is not None:
            self.times[self.phase] = self.times.get(self.phase, 0.0) + self.clock() - self._phase_t
            self.fraction = self.spans.get(self.phase, (self.fraction, self.fraction))[1]

    def _within(self, share: float):
        a, b = self.spans.get(self.phase, (self.fraction, self.fraction))
        self.fraction = max(self.fraction, a + (b - a) * min(max(float(share), 0.0), 1.0))

    def _start(self, work: Work):
        box = {}

        def run():
            try:
                box["value"] = work()
            except Exception as e:  # noqa: BLE001 - handed to the job on the main thread
                box["error"] = e

        if not self.threads:
            run()
            self._worker = (None, box)
            return

        # A daemon: a cancelled build does not wait for its C++ work, whose result nobody takes.
        thread = threading.Thread(target=run, name="hbc-step", daemon=True)
        self._worker = (thread, box)
        thread.start()

    def _send(self):
        """One step of the job; False when it waits for its worker."""
        if self._worker is not None:
            thread, box = self._worker
            if thread is not None and thread.is_alive():
                return False
            self._worker = None
            if "error" in box:
                item = self.job.throw(box["error"])
            else:
                item = self.job.send(box.get("value"))
        else:
            item = self.job.send(None)
        if isinstance(item, Work):
            self._start(item)
        elif isinstance(item, Phase):
            self._enter(item)
        elif isinstance(item, float):
            self._within(item)
        elif isinstance(item, str):
            self._within(1.0)
            self.message = item
            self.report(self.fraction, item)
        return True

    def advance(self, budget: float = 0.05) -> bool:
        """Runs steps for about `budget` seconds; True once the job has ended."""
        if self.done:
            return True
        end = self.clock() + budget
        try:
            while self._send() and self.clock() < end:
                pass
        except StopIteration as stop:
            self._close_phase()
            self.done, self.result, self.fraction = True, stop.value, 1.0
        except BaseException:
            self.done = True
            raise
        return self.done

    def waiting(self) -> bool:
        """Whether a worker thread is running the job's C++ work."""
        return self._worker is not None and self._worker[0] is not None and self._worker[0].is_alive()

    def cancel(self):
        """Ends the job where it stands (its transaction rolls back); a running worker is left to
        finish alone, its result dropped."""
        if not self.done:
            self.done = self.cancelled = True
            self._worker = None
            self.job.close()

    def run(self):
        """To the end without stopping (the job's Work still in threads when `threads`)."""
        while not self.advance(1.0):
            if self.waiting():
                self._worker[0].join()
        return self.result
