"""Structure, the add-on's view of an analysis, on real analyses of generated meshes whose
structure is known by construction (native/include/hbc/generate.hpp) and of one shared mesh."""

import numpy as np
import pytest

from hybrid_base_complex.plan import planning as P
from hybrid_base_complex.plan.structure import Structure


@pytest.fixture(scope="module")
def grid(generate):
    # 3x2x2 unit hexes: 12 cells, boundary 2(2*2 + 3*2 + 3*2) = 32 quads. Every edge of the box's
    # outline has valence 1 (singular on the boundary): 12 chains (4 of 3 edges along x, 8 of 2
    # along y or z), 4*3 + 8*2 = 28 edges. No singularity inside, so the base complex is one
    # component, and its sheets are the three slabs along x, y and z, each the whole box.
    return generate("grid", "--size", "3", "2", "2")


@pytest.fixture(scope="module")
def sector5(generate):
    # Valence 5 around the z axis, 2 rings, 2 layers: 5 parallelogram sectors of 2x2x2 hexes (40
    # cells); the axis is one valence-5 chain of 2 edges (3 points) and cuts the mesh into 5
    # components, one per sector.
    return generate("sector", "--valence", "5", "--rings", "2", "--layers", "2")


@pytest.fixture(scope="module")
def pyramids(generate):
    # A row of 3 hexes whose middle one is split into 6 pyramids around its centre: 2 hexes and 6
    # pyramids (8 cells). The split keeps the middle cell's quads, so the boundary is still the
    # 2(1*1 + 3*1 + 3*1) = 14 quads of the 3x1x1 box: 5 on each end hex, 4 on pyramids.
    return generate("split", "--size", "3", "1", "1", "--split", "pyramids", "--cells", "1,0,0")


def test_grid_boundary_and_blocks_are_placed(grid):
    m, a = grid
    s = Structure(m, a, scale=2.0, offset=(10.0, 0.0, 0.0))
    # Points: [0,3]x[0,2]x[0,2] scaled by 2, shifted 10 along x.
    lo, hi = s.bbox()
    np.testing.assert_allclose(lo, [10, 0, 0])
    np.testing.assert_allclose(hi, [16, 4, 4])
    boundary = s.direct_boundary()
    assert boundary.num_faces == 32 and set(boundary.face_owner.tolist()) == {0}  # owner: hex type
    assert s.hex_region().num_faces == 32  # all hex: the hex region's surface is the boundary
    assert s.non_hex_cells().num_faces == 0
    assert s.num_components == 1
    blocks = s.blocks(0.5)
    # One component: its separation faces are the 32 boundary quads; shrink 0.5 pulls every point
    # half-way to the centroid of the block's distinct vertices. The grid's vertices are symmetric
    # about the box centre (13, 2, 2), so x spans [13 - 1.5, 13 + 1.5].
    assert blocks.num_faces == 32
    assert blocks.positions[:, 0].min() == pytest.approx(11.5) and blocks.positions[:, 0].max() == pytest.approx(14.5)
    assert blocks.positions[:, 2].min() == pytest.approx(1.0) and blocks.positions[:, 2].max() == pytest.approx(3.0)


def test_grid_graph_and_sheets(grid):
    m, a = grid
    s = Structure(m, a)
    (name, color, lines), = s.singularity_lines()
    assert name == "Valence 1" and color == P.valence_color(1)
    assert lines.num_polylines == 12 and len(lines.edges) == 28
    points_per_chain = np.bincount(lines.polyline)
    assert sorted(points_per_chain.tolist()) == [3] * 8 + [4] * 4  # 8 chains of 2 edges, 4 of 3
    assert s.num_sheets == 3 and s.sheet_types().tolist() == [0, 0, 0]
    cells, comps = s.sheet_sizes()
    assert cells.tolist() == [12, 12, 12] and comps.tolist() == [1, 1, 1]
    np.testing.assert_array_equal(s.component_sheets(0), [0, 1, 2])
    sheets = s.all_sheets(0.0)
    assert np.bincount(sheets.face_owner).tolist() == [32, 32, 32]  # each sheet is the whole box
    one = s.sheet_blocks(1, 0.0)
    assert one.num_faces == 32 and set(one.face_owner.tolist()) == {0}  # its one block: component 0
    # A perfect sheet has nothing to highlight.
    unmatched, shared, edges, si = s.sheet_highlights(0, 0.1)
    assert (unmatched.num_faces, shared.num_faces, edges.num_polylines, si.num_faces) == (0, 0, 0, 0)


def test_sector_graph_and_components(sector5):
    m, a = sector5
    s = Structure(m, a)
    assert s.num_cells == 40
    groups = {name: lines for name, _, lines in s.singularity_lines()}
    assert sorted(groups) == ["Valence 1", "Valence 5"]
    axis = groups["Valence 5"]
    assert axis.num_polylines == 1 and len(axis.positions) == 3 and len(axis.edges) == 2
    np.testing.assert_allclose(axis.positions[:, :2], 0.0, atol=1e-6)  # on the z axis
    assert s.num_components == 5
    blocks = s.blocks(0.0)
    assert set(blocks.face_owner.tolist()) == set(range(5))
    # Each sector is a 2x2x2 block of hexes: 6 sides of 2x2 quads.
    assert np.bincount(blocks.face_owner).tolist() == [24] * 5
    np.testing.assert_allclose(s.component_colors(), P.component_colors(s.component_kinds()))


