"""plan/figures_job.py without Blender: the command lines, where render_figures.py is found (in the
add-on package), what stops it from running, the child's environment, and a
job's progress, exit status and cancel on stand-in processes (a Python printing what the script
prints)."""
import os
import pathlib
import sys
import time

from hybrid_base_complex.plan import figures_job as F

PRINTS = "import sys, time\nfor i in range({n}):\n    print(f'wrote /x/m_{{i}}.png', flush=True)\n{tail}"


def run_to_end(job, limit=20.0):
    t = time.perf_counter()
    while (status := job.poll()) is None:
        assert time.perf_counter() - t < limit
        time.sleep(0.02)
    return status


ADDON = pathlib.Path(__file__).resolve().parents[3] / "addon" / "hybrid_base_complex"


def test_command_for_blender_and_for_the_bpy_module():
    blender = F.command("/usr/bin/blender", "/py", "s.py", "m.mesh", "out", "workbench", (64, 48), 2)
    assert blender[:7] == ["/usr/bin/blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python", "s.py"]
    # No --addon: the script is the add-on's own and renders with the package it belongs to.
    assert blender[7:] == ["--", "m.mesh", "--out", "out", "--engine", "workbench",
                           "--resolution", "64", "48", "--samples", "2"]
    module = F.command("", "/venv/bin/python", "s.py", "m.mesh", "out")
    assert module[:3] == ["/venv/bin/python", "s.py", "m.mesh"] and "--" not in module
    assert "--subsheet-rule" not in module  # the script's default (layers) unless the panel says
    fewest = F.command("", "/py", "s.py", "m.mesh", "out", subsheet_rule="fewest")
    assert fewest[-2:] == ["--subsheet-rule", "fewest"]


def test_figure_script_takes_the_subsheet_rule():
    """render_figures.py's options (the add-on's figures/plan.py) take the rule the job passes."""
    from hybrid_base_complex.figures import plan

    args = plan.parse(F.command("", "/py", "s.py", "m.mesh", "out", subsheet_rule="fewest")[2:])
    assert args.subsheet_rule == "fewest" and plan.parse(["m.mesh", "--out", "o"]).subsheet_rule == "layers"


def test_the_script_ships_in_the_add_on_package():
    """The entry file is found in the add-on's own folder, whatever surrounds it (no source or build
    tree: an installed add-on has neither)."""
    assert F.find_script(str(ADDON)) == str(ADDON / F.SCRIPT)
    assert (ADDON / "figures" / "script.py").is_file()


def test_the_extension_packs_the_figures():
    """pack_extension.py (the 4.2+ package) takes every file of figures/ with the add-on; the legacy
    zip is the assembled folder itself (addon/assemble.cmake copies every .py; the installed zip's
    Figures runs in tests/addon/blender/test_installed_figures.py)."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("pack_extension", ADDON.parent / "pack_extension.py")
    pack = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(pack)
    shipped = {f"figures/{p.name}" for p in (ADDON / "figures").glob("*.py")}
    assert "figures/render_figures.py" in shipped and len(shipped) >= 5
    assert shipped <= set(pack.addon_sources(str(ADDON)))


def test_problem_is_said_before_anything_is_asked(tmp_path):
    """Why Figures cannot run, in words: the script missing from this copy of the add-on, the
    compiled module not importing, no Blender to start; None when it can run."""
    blender = sys.executable  # an executable file standing where Blender's would be
    assert F.problem(str(ADDON), blender, sys.executable) is None
    assert F.problem(str(ADDON), "", sys.executable) is None  # the bpy module: its Python runs the script
    damaged = tmp_path / "hybrid_base_complex"
    damaged.mkdir()
    why = F.problem(str(damaged), blender, sys.executable)
    assert "figures/render_figures.py" in why and str(damaged) in why and "install the add-on again" in why
    assert F.find_script(str(damaged)) is None
    module = "The compiled hbc module is built for CPython 3.11 (...)"
    assert F.problem(str(ADDON), blender, sys.executable, module) == f"Cannot render figures: {module}"
    assert "no Blender executable" in F.problem(str(ADDON), str(tmp_path / "blender"), sys.executable)


def test_child_environment(tmp_path):
    """The child takes this Python first on PATH; an hbc module from outside the add-on (the
    extension's wheel) is put on PYTHONPATH, the add-on's bundled copy is not."""
    env = {"PATH": "/usr/bin", "PYTHONPATH": "/x"}
    addon = tmp_path / "hybrid_base_complex"
    bundled = F.child_env(env, "/opt/py/bin/python3", str(addon / "hbc" / "__init__.py"), str(addon))
    assert bundled["PATH"] == "/opt/py/bin" + os.pathsep + "/usr/bin" and bundled["PYTHONPATH"] == "/x"
    site = tmp_path / "site-packages"
    wheel = F.child_env(env, "/opt/py/bin/python3", str(site / "hbc" / "__init__.py"), str(addon))
    assert wheel["PYTHONPATH"] == str(site) + os.pathsep + "/x"
    assert env == {"PATH": "/usr/bin", "PYTHONPATH": "/x"}  # the caller's mapping is left as it was


def test_progress_counts_written_files_and_keeps_the_status():
    job = F.Job([sys.executable, "-c", PRINTS.format(n=4, tail="sys.exit(0)")], expected_files=8)
    assert run_to_end(job) == 0
    assert job.written == [f"/x/m_{i}.png" for i in range(4)] and job.fraction == 0.5
    failed = F.Job([sys.executable, "-c", PRINTS.format(n=1, tail="print('boom'); sys.exit(3)")])
    assert run_to_end(failed) == 3 and failed.tail[-1] == "boom"


def test_cancel_stops_the_process_at_once():
    job = F.Job([sys.executable, "-c", PRINTS.format(n=1, tail="time.sleep(60)")])
    t = time.perf_counter()
    while not job.written:
        job.poll()
        time.sleep(0.02)
        assert time.perf_counter() - t < 20
    job.cancel()
    assert job.cancelled and run_to_end(job) is not None and time.perf_counter() - t < 20
    assert job.proc.returncode != 0
