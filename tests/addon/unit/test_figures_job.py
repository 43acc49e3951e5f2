"""plan/figures_job.py without Blender: the command lines, where render_figures.py is found, and a
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


def test_command_for_blender_and_for_the_bpy_module():
    blender = F.command("/usr/bin/blender", "/py", "s.py", "m.mesh", "out", "addon", "workbench", (64, 48), 2)
    assert blender[:7] == ["/usr/bin/blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python", "s.py"]
    assert blender[7:] == ["--", "m.mesh", "--out", "out", "--addon", "addon", "--engine", "workbench",
                           "--resolution", "64", "48", "--samples", "2"]
    module = F.command("", "/venv/bin/python", "s.py", "m.mesh", "out", "addon")
    assert module[:3] == ["/venv/bin/python", "s.py", "m.mesh"] and "--" not in module
    assert "--subsheet-rule" not in module  # the script's default (layers) unless the panel says
    fewest = F.command("", "/py", "s.py", "m.mesh", "out", "addon", subsheet_rule="fewest")
    assert fewest[-2:] == ["--subsheet-rule", "fewest"]


def test_figure_script_takes_the_subsheet_rule():
    """render_figures.py's options (blender_scripts/figures/plan.py) take the rule the job passes."""
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "blender_scripts"))
    try:
        from figures import plan
    finally:
        sys.path.pop(0)
    args = plan.parse(F.command("", "/py", "s.py", "m.mesh", "out", "addon", subsheet_rule="fewest")[2:])
    assert args.subsheet_rule == "fewest" and plan.parse(["m.mesh", "--out", "o"]).subsheet_rule == "layers"


def test_script_found_beside_the_sources_and_through_a_build_tree(tmp_path):
    src, build = tmp_path / "src", tmp_path / "build"
    (src / "blender_scripts").mkdir(parents=True)
    (src / F.SCRIPT).write_text("")
    (build / "addon" / "hybrid_base_complex").mkdir(parents=True)
    (build / "CMakeCache.txt").write_text(f"CMAKE_HOME_DIRECTORY:INTERNAL={src}\n")
    assert F.find_script(str(build / "addon" / "hybrid_base_complex"), env={}) == str(src / F.SCRIPT)
    (src / "addon").mkdir()
    assert F.find_script(str(src / "addon"), env={}) == str(src / F.SCRIPT)
    assert F.find_script(str(tmp_path), env={}) is None
    assert F.find_script("anywhere", env={"HBC_FIGURES_SCRIPT": str(src / F.SCRIPT)}) == str(src / F.SCRIPT)


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
