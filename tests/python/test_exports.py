"""The binding surface against its one description in the library (hbc/exports.hpp, exposed as
hbc._core.EXPORTED_ARRAYS, DIMENSIONS and ANALYZE_OPTIONS): every array the Python objects hand
out is in the table with its dtype and shape, every Python entry of the table is handed out, and
_core.pyi says the same names, dtypes, shapes and analyze() options. The JavaScript half (the wasm
module's objects and hbc_core.d.ts) is checked against the same table by tests/wasm/surface_test.mjs."""

import ast
import pathlib
import re

import numpy as np
import pytest

import hbc
from hbc import _core

from conftest import TABLE1

HOLDERS = ("Mesh", "SingularityGraph", "BaseComplex", "Analysis", "Subsheets", "Wireframe", "BlockSoup")
STUB_DTYPES = {"I32": "int32", "U8": "uint8", "Bool": "bool",
               "npt.NDArray[np.float32]": "float32", "npt.NDArray[np.float64]": "float64"}


def python_entries(holder):
    return [a for a in _core.EXPORTED_ARRAYS if a["python"] and a["holder"] == holder]


def array_names(entry):
    return [entry["name"] + "_offsets", entry["name"] + "_items"] if entry["csr"] else [entry["name"]]


@pytest.fixture(scope="module")
def surface(shared_data_dir):
    """holder -> (object, {dimension: value}) on teapot, whose sheet 2 is self-intersecting."""
    m = hbc.load(shared_data_dir / TABLE1 / "teapot.hedra")
    a = m.analyze()
    sub = a.subsheets(int(a.self_intersecting_sheets[0]))
    w = a.wireframe()
    soup = hbc.block_soup(m, a, "components", shrink=0.1)
    dims = {"nv": m.num_vertices, "ne": m.num_edges, "nf": m.num_faces, "nc": m.num_cells,
            "ncf": int(m.cell_faces_offsets[-1]), "ns": a.graph.num_singularities,
            "ncomp": a.complex.num_components, "npatch": a.complex.num_patches, "ncurve": a.complex.num_curves,
            "num_sheets": a.num_sheets, "npp": int(w.polylines_offsets[-1]),
            "nsimp": w.counts["wireframe_edges_simplified"],
            # a soup's points and faces: its face_owner and point_vertex are one per face and point
            "np": len(soup["point_vertex"]), "nsf": len(soup["face_owner"])}
    objects = {"Mesh": m, "SingularityGraph": a.graph, "BaseComplex": a.complex, "Analysis": a,
               "Subsheets": sub, "Wireframe": w, "BlockSoup": soup}
    counts = {"Subsheets": sub.count, "Wireframe": w.count}
    return {h: (objects[h], {**dims, "count": counts.get(h)}) for h in HOLDERS}


def get(obj, name):
    return obj[name] if isinstance(obj, dict) else getattr(obj, name)


@pytest.mark.parametrize("holder", HOLDERS)
def test_every_entry_is_handed_out_with_its_dtype_and_shape(surface, holder):
    obj, dims = surface[holder]
    entries = python_entries(holder)
    assert entries, holder
    for e in entries:
        rows = dims.get(e["rows"])
        if e["csr"]:
            offsets, items = get(obj, e["name"] + "_offsets"), get(obj, e["name"] + "_items")
            assert offsets.dtype == np.int32 and items.dtype == np.int32, e["name"]
            assert offsets.shape == (rows + 1,), e["name"]
            assert items.shape == (offsets[-1],), e["name"]
            continue
        v = get(obj, e["name"])
        assert isinstance(v, np.ndarray), e["name"]
        assert v.dtype == np.dtype(e["dtype"]), (e["name"], v.dtype, e["dtype"])
        want = (rows, e["width"]) if e["width"] else (rows,)
        if e["rows"] == "k":
            assert v.ndim == 1, e["name"]
        else:
            assert v.shape == want, (e["name"], v.shape, want)


@pytest.mark.parametrize("holder", HOLDERS)
def test_every_array_handed_out_is_in_the_table(surface, holder):
    obj, _ = surface[holder]
    names = obj.keys() if isinstance(obj, dict) else [n for n in dir(type(obj)) if not n.startswith("_")]
    handed = {n for n in names if isinstance(get(obj, n), np.ndarray)}
    described = {n for e in python_entries(holder) for n in array_names(e)}
    assert handed == described


def test_docstrings_are_the_tables(surface):
    mesh, _ = surface["Mesh"]
    assert type(mesh).edges.__doc__ == "int32 (ne, 2): edge end vertices, lower id first."
    wire, _ = surface["Wireframe"]
    assert type(wire).simplified_polylines_offsets.__doc__.startswith("int32 (nsimp + 1,)")


