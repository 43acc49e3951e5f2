"""hbc.gallery() on a Dask cluster: a LocalCluster of 2 worker processes through the executor its
client gives (Client.get_executor()), against the same gallery made locally: the same rows (the
stage times aside), each mesh measured by a worker of the cluster. Dask's own scheduler and
workers, started here: nothing is mocked.

Runs in the Dask environment (scripts/env/dask_env.sh), started by tests/python/run_dask_test.sh
(ctest python_gallery_dask).
"""

import json

from distributed import Client, LocalCluster, get_task_stream

import hbc

MESHES = ["hybrid-base-complex/teapot.hedra", "openvolumemesh/Cylinder.ovm", "openvolumemesh/Cylinder.ovmb"]
BROKEN = "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n"


def _rows_but_timings(site):
    rows = json.loads((site / "gallery.json").read_text())["rows"]
    for r in rows:
        r["values"] = {k: v for k, v in r["values"].items() if not k.startswith("timings.")}
    return rows


def test_dask_local_cluster_gives_the_local_gallery(shared_data_dir, tmp_path):
    broken = tmp_path / "broken.mesh"
    broken.write_text(BROKEN)
    files = [str(shared_data_dir / m) for m in MESHES] + [str(broken)]
    local = hbc.gallery(files, tmp_path / "local", thumbnails=False, progress=False)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        with get_task_stream(client) as stream:
            remote = hbc.gallery(files, tmp_path / "dask", executor=client.get_executor(), thumbnails=False,
                                 progress=False)
        workers = set(cluster.scheduler_info["workers"])
    units = [t for t in stream.data if str(t["key"]).startswith("measure_mesh")]
    assert len(units) == len(files) and {t["worker"] for t in units} <= workers, stream.data
    assert remote["measured"] == local["measured"] == len(files)
    assert list(remote["failed"]) == list(local["failed"]) == [str(broken)]
    assert _rows_but_timings(tmp_path / "dask") == _rows_but_timings(tmp_path / "local")
    # The viewer's copies of the meshes came back from the workers byte for byte.
    for m in (tmp_path / "local" / "meshes").glob("*.js"):
        assert (tmp_path / "dask" / "meshes" / m.name).read_bytes() == m.read_bytes()
