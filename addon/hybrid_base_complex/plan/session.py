"""Loaded meshes and their analyzes, kept in memory by mesh name (Blender data cannot hold Python
objects). After a .blend is reopened the cache is empty: `ensure` loads and analyzes the file
again from the path stored on the mesh's collection. No ``bpy`` here."""

from __future__ import annotations

import time

from .native import import_hbc
from .structure import Structure

_SESSIONS: dict[str, Structure] = {}


def get(name: str):
    return _SESSIONS.get(name)


def put(name: str, structure: Structure):
    _SESSIONS[name] = structure


def drop(name: str):
    _SESSIONS.pop(name, None)


def clear():
    _SESSIONS.clear()


def names():
    return list(_SESSIONS)


def dropped_text(dropped) -> str:
    """What hbc.load(skip_invalid=True) dropped (Mesh.dropped, docs/check.md), in one line for a
    report: "dropped 5 cells (2 few_faces, 3 open_cells)"; empty when none was."""
    if not dropped or not dropped["count"]:
        return ""
    reasons = ", ".join(f"{n} {key}" for key, n in dropped["by_reason"].items())
    return f"dropped {dropped['count']} cell{'s' if dropped['count'] != 1 else ''} ({reasons})"


def load(path: str, scale: float = 1.0, log=print, offset=(0.0, 0.0, 0.0), skip_invalid: bool = False) -> Structure:
    """Reads a mesh (raises hbc.MeshFormatError / OSError on a bad file). skip_invalid: drop the
    cells that cannot be volumes instead (structure.mesh.dropped says which)."""
    hbc = import_hbc()
    t = time.perf_counter()
    mesh = hbc.load(path, skip_invalid=skip_invalid)
    log(f"hbc: loaded {path}: {mesh.num_cells} cells in {time.perf_counter() - t:.2f} s")
    if dropped_text(mesh.dropped):
        log(f"hbc: {path}: {dropped_text(mesh.dropped)}")
    s = Structure(mesh, None, scale, offset)
    s.source = path
    return s


#: The subsheet rules (Mesh.analyze's subsheet_rule): the paper's authors' decomposition, or the
#: fewest subsheets (docs/validation.md).
SUBSHEET_RULES = ("layers", "fewest")


def analyze(structure: Structure, rho: float = 0.8, log=print, subsheet_rule: str = "layers") -> Structure:
    """Runs the whole analysis on a loaded mesh (sheets, subsheets, wireframe); subsheet_rule:
    one of SUBSHEET_RULES. The structure remembers the rule (Structure.subsheet_rule)."""
    if subsheet_rule not in SUBSHEET_RULES:
        raise ValueError(f"Unknown subsheet rule {subsheet_rule!r}: expected one of {', '.join(SUBSHEET_RULES)}")
    t = time.perf_counter()
    structure.analysis = structure.mesh.analyze(rho=rho, level="complex", sheets=True, subsheets=True,
                                                wireframe=True, subsheet_rule=subsheet_rule)
    structure.rho = rho
    structure.subsheet_rule = subsheet_rule
    structure.analyses += 1
    log(f"hbc: analyzed in {time.perf_counter() - t:.2f} s (subsheets: {subsheet_rule})")
    return structure


def restyle(structure: Structure, rho: float) -> Structure:
    """A new ρ for the structure's wireframes: their colour classes are the render layer's style
    (hbc.Wireframe.restyled), so nothing is analysed again (structure.analysis stays the same
    object; structure.analyses does not grow)."""
    if not 0.0 <= float(rho) <= 1.0:
        raise ValueError(f"rho must be in [0, 1], not {rho}")
    structure.rho = float(rho)
    return structure


def ensure(name: str, path: str, scale: float, rho: float, analyzed: bool, log=print,
           offset=(0.0, 0.0, 0.0), skip_invalid: bool = False, subsheet_rule: str = "layers") -> Structure:
    """The cached structure of `name`, re-read from `path` when the cache lost it or the mesh was
    pointed at another file; with `analyzed`, analyzed by `subsheet_rule` (again, when the cached
    analysis used the other rule: every path that reads subsheets gets the rule it asks for)."""
    s = _SESSIONS.get(name)
    if s is None or getattr(s, "source", path) != path:
        s = load(path, scale, log, offset, skip_invalid)
        _SESSIONS[name] = s
    if analyzed and (s.analysis is None or s.subsheet_rule != subsheet_rule):
        analyze(s, rho, log, subsheet_rule)
    return s
