"""The add-on's import graph, read from its sources with `ast` (nothing is imported): no cycles,
the layers import downwards only (ui -> blender -> plan), the bpy-free layer (plan/) reaches no
Blender module through any chain of imports, and no function imports an add-on module (lazy
imports that only hide a cycle). Imports inside functions count like those at the top.

A package's parent packages are imported before it by Python itself; those implicit edges are left
out: the package's own __init__ imports the UI only when bpy imports (test_planning.py's
test_package_imports_without_bpy runs that in plain Python).
"""

from __future__ import annotations

import ast
import pathlib

import pytest

ADDON = pathlib.Path(__file__).resolve().parents[3] / "addon" / "hybrid_base_complex"

#: Modules that exist only inside Blender (or with the bpy wheel).
BLENDER_MODULES = {
    "bpy", "bpy_extras", "bpy_types", "bmesh", "mathutils", "gpu", "gpu_extras", "blf", "bgl", "aud",
    "idprop", "bl_math", "bl_ui", "bl_operators", "bl_keymap_utils", "addon_utils", "rna_prop_ui",
    "nodeitems_utils", "freestyle", "imbuf", "_bpy", "_cycles",
}
#: Layers from the bottom up; a module may import its own layer and those below it.
LAYERS = ("plan", "blender", "ui")


class Graph:
    """modules: {name: path}; edges: {name: {imported add-on module: [(line, in_function)]}};
    external: {name: {top-level name of a module outside the add-on}}."""

    def __init__(self, root: pathlib.Path):
        self.package = root.name
        self.modules = {}
        for path in sorted(root.rglob("*.py")):
            if "__pycache__" in path.parts:
                continue
            parts = path.relative_to(root).with_suffix("").parts
            if parts[-1] == "__init__":
                parts = parts[:-1]
            self.modules[".".join((self.package,) + parts)] = path
        self.edges = {m: {} for m in self.modules}
        self.external = {m: set() for m in self.modules}
        for name, path in self.modules.items():
            self._read(name, path)

    def is_package(self, name) -> bool:
        return self.modules.get(name, pathlib.Path()).name == "__init__.py"

    def _defines(self, package, attr) -> bool:
        """Whether the __init__ of `package` binds `attr` at its top level (from X import attr)."""
        tree = ast.parse(self.modules[package].read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and node.name == attr:
                return True
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                if any((a.asname or a.name.split(".")[0]) == attr for a in node.names):
                    return True
            if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == attr for t in node.targets):
                return True
        return False

    def _add(self, name, target, node, in_function):
        if target in self.modules:
            self.edges[name].setdefault(target, []).append((node.lineno, in_function))
        elif target == self.package or target.startswith(self.package + "."):
            # In the package but not one of its sources: the bundled compiled hbc package.
            self.external[name].add(target)
        else:
            self.external[name].add(target.split(".")[0])

    def _read(self, name, path):
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        functions = set()
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                functions.update(id(n) for n in ast.walk(node) if n is not node)
        here = name if self.is_package(name) else name.rpartition(".")[0]
        for node in ast.walk(tree):
            inside = id(node) in functions
            if isinstance(node, ast.Import):
                for alias in node.names:
                    self._add(name, self._longest_module(alias.name), node, inside)
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = here.split(".")
                    base = base[:len(base) - (node.level - 1)]
                    if not base:
                        raise AssertionError(f"{path}:{node.lineno}: relative import above the package")
                    base = ".".join(base + ([node.module] if node.module else []))
                else:
                    base = node.module
                for alias in node.names:
                    sub = f"{base}.{alias.name}"
                    if sub in self.modules:
                        self._add(name, sub, node, inside)
                    elif base in self.modules and not (self.is_package(base) and not self._defines(base, alias.name)):
                        self._add(name, base, node, inside)
                    elif base in self.modules:
                        self._add(name, sub, node, inside)  # a submodule that is not a source
                    else:
                        self._add(name, self._longest_module(base), node, inside)

    def _longest_module(self, dotted):
        parts = dotted.split(".")
        for k in range(len(parts), 0, -1):
            if ".".join(parts[:k]) in self.modules:
                return ".".join(parts[:k])
        return dotted

    def layer(self, name):
        parts = name.split(".")
        return parts[1] if len(parts) > 1 and parts[1] in LAYERS else None

    def cycles(self):
        """Every strongly connected component of more than one module, or with a self-import."""
        index, low, stack, on, out = {}, {}, [], set(), []

        def visit(v):
            index[v] = low[v] = len(index)
            stack.append(v)
            on.add(v)
            for w in self.edges[v]:
                if w not in index:
                    visit(w)
                    low[v] = min(low[v], low[w])
                elif w in on:
                    low[v] = min(low[v], index[w])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1 or v in self.edges[v]:
                    out.append(sorted(comp))

        for v in sorted(self.modules):
            if v not in index:
                visit(v)
        return out

    def blender_chain(self, start):
        """A chain of imports from `start` to a module importing a Blender module, else None."""
        seen, todo = {start}, [[start]]
        while todo:
            chain = todo.pop(0)
            hit = self.external[chain[-1]] & BLENDER_MODULES
            if hit:
                return chain + sorted(hit)[:1]
            for nxt in sorted(self.edges[chain[-1]]):
                if nxt not in seen:
                    seen.add(nxt)
                    todo.append(chain + [nxt])
        return None

    def upward(self):
        """(importer, imported) where a layer imports a layer above it; a module outside the
        layers (the package's __init__) sits above them all."""
        rank = {None: len(LAYERS)} | {layer: k for k, layer in enumerate(LAYERS)}
        return [(a, b) for a in self.modules for b in self.edges[a]
                if rank[self.layer(b)] > rank[self.layer(a)]]

    def lazy(self):
        """(importer, imported, line) of every import of an add-on module inside a function."""
        return [(a, b, line) for a in self.modules for b, sites in self.edges[a].items()
                for line, inside in sites if inside]


