"""Writes every array the hbc module gives for each shared mesh, under the Python running it.

    python dump_arrays.py NUMPY_MAJOR OUT_DIR

PYTHONPATH holds the build's hbc package, HBC_DATA_DIR the shared meshes. Stops (exit 1) unless
this Python's NumPy has major version NUMPY_MAJOR, so that a run meant for NumPy 2 cannot quietly
be a second NumPy 1 run. test_numpy_versions.py runs it under two Pythons and compares the files.

What is dumped, per mesh (a file whose extension is one of hbc.FORMATS'):
- every property of hbc.Mesh that returns an ndarray, and of every hbc class a property leads to
  (Mesh -> nothing more; Analysis -> SingularityGraph, BaseComplex), found by walking the classes,
  so an array added to the binding is compared without touching this file;
- Analysis.subsheets(s) for every self-intersecting sheet and Analysis.wireframe(), walked the same;
- Mesh.from_arrays() fed the mesh's own arrays (its parameters are the properties of the same names),
  walked the same: NumPy arrays going in, not only out;
- every module function of _core.pyi whose one required parameter is `mesh` (cell_quality, ...),
  and block_soup for every kind of the stub's SoupWhat.
A call that raises is recorded as its message (key "...!error"), compared like an array.

OUT_DIR/<i>.npz holds mesh i's arrays under keys such as "analysis.graph.edge_class";
OUT_DIR/manifest.json: numpy's version, the module's file, the meshes (paths under HBC_DATA_DIR)
and, per class walked, the names of its array properties.
"""

import ast
import inspect
import json
import os
import pathlib
import sys

import numpy as np


def stub_tree(hbc):
    return ast.parse(pathlib.Path(hbc.__file__).with_name("_core.pyi").read_text())


def mesh_functions(tree):
    """Names of the stub's module functions whose only parameter without a default is `mesh`."""
    out = []
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            args = node.args
            required = [a.arg for a in args.posonlyargs + args.args][: len(args.posonlyargs + args.args) - len(args.defaults)]
            required += [a.arg for a, d in zip(args.kwonlyargs, args.kw_defaults) if d is None]
            if required == ["mesh"]:
                out.append(node.name)
    return out


def soup_kinds(tree):
    """The values of the stub's SoupWhat = Literal[...]."""
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == "SoupWhat" for t in node.targets):
            return [e.value for e in node.value.slice.elts]
    raise LookupError("_core.pyi has no SoupWhat")


class Dump:
    def __init__(self):
        self.arrays = {}
        self.classes = {}  # class name -> set of its array properties
        self.walked = set()  # classes walked already: a property leading to one is not followed

    def error(self, key, e):
        self.arrays[key + "!error"] = np.array(f"{type(e).__name__}: {e}")

    def value(self, key, v):
        """An ndarray, a dict of them (cell_quality, block_soup) or an hbc object (walked)."""
        if isinstance(v, np.ndarray):
            self.arrays[key] = np.array(v)  # a C-ordered copy of what the view shows
        elif isinstance(v, dict):
            for k, item in v.items():
                if isinstance(item, np.ndarray):
                    self.arrays[f"{key}[{k}]"] = np.array(item)
        elif type(v).__module__ == "hbc._core":
            self.walk(key, v)

    def call(self, key, f, *args, **kwargs):
        try:
            v = f(*args, **kwargs)
        except Exception as e:  # the same refusal under both NumPys is part of what is compared
            self.error(key, e)
            return None
        self.value(key, v)
        return v

    def walk(self, prefix, obj):
        cls = type(obj)
        self.walked.add(cls)
        found = self.classes.setdefault(cls.__name__, set())
        for name, attr in inspect.getmembers(cls):
            if name.startswith("_") or not isinstance(attr, property):
                continue
            key = f"{prefix}.{name}"
            try:
                v = getattr(obj, name)
            except Exception as e:
                self.error(key, e)
                continue
            if isinstance(v, np.ndarray):
                found.add(name)
                self.value(key, v)
            elif type(v).__module__ == "hbc._core" and type(v) not in self.walked:
                self.walk(key, v)  # Analysis.graph; not Analysis.mesh, the Mesh walked first


def dump_mesh(hbc, path, tree):
    d = Dump()
    try:
        mesh = hbc.load(path)
    except Exception as e:
        d.error("load", e)
        return d
    d.walk("mesh", mesh)
    # pybind11 gives no signature object: the stub names from_arrays' parameters, which are the
    # names of the properties that hold them.
    cls = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Mesh")
    fa = next(n for n in cls.body if isinstance(n, ast.FunctionDef) and n.name == "from_arrays")
    params = [a.arg for a in fa.args.args if a.arg != "source"]
    d.call("from_arrays", hbc.Mesh.from_arrays, **{p: getattr(mesh, p) for p in params})
    for name in mesh_functions(tree):
        d.call(f"{name}(mesh)", getattr(hbc, name), mesh)
    a = d.call("analysis", mesh.analyze)
    if a is None:
        return d
    for s in a.self_intersecting_sheets.tolist():
        d.call(f"analysis.subsheets({s})", a.subsheets, s)
    d.call("analysis.wireframe()", a.wireframe)
    sheet = a.largest_self_intersecting if a.largest_self_intersecting is not None else (0 if a.num_sheets else None)
    for what in soup_kinds(tree):
        d.call(f"block_soup({what})", hbc.block_soup, mesh, a, what, sheet)
    return d


def main():
    major, out = int(sys.argv[1]), pathlib.Path(sys.argv[2])
    if int(np.__version__.split(".")[0]) != major:
        sys.exit(f"{sys.executable} has NumPy {np.__version__}, not NumPy {major}.x")
    import hbc

    tree = stub_tree(hbc)
    root = pathlib.Path(os.environ["HBC_DATA_DIR"])
    suffixes = {f["extension"].lower() for f in hbc.FORMATS}
    meshes = sorted(p for p in root.rglob("*") if p.is_file() and p.suffix.lower() in suffixes)
    if not meshes:
        sys.exit(f"no mesh under HBC_DATA_DIR={root}")
    classes = {}
    for i, path in enumerate(meshes):
        d = dump_mesh(hbc, path, tree)
        np.savez(out / f"{i}.npz", **d.arrays)
        for c, names in d.classes.items():
            classes.setdefault(c, set()).update(names)
    manifest = {"numpy": np.__version__, "module": hbc._core.__file__,
                "meshes": [str(p.relative_to(root)) for p in meshes],
                "classes": {c: sorted(n) for c, n in sorted(classes.items())}}
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1))


if __name__ == "__main__":
    main()
