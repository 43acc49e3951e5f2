"""hbc gallery (hbc.gallery, hbc._gallery): the site's data against the library's own numbers, tags
from the folders and from --tags, a failing mesh's row, the cache (a re-run measures only new or
changed meshes; a run killed midway resumes), JSON progress lines, and the command (`hbc gallery`
runs the package's Python). Thumbnails and the pages in a browser: tests/web/gallery.test.mjs.

Environment (ctest python_gallery): PYTHONPATH the built package, HBC_DATA_DIR, HBC_CLI.
"""

import json
import os
import pathlib
import subprocess
import sys

import pytest

import hbc
from hbc import _gallery

#: The reading options the cache key holds (hbc._gallery.gallery's defaults).
OPTIONS = {"format": None, "skip_invalid": False}
BROKEN = "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n"


def _collection(root: pathlib.Path, data: pathlib.Path) -> pathlib.Path:
    """model/mesher/file: two meshes of model Cylinder (.ovm and .ovmb), teapot, one broken file."""
    col = root / "collection"
    for rel, src in [("Cylinder/ovm/Cylinder.ovm", "openvolumemesh/Cylinder.ovm"),
                     ("Cylinder/ovmb/Cylinder.ovmb", "openvolumemesh/Cylinder.ovmb"),
                     ("teapot/authors/teapot.hedra", "hybrid-base-complex/teapot.hedra")]:
        (col / rel).parent.mkdir(parents=True, exist_ok=True)
        (col / rel).symlink_to(data / src)
    (col / "broken" / "hand").mkdir(parents=True)
    (col / "broken" / "hand" / "broken.mesh").write_text(BROKEN)
    (col / "notes.txt").write_text("not a mesh: left out")
    return col


def _rows(site):
    return {r["name"]: r for r in json.loads((site / "gallery.json").read_text())["rows"]}


def test_site_holds_the_librarys_numbers_tags_and_errors(shared_data_dir, tmp_path):
    col = _collection(tmp_path, shared_data_dir)
    summary = hbc.gallery([col], tmp_path / "site", thumbnails=False, progress=False)
    assert summary["meshes"] == 4 and summary["measured"] == 4
    assert list(summary["failed"]) == [str(col / "broken/hand/broken.mesh")]
    rows = _rows(tmp_path / "site")
    assert set(rows) == {"Cylinder/ovm/Cylinder.ovm", "Cylinder/ovmb/Cylinder.ovmb", "teapot/authors/teapot.hedra",
                         "broken/hand/broken.mesh"}
    teapot = rows["teapot/authors/teapot.hedra"]
    a = hbc.load(str(shared_data_dir / "hybrid-base-complex/teapot.hedra")).analyze()
    # Table 1's columns are the analysis' statistics under their keys (the JSON keys are a contract).
    for field, timing in hbc.TABLE1_COLUMNS:
        if not timing:
            assert teapot["values"][field.key] == a.stats[field.key], field.key
    assert teapot["values"]["summary.score"] == a.metrics()["summary"]["score"]
    assert teapot["values"]["model"] == "teapot" and teapot["values"]["mesher"] == "authors"
    assert set(teapot["values"]["cell_kinds"].split()) <= set(hbc.CELL_TYPES)
    assert rows["broken/hand/broken.mesh"]["error"] and rows["broken/hand/broken.mesh"]["values"]["cells"] is None
    # The two Cylinders share one model page, which shows both.
    assert rows["Cylinder/ovm/Cylinder.ovm"]["model_page"] == rows["Cylinder/ovmb/Cylinder.ovmb"]["model_page"]
    page = (tmp_path / "site" / rows["Cylinder/ovm/Cylinder.ovm"]["model_page"]).read_text()
    assert "Cylinder.ovm<" in page and "Cylinder.ovmb<" in page
    index = (tmp_path / "site" / "index.html").read_text()
    assert 'id="gallery-data"' in index and "gallery_index.js" in index
    assert rows["Cylinder/ovm/Cylinder.ovm"]["values"]["cells"] == rows["Cylinder/ovmb/Cylinder.ovmb"]["values"]["cells"]


def test_tags_csv_over_the_folders(shared_data_dir, tmp_path):
    col = _collection(tmp_path, shared_data_dir)
    tags = tmp_path / "tags.csv"
    tags.write_text("file,model,source\nteapot.hedra,Teapot,Utah\nCylinder/ovm/Cylinder.ovm,,OVM\n")
    hbc.gallery([col], tmp_path / "site", tags=tags, thumbnails=False, progress=False)
    rows = _rows(tmp_path / "site")
    assert rows["teapot/authors/teapot.hedra"]["values"]["model"] == "Teapot"
    assert rows["teapot/authors/teapot.hedra"]["values"]["source"] == "Utah"
    assert rows["teapot/authors/teapot.hedra"]["values"]["mesher"] == "authors"  # the folder's, not overridden
    assert rows["Cylinder/ovmb/Cylinder.ovmb"]["values"]["source"] == ""
    bad = tmp_path / "bad.csv"
    bad.write_text("file,model\na,b,c\n")
    with pytest.raises(ValueError, match="line 2"):
        hbc.gallery([col], tmp_path / "site2", tags=bad, thumbnails=False, progress=False)