@pytest.fixture(scope="module")
def graph():
    g = Graph(ADDON)
    assert g.modules, f"no add-on modules under {ADDON}"
    missing = [f"{g.package}.{layer}" for layer in LAYERS if f"{g.package}.{layer}" not in g.modules]
    assert not missing, f"layer packages missing: {missing}"
    for layer in LAYERS:
        assert any(g.layer(m) == layer and m != f"{g.package}.{layer}" for m in g.modules), layer
    return g


def test_the_graph_is_read(graph):
    """Known imports are found, at the top and inside functions alike, so an empty result below
    means something."""
    p = graph.package
    assert f"{p}.plan.structure" in graph.edges[f"{p}.plan.session"]
    assert f"{p}.blender.inspect" in graph.edges[f"{p}.blender.layers"]
    assert f"{p}.ui.addon" in graph.edges[p]
    assert "bpy" in graph.external[f"{p}.blender.scene"]
    # native.import_hbc imports the bundled hbc inside a function: not a source, not a cycle.
    assert f"{p}.hbc" in graph.external[f"{p}.plan.native"]


def test_no_import_cycles(graph):
    assert graph.cycles() == []


def test_layers_import_downwards(graph):
    assert graph.upward() == []


def test_plan_reaches_no_blender_module(graph):
    plan = [m for m in graph.modules if graph.layer(m) == "plan"]
    chains = {m: graph.blender_chain(m) for m in plan}
    assert {m: c for m, c in chains.items() if c} == {}


def test_no_lazy_imports_of_addon_modules(graph):
    assert graph.lazy() == []


def write(root, files):
    for rel, text in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def test_the_checks_catch_what_they_look_for(tmp_path):
    """A made-up add-on with each fault: a cycle through an import inside a function, a plan module
    reaching bpy through another module, an upward import, and a bundled package that is none of
    them."""
    root = tmp_path / "pkg"
    write(root, {
        "__init__.py": "",
        "plan/__init__.py": "",
        "plan/a.py": "from . import b\n",
        "plan/b.py": "def f():\n    from .a import x\n",
        "plan/c.py": "from ..blender import scene\nfrom .. import bundled\n",
        "blender/__init__.py": "",
        "blender/scene.py": "import bpy\nfrom ..ui import panel\n",
        "ui/__init__.py": "",
        "ui/panel.py": "from ..blender import scene\n",
    })
    g = Graph(root)
    assert sorted(g.cycles()) == [["pkg.blender.scene", "pkg.ui.panel"], ["pkg.plan.a", "pkg.plan.b"]]
    assert g.blender_chain("pkg.plan.c") == ["pkg.plan.c", "pkg.blender.scene", "bpy"]
    assert g.blender_chain("pkg.plan.a") is None
    assert sorted(g.upward()) == [("pkg.blender.scene", "pkg.ui.panel"), ("pkg.plan.c", "pkg.blender.scene")]
    assert g.lazy() == [("pkg.plan.b", "pkg.plan.a", 2)]
    assert "pkg.bundled" in g.external["pkg.plan.c"]
