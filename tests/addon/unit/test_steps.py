"""plan/steps.py, the builds in steps without Blender: a job run at once and the same job stepped
give the same result; work runs in a worker thread while the stepper returns to its caller; a
failure inside the work reaches the job (its `with` blocks unwind) and the caller; a cancel closes
the job where it stands; the overall progress follows the plan's weights."""

import threading
import time

import pytest

from hybrid_base_complex.plan import steps
from hybrid_base_complex.plan.steps import Phase, Work


class Undo:
    """Stands for scene.Transaction: records whether the job's block ended by an exception."""

    def __init__(self, log):
        self.log = log

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, tb):
        self.log.append("rolled back" if exc_type is not None else "kept")
        return False


def job(log, work=lambda x: x * 2, gate=None):
    """load (work in a thread), then three chunks of a layer, inside one 'transaction'."""
    with Undo(log):
        yield Phase("load", "loading")
        value = yield Work(work, 21)
        log.append(("loaded", value, threading.current_thread() is threading.main_thread()))
        yield "loaded"
        yield Phase("components", "building")
        for i in range(3):
            log.append(("chunk", i))
            yield (i + 1) / 3
    return value


def test_direct_and_stepped_runs_agree():
    direct_log, stepped_log = [], []
    assert steps.run_direct(job(direct_log)) == 42
    st = steps.Stepper(job(stepped_log), steps.phases(["load", "components"]))
    assert st.run() == 42 and st.done and st.fraction == 1.0
    assert direct_log == stepped_log == [("loaded", 42, True), ("chunk", 0), ("chunk", 1), ("chunk", 2), "kept"]
    assert set(st.times) == {"load", "components"}


def test_work_runs_in_a_thread_while_the_caller_goes_on():
    """advance() returns while the work runs (the window redraws meanwhile), the work ran off the
    main thread, and its result reaches the job once it ended."""
    gate = threading.Event()
    ran_on = []

    def work(x):
        ran_on.append(threading.current_thread() is threading.main_thread())
        gate.wait(5)
        return x + 1

    log = []
    st = steps.Stepper(job(log, work), steps.phases(["load", "components"]))
    assert not st.advance(0.01)
    assert st.waiting() and st.phase == "load" and st.message == "loading"
    for _ in range(3):
        assert not st.advance(0.01)  # still waiting: nothing of the job ran on
    assert log == []
    gate.set()
    while not st.advance(0.01):
        time.sleep(0.001)
    assert ran_on == [False] and st.result == 22 and log[-1] == "kept"


def test_failing_work_unwinds_the_job():
    def work(_x):
        raise ValueError("bad file")

    for threads in (True, False):
        log = []
        st = steps.Stepper(job(log, work), steps.phases(["load"]), threads=threads)
        with pytest.raises(ValueError, match="bad file"):
            st.run()
        assert log == ["rolled back"] and st.done
    log = []
    with pytest.raises(ValueError, match="bad file"):
        steps.run_direct(job(log, work))
    assert log == ["rolled back"]


def test_cancel_half_way_closes_the_job():
    log = []
    st = steps.Stepper(job(log), steps.phases(["load", "components"]), threads=False)
    while ("chunk", 1) not in log:
        st.advance(0.0)  # one step at a time
    st.cancel()
    assert st.done and st.cancelled and log[-1] == "rolled back" and ("chunk", 2) not in log
    assert st.advance() is True  # nothing more runs


def test_cancel_while_the_work_runs_drops_its_result():
    gate = threading.Event()
    log = []
    st = steps.Stepper(job(log, lambda x: gate.wait(5) and x), steps.phases(["load"]))
    st.advance(0.0)  # the phase
    st.advance(0.0)  # the work started
    assert st.waiting()
    st.cancel()
    assert log == ["rolled back"]
    gate.set()


def test_progress_follows_the_weights():
    """Phases by weight: load 2, analysis 6, components 2 -> 0.2, 0.8, 1.0; the reports come at each
    phase's start and end, a chunk moves within its phase."""
    plan = steps.phases(["load", "analysis", "components"])
    assert [(k, round(a, 3), round(b, 3)) for k, a, b in plan] == \
        [("load", 0.0, 0.2), ("analysis", 0.2, 0.8), ("components", 0.8, 1.0)]
    assert [k for k, _, _ in steps.import_phases(True, ["direct"])] == ["load", "analysis", "direct"]
    assert [k for k, _, _ in steps.build_phases(["sheets"], False)] == ["sheets"]
    reports = []

    def three():
        yield Phase("load", "loading")
        yield "loaded"
        yield Phase("analysis", "analyzing")
        yield 0.5
        mid = st.fraction
        yield "analyzed"
        yield Phase("components", "building")
        return mid

    st = steps.Stepper(three(), plan, threads=False, report=lambda f, m: reports.append((round(f, 3), m)))
    assert round(st.run(), 3) == 0.5
    assert reports == [(0.0, "loading"), (0.2, "loaded"), (0.2, "analyzing"), (0.8, "analyzed"), (0.8, "building")]
