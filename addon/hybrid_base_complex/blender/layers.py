"""One builder per layer: structure arrays -> objects in a (not yet linked) collection.

Each builder takes (tx, coll, structure, settings, name) where settings is the scene's
HBCSettings (or any object with the same attributes) and name the mesh's root collection name,
and returns the number of objects it made. A builder is a build step (plan/steps.py): a generator
that asks for its C++ geometry through `Work` (a worker thread in a window) and yields between the
objects it writes; a plain function returning the count is taken as one step. `build_layer` wraps
a builder in a transaction and swaps the result in; `build_layer_steps` is the same as a step.
"""

from __future__ import annotations

import json
import time

import numpy as np

from ..plan import planning as P
from ..plan.steps import Work, run_direct
from . import inspect
from . import scene as S
from .context import SUBSHEET_RULE_PROP


def _props(name, layer, **extra):
    d = {"hbc_mesh": name, "hbc_layer": layer}
    d.update(extra)
    return d


def build_direct(tx, coll, s, st, name):
    made = 0
    if st.direct_boundary:
        soup, edges = yield Work(S.with_edges, s.direct_boundary)
        alpha = st.boundary_opacity if st.direct_transparent else 1.0
        color = P.role_color(P.part_request("direct", "boundary"))
        mat = S.material(tx, "flat", color, alpha)
        ob = S.soup_object(tx, coll, f"{name} boundary", soup, None, mat, _props(name, "direct", hbc_part="boundary"),
                           edges=edges)
        # No colour attribute: Solid > Attribute (the add-on's setting) draws such an object in its
        # object colour, transparent when that colour's alpha is below 1 (the material's alpha
        # counts in Solid > Material only).
        ob.color = tuple(color[:3]) + (float(alpha),)
        # A click selects the front-most selectable object under the cursor: a see-through
        # boundary in front of everything would take every click meant for what it lets show.
        ob.hide_select = S.see_through(ob)
        made += 1
        yield None
    types = np.asarray(s.mesh.cell_types)
    if s.wants(P.part_request("direct", "non_hex")):
        soup, edges = yield Work(S.with_edges, s.non_hex_cells, st.direct_shrink)
        S.soup_object(tx, coll, f"{name} non-hex cells", soup, s.cell_type_colors(soup.face_owner), None,
                      _props(name, "direct", hbc_part="non_hex"), edges=edges)
        made += 1
        yield None
    if st.direct_hex_cells and np.any(types == 0):
        soup, edges = yield Work(S.with_edges, s.hex_region)
        mat = S.material(tx, "flat", P.role_color(P.part_request("direct", "hex")), 1.0)
        S.soup_object(tx, coll, f"{name} hex cells", soup, None, mat, _props(name, "direct", hbc_part="hex"),
                      edges=edges)
        made += 1
        yield None
    return made + inspect.build_direct_cells(tx, coll, s, st, name)


def build_graph(tx, coll, s, st, name):
    radius = st.line_radius * s.length
    made = 0
    for group, _color, lines in (yield Work(s.singularity_lines)):
        if lines.positions.size:
            S.lines_object(tx, coll, f"{name} {group}", lines, radius, _props(name, "graph", hbc_group=group))
            made += 1
            yield None
    return made


def build_blocks(tx, coll, s, st, name):
    big = s.num_components > st.split_max  # one object: its edges made off the main thread too
    soup, edges = yield Work(S.with_edges if big else S.without_edges, s.blocks, st.shrink)
    colors = s.component_colors()
    kinds = s.component_kinds()

    def props_of(c):
        return _props(name, "components", hbc_component=c, hbc_kind=P.COMPONENT_KINDS[int(kinds[c])])

    if not big:
        return len((yield from S.split_soup_objects(tx, coll, f"{name} component", soup, colors, props_of)))
    S.soup_object(tx, coll, f"{name} components", soup, None, None, _props(name, "components", hbc_owner="component"),
                  owner_colors=colors, edges=edges)
    return 1


def build_sheets(tx, coll, s, st, name):
    """Every sheet as one large coloured piece: one object per sheet (clickable) up to split_max."""
    n = s.num_sheets
    if n == 0:
        return 0
    colors = P.part_colors(P.part_request("sheets", "sheets"), np.arange(n))
    types = s.sheet_types()
    big = n > st.split_max
    soup, edges = yield Work(S.with_edges if big else S.without_edges, s.all_sheets, st.shrink)

    def props_of(i):
        return _props(name, "sheets", hbc_sheet=i, hbc_sheet_type=P.SHEET_TYPES[int(types[i])])

    if not big:
        objects = yield from S.split_soup_objects(tx, coll, f"{name} sheet", soup, colors, props_of)
        show_sheets(objects, st)
        return len(objects)
    S.soup_object(tx, coll, f"{name} sheets", soup, None, None, _props(name, "sheets", hbc_owner="sheet"),
                  owner_colors=colors, edges=edges)
    return 1


