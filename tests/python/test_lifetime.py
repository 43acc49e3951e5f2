"""Resources: no memory growth over repeated loads, and the GIL released while C++ works."""

import subprocess

import numpy as np

import hbc

PROPERTIES = [name for name in dir(hbc.Mesh)
              if not name.startswith("_") and name not in ("info", "from_arrays")]


def test_no_leak_over_100_load_cycles(shared_data_dir, tmp_path, resident_growth):
    path = shared_data_dir / "cinolib" / "ellipsoid.mesh"  # 7,293 vertices, 6,816 hexes
    missing = tmp_path / "missing.mesh"

    def cycle():
        m = hbc.load(path)
        for name in PROPERTIES:
            getattr(m, name)
        m.info()
        repr(m)
        hbc.Mesh.from_arrays(m.points64, m.face_vertices_offsets, m.face_vertices_items, m.cell_faces_offsets,
                             m.cell_faces_items, m.cell_face_flip)
        try:
            hbc.load(missing)
        except hbc.MeshFormatError:
            pass

    growth = resident_growth(cycle)

    # What one mesh costs at least (its exposed arrays; the C++ side holds more incidences), so
    # that the bound is known to be meaningful: leaking a whole mesh per cycle would exceed it a
    # hundredfold, and even the float32 copy of the points alone (87 kB a cycle) would exceed it.
    m = hbc.load(path)
    per_mesh = sum(getattr(m, name).nbytes for name in PROPERTIES
                   if isinstance(getattr(m, name), np.ndarray))
    assert per_mesh > 1e6
    assert growth < 4e6, f"resident memory grew by {growth / 1e6:.1f} MB over 100 cycles"


def test_load_releases_the_gil(tmp_path, hbc_cli, main_thread_share):
    # The shared meshes now load in 20-30 ms, too quick for the main thread's CPU share to mean
    # much next to starting and joining the thread: a generated 60^3 grid (216,000 hexes, 14 MB) takes about 0.1 s a load.
    path = tmp_path / "grid60.mesh"
    subprocess.run([hbc_cli, "generate", "grid", "--size", "60", "60", "60", "-o", str(path)],
                   check=True, capture_output=True)
    share, elapsed = main_thread_share(lambda: hbc.load(path))
    assert elapsed > 0.1, "the loads were too quick to tell"
    assert share > 0.15, (share, elapsed)
