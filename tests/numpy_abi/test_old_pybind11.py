"""A module built with a pybind11 older than 2.12 refuses to import under NumPy 2, saying why and how
to rebuild, and works under NumPy 1 (native/python/bindings/numpy_abi.hpp, what hbc._core does
first). The build asks for pybind11 >= 2.12; this is the module one gets anyway with
-DHBC_ALLOW_OLD_PYBIND11=ON. probe/ is compiled against Debian's pybind11 2.10.3
(HBC_OLD_PYBIND11_DIR) for Debian's CPython (HBC_NUMPY1_PYTHON, NumPy 1.24), into HBC_PROBE_BUILD;
this file runs under the checks' Python, the same CPython with NumPy 2.
"""

import os
import pathlib
import subprocess
import sys

import pytest
from conftest import env

HERE = pathlib.Path(__file__).resolve().parent


@pytest.fixture(scope="module")
def probe():
    """The folder holding the probe module, built (again, incrementally) for this run."""
    build = pathlib.Path(env("HBC_PROBE_BUILD"))
    config = [f"-Dpybind11_DIR={env('HBC_OLD_PYBIND11_DIR')}", f"-DPython_EXECUTABLE={env('HBC_NUMPY1_PYTHON')}",
              "-DCMAKE_BUILD_TYPE=Release"]
    if os.environ.get("HBC_CXX_LAUNCHER"):
        config.append(f"-DCMAKE_CXX_COMPILER_LAUNCHER={os.environ['HBC_CXX_LAUNCHER']}")
    for cmd in (["cmake", "-S", str(HERE / "probe"), "-B", str(build), *config], ["cmake", "--build", str(build)]):
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        assert r.returncode == 0, f"{' '.join(cmd)}:\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return build


def run(python, probe, code):
    return subprocess.run([python, "-c", code], capture_output=True, text=True, timeout=120,
                          env={**os.environ, "PYTHONPATH": str(probe)})


def test_probe_is_built_with_a_pybind11_before_2_12(probe):
    r = run(env("HBC_NUMPY1_PYTHON"), probe, "import numpy_abi_probe as p; print(*p.pybind11_version)")
    assert r.returncode == 0, r.stderr
    major, minor = map(int, r.stdout.split())
    assert (major, minor) < (2, 12), "HBC_OLD_PYBIND11_DIR must name a pybind11 that predates NumPy 2"


def test_refuses_to_import_under_numpy2(probe):
    import numpy

    assert int(numpy.__version__.split(".")[0]) >= 2, f"{sys.executable} has NumPy {numpy.__version__}"
    r = run(sys.executable, probe, "import numpy_abi_probe")
    assert r.returncode != 0, f"imported under NumPy {numpy.__version__}: {r.stdout}"
    last = r.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: hbc._core was built with pybind11 2."), last
    assert f"this Python has NumPy {numpy.__version__}" in last, last
    assert "pybind11 2.12 or newer" in last and "scripts/build.sh" in last and "pip install ." in last, last


def test_works_under_numpy1(probe):
    code = ("import numpy, numpy_abi_probe as p; a = p.iota(5)\n"
            "assert numpy.__version__.startswith('1.'), numpy.__version__\n"
            "print(a.tolist(), a.strides)")
    r = run(env("HBC_NUMPY1_PYTHON"), probe, code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[0, 1, 2, 3, 4] (4,)"


def configure(build, *extra):
    """The project's configure (no tests, no benchmarks) with the old pybind11."""
    return subprocess.run(["cmake", "-S", str(HERE.parents[1]), "-B", str(build),
                           f"-Dpybind11_DIR={env('HBC_OLD_PYBIND11_DIR')}",
                           f"-DPython_EXECUTABLE={env('HBC_NUMPY1_PYTHON')}", "-DHBC_BUILD_TESTS=OFF",
                           "-DHBC_BUILD_BENCHMARKS=OFF", *extra], capture_output=True, text=True, timeout=300)


def test_cmake_refuses_an_old_pybind11_unless_told(tmp_path):
    """The project's configure names what it found and how to get a newer pybind11; with
    HBC_ALLOW_OLD_PYBIND11 it takes the old one and warns what the module will do."""
    r = configure(tmp_path / "refused")
    assert r.returncode != 0, r.stdout[-2000:]
    err = " ".join(r.stderr.split())
    assert "needs pybind11 2.12 or newer" in err and "found only 2.10" in err, err[-3000:]
    assert "scripts/env/pybind11.sh" in err and "python -m pybind11 --cmakedir" in err, err[-3000:]
    r = configure(tmp_path / "allowed", "-DHBC_ALLOW_OLD_PYBIND11=ON")
    assert r.returncode == 0, r.stderr[-3000:]
    err = " ".join(r.stderr.split())
    assert "pybind11 2.10" in err and "refuse to import under NumPy 2" in err, err[-3000:]
