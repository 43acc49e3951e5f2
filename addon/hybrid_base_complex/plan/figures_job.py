"""The panel's "Render figures": the figure pipeline (blender_scripts/render_figures.py) run on a
mesh file in a separate Blender process, so the window stays responsive; the operator polls it.
No ``bpy`` here: where the script is, the command line, and a job that reads the process's output
line by line without blocking (a reader thread) and can be cancelled."""

from __future__ import annotations

import os
import queue
import subprocess
import threading

SCRIPT = os.path.join("blender_scripts", "render_figures.py")
#: The panels render_figures.py renders by default, plus its contact sheet: one "wrote" line each.
DEFAULT_FILES = 8


def _source_of_build(folder: str):
    """The source folder of the CMake build tree holding `folder` (its CMakeCache.txt says), if any."""
    cache = os.path.join(folder, "CMakeCache.txt")
    if not os.path.isfile(cache):
        return None
    with open(cache, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("CMAKE_HOME_DIRECTORY:"):
                return line.split("=", 1)[1].strip()
    return None


def find_script(addon_dir: str, env=os.environ):
    """render_figures.py: $HBC_FIGURES_SCRIPT, else in the source tree the add-on was built or
    copied from (the add-on is assembled in <build>/addon/, the script lives in the sources);
    None when the add-on was installed without them."""
    given = env.get("HBC_FIGURES_SCRIPT")
    if given:
        return given if os.path.isfile(given) else None
    folder = os.path.abspath(addon_dir)
    while True:
        for root in (folder, _source_of_build(folder)):
            if root and os.path.isfile(os.path.join(root, SCRIPT)):
                return os.path.join(root, SCRIPT)
        parent = os.path.dirname(folder)
        if parent == folder:
            return None
        folder = parent


def command(blender: str, python: str, script: str, mesh: str, out: str, addon_dir: str, engine="cycles",
            resolution=(640, 480), samples=None, sheet=None, subsheet_rule=None):
    """The command line: Blender's executable runs the script in background mode; with Blender as a
    Python module (no executable: blender is empty) that module's Python runs it directly.
    subsheet_rule: the rule the child analyzes by (the panel's Subsheets setting)."""
    args = [mesh, "--out", out, "--addon", addon_dir, "--engine", engine,
            "--resolution", str(resolution[0]), str(resolution[1])]
    if samples:
        args += ["--samples", str(samples)]
    if sheet is not None:
        args += ["--sheet", str(sheet)]
    if subsheet_rule is not None:
        args += ["--subsheet-rule", subsheet_rule]
    if blender:
        return [blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", script, "--", *args]
    return [python, script, *args]


class Job:
    """One figure run: started at once; poll() from a timer, cancel() to stop it."""

    def __init__(self, cmd, expected_files=DEFAULT_FILES, env=None):
        self.expected = max(1, expected_files)
        self.written: list[str] = []
        self.tail: list[str] = []  # the last lines, for the report when it fails
        self.last = ""
        self.cancelled = False
        self._lines: queue.Queue = queue.Queue()
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                     errors="replace", env=env)
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for line in self.proc.stdout:
            self._lines.put(line.rstrip("\n"))
        self.proc.stdout.close()

    def poll(self):
        """Takes the lines printed so far; returns the exit status once the process has ended and
        all its output was read, else None."""
        while True:
            try:
                line = self._lines.get_nowait()
            except queue.Empty:
                break
            self.tail = (self.tail + [line])[-20:]
            if line.startswith("wrote "):
                self.written.append(line[len("wrote "):])
            if line.startswith(("wrote ", "render_figures: ")):
                self.last = line
        if self.proc.poll() is None or self._reader.is_alive():
            return None
        if not self._lines.empty():
            return self.poll()
        return self.proc.returncode

    @property
    def fraction(self) -> float:
        return min(0.99, len(self.written) / self.expected)

    def cancel(self):
        """Stops the process (and waits for it): the files written so far stay."""
        self.cancelled = True
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
