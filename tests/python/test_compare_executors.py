"""hbc.compare() on concurrent.futures executors (hbc/comparison.py): the work unit is one mesh
(load, analysis, metrics in the compiled module), handed to the executor and collected as it
finishes; the tables are written in file order whatever order the units end in.

Three meshes of the paper's data (RHDM, LoopyCuts, At-Most-Hexa) and a broken MEDIT file between
them. The default (a thread pool) is the reference; test_compare.py checks that it writes what the
`hbc compare` command writes. Dask: test_compare_dask.py (its own environment). Run by ctest
python_compare with Debian's Python.
"""

import concurrent.futures
import json
import multiprocessing
import sys

import pytest

import hbc

MESHES = ["hybrid-base-complex/cube_twist-comp.obj.HYBRID", "hybrid-base-complex/teapot.hedra",
          "hybrid-base-complex/twistcube_s.mesh"]
# Announces 3 vertices and gives 1: the reader names the file and line 4.
BROKEN = "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n"


@pytest.fixture(scope="module")
def files(shared_data_dir, tmp_path_factory):
    broken = tmp_path_factory.mktemp("broken") / "broken.mesh"
    broken.write_text(BROKEN)
    paths = [str(shared_data_dir / m) for m in MESHES]
    paths.insert(1, str(broken))
    return paths


@pytest.fixture(scope="module")
def local(files, tmp_path_factory):
    """(out dir, metrics.json) of the default run: a thread pool of 2."""
    out = tmp_path_factory.mktemp("local") / "out"
    return out, hbc.compare(files, out, report=False)


def same_tables(a, b, same_but_timings):
    return all(same_but_timings(a / n, b / n) for n in ("metrics.json", "metrics.csv", "metrics.tex"))


def test_the_local_run(local, files):
    out, data = local
    assert [m["file"] for m in data["meshes"]] == files
    assert list(data["errors"]) == ["broken.mesh"] and data["errors"]["broken.mesh"].startswith(f"{files[1]}:4: ")
    assert all(v > 0 for i, v in enumerate(data["values"]["census.cells"]) if i != 1)
    assert not (out / "report.html").exists()  # report=False


def test_process_pool(files, local, tmp_path, same_but_timings):
    """A process pool (spawned workers: each unit pickled by reference, the module imported anew
    in each worker) gives the local tables."""
    with concurrent.futures.ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as pool:
        data = hbc.compare(files, tmp_path / "p", executor=pool, report=False)
        # The executor is the caller's: used, not shut down.
        assert pool.submit(sum, [1, 2]).result() == 3
    assert same_tables(tmp_path / "p", local[0], same_but_timings)
    assert data["errors"] == local[1]["errors"]


def test_one_thread_or_several(files, local, tmp_path, same_but_timings):
    """Results do not depend on how many meshes are measured at once, nor on the order the units
    finish in (a pool of 3 finishes the small first mesh before the larger ones)."""
    hbc.compare(files, tmp_path / "one", jobs=1, report=False)
    with concurrent.futures.ThreadPoolExecutor(3) as pool:
        hbc.compare(files, tmp_path / "three", executor=pool, report=False)
    assert same_tables(tmp_path / "one", local[0], same_but_timings)
    assert same_tables(tmp_path / "three", local[0], same_but_timings)


def _refuse_to_start():
    sys.exit(3)


def test_a_lost_unit_fails_its_column(files, tmp_path):
    """An executor that loses the units (every worker process of this pool dies while starting)
    fails their columns with what the executor said; the tables are still written."""
    pool = concurrent.futures.ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn"),
                                                  initializer=_refuse_to_start)
    try:
        data = hbc.compare(files[:2], tmp_path / "o", executor=pool, report=False)
    finally:
        pool.shutdown()
    assert data["values"]["census.cells"] == [None, None]
    for name in ("cube_twist-comp.obj.HYBRID", "broken.mesh"):
        assert data["errors"][name].startswith("the executor lost the measurement (BrokenProcessPool"), data["errors"]
    assert json.loads((tmp_path / "o" / "metrics.json").read_text()) == data
    assert (tmp_path / "o" / "metrics.tex").read_text().count("failed") >= 2


def test_measure_is_the_work_unit(files):
    """hbc.comparison.measure: the JSON document of one mesh (what `hbc compare-one` prints); a
    broken file raises the reader's error, which measure_or_error turns into the column's text."""
    doc = json.loads(hbc.comparison.measure(files[0], threads=1))
    assert set(doc) == {"metrics", "scaled_jacobian_by_type"}
    assert doc["metrics"]["file"] == files[0] and doc["metrics"]["census"]["cells"] == 493
    assert sum(doc["scaled_jacobian_by_type"]["hex"]) == doc["metrics"]["census"]["hexahedra"]
    with pytest.raises(hbc.MeshFormatError):
        hbc.comparison.measure(files[1])
    text, error = hbc.comparison.measure_or_error(files[1])
    assert text == "" and error.startswith(f"{files[1]}:4: ")


def test_the_measurement_releases_the_gil(shared_data_dir, main_thread_share, held_gil_share):
    """What makes a thread pool the default: the measurement's analysis and metrics run without the
    GIL (the load's release is test_lifetime.py's), so the other threads run meanwhile."""
    path = shared_data_dir / "hexalab-edge-cone-rectification" / "armadillo_out.mesh"
    mesh = hbc.load(path)
    from hbc import _core

    share, elapsed = main_thread_share(lambda: _core._comparison_measurement(mesh, path, threads=1))
    assert elapsed > 0.1, "the measurements were too quick to tell"
    assert share > 0.15 or share > 3 * held_gil_share, (share, held_gil_share, elapsed)