def test_sector_wireframe_opacity_and_simplification(sector5):
    m, a = sector5
    s = Structure(m, a)
    w = a.wireframe()
    full = s.wireframe(floor=0.3, simplified=False)
    assert full.num_polylines == w.count
    simple = s.wireframe(floor=0.3)
    assert simple.num_polylines == int(np.sum(w.shown))
    # The floor is where the lowest opacity lands; the highest stays 1.
    assert full.colors[:, 3].min() == pytest.approx(0.3) and full.colors[:, 3].max() == pytest.approx(1.0)


def test_split_direct_view(pyramids):
    m, a = pyramids
    s = Structure(m, a)
    types = np.asarray(m.cell_types)
    assert int(np.sum(types == 3)) == 6 and int(np.sum(types == 0)) == 2
    non_hex = s.non_hex_cells()
    # 6 pyramids of 5 faces, each its own block (owner = cell id).
    assert non_hex.num_faces == 30
    assert set(non_hex.face_owner.tolist()) == set(np.flatnonzero(types == 3).tolist())
    np.testing.assert_allclose(s.cell_type_colors(non_hex.face_owner), np.tile(P.CELL_TYPE_COLORS[3], (30, 1)))
    # The two hexes touch only pyramids (the middle cell's end quads) and the boundary: all 12 of
    # their faces bound the hex region.
    assert s.hex_region().num_faces == 12
    boundary = s.direct_boundary()
    assert boundary.num_faces == 14
    assert np.bincount(boundary.face_owner, minlength=4)[[0, 3]].tolist() == [10, 4]
    # Without an analysis the direct view is the same.
    bare = Structure(m, None)
    assert bare.direct_boundary().num_faces == 14 and bare.non_hex_cells().num_faces == 30
    # Pseudo-singular edges (edge_class 2, 20 around the pyramids here) are drawn one 2-point
    # polyline each, in their own group after the valence groups.
    names = [g[0] for g in s.singularity_lines()]
    assert names[-1] == "Pseudo-singular"
    pseudo = s.singularity_lines()[-1][2]
    assert pseudo.num_polylines == int(np.sum(np.asarray(a.graph.edge_class) == 2)) == 20


def test_real_mesh_highlights_and_subsheets(shared_data_dir):
    """twistcube_s: sheets of every type; highlight counts follow the analysis' rows."""
    import hbc

    m = hbc.load(shared_data_dir / "hybrid-base-complex" / "twistcube_s.mesh")
    a = m.analyze()
    s = Structure(m, a)
    types = s.sheet_types()
    assert {0, 1, 2, 3} <= set(types.tolist())

    def row(name, i):
        off, items = getattr(a, f"sheet_{name}_offsets"), getattr(a, f"sheet_{name}_items")
        return items[off[i]:off[i + 1]]

    for i in (int(np.flatnonzero(types == t)[0]) for t in (1, 2, 3)):
        unmatched, shared, edges, si = s.sheet_highlights(i, 0.1)
        # One octahedron (8 triangles) per listed vertex, one polyline per self-parallel curve.
        assert unmatched.num_faces == 8 * len(row("unmatched_vertices", i))
        assert shared.num_faces == 8 * len(row("shared_vertices", i))
        assert edges.num_polylines == len(row("self_parallel_curves", i))
        comps = row("self_intersecting_components", i)
        assert set(si.face_owner.tolist()) == set(comps.tolist())
        assert (si.num_faces > 0) == (types[i] == 3)
    (sheet,) = [int(x) for x in a.self_intersecting_sheets]
    sub = s.subsheets(sheet)
    soup = s.subsheet_soup(sheet, 0.0)
    assert set(soup.face_owner.tolist()) == set(range(int(sub.count)))


def test_legend_facts_of_known_meshes(grid, sector5, pyramids):
    """What the legend names comes from the analysis: the grid has only valence-1 boundary chains
    and no non-hex cell; the sector adds its valence-5 axis; the split row has pyramids and a
    non-hex block."""
    facts = Structure(*grid).legend_facts()
    assert facts == {"non_hex_types": [], "valences": [1], "has_pseudo": False, "has_non_manifold": False,
                     "has_non_hex_blocks": False}
    assert P.legend(["graph", "components"], **facts) == [("valence1", "Valence 1 edge")]
    assert Structure(*sector5).legend_facts()["valences"] == [1, 5]
    split = Structure(*pyramids).legend_facts()
    assert split["non_hex_types"] == [3] and split["has_non_hex_blocks"]
    assert P.legend(["direct", "components"], **split) == [("hex", "Boundary, hex cells"), ("pyramid", "Pyramid cells"),
                                                       ("non_hex_component", "Non-hex component")]
    assert Structure(pyramids[0]).legend_facts() == {"non_hex_types": [3]}  # not analysed: cell types only


def test_legend_names_only_the_highlights_drawn():
    every = [k for k, _ in P.legend(["sheet"])]
    assert every == [k for k, _ in P.SHEET_HIGHLIGHTS]
    assert P.legend(["subsheets"], highlights={"unmatched", None}) == [("unmatched", "Dot: unmatched")]
    assert P.legend(["sheet"], highlights=set()) == []
