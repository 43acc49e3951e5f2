"""The build's hbc module gives the same arrays under NumPy 2 as under NumPy 1 (issue 62).

Run by ctest with the independent checks' Python (scripts/env/check_env.sh: the build's CPython
3.11 with the newest NumPy 2.x); HBC_NUMPY1_PYTHON is the Python the module is built for (Debian's
/usr/bin/python3, NumPy 1.24), PYTHONPATH the build's package, HBC_DATA_DIR the shared meshes.
dump_arrays.py runs once under each, on every shared mesh, and every array must be equal bit for
bit (dtype, shape and bytes). A module built with a pybind11 older than 2.12 (Debian's 2.10.3)
fails here: under NumPy 2 its arrays have stride 0, every element equal to the first.
"""

import ast
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest
from conftest import env

HERE = pathlib.Path(__file__).resolve().parent


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """{'numpy2': (folder, manifest), 'numpy1': (...)}: dump_arrays.py under each Python."""
    out = {}
    for name, python, major in [("numpy2", sys.executable, 2), ("numpy1", env("HBC_NUMPY1_PYTHON"), 1)]:
        folder = tmp_path_factory.mktemp(name)
        r = subprocess.run([python, str(HERE / "dump_arrays.py"), str(major), str(folder)],
                           capture_output=True, text=True, timeout=600)
        assert r.returncode == 0, f"dump_arrays.py under {python} exited {r.returncode}:\n{r.stderr[-4000:]}"
        out[name] = folder, json.loads((folder / "manifest.json").read_text())
    return out


def test_one_module_under_two_numpy_versions(runs):
    (_, new), (_, old) = runs["numpy2"], runs["numpy1"]
    assert int(new["numpy"].split(".")[0]) >= 2, new["numpy"]
    assert int(old["numpy"].split(".")[0]) == 1, old["numpy"]
    assert new["module"] == old["module"], "the two runs imported different hbc._core files"
    build = pathlib.Path(env("PYTHONPATH").split(os.pathsep)[0]).resolve()
    assert pathlib.Path(new["module"]).resolve().is_relative_to(build), (new["module"], build)
    assert new["meshes"] == old["meshes"] and len(new["meshes"]) >= 10, new["meshes"]


def first_difference(a, b):
    """None when a and b are the same array bit for bit (NaN included), else how they differ."""
    if a.dtype != b.dtype or a.shape != b.shape:
        return f"{a.dtype}{a.shape} against {b.dtype}{b.shape}"
    if a.tobytes() == b.tobytes():
        return None
    if a.ndim == 0:
        return f"{a} against {b}"
    fa, fb = np.ascontiguousarray(a).reshape(-1), np.ascontiguousarray(b).reshape(-1)
    bad = np.flatnonzero((fa.view(np.uint8).reshape(fa.size, -1) != fb.view(np.uint8).reshape(fb.size, -1)).any(axis=1))
    i = int(bad[0])
    return f"{len(bad)} of {fa.size} elements differ; element {i}: {fa[i]!r} under NumPy 2, {fb[i]!r} under NumPy 1"


def test_every_array_equal(runs):
    (new_dir, manifest), (old_dir, _) = runs["numpy2"], runs["numpy1"]
    problems, compared = [], 0
    for i, mesh in enumerate(manifest["meshes"]):
        with np.load(new_dir / f"{i}.npz") as new, np.load(old_dir / f"{i}.npz") as old:
            if set(new.files) != set(old.files):
                problems.append(f"{mesh}: only under NumPy 2: {sorted(set(new.files) - set(old.files))}, "
                                f"only under NumPy 1: {sorted(set(old.files) - set(new.files))}")
            for key in sorted(set(new.files) & set(old.files)):
                compared += 1
                why = first_difference(new[key], old[key])
                if why:
                    problems.append(f"{mesh}: {key}: {why}")
    assert not problems, f"{len(problems)} of {compared} arrays differ:\n" + "\n".join(problems[:60])
    assert compared > 1000, compared


def stub_array_properties():
    """class name -> the properties _core.pyi annotates as numpy arrays."""
    tree = ast.parse((HERE.parents[1] / "native/python/hbc/_core.pyi").read_text())
    aliases = {"I32", "U8", "Bool"}
    out = {}
    for cls in (n for n in tree.body if isinstance(n, ast.ClassDef)):
        names = {f.name for f in cls.body if isinstance(f, ast.FunctionDef)
                 and any(getattr(d, "id", None) == "property" for d in f.decorator_list)
                 and f.returns is not None
                 and (getattr(f.returns, "id", None) in aliases or "NDArray" in ast.unparse(f.returns))}
        if names:
            out[cls.name] = names
    return out


def test_every_array_property_was_compared(runs):
    """Every class of the stub with array properties was walked, and the binding's array
    properties are the stub's: a new array (or class) is compared or this fails."""
    (_, manifest) = runs["numpy1"]
    walked = {c: set(names) for c, names in manifest["classes"].items()}
    stub = stub_array_properties()
    assert {"Mesh", "Analysis", "SingularityGraph", "BaseComplex", "Subsheets", "Wireframe"} <= set(stub)
    assert set(stub) <= set(walked), f"never walked: {sorted(set(stub) - set(walked))}"
    for c, names in stub.items():
        assert walked[c] == names, (c, sorted(walked[c] ^ names))
