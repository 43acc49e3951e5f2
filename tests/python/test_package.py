"""The package layout: hbc re-exports hbc._core, and the type stub matches the compiled module, so
that a binding added later without its stub entry (or the reverse) is caught."""

import ast
import pathlib

import pytest

import hbc
from hbc import _core


def stub_tree():
    path = pathlib.Path(hbc.__file__).with_name("_core.pyi")
    assert path.is_file(), "the build must copy _core.pyi next to the module"
    assert path.with_name("py.typed").is_file()
    return ast.parse(path.read_text())


def defined_names(body):
    names = set()
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets)
    return names


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_package_reexports_core():
    assert set(hbc.__all__) == {"Mesh", "MeshFormatError", "load", "check", "__version__", "Analysis",
                                "SingularityGraph", "BaseComplex", "Subsheets", "Wireframe",
                                "block_soup", "polylines", "cell_quality", "cell_depth", "cell_centroids",
                                "kept_surface_soup", "Field", "STAT_FIELDS", "TIMING_FIELDS",
                                "WIREFRAME_COUNT_FIELDS", "TABLE1_COLUMNS", "SHEET_TYPES", "CELL_TYPES",
                                "COMPONENT_KINDS", "FORMATS", "MetricField", "METRIC_FIELDS", "SUMMARY_FIELDS",
                                "compare", "gallery"}
    # compare and gallery are pure Python (hbc/comparison.py, hbc/_gallery.py); everything else is _core's.
    for name in set(hbc.__all__) - {"compare", "gallery"}:
        assert getattr(hbc, name) is getattr(_core, name)
    assert hbc.compare.__module__ == "hbc.comparison"
    assert callable(hbc.gallery)
    assert issubclass(hbc.MeshFormatError, ValueError)


def test_stub_matches_module():
    tree = stub_tree()
    stub_top = defined_names(tree.body)
    # Helper types that exist only for typing (TypedDicts, aliases) are not in the module.
    typing_only = {"Format", "CellTypeCounts", "MeshInfo", "Level", "SoupWhat", "I32", "U8", "Bool",
                   "Timings", "AnalysisStats", "WireframeCounts", "BlockSoup", "CellQuality", "FormatInfo",
                   "CheckReport", "DefectClass", "DefectItem", "Dropped", "DroppedCell",
                   "F32", "Rgba", "LegendEntry", "LayerPalette", "LegendFacts", "PartRequest"}
    assert public(stub_top) - typing_only == public(dir(_core))
    assert "__version__" in stub_top

    for cls in (node for node in tree.body if isinstance(node, ast.ClassDef)):
        if cls.name in typing_only:
            continue
        runtime = getattr(_core, cls.name)
        members = public(defined_names(cls.body))
        if issubclass(runtime, BaseException):
            # Attributes set per instance by the translator; check them on a real error.
            with pytest.raises(runtime) as info:
                hbc.load("/nonexistent/x.mesh")
            assert members and all(hasattr(info.value, m) for m in members), members
        else:
            assert members == public(vars(runtime)), cls.name


def test_every_csr_is_offsets_and_items():
    """One vocabulary (docs/concepts.md): every CSR a class exposes is `<name>_offsets` with `<name>_items`,
    and nothing else ends in `_offsets` or `_items`."""
    pairs = 0
    for cls in (hbc.Mesh, hbc.Analysis, hbc.SingularityGraph, hbc.BaseComplex, hbc.Subsheets, hbc.Wireframe):
        names = public(vars(cls))
        offsets = {n[:-len("_offsets")] for n in names if n.endswith("_offsets")}
        items = {n[:-len("_items")] for n in names if n.endswith("_items")}
        assert offsets == items, (cls.__name__, offsets ^ items)
        pairs += len(offsets)
    assert pairs == 30  # Mesh 3, SingularityGraph 2, BaseComplex 5, Subsheets 7, Wireframe 4, Analysis 9
