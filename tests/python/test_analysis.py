"""Mesh.analyze(): the stats equal `hbc analyze --json`, Table 1 of the paper, the arrays of the
singularity graph, base complex, sheets, subsheets and wireframes (shapes, dtypes, invariants),
lifetime, the GIL, and no leak over repeated analyses."""

import gc
import json
import subprocess

import numpy as np
import pytest

import hbc

from conftest import MESHES, TABLE1

TIMING_KEYS = {"load", "singularity_graph", "base_complex", "sheets", "subsheets", "vsg_wireframe"}


def cli_analyze(cli, path, *flags):
    out = subprocess.run([cli, "analyze", str(path), "--json", *flags], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    d = json.loads(out.stdout)
    del d["file"]
    return d


def assert_same_stats(got, expected):
    assert set(got) == set(expected)
    for key, value in expected.items():
        if key == "timings":
            assert set(got[key]) == TIMING_KEYS == set(value)
            assert all(isinstance(t, float) and t >= 0 for t in got[key].values())
        elif isinstance(value, float):
            assert got[key] == pytest.approx(value, abs=1e-6), key
        else:
            assert got[key] == value and isinstance(got[key], int), key


def check_csr(offsets, items, rows):
    assert offsets.dtype == np.int32 and items.dtype == np.int32
    assert offsets.shape == (rows + 1,) and items.ndim == 1
    assert offsets[0] == 0 and offsets[-1] == len(items)
    assert np.all(np.diff(offsets) >= 0)


def rows(offsets, items):
    return [items[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def edge_set(m):
    return {tuple(e) for e in m.edges.tolist()}


def assert_chains_of_edges(m, offsets, verts, closed=None):
    """Consecutive vertices of every row are joined by a mesh edge (and last-first when closed)."""
    edges = edge_set(m)
    for i, r in enumerate(rows(offsets, verts)):
        r = r.tolist()
        if closed is not None and closed[i] and len(r) > 1:
            r = r + r[:1]
        for a, b in zip(r, r[1:]):
            assert (min(a, b), max(a, b)) in edges


@pytest.mark.parametrize("name", MESHES)
def test_stats_match_cli(analyzed, shared_data_dir, hbc_cli, name):
    _, a = analyzed[name]
    assert_same_stats(a.stats, cli_analyze(hbc_cli, shared_data_dir / name))
    assert a.stats["timings"]["load"] > 0  # hbc.load timed the load


def test_stats_without_stages_match_cli(shared_data_dir, hbc_cli):
    path = shared_data_dir / TABLE1 / "twistcube_s.mesh"
    m = hbc.load(path)
    a = m.analyze(sheets=False, wireframe=False)
    stats = a.stats
    for key in ("sheets", "sheets_type3", "subsheets_of_largest_self_intersecting", "vsg_edges",
                "wireframe_edges"):
        assert key not in stats
    assert_same_stats(stats, cli_analyze(hbc_cli, path, "--no-sheets", "--no-wireframe"))
    assert not a.has_sheets and not a.has_subsheets and not a.has_wireframe and a.num_sheets == 0
    assert a.largest_self_intersecting is None
    with pytest.raises(ValueError, match="without sheets"):
        a.subsheets(0)
    without_sub = m.analyze(subsheets=False)
    assert without_sub.has_sheets and not without_sub.has_subsheets
    with pytest.raises(ValueError, match="without subsheets"):
        without_sub.subsheets(without_sub.largest_self_intersecting)
    assert "subsheets_of_largest_self_intersecting" not in m.analyze(subsheets=False).stats
    # The whole-mesh wireframe is then computed on demand, the same as in a full analysis.
    assert a.wireframe().counts == m.analyze().wireframe().counts


def test_mesh_level_matches_cli(shared_data_dir, hbc_cli):
    path = shared_data_dir / TABLE1 / "cube_twist-comp.obj.HYBRID"
    a = hbc.load(path).analyze(level="mesh", rho=0.5)
    assert a.level == "mesh" and a.rho == 0.5
    assert_same_stats(a.stats, cli_analyze(hbc_cli, path, "--level", "mesh", "--rho", "0.5"))


def test_bad_options(analyzed):
    m, _ = analyzed[MESHES[3]]
    with pytest.raises(ValueError, match="level"):
        m.analyze(level="fine")
    with pytest.raises(ValueError, match="rho"):
        m.analyze(rho=1.5)


@pytest.mark.parametrize("name, comps, hex_comps, sheets, t1, t2, t3", [
    (TABLE1 + "teapot.hedra", 772, 748, 23, 5, 1, 2),
    (TABLE1 + "twistcube_s.mesh", 1301, 1157, 20, 16, 2, 1),
    (TABLE1 + "cube_twist-comp.obj.HYBRID", 221, 203, 19, 8, 0, 0),
])
def test_table1(analyzed, name, comps, hex_comps, sheets, t1, t2, t3):
    _, a = analyzed[name]
    s = a.stats
    assert (s["components"], s["hex_components"]) == (comps, hex_comps)
    assert (s["sheets"], s["sheets_type1"], s["sheets_type2"], s["sheets_type3"]) == (sheets, t1, t2, t3)
    # The same from the arrays.
    assert len(a.complex.component_kind) == comps
    assert np.count_nonzero(a.complex.component_kind == 0) == hex_comps
    assert a.num_sheets == sheets
    assert np.bincount(a.sheet_type, minlength=4)[1:].tolist() == [t1, t2, t3]


def test_table1_subsheets(analyzed):
    _, a = analyzed[TABLE1 + "twistcube_s.mesh"]
    big = a.largest_self_intersecting
    assert big is not None
    assert a.subsheets(big).count == 9 == a.stats["subsheets_of_largest_self_intersecting"]
    _, a = analyzed[TABLE1 + "cube_twist-comp.obj.HYBRID"]
    assert a.largest_self_intersecting is None and len(a.self_intersecting_sheets) == 0


@pytest.mark.parametrize("name", MESHES)
def test_graph_arrays(analyzed, name):
    m, a = analyzed[name]
    g, s = a.graph, a.stats
    assert g.edge_class.dtype == np.uint8 and g.edge_class.shape == (m.num_edges,)
    assert not g.edge_class.flags.writeable
    counts = np.bincount(g.edge_class, minlength=4)
    assert counts[1] == s["singular_edges"]
    assert counts[2] == s["pseudo_singular_edges"] == len(g.pseudo_singular_edges)
    assert counts[3] == s["non_manifold_edges"] == len(g.non_manifold_edges)
    assert np.all(g.edge_class[g.pseudo_singular_edges] == 2)
    ns = g.num_singularities
    assert ns == s["singularities"]
    check_csr(g.chain_vertices_offsets, g.chain_vertices_items, ns)
    check_csr(g.chain_edges_offsets, g.chain_edges_items, ns)
    assert g.chain_valence.dtype == np.int32 and g.chain_valence.shape == (ns,)
    for arr in (g.chain_boundary, g.chain_closed):
        assert arr.dtype == np.bool_ and arr.shape == (ns,)
    assert np.all(g.edge_class[g.chain_edges_items] == 1)
    assert np.array_equal(np.sort(g.chain_edges_items), np.flatnonzero(g.edge_class == 1))
    assert_chains_of_edges(m, g.chain_vertices_offsets, g.chain_vertices_items, g.chain_closed)
    assert len(g.singular_vertices) == s["singular_vertices"]
    for arr in (g.singular_vertices, g.pseudo_singular_vertices):
        assert arr.dtype == np.int32 and np.all(np.diff(arr) > 0)
    # Pseudo-singular vertices are exactly the ends of pseudo-singular and non-manifold edges.
    ends = m.edges[np.concatenate([g.pseudo_singular_edges, g.non_manifold_edges])]
    assert np.array_equal(np.unique(ends), g.pseudo_singular_vertices)


@pytest.mark.parametrize("name", MESHES)
def test_complex_arrays(analyzed, name):
    m, a = analyzed[name]
    c, s = a.complex, a.stats
    ncomp = s["components"]
    assert c.cell_component.shape == (m.num_cells,) and c.cell_component.dtype == np.int32
    assert c.component_kind.dtype == np.uint8 and c.component_kind.shape == (ncomp,)
    check_csr(c.component_cells_offsets, c.component_cells_items, ncomp)
    # Every cell in exactly one component, the one cell_component names.
    owner = np.repeat(np.arange(ncomp), np.diff(c.component_cells_offsets))
    assert np.array_equal(np.sort(c.component_cells_items), np.arange(m.num_cells))
    assert np.array_equal(c.cell_component[c.component_cells_items], owner)
    # Non-hex components are single non-hex cells.
    nonhex = c.component_kind == 3
    assert np.all(np.diff(c.component_cells_offsets)[nonhex] == 1)
    assert np.all(m.cell_types[c.component_cells_items[c.component_cells_offsets[:-1][nonhex]]] != 0)
    check_csr(c.component_adjacency_offsets, c.component_adjacency_items, ncomp)
    assert c.face_separation.dtype == np.bool_ and c.face_separation.shape == (m.num_faces,)
    assert c.face_patch.shape == (m.num_faces,)
    assert np.array_equal(c.face_patch >= 0, c.face_separation)
    assert np.all(c.face_separation[m.face_boundary])
    # Faces between two components are separation faces.
    fc = m.face_cells
    inner = fc[:, 1] >= 0
    across = c.cell_component[fc[inner, 0]] != c.cell_component[fc[inner, 1]]
    assert np.all(c.face_separation[inner][across])
    assert c.num_patches == s["patches"] and c.num_curves == s["curves"]
    check_csr(c.patch_faces_offsets, c.patch_faces_items, c.num_patches)
    check_csr(c.curve_vertices_offsets, c.curve_vertices_items, c.num_curves)
    check_csr(c.curve_edges_offsets, c.curve_edges_items, c.num_curves)
    assert c.curve_closed.dtype == np.bool_ and c.curve_closed.shape == (c.num_curves,)
    assert_chains_of_edges(m, c.curve_vertices_offsets, c.curve_vertices_items, c.curve_closed)
    assert len(c.corners) == s["corners"] and c.corners.dtype == np.int32
    assert len(c.self_adjacent_faces) == s["self_adjacent_faces"]


@pytest.mark.parametrize("name", MESHES)
def test_sheet_arrays(analyzed, name):
    m, a = analyzed[name]
    ns = a.num_sheets
    assert ns == a.stats["sheets"]
    assert a.sheet_type.dtype == np.uint8 and a.sheet_type.shape == (ns,)
    assert a.sheet_flags.dtype == np.bool_ and a.sheet_flags.shape == (ns, 3)
    # The type is the highest configuration present (precedence 3 > 2 > 1), 0 when none.
    highest = np.where(a.sheet_flags.any(axis=1), 3 - np.argmax(a.sheet_flags[:, ::-1], axis=1), 0)
    assert np.array_equal(a.sheet_type, highest)
    for name_ in ("components", "cells", "curves", "edges", "non_hex_cells", "unmatched_vertices", "shared_vertices",
                  "self_parallel_curves", "self_intersecting_components"):
        check_csr(getattr(a, f"sheet_{name_}_offsets"), getattr(a, f"sheet_{name_}_items"), ns)
    comp = a.complex.cell_component
    types = m.cell_types
    for s in range(ns):
        cells = rows(a.sheet_cells_offsets, a.sheet_cells_items)[s]
        comps = rows(a.sheet_components_offsets, a.sheet_components_items)[s]
        assert np.all(types[cells] == 0)
        assert np.array_equal(np.unique(comp[cells]), comps)
        non_hex = rows(a.sheet_non_hex_cells_offsets, a.sheet_non_hex_cells_items)[s]
        assert np.all(types[non_hex] != 0)
        # Perfect sheets leave no vertex unmatched; type 3 ones name the components holding it.
        unmatched = rows(a.sheet_unmatched_vertices_offsets, a.sheet_unmatched_vertices_items)[s]
        if a.sheet_type[s] == 0:
            assert len(unmatched) == 0
        inter = rows(a.sheet_self_intersecting_components_offsets, a.sheet_self_intersecting_components_items)[s]
        assert (len(inter) > 0) == a.sheet_flags[s, 2]
        assert np.all(np.isin(inter, comps))
    assert np.array_equal(a.self_intersecting_sheets, np.flatnonzero(a.sheet_flags[:, 2]))


@pytest.mark.parametrize("name", MESHES)
def test_subsheets(analyzed, name):
    m, a = analyzed[name]
    for s in range(a.num_sheets):
        if s not in a.self_intersecting_sheets:
            with pytest.raises(ValueError, match="not self-intersecting"):
                a.subsheets(s)
            continue
        sub = a.subsheets(s)
        n = sub.count
        assert sub.sheet == s and n >= 2
        assert sub.subsheet_type.dtype == np.uint8 and sub.subsheet_type.shape == (n,)
        # The authors' layers may keep two curves meeting in a block (one twistcube_s subsheet
        # does, as in their code; docs/validation.md): the flags agree with the type all the same.
        assert sub.rule == "layers" and sub.lower_bound == 0 and not sub.proven
        assert sub.subsheet_flags.shape == (n, 3)
        assert np.array_equal(sub.subsheet_type == 3, sub.subsheet_flags[:, 2])
        for name_ in ("components", "cells", "curves", "unmatched_vertices", "shared_vertices", "self_parallel_curves",
                      "self_intersecting_components"):
            check_csr(getattr(sub, f"subsheet_{name_}_offsets"), getattr(sub, f"subsheet_{name_}_items"), n)
        # Subsheets cover the sheet's curves and stay within its cells and components.
        sheet_curves = rows(a.sheet_curves_offsets, a.sheet_curves_items)[s]
        assert np.array_equal(np.unique(sub.subsheet_curves_items), sheet_curves)
        assert np.all(np.isin(sub.subsheet_cells_items, rows(a.sheet_cells_offsets, a.sheet_cells_items)[s]))
        assert np.all(np.isin(sub.subsheet_components_items, rows(a.sheet_components_offsets, a.sheet_components_items)[s]))
    with pytest.raises(ValueError, match="out of range"):
        a.subsheets(a.num_sheets)


def test_fewest_subsheets(shared_data_dir):
    """subsheet_rule='fewest': each curve of the sheet in exactly one subsheet, none type 3, and a
    lower bound never above the count (proven exactly when they meet)."""
    m = hbc.load(shared_data_dir / TABLE1 / "teapot.hedra")
    a = m.analyze(wireframe=False, subsheet_rule="fewest", search_steps=20000)
    for s in a.self_intersecting_sheets:
        sub = a.subsheets(int(s))
        assert sub.rule == "fewest" and 2 <= sub.lower_bound <= sub.count
        assert sub.proven == (sub.lower_bound == sub.count)
        assert not np.any(sub.subsheet_type == 3)
        sheet_curves = rows(a.sheet_curves_offsets, a.sheet_curves_items)[int(s)]
        assert np.array_equal(np.sort(sub.subsheet_curves_items), sheet_curves)
    with pytest.raises(ValueError, match="subsheet_rule"):
        m.analyze(subsheet_rule="greedy")


def check_wireframe(m, w, counts=None):
    n = w.count
    check_csr(w.polylines_offsets, w.polylines_items, n)
    assert np.all(np.diff(w.polylines_offsets) >= 2)
    assert w.point_opacity.dtype == np.float32 and w.point_opacity.shape == w.polylines_items.shape
    assert np.all((w.point_opacity >= 0.15 - 1e-6) & (w.point_opacity <= 1.0))
    for arr, dtype in ((w.kind, np.uint8), (w.non_important, np.uint8), (w.stop, np.uint8),
                       (w.shown, np.bool_), (w.reactivated, np.bool_), (w.color, np.int32),
                       (w.color_class, np.int32), (w.valence, np.int32)):
        assert arr.dtype == dtype and arr.shape == (n,)
    assert set(np.unique(w.kind)) <= {0, 1}
    # Chains of VSG edges are fully opaque; a shown chain is kept or reactivated.
    vsg_points = np.repeat(w.kind == 0, np.diff(w.polylines_offsets))
    assert np.all(w.point_opacity[vsg_points] == 1.0)
    assert not np.any(w.shown & (w.non_important != 0) & ~w.reactivated)
    assert not np.any(w.reactivated & (w.non_important == 0))
    assert np.all(w.color >= 0)
    assert np.all(w.color_class[w.color_class] == w.color_class), "a class is named by one of its edges"
    assert_chains_of_edges(m, w.polylines_offsets, w.polylines_items)
    c = w.counts
    assert c["wireframe_edges"] == n
    check_csr(w.simplified_polylines_offsets, w.simplified_polylines_items, c["wireframe_edges_simplified"])
    assert_chains_of_edges(m, w.simplified_polylines_offsets, w.simplified_polylines_items)
    # Each VSG chain holds an irregular edge; the simplification covers no more than the whole.
    assert c["vsg_chains"] <= c["vsg_edges"]
    assert c["wireframe_mesh_edges_simplified"] <= c["wireframe_mesh_edges"]
    if counts is not None:
        assert {k: c[k] for k in counts} == counts


@pytest.mark.parametrize("name", MESHES)
def test_wireframe_whole(analyzed, name):
    m, a = analyzed[name]
    s = a.stats
    w = a.wireframe()
    check_wireframe(m, w, {k: s[k] for k in ("vsg_edges", "wireframe_edges", "wireframe_edges_simplified")})
    assert not w.polylines_items.flags.writeable


@pytest.mark.parametrize("name", [TABLE1 + "teapot.hedra", TABLE1 + "twistcube_s.mesh"])
def test_wireframe_regions(analyzed, name):
    m, a = analyzed[name]
    face_of_point = np.repeat(np.arange(m.num_faces), np.diff(m.face_vertices_offsets))

    def region_vertices(cells):
        inside = np.zeros(m.num_cells + 1, bool)  # index -1 (no cell) stays False
        inside[cells] = True
        faces = inside[m.face_cells[:, 0]] | inside[m.face_cells[:, 1]]
        return np.unique(m.face_vertices_items[faces[face_of_point]])

    for s in range(min(a.num_sheets, 4)):
        w = a.wireframe(sheet=s)
        check_wireframe(m, w)
        cells = np.concatenate([rows(a.sheet_cells_offsets, a.sheet_cells_items)[s],
                                rows(a.sheet_non_hex_cells_offsets, a.sheet_non_hex_cells_items)[s]])
        # At the complex level the region is the components of those cells.
        comps = np.unique(a.complex.cell_component[cells])
        region = np.flatnonzero(np.isin(a.complex.cell_component, comps))
        assert np.all(np.isin(w.polylines_items, region_vertices(region)))
    big = a.largest_self_intersecting
    sub = a.subsheets(big)
    for k in range(sub.count):
        w = a.wireframe(sheet=big, subsheet=k)
        check_wireframe(m, w)
        assert w.count > 0
    with pytest.raises(ValueError):
        a.wireframe(subsheet=0)
    with pytest.raises(ValueError):
        a.wireframe(sheet=a.num_sheets)
    with pytest.raises(ValueError):
        a.wireframe(sheet=big, subsheet=sub.count)


def test_arrays_outlive_their_objects(shared_data_dir):
    m = hbc.load(shared_data_dir / TABLE1 / "cube_twist-comp.obj.HYBRID")
    a = m.analyze()
    kept = {"edge_class": a.graph.edge_class, "component_cells_items": a.complex.component_cells_items,
            "sheet_cells_items": a.sheet_cells_items, "polylines_items": a.wireframe().polylines_items,
            "region": a.wireframe(sheet=0).point_opacity}
    copies = {k: v.copy() for k, v in kept.items()}
    assert a.mesh is m
    del a, m
    gc.collect()
    hbc.load(shared_data_dir / TABLE1 / "teapot.hedra").analyze()  # reuse freed memory, if any
    for k, v in kept.items():
        assert np.array_equal(v, copies[k]), k


def test_no_leak_over_100_analyze_cycles(shared_data_dir, resident_growth):
    m = hbc.load(shared_data_dir / TABLE1 / "teapot.hedra")

    def arrays(a):
        out = [getattr(a, n) for n in dir(a) if n.startswith("sheet_")]
        out += [getattr(a.graph, n) for n in dir(a.graph) if not n.startswith("_")]
        out += [getattr(a.complex, n) for n in dir(a.complex) if not n.startswith("_")]
        sub = a.subsheets(a.largest_self_intersecting)
        out += [getattr(sub, n) for n in dir(sub) if not n.startswith("_")]
        for w in (a.wireframe(), a.wireframe(sheet=0)):
            out += [getattr(w, n) for n in dir(w) if not n.startswith("_")]
        out += list(hbc.block_soup(m, a, "components", shrink=0.1).values())
        return [x for x in out if isinstance(x, np.ndarray)]

    def cycle():
        # One thread: a worker thread's glibc arena keeps pages it freed (up to ~10 MB here in
        # Blender 3.4), growth of the allocator that is no leak of ours; the threaded analysis is
        # checked by test_threads_keyword_changes_no_array.
        a = m.analyze(threads=1)
        a.stats
        arrays(a)
        try:
            a.subsheets(0 if a.largest_self_intersecting != 0 else 1)
        except ValueError:
            pass

    growth = resident_growth(cycle)
    # What one cycle exposes at least; leaking it every cycle would exceed the bound tenfold.
    per_cycle = sum(x.nbytes for x in arrays(m.analyze()))
    assert per_cycle > 4e5
    assert growth < 4e6, f"resident memory grew by {growth / 1e6:.1f} MB over 100 cycles"


def test_analyze_releases_the_gil(shared_data_dir, main_thread_share, held_gil_share):
    m = hbc.load(shared_data_dir / "hexalab-edge-cone-rectification" / "armadillo_out.mesh")
    share, elapsed = main_thread_share(m.analyze)
    assert elapsed > 0.1, "the analyses were too quick to tell"
    assert share > 0.15 or share > 3 * held_gil_share, (share, held_gil_share, elapsed)


def analysis_arrays(a):
    """Every ndarray an Analysis exposes, by name (properties read once)."""
    out = {}
    for n in dir(a):
        if n.startswith("_"):
            continue
        v = getattr(a, n)
        if isinstance(v, np.ndarray):
            out[n] = v
    return out


def test_threads_keyword_changes_no_array(shared_data_dir):
    # The stages may split their work over threads; one thread and two must give the same arrays
    # and statistics (a mesh with sheets, subsheets and a wireframe of every kind).
    m = hbc.load(shared_data_dir / "hybrid-base-complex" / "twistcube_s.mesh")
    one, two = m.analyze(threads=1), m.analyze(threads=2)
    a1, a2 = analysis_arrays(one), analysis_arrays(two)
    assert len(a1) >= 20 and a1.keys() == a2.keys()
    for n in a1:
        np.testing.assert_array_equal(a1[n], a2[n], err_msg=n)
    s1, s2 = dict(one.stats), dict(two.stats)
    s1.pop("timings", None), s2.pop("timings", None)
    assert s1 == s2
    with pytest.raises(ValueError):
        m.analyze(threads=0)


def cli_wireframe_style(cli, path, *flags):
    """(color_class, color, opacity) per chain of `hbc wireframe --json` (the CLI's own style)."""
    out = json.loads(subprocess.run([cli, "wireframe", str(path), "--json", *flags], capture_output=True, text=True,
                                    check=True).stdout)
    edges = out["edges"]
    return ([e["color_class"] for e in edges], [e["color"] for e in edges],
            np.concatenate([np.asarray(e["opacity"], np.float32) for e in edges]))


def test_rho_restyles_without_analysing(hbc_cli, shared_data_dir):
    """The style is the render layer's step: Analysis.wireframe(rho=) and Wireframe.restyled(rho)
    give at another rho what `hbc wireframe --rho` gives, on the same analysis and the same
    wireframe arrays (shared, not computed again); the analysis' own rho is only their default."""
    # The twist cube's whole-mesh wireframe has classes that join at rho 0 (teapot's does not).
    path = shared_data_dir / TABLE1 / "cube_twist-comp.obj.HYBRID"
    a = hbc.load(path).analyze(rho=0.8)
    stats = a.stats
    w8 = a.wireframe()
    assert w8.rho == 0.8 and a.rho == 0.8
    w0 = a.wireframe(rho=0.0)
    again = w8.restyled(0.0)
    assert w0.rho == again.rho == 0.0
    for w, flags in ((w8, ()), (w0, ("--rho", "0")), (again, ("--rho", "0"))):
        classes, colors, opacity = cli_wireframe_style(hbc_cli, path, *flags)
        assert w.color_class.tolist() == classes and w.color.tolist() == colors
        assert np.array_equal(w.point_opacity, opacity)
    assert len(np.unique(w0.color_class)) < len(np.unique(w8.color_class)), "rho 0 joins classes"
    # The restyle shares the wireframe: the same polylines, not a copy; the counts are unchanged.
    assert np.shares_memory(again.polylines_items, w8.polylines_items)
    assert a.stats["vsg_edges"] == stats["vsg_edges"] and a.stats["timings"] == stats["timings"]
    # A sheet's wireframe restyles the same way.
    s = 0
    ws = a.wireframe(sheet=s, rho=0.0)
    classes, colors, _ = cli_wireframe_style(hbc_cli, path, "--sheet", str(s), "--rho", "0")
    assert ws.color_class.tolist() == classes and ws.color.tolist() == colors
    with pytest.raises(ValueError, match="rho"):
        w8.restyled(1.5)
    with pytest.raises(ValueError, match="rho"):
        a.wireframe(rho=-0.1)
