"""hbc.compare() on a Dask cluster: a LocalCluster of 2 worker processes, through the executor a
Dask client gives (Client.get_executor(), a concurrent.futures.Executor), and on submitit's
executor (local jobs), against the same comparison run locally. Dask's own scheduler and workers,
submitit's own jobs, started here: nothing is mocked.

Runs in the Dask environment (scripts/env/dask_env.sh: `distributed` and `submitit` from PyPI on
the build's CPython), started by tests/python/run_dask_test.sh (ctest python_compare_dask). No matplotlib
there: report=False (the report is tested in test_compare.py).
"""

from distributed import Client, LocalCluster, get_task_stream

import hbc

MESHES = ["hybrid-base-complex/cube_twist-comp.obj.HYBRID", "hybrid-base-complex/teapot.hedra",
          "hybrid-base-complex/twistcube_s.mesh"]
BROKEN = "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n"


def test_dask_local_cluster_gives_the_local_results(shared_data_dir, tmp_path, same_but_timings):
    broken = tmp_path / "broken.mesh"
    broken.write_text(BROKEN)
    files = [str(shared_data_dir / m) for m in MESHES]
    files.insert(1, str(broken))
    local = hbc.compare(files, tmp_path / "local", report=False)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        with get_task_stream(client) as stream:
            data = hbc.compare(files, tmp_path / "dask", executor=client.get_executor(), report=False)
        workers = set(cluster.scheduler_info["workers"])
    # One unit per mesh, each run by a worker of the cluster (not in this process).
    units = [t for t in stream.data if str(t["key"]).startswith("measure_or_error")]
    assert len(units) == len(files) and {t["worker"] for t in units} <= workers, stream.data
    for name in ("metrics.json", "metrics.csv", "metrics.tex"):
        assert same_but_timings(tmp_path / "dask" / name, tmp_path / "local" / name), name
    assert data["errors"] == local["errors"] and list(data["errors"]) == ["broken.mesh"]
    assert data["values"]["census.cells"][0] == 493


def test_submitit_local_jobs_give_the_local_results(shared_data_dir, tmp_path, same_but_timings):
    """submitit's executor (the SLURM form: AutoExecutor(folder) on a cluster; cluster="local" runs
    each job as a process here), whose jobs are not concurrent.futures futures: hbc.compare polls
    them. The same tables as the local run."""
    import submitit

    files = [str(shared_data_dir / m) for m in MESHES[:2]]
    hbc.compare(files, tmp_path / "local", report=False, threads=1)
    executor = submitit.AutoExecutor(folder=tmp_path / "jobs", cluster="local")
    executor.update_parameters(timeout_min=10)
    data = hbc.compare(files, tmp_path / "submitit", executor=executor, report=False, threads=1)
    assert data["errors"] == {}
    # Each mesh ran as a job of its own: submitit's folder holds one result per job.
    assert len(list((tmp_path / "jobs").glob("*_result.pkl"))) == len(files)
    for name in ("metrics.json", "metrics.csv", "metrics.tex"):
        assert same_but_timings(tmp_path / "submitit" / name, tmp_path / "local" / name), name