def test_rerun_measures_only_new_and_changed_meshes(shared_data_dir, tmp_path):
    col = _collection(tmp_path, shared_data_dir)
    site = tmp_path / "site"
    assert hbc.gallery([col], site, thumbnails=False, progress=False)["measured"] == 4
    before = _rows(site)
    assert hbc.gallery([col], site, thumbnails=False, progress=False)["measured"] == 0
    assert _rows(site) == before
    # A new mesh and a changed one (same name, other content): those two only.
    (col / "grid" / "gen").mkdir(parents=True)
    hbc_cli = os.environ["HBC_CLI"]
    subprocess.run([hbc_cli, "generate", "grid", "--size", "3", "3", "2", "-o", str(col / "grid/gen/grid.mesh")],
                   check=True)
    (col / "broken/hand/broken.mesh").write_text(BROKEN + "\n")
    summary = hbc.gallery([col], site, thumbnails=False, progress=False)
    assert summary["meshes"] == 5 and summary["measured"] == 2
    assert _rows(site)["grid/gen/grid.mesh"]["values"]["cells"] == 18


def test_a_killed_run_resumes(shared_data_dir, tmp_path):
    """The run is killed (SIGKILL) once it has reported its first finished mesh; the next run
    measures only the meshes whose results were not kept, and its JSON lines say so."""
    col = _collection(tmp_path, shared_data_dir)
    # A mesh that takes a while, measured after the first ones (file order, one at a time): the run
    # is killed while it is on it.
    (col / "big" / "gen").mkdir(parents=True)
    subprocess.run([os.environ["HBC_CLI"], "generate", "grid", "--size", "40", "40", "40", "-o",
                    str(col / "big/gen/big.mesh")], check=True)
    site = tmp_path / "site"
    env = dict(os.environ)
    cmd = [sys.executable, "-m", "hbc._gallery", str(col), "-o", str(site), "-j", "1", "--no-thumbnails",
           "--json-progress"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True, env=env)
    for line in proc.stdout:
        event = json.loads(line)
        if event["event"] == "step":
            proc.kill()
            break
    proc.wait()
    kept = len(list((site / "cache").glob("*.json")))
    assert 1 <= kept < 5
    assert not (site / "cache" / f"{_gallery.content_key(str(col / 'big/gen/big.mesh'), OPTIONS)[:20]}.json").exists()
    run = subprocess.run(cmd, capture_output=True, text=True, env=env)
    assert run.returncode == 1, run.stderr  # the broken mesh
    events = [json.loads(line) for line in run.stdout.splitlines()]
    start = events[0]
    assert start == {"event": "start", "stage": "measure", "total": 5 - kept}
    steps = [e for e in events if e["event"] == "step"]
    assert [e["done"] for e in steps] == list(range(1, 6 - kept))
    assert "big/gen/big.mesh" in [e["name"] for e in steps]
    assert all(e["total"] == 5 - kept and e["rate"] > 0 and e["eta"] >= 0 for e in steps)
    assert events[-1]["event"] == "summary" and events[-1]["measured"] == 5 - kept
    assert len(_rows(site)) == 5


def test_command_runs_the_packages_gallery(shared_data_dir, tmp_path):
    col = _collection(tmp_path, shared_data_dir)
    run = subprocess.run([os.environ["HBC_CLI"], "gallery", str(col), "-o", str(tmp_path / "site"),
                          "--no-thumbnails", "--json-progress"], capture_output=True, text=True)
    assert run.returncode == 1, run.stderr  # one mesh failed: its row says why
    assert "4 mesh(es), 4 measured, 1 failed" in run.stderr
    assert json.loads(run.stdout.splitlines()[-1])["meshes"] == 4
    helped = subprocess.run([os.environ["HBC_CLI"], "gallery", "--help"], capture_output=True, text=True)
    assert helped.returncode == 0 and "--dask" in helped.stdout and "--tags" in helped.stdout
    none = subprocess.run([os.environ["HBC_CLI"], "gallery", str(tmp_path / "missing"), "-o", str(tmp_path / "s")],
                          capture_output=True, text=True)
    assert none.returncode == 2 and "no such file or folder" in none.stderr


def test_folder_tags_layout():
    assert _gallery.folder_tags("bunny/hexme/b.mesh") == {"model": "bunny", "mesher": "hexme"}
    assert _gallery.folder_tags("x/bunny/hexme/b.mesh") == {"model": "bunny", "mesher": "hexme"}
    assert _gallery.folder_tags("hexalab/armadillo_out.mesh") == {"model": "armadillo_out", "mesher": "hexalab"}
    assert _gallery.folder_tags("teapot.hedra") == {"model": "teapot", "mesher": ""}
