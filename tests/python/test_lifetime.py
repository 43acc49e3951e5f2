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

    # The bound is meaningful: one mesh costs at least its exposed arrays (1.8 MB for this one; the
    # C++ side holds more incidences), so a mesh leaked per cycle would add at least 100 MB over the
    # 100 cycles, 25 times the bound, and even the float32 copy of the points alone (87 kB a cycle,
    # 8.7 MB in all) would exceed it.
    bound = 4e6
    m = hbc.load(path)
    per_mesh = sum(getattr(m, name).nbytes for name in PROPERTIES
                   if isinstance(getattr(m, name), np.ndarray))
    assert 100 * per_mesh >= 25 * bound, per_mesh
    assert 100 * m.points.nbytes > bound, m.points.nbytes
    assert growth < bound, f"resident memory grew by {growth / 1e6:.1f} MB over 100 cycles"


def test_load_releases_the_gil(tmp_path, hbc_cli, main_thread_share, held_gil_share):
    # The shared meshes load in 20-30 ms, too quick for the main thread's CPU share to mean much next
    # to starting and joining the thread: a generated 60^3 grid (216,000 hexes, 14 MB) takes about
    # 0.1 s a load.
    path = tmp_path / "grid60.mesh"
    subprocess.run([hbc_cli, "generate", "grid", "--size", "60", "60", "60", "-o", str(path)],
                   check=True, capture_output=True)
    share, elapsed = main_thread_share(lambda: hbc.load(path))
    assert elapsed > 0.1, "the loads were too quick to tell"
    assert share > 0.15 or share > 3 * held_gil_share, (share, held_gil_share, elapsed)
