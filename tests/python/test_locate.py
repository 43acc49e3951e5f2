"""Where the Python side looks for the pieces (hbc/locate.py; docs/development.md, "Where hbc looks
for its pieces"): each piece's variable first, then the build tree the package sits in, then PATH.

The package under test is the build's (PYTHONPATH=<build>/python), so its build tree is the one
holding the `hbc` command ctest names (HBC_CLI) and the add-on. The rules of an installed package
(no build tree) are checked on a copy of locate.py outside any build tree. Run by ctest
python_compare with Debian's Python.
"""

import importlib.util
import os
import pathlib
import shutil

import pytest

import hbc
from hbc import locate

PIECES = ("HBC_CLI", "HBC_BLENDER", "HBC_ADDON_DIR", "HBC_RENDER_FIGURES", "HBC_VIEWER", "HBC_CHROMIUM")
#: The command ctest built (read before any test clears the variable).
BUILT_CLI = os.environ.get("HBC_CLI")


@pytest.fixture
def clean_env(monkeypatch, tmp_path):
    """No piece's variable set and a PATH of one empty folder (returned), so that only the rule
    under test can find anything."""
    for name in PIECES:
        monkeypatch.delenv(name, raising=False)
    path = tmp_path / "bin"
    path.mkdir()
    monkeypatch.setenv("PATH", str(path))
    return path


@pytest.fixture
def installed(tmp_path):
    """locate.py as an installed package holds it: site-packages/hbc/locate.py, no build tree above."""
    pkg = tmp_path / "site-packages" / "hbc"
    pkg.mkdir(parents=True)
    shutil.copy(locate.__file__, pkg / "locate.py")
    spec = importlib.util.spec_from_file_location("installed_hbc_locate", pkg / "locate.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def executable(folder: pathlib.Path, name: str) -> pathlib.Path:
    p = folder / name
    p.write_text("#!/bin/sh\nexit 0\n")
    p.chmod(0o755)
    return p


def build_root() -> pathlib.Path:
    return pathlib.Path(hbc.__file__).resolve().parents[2]


def test_the_package_knows_its_build_tree(installed):
    assert locate.build_dir() == build_root()
    assert (build_root() / "CMakeCache.txt").is_file()
    assert installed.build_dir() is None


def test_hbc_command(clean_env, installed, monkeypatch, tmp_path):
    # Beside the package in its build tree: the command ctest built.
    assert BUILT_CLI, "HBC_CLI is not set (path of the built `hbc` command)"
    assert pathlib.Path(locate.hbc_command()).samefile(BUILT_CLI)
    # The variable wins over the build tree.
    monkeypatch.setenv("HBC_CLI", "/opt/x/hbc")
    assert locate.hbc_command() == "/opt/x/hbc"
    monkeypatch.delenv("HBC_CLI")
    # Installed: PATH, else an error naming the variable.
    with pytest.raises(installed.LocateError, match="HBC_CLI"):
        installed.hbc_command()
    on_path = executable(clean_env, "hbc")
    assert installed.hbc_command() == str(on_path)


def test_blender(clean_env, monkeypatch):
    with pytest.raises(locate.LocateError, match="HBC_BLENDER"):
        locate.blender()
    on_path = executable(clean_env, "blender")
    assert locate.blender() == str(on_path)
    monkeypatch.setenv("HBC_BLENDER", "/opt/blender-4.5/blender")
    assert locate.blender() == "/opt/blender-4.5/blender"


def test_chromium(clean_env, monkeypatch):
    with pytest.raises(locate.LocateError, match="HBC_CHROMIUM"):
        locate.chromium()
    on_path = executable(clean_env, "chromium-browser")
    assert locate.chromium() == str(on_path)
    monkeypatch.setenv("HBC_CHROMIUM", "/opt/chrome/chrome")
    assert locate.chromium() == "/opt/chrome/chrome"


def test_viewer_page(clean_env, installed, monkeypatch, tmp_path):
    """The build tree's web/viewer.html when scripts/build_web.sh has made it; $HBC_VIEWER first;
    an installed package without the variable names it."""
    built = build_root() / "web" / "viewer.html"
    if built.is_file():
        assert locate.viewer_page() == built
    with pytest.raises(installed.LocateError, match="HBC_VIEWER"):
        installed.viewer_page()
    monkeypatch.setenv("HBC_VIEWER", str(tmp_path / "v.html"))
    assert locate.viewer_page() == tmp_path / "v.html"


def test_addon_and_its_figures_script(clean_env, installed, monkeypatch, tmp_path):
    built = build_root() / "addon" / "hybrid_base_complex"
    assert locate.addon_dir() == built
    assert locate.figures_script() == built / "figures" / "render_figures.py"
    with pytest.raises(installed.LocateError, match="HBC_ADDON_DIR"):
        installed.addon_dir()
    # The variable names the add-on; the script is always the add-on's own.
    copy = tmp_path / "addons" / "hybrid_base_complex"
    (copy / "figures").mkdir(parents=True)
    (copy / "figures" / "render_figures.py").write_text("")
    monkeypatch.setenv("HBC_ADDON_DIR", str(copy))
    assert locate.addon_dir() == copy and installed.addon_dir() == copy
    assert locate.figures_script() == copy / "figures" / "render_figures.py"
    # An add-on without figures is refused, saying what is missing.
    (copy / "figures" / "render_figures.py").unlink()
    with pytest.raises(locate.LocateError, match="render_figures.py is missing"):
        locate.figures_script()


def test_render_figures_variable_is_a_deprecated_alias(clean_env, monkeypatch, tmp_path):
    script = tmp_path / "render_figures.py"
    monkeypatch.setenv("HBC_RENDER_FIGURES", str(script))
    with pytest.warns(FutureWarning, match="HBC_RENDER_FIGURES is deprecated"):
        assert locate.figures_script() == script


def test_metrics_doc(installed):
    # The build tree's source folder (this repository) holds docs/metrics.md.
    repo = pathlib.Path(__file__).resolve().parents[2]
    assert locate.metrics_doc() == (repo / "docs" / "metrics.md").resolve().as_uri()
    assert installed.metrics_doc() == "docs/metrics.md"


def test_report_uses_no_other_rule():
    """hbc.report and hbc.comparison read no piece's variable themselves: locate.py is the one place
    the Python side looks (the deprecated alias included)."""
    package = pathlib.Path(hbc.__file__).parent
    for name in ("report.py", "comparison.py", "__init__.py", "_gallery.py", "_gallery_site.py", "_thumbnails.py"):
        text = (package / name).read_text()
        for var in PIECES + ("HBC_PYTHON",):
            assert f'environ.get("{var}"' not in text and f'environ["{var}"' not in text, (name, var)
        assert "CMakeCache" not in text and "shutil.which" not in text, name