def stub():
    return ast.parse(pathlib.Path(hbc.__file__).with_name("_core.pyi").read_text())


def stub_class(name):
    for node in stub().body:
        if isinstance(node, ast.ClassDef) and node.name == name:
            return node
    raise AssertionError(f"{name} is not in _core.pyi")


def shape_text(entry, half=None):
    if half == "_offsets":
        return f"({entry['rows']} + 1,)"
    if half == "_items":
        return f"({entry['name']}_offsets[-1],)"
    return f"({entry['rows']}, {entry['width']})" if entry["width"] else f"({entry['rows']},)"


@pytest.mark.parametrize("holder", [h for h in HOLDERS if h != "BlockSoup"])
def test_stub_classes_say_the_tables_names_dtypes_and_shapes(holder):
    props = {}
    for node in stub_class(holder).body:
        if isinstance(node, ast.FunctionDef) and any(ast.unparse(d) == "property" for d in node.decorator_list):
            ann = ast.unparse(node.returns)
            if ann in STUB_DTYPES:
                props[node.name] = (STUB_DTYPES[ann], ast.get_docstring(node) or "")
    want = {}
    for e in python_entries(holder):
        for n in array_names(e):
            half = n[len(e["name"]):] or None
            want[n] = ("int32" if half else e["dtype"], shape_text(e, half))
    assert set(props) == set(want)
    for n, (dtype, shape) in want.items():
        assert props[n][0] == dtype, n
        assert props[n][1].startswith(shape), f"{holder}.{n}: the stub says {props[n][1]!r}, the table {shape}"


def test_stub_block_soup_says_the_tables_keys_dtypes_and_shapes():
    text = pathlib.Path(hbc.__file__).with_name("_core.pyi").read_text()
    body = text[text.index("class BlockSoup(TypedDict):"):]
    body = body[:body.index("\nclass ")]
    found = re.findall(r"^    (\w+): ([^#\n]+?)  # (\([^)]*\))", body, re.M)
    lines = {n: ann for n, ann, _ in found}
    shapes = {n: shape for n, _, shape in found}
    want = {}
    for e in python_entries("BlockSoup"):
        for n in array_names(e):
            half = n[len(e["name"]):] or None
            want[n] = ("int32" if half else e["dtype"], shape_text(e, half))
    assert set(lines) == set(want)
    for n, (dtype, shape) in want.items():
        assert STUB_DTYPES[lines[n].strip()] == dtype, n
        assert shapes[n] == shape, n


def test_stub_analyze_takes_the_tables_options():
    analyze = next(n for n in stub_class("Mesh").body if isinstance(n, ast.FunctionDef) and n.name == "analyze")
    # Keyword-only, as the module's analyze(**options)
    assert [a.arg for a in analyze.args.args] == ["self"]
    args = analyze.args.kwonlyargs
    options = _core.ANALYZE_OPTIONS
    assert [a.arg for a in args] == [o["key"] for o in options]
    aliases = {n.targets[0].id: ast.unparse(n.value) for n in stub().body if isinstance(n, ast.Assign)}
    types = {"bool": "bool", "int": "int", "float": "float"}
    for a, default, o in zip(args, analyze.args.kw_defaults, options):
        ann = aliases.get(ast.unparse(a.annotation), ast.unparse(a.annotation))
        if o["type"] == "choice":
            assert ann == "Literal[" + ", ".join(repr(c) for c in o["choices"]) + "]", o["key"]
        else:
            assert ann == types[o["type"]] + (" | None" if o["default"] == "none" else ""), o["key"]
        value = ast.literal_eval(default)
        text = "none" if value is None else str(value).lower() if isinstance(value, bool) else str(value)
        assert text == o["default"], o["key"]


def test_analyze_reads_the_tables_options(shared_data_dir):
    m = hbc.load(shared_data_dir / TABLE1 / "test_2.HYBRID")
    with pytest.raises(TypeError, match="colour"):
        m.analyze(colour="red")
    with pytest.raises(ValueError, match="level must be one of 'complex', 'mesh', not 'fine'"):
        m.analyze(level="fine")
    with pytest.raises(ValueError, match="sheets must be true or false"):
        m.analyze(sheets=1)
    with pytest.raises(ValueError, match="search_steps"):
        m.analyze(search_steps=-1)
    # numpy's scalars are numbers; None leaves threads at its default
    a = m.analyze(rho=np.float64(0.5), threads=None, search_steps=np.int64(10), subsheet_rule="fewest")
    assert a.rho == 0.5 and a.has_sheets and a.has_wireframe
    assert not m.analyze(sheets=False, subsheets=True).has_subsheets  # subsheets need sheets