def show_sheets(objects, st):
    """All sheets share one space and z-fight: by default only the picked one is shown."""
    for ob in objects:
        ob.hide_viewport = not st.sheets_all and ob.get("hbc_sheet") != st.sheet_index


def _dot_radius(s, st):
    return st.dot_radius * s.length


def build_sheet(tx, coll, s, st, name):
    """The picked sheet with its highlights (named "picked sheet": the sheets layer has a "sheet i"
    of its own, and a second one would be named "sheet i.001")."""
    i = st.sheet_index
    if not (0 <= i < s.num_sheets):
        raise ValueError(f"no sheet {i} (the mesh has {s.num_sheets})")
    t = P.SHEET_TYPES[int(s.sheet_types()[i])]
    soup = yield Work(s.sheet_blocks, i, st.shrink)
    owners = np.arange(int(soup.face_owner.max()) + 1 if soup.num_faces else 0)
    oc = P.part_colors(P.part_request("sheet", "sheet"), owners, sheet=i)
    S.soup_object(tx, coll, f"{name} picked sheet {i}", soup, None, None,
                  _props(name, "sheet", hbc_sheet=i, hbc_sheet_type=t, hbc_owner="component"), owner_colors=oc)
    made = 1
    yield None
    unmatched, shared, edges, cells = yield Work(s.sheet_highlights, i, _dot_radius(s, st))
    if unmatched.num_faces:
        S.soup_object(tx, coll, f"{name} picked sheet {i} unmatched vertices", unmatched,
                      P.part_colors(P.part_request("sheet", "unmatched"), unmatched.face_owner), None,
                      _props(name, "sheet", hbc_sheet=i, hbc_highlight="unmatched", hbc_count=unmatched.num_faces // 8))
        made += 1
    if shared.num_faces:
        S.soup_object(tx, coll, f"{name} picked sheet {i} shared vertices", shared,
                      P.part_colors(P.part_request("sheet", "shared"), shared.face_owner), None,
                      _props(name, "sheet", hbc_sheet=i, hbc_highlight="shared", hbc_count=shared.num_faces // 8))
        made += 1
    if edges.positions.size:
        S.lines_object(tx, coll, f"{name} picked sheet {i} self-parallel edges", edges, st.line_radius * s.length * 1.5,
                       _props(name, "sheet", hbc_sheet=i, hbc_highlight="self_parallel"))
        made += 1
    if cells.num_faces:
        S.soup_object(tx, coll, f"{name} picked sheet {i} self-intersecting cells", cells,
                      P.part_colors(P.part_request("sheet", "self_intersecting"), cells.face_owner), None,
                      _props(name, "sheet", hbc_sheet=i, hbc_highlight="self_intersecting"))
        made += 1
    return made


def build_subsheets(tx, coll, s, st, name):
    """Subsheets of the picked (self-intersecting) sheet side by side, each with its VSG wireframe
    beneath it."""
    i = st.sheet_index
    if not (0 <= i < s.num_sheets):
        raise ValueError(f"no sheet {i} (the mesh has {s.num_sheets})")
    if int(s.sheet_types()[i]) != 3:
        raise ValueError(f"sheet {i} is not self-intersecting: it has no subsheets")
    sub = s.subsheets(i)
    count = int(sub.count)
    colors = P.part_colors(P.part_request("subsheets", "subsheets"), np.arange(count))
    made = 0
    all_soup = yield Work(s.subsheet_soup, i, st.shrink)
    radius = _dot_radius(s, st)
    for k in range(count):
        soup = all_soup.select(all_soup.face_owner == k)
        offset = np.array(P.spread_translation(k, s.points), np.float32) if st.spread else np.zeros(3, np.float32)
        soup.positions = soup.positions + offset
        fc = np.tile(colors[k], (soup.num_faces, 1))
        S.soup_object(tx, coll, f"{name} sheet {i} subsheet {k}", soup, fc, None,
                      _props(name, "subsheets", hbc_sheet=i, hbc_subsheet=k, hbc_owner="subsheet"))
        made += 1
        unmatched = s.subsheet_unmatched(sub, k)
        if len(unmatched):
            d = P.dots(s.points[unmatched] + offset, radius, unmatched)
            S.soup_object(tx, coll, f"{name} sheet {i} subsheet {k} unmatched vertices", d,
                          P.part_colors(P.part_request("subsheets", "unmatched"), d.face_owner), None,
                          _props(name, "subsheets", hbc_sheet=i, hbc_subsheet=k, hbc_highlight="unmatched"))
            made += 1
        lines = yield Work(s.wireframe, i, k, st.opacity_floor, st.simplified, _by_kind(st), _rho(st))
        below = np.array(P.spread_translation(k, s.points, below=True), np.float32) if st.spread else offset
        lines.positions = lines.positions + below
        if lines.positions.size:
            S.lines_object(tx, coll, f"{name} sheet {i} subsheet {k} wireframe", lines, st.line_radius * s.length,
                           _props(name, "subsheets", hbc_sheet=i, hbc_subsheet=k, hbc_wireframe=True))
            made += 1
        yield (k + 1) / count
    coll[SUBSHEET_RULE_PROP] = s.subsheet_rule  # stale once the mesh is analyzed by the other rule
    return made


def _by_kind(st):
    """Wireframes coloured by non-hex kind (planning.WIRE_COLORINGS); settings without the choice
    (older figure scripts) keep the colour classes."""
    return getattr(st, "wireframe_colors", "CLASS") == "KIND"


def _rho(st):
    """The panel's ρ (Scene.hbc.rho) the wireframes are styled at; settings without one (the figure
    script's) leave the structure's (session.analyze's)."""
    return getattr(st, "rho", None)


#: The layers whose colours depend on ρ: a new ρ rebuilds them (restyle) and nothing else.
STYLED_LAYERS = ("wireframe", "subsheets")


def build_wireframe(tx, coll, s, st, name):
    sheet = st.sheet_index if st.wireframe_scope == "SHEET" else None
    lines = yield Work(s.wireframe, sheet, None, st.opacity_floor, st.simplified, _by_kind(st), _rho(st))
    if not lines.positions.size:
        return 0
    S.lines_object(tx, coll, f"{name} wireframe" + (f" sheet {sheet}" if sheet is not None else ""), lines,
                   st.line_radius * s.length, _props(name, "wireframe", hbc_sheet=-1 if sheet is None else sheet))
    return 1


BUILDERS = {
    "direct": build_direct,
    "graph": build_graph,
    "components": build_blocks,
    "sheets": build_sheets,
    "sheet": build_sheet,
    "subsheets": build_subsheets,
    "wireframe": build_wireframe,
}
NEEDS_ANALYSIS = {k for k in BUILDERS if k != "direct"}


def build_into_steps(tx, root, layer, s, st):
    """Builds a layer and returns its collection: the existing layer, rebuilt in place (its
    objects refilled, see scene.Transaction), else a new unlinked collection (registered in tx).
    `root` is the mesh's collection, or (figures/render.py, which links the result
    itself) a name: then the layer is always new. A build step (plan/steps.py)."""
    name = root if isinstance(root, str) else root.name
    coll = None if isinstance(root, str) else S.find_layer(root, layer)
    if coll is not None:
        tx.reuse(coll)
    else:
        coll = tx.collection(P.layer_collection_name(name, layer) + " (building)")
    made = BUILDERS[layer](tx, coll, s, st, name)
    if _is_step(made):
        yield from made
    inspect.equip_layer(tx, coll, layer, s, st)
    if not isinstance(root, str):
        store_legend_facts(root, s, tx)
    return coll


def _is_step(value) -> bool:
    """Whether a builder's result is a build step to run (a generator), not its count."""
    return hasattr(value, "send") and hasattr(value, "throw")


def build_into(tx, root, layer, s, st):
    """build_into_steps run to its end at once."""
    return run_direct(build_into_steps(tx, root, layer, s, st))


LEGEND_FACTS = "hbc_legend_facts"


def store_legend_facts(root, s, tx=None):
    """Keeps the mesh's legend facts (Structure.legend_facts, JSON) on its collection, so that the
    legend of a reopened file is whole before the mesh is read and analyzed again (set through
    the transaction `tx` when given: a rollback puts the old facts back)."""
    text = json.dumps(s.legend_facts(), sort_keys=True)
    if root.get(LEGEND_FACTS) != text:
        if tx is not None:
            tx.set_prop(root, LEGEND_FACTS, text)
        else:
            root[LEGEND_FACTS] = text


def stored_legend_facts(root) -> dict:
    try:
        return json.loads(root.get(LEGEND_FACTS, "{}"))
    except ValueError:
        return {}


def build_layer(root, layer, s, st, log=print):
    """Builds one layer of the mesh under `root`, replacing the old one; all or nothing. Returns
    (collection, a sentence saying what was built and how long it took)."""
    return run_direct(build_layer_steps(root, layer, s, st, log))


def build_layer_steps(root, layer, s, st, log=print):
    """build_layer as a build step (plan/steps.py): a cancel (the step closed) leaves the file as it
    was. The time it reports is the whole build's, waits between steps included."""
    t = time.perf_counter()
    with S.Transaction() as tx:
        coll = yield from build_into_steps(tx, root, layer, s, st)
        S.swap_layer(root, layer, coll, tx)
    done = (f"{root.name}: built {P.LAYER_TITLES[layer]} ({len(S.objects_in(coll))} objects) "
            f"in {time.perf_counter() - t:.2f} s")
    log("hbc: " + done)
    return coll, done
