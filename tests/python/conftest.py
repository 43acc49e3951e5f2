"""Shared fixtures of the binding tests.

Environment (set by ctest, see CMakeLists.txt here): PYTHONPATH holds the built package,
HBC_DATA_DIR the shared real meshes, HBC_CLI the `hbc` command whose output the binding must match.
A missing variable makes the tests that need it fail, never skip: a silent skip would pass CI.
"""

import os
import pathlib

import pytest

# File endings the readers support (the .HYBRID ending is matched case-insensitively like the CLI).
MESH_SUFFIXES = (".ovm", ".ovmb", ".mesh", ".hybrid", ".hedra")

TABLE1 = "hybrid-base-complex/"
#: The three Table 1 meshes we hold and two others (a tiny hybrid one and a polyhedral one): the
#: meshes of the `analyzed` fixture.
MESHES = [TABLE1 + "teapot.hedra", TABLE1 + "twistcube_s.mesh", TABLE1 + "cube_twist-comp.obj.HYBRID",
          TABLE1 + "test_2.HYBRID", "cinolib/eight_voronoi.hedra"]


def data_dir():
    value = os.environ.get("HBC_DATA_DIR")
    return pathlib.Path(value) if value else None


def shared_meshes():
    """Every mesh file under HBC_DATA_DIR the readers support, in a stable order."""
    root = data_dir()
    if root is None or not root.is_dir():
        return []
    return sorted(p for p in root.rglob("*") if p.is_file() and p.suffix.lower() in MESH_SUFFIXES)


def pytest_generate_tests(metafunc):
    # A test asking for `shared_mesh` runs once per shared file, named by its path under the data dir.
    if "shared_mesh" in metafunc.fixturenames:
        files = shared_meshes()
        root = data_dir()
        metafunc.parametrize("shared_mesh", files, ids=[str(p.relative_to(root)) for p in files])


@pytest.fixture(scope="session")
def shared_data_dir():
    root = data_dir()
    if root is None:
        pytest.fail("HBC_DATA_DIR is not set")
    if not root.is_dir():
        pytest.fail(f"HBC_DATA_DIR={root} is not a folder")
    return root


@pytest.fixture(scope="session")
def analyzed(shared_data_dir):
    """name -> (mesh, analysis) with the defaults for every mesh of MESHES, computed once."""
    import hbc

    out = {}
    for name in MESHES:
        m = hbc.load(shared_data_dir / name)
        out[name] = (m, m.analyze())
    return out


@pytest.fixture
def resident_growth():
    """Runs `cycle` 10 times (the allocator and caches reach their steady state), then 100 times;
    returns by how many bytes the resident memory grew over the 100. Skips under AddressSanitizer,
    which keeps freed memory in quarantine (the plain build runs these tests)."""
    import gc

    if os.environ.get("HBC_SANITIZED") == "1":
        pytest.skip("ASan keeps freed memory in quarantine; the plain build runs this test")

    def resident_bytes():
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")

    def measure(cycle):
        for _ in range(10):
            cycle()
        gc.collect()
        before = resident_bytes()
        for _ in range(100):
            cycle()
        gc.collect()
        return resident_bytes() - before

    return measure


@pytest.fixture(scope="session")
def hbc_cli():
    value = os.environ.get("HBC_CLI")
    if not value:
        pytest.fail("HBC_CLI is not set (path of the built `hbc` command)")
    if not os.access(value, os.X_OK):
        pytest.fail(f"HBC_CLI={value} is not an executable")
    return value


@pytest.fixture(scope="session")
def main_thread_share():
    """Runs `work` in a thread, at least three times and until 0.3 s have passed, while the main
    thread spins asking for the GIL; returns (the main thread's CPU time over the elapsed time,
    elapsed). Repeating by time, not by a count, keeps the measure long enough to mean something
    as the calls get faster (armadillo's three analyses once took 0.088 s in all). A GIL held in
    C++ blocks the main thread for the whole call, so it gets almost no CPU (about 0.03 here,
    measured with a 0.5 s `sorted()`); released, it runs beside the work and gets its share of a
    core (0.35 or more even with three busy processes beside it). The CPU share, unlike the longest
    gap between two time stamps, does not grow when other jobs on the machine delay the main
    thread."""
    import threading
    import time

    def measure(work):
        done = threading.Event()

        def run():
            calls = 0
            while calls < 3 or time.perf_counter() - wall0 < 0.3:
                work()
                calls += 1
            done.set()

        worker = threading.Thread(target=run)
        cpu0, wall0 = time.thread_time(), time.perf_counter()
        worker.start()
        while not done.is_set():
            pass
        elapsed = time.perf_counter() - wall0
        share = (time.thread_time() - cpu0) / elapsed
        worker.join()
        return share, elapsed

    return measure


@pytest.fixture(scope="session")
def held_gil_share(main_thread_share):
    """The main thread's share beside work that holds the GIL throughout (one `sorted()` of a million
    floats, about 0.5 s in C): the scale of a held GIL on this machine now. A test of a released GIL
    passes when its share is above 0.15 (an idle or lightly loaded machine: 0.35 or more) or three
    times this one: on a machine loaded 10-25 times over by other jobs a released GIL still gave
    0.06-0.14 against 0.013-0.018 held (measured), where a fixed threshold alone failed."""
    import random

    rng = random.Random(1)
    numbers = [rng.random() for _ in range(1_000_000)]
    held, _ = main_thread_share(lambda: sorted(numbers))
    return held


@pytest.fixture(scope="session")
def same_but_timings():
    """compare(a, b): two files of hbc compare (metrics.json, .csv, .tex) equal byte for byte but for
    the per-mesh timings ("load", "analysis", "metrics" under "timings"), whose numbers are masked:
    the one thing two runs of one comparison may write differently."""
    import re

    timing = re.compile(r'("(?:load|analysis|metrics)": )-?[0-9][0-9.e+-]*')

    def compare(a, b):
        return timing.sub(r"\1T", pathlib.Path(a).read_text()) == timing.sub(r"\1T", pathlib.Path(b).read_text())

    compare.pattern = timing
    return compare
