"""The panel's "Render figures": the add-on's own figure script (figures/render_figures.py, shipped
inside the add-on package) run on a mesh file in a separate Blender process, so the window stays
responsive; the operator polls it. No ``bpy`` here: where the script is and whether it can run
(asked before the user is asked anything), the command line and environment of the child, and a job
that reads the process's output line by line without blocking (a reader thread) and can be
cancelled."""

from __future__ import annotations

import os
import queue
import subprocess
import threading

#: The figure script's entry file, inside the add-on package (figures/render_figures.py).
SCRIPT = os.path.join("figures", "render_figures.py")
#: The panels render_figures.py renders by default, plus its contact sheet: one "wrote" line each.
DEFAULT_FILES = 8


def find_script(addon_dir: str):
    """The entry file of the figures shipped in the add-on package at `addon_dir`, or None when
    this copy of the add-on lacks it (a damaged install)."""
    path = os.path.join(os.path.abspath(addon_dir), SCRIPT)
    return path if os.path.isfile(path) else None


def problem(addon_dir: str, blender: str, python: str, module_problem=None):
    """Why *Figures* cannot run here, in words for the user, or None: the script is missing from the
    add-on, the compiled hbc module does not import (`module_problem`: plan.native's sentence),
    or there is no Blender to start (`blender`, the running Blender's executable; empty for the
    bpy module, whose `python` runs the script instead)."""
    if find_script(addon_dir) is None:
        return (f"Cannot render figures: this add-on has no {SCRIPT.replace(os.sep, '/')} "
                f"(in {os.path.abspath(addon_dir)}); install the add-on again from its zip")
    if module_problem:
        return f"Cannot render figures: {module_problem}"
    child = blender or python
    if not child or not os.path.isfile(child) or not os.access(child, os.X_OK):
        return (f"Cannot render figures: no {'Blender executable' if blender or not python else 'Python'} "
                f"to run them in ({child or 'none given'})")
    return None


def command(blender: str, python: str, script: str, mesh: str, out: str, engine="cycles",
            resolution=(640, 480), samples=None, sheet=None, subsheet_rule=None):
    """The command line: Blender's executable runs the script in background mode; with Blender as a
    Python module (no executable: blender is empty) that module's Python runs it directly. The
    script renders with the add-on package it belongs to. subsheet_rule: the rule the child
    analyzes by (the panel's Subsheets setting)."""
    args = [mesh, "--out", out, "--engine", engine, "--resolution", str(resolution[0]), str(resolution[1])]
    if samples:
        args += ["--samples", str(samples)]
    if sheet is not None:
        args += ["--sheet", str(sheet)]
    if subsheet_rule is not None:
        args += ["--subsheet-rule", subsheet_rule]
    if blender:
        return [blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", script, "--", *args]
    return [python, script, *args]


def child_env(environ, python: str, hbc_file: str, addon_dir: str) -> dict:
    """The child's environment. Debian's Blender takes its Python from the first python3 on PATH:
    this one's (`python`) goes first. When the hbc module is not the copy bundled in the add-on
    (the extension installs it from a wheel into a folder Blender adds to sys.path only for enabled
    extensions, which a --factory-startup child has none of), the folder it was imported from goes
    on PYTHONPATH, so the child imports the same module."""
    env = dict(environ)
    if python:
        env["PATH"] = os.path.dirname(python) + os.pathsep + environ.get("PATH", "")
    package = os.path.dirname(os.path.abspath(hbc_file))
    if os.path.dirname(package) != os.path.abspath(addon_dir):
        where = os.path.dirname(package)
        env["PYTHONPATH"] = os.pathsep.join(p for p in (where, environ.get("PYTHONPATH", "")) if p)
    return env


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
