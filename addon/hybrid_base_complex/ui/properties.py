"""Scene settings of the add-on (bpy.types.Scene.hbc), the sheet list items, the inspection's
settings (bpy.types.Scene.hbc_inspect) and the source path of an imported mesh
(bpy.types.Collection.hbc_path), with the update callbacks that act on the scene when they change.
ui/addon.py adds them to Blender's types."""

import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty, FloatVectorProperty,
                       IntProperty, PointerProperty, StringProperty)

from ..blender import inspect
from ..blender import layers
from ..blender import scene
from ..blender.context import active_root, drawn_sheet, find_root, refresh_subsheets_stale
from ..plan import inspection as IP
from ..plan import planning as P
from ..plan import session


class HBCSheetItem(bpy.types.PropertyGroup):
    index: IntProperty()
    type: IntProperty(description="0 perfect, 1 type 1 (non-hex), 2 type 2 (self-parallel), "
                                  "3 type 3 (self-intersecting)")
    cells: IntProperty()
    components: IntProperty()


def _legend_color(key):
    return FloatVectorProperty(subtype="COLOR", size=4, min=0.0, max=1.0,
                               get=lambda self: tuple(P.LEGEND_COLORS[key]),
                               description="Legend colour (read-only)")


class HBCSettings(bpy.types.PropertyGroup):
    active_mesh: StringProperty(name="Mesh", description="Root collection of the mesh the panel acts on")

    # direct view
    direct_boundary: BoolProperty(name="Boundary", default=True, description="Show the boundary surface")
    direct_transparent: BoolProperty(name="See-through", default=True,
                                     description="Draw the boundary transparent so the inside shows")
    boundary_opacity: FloatProperty(name="Opacity", default=0.15, min=0.0, max=1.0,
                                  description="Opacity of the see-through boundary")
    direct_hex_cells: BoolProperty(name="Hex region", default=False,
                                   description="Also show the surface of the hex region as an opaque solid")
    direct_shrink: FloatProperty(name="Shrink", default=0.0, min=0.0, max=0.9,
                                 description="Pull every non-hex cell towards its centre")

    # components (the Components layer), sheets
    shrink: FloatProperty(name="Shrink", default=0.1, min=0.0, max=0.9,
                          description="Pull every component or sheet towards its centre to separate them")
    split_max: IntProperty(name="Max objects", default=1000, min=0,
                           description="Up to this many components or sheets, one object each (clickable); "
                                       "more: one merged mesh with a face attribute 'owner'")
    sheets: CollectionProperty(type=HBCSheetItem)
    sheet_index: IntProperty(name="Sheet", default=0, min=0, update=lambda self, context: _sheet_picked(self, context))
    auto_show: BoolProperty(name="Show on pick", default=True,
                            description="Rebuild the picked-sheet layer when another sheet is picked in the list")
    sheets_all: BoolProperty(name="All sheets", default=False,
                             update=lambda self, context: _sheets_visibility(self),
                             description="Show every sheet of the sheets layer at once (they overlap); "
                                         "off: only the picked sheet")
    sheet_sort: EnumProperty(name="Sort", default="INDEX",
                             items=[("INDEX", "Index", "Sheets in analysis order"),
                                    ("TYPE", "Type", "By type, then size (largest first)"),
                                    ("SIZE", "Size", "By number of cells, largest first")],
                             description="Order of the sheet list")

    # lines
    line_radius: FloatProperty(name="Tube", default=0.0035, min=0.0, max=0.1, precision=4,
                               description="Tube radius of the lines, as a fraction of the model's diagonal")
    dot_radius: FloatProperty(name="Dot", default=0.006, min=0.0, max=0.1, precision=4,
                              description="Radius of the highlight dots, as a fraction of the model's diagonal")

    # wireframe
    rho: FloatProperty(name="ρ", default=0.8, min=0.0, max=1.0,
                       update=lambda self, context: _rho_changed(self),
                       description="Threshold of the wireframe's colour classes (partial-parallel fraction; "
                                   "only colours depend on it): a change restyles the wireframes, "
                                   "without analysing again")
    subsheet_rule: EnumProperty(
        name="Subsheets", default="layers",
        items=[("layers", "Layers", "The paper's authors' decomposition of self-intersecting sheets"),
               ("fewest", "Fewest", "The fewest subsheets, with a lower bound that proves it when they meet")],
        description="How self-intersecting sheets are split into subsheets, in every analysis: the import, Analyze, "
                    "and a mesh analyzed again for a layer, Export VTU, the Metrics box or Figures")
    opacity_floor: FloatProperty(name="Floor", default=0.15, min=0.0, max=1.0,
                                 description="Opacity of the faintest (farthest) wireframe lines")
    simplified: BoolProperty(name="Simplified", default=True,
                             description="The simplified wireframe (kept and reactivated chains); "
                                         "off: the complete wireframe")
    wireframe_colors: EnumProperty(name="Colour", default="CLASS", items=list(P.WIRE_COLORINGS),
                                   description="What the wireframes' colours show")
    wireframe_scope: EnumProperty(name="Scope", description="Wireframe of the whole mesh or of the picked sheet", items=[("MESH", "Mesh", "The whole mesh's wireframe"),
                                                       ("SHEET", "Sheet", "The picked sheet's wireframe")])
    spread: BoolProperty(name="Side by side", default=True,
                         description="Lay subsheets out side by side with their wireframe beneath")


def _sheets_visibility(settings):
    root = find_root(settings.active_mesh) if settings.active_mesh else None
    coll = scene.find_layer(root, "sheets") if root is not None else None
    if coll is not None:
        layers.show_sheets([ob for ob in scene.objects_in(coll) if "hbc_sheet" in ob], settings)


def _rho_changed(settings):
    """A new ρ: the active mesh's wireframe layers (layers.STYLED_LAYERS) are rebuilt at it from
    the analysis in memory, which stays as it is (the style is the render layer's, not the
    analysis'); a mesh not in memory gets it at its next build."""
    root = find_root(settings.active_mesh) if settings.active_mesh else None
    s = session.get(root.name) if root is not None else None
    if s is None or s.analysis is None:
        return
    session.restyle(s, settings.rho)
    root["hbc_rho"] = float(settings.rho)
    for layer in layers.STYLED_LAYERS:
        coll = scene.find_layer(root, layer)
        if coll is None or coll.get("hbc_stale"):
            continue
        try:
            layers.build_layer(root, layer, s, settings)
        except Exception as e:  # noqa: BLE001 - an update callback cannot report; the layer stays as it was
            print(f"hbc: could not restyle {P.LAYER_TITLES[layer]}: {P.describe_error(e)}")


def _sheet_picked(settings, context):
    """Picking a sheet in the list: the sheets layer shows it, the subsheets layer (of another
    sheet) is marked stale and hidden, and the picked-sheet layer is rebuilt (with auto_show)."""
    if not settings.active_mesh:
        return
    root = find_root(settings.active_mesh)
    if root is None:
        return
    _sheets_visibility(settings)
    refresh_subsheets_stale(root, settings.sheet_index)
    s = session.get(settings.active_mesh)
    if not settings.auto_show or s is None or s.analysis is None or scene.find_layer(root, "sheet") is None:
        return
    if 0 <= settings.sheet_index < s.num_sheets:
        try:
            layers.build_layer(root, "sheet", s, settings)
        except Exception as e:  # noqa: BLE001 - an update callback cannot report; the layer stays as it was
            print(f"hbc: could not show sheet {settings.sheet_index}: {P.describe_error(e)}")


def _picked_sheet_swatch(settings):
    """The legend's *Picked sheet* swatch: the colour of the sheet the active mesh's picked-sheet
    layer draws (the list's pick before that layer is built)."""
    sheet = drawn_sheet(active_root(bpy.context))
    return P.sheet_color(settings.sheet_index if sheet is None else sheet)


# Legend swatches: one read-only colour property per planning.LEGEND_COLORS key (the library's
# layer plan; none without the compiled module, when no legend can be shown); the picked sheet's
# is the colour of that sheet.
HBCSettings.__annotations__.update({f"legend_{k}": _legend_color(k) for k in P.legend_color_keys()
                                    if k != "picked_sheet"})
HBCSettings.__annotations__["legend_picked_sheet"] = FloatVectorProperty(
    subtype="COLOR", size=4, min=0.0, max=1.0, get=_picked_sheet_swatch,
    description="Legend colour: the picked sheet's own (read-only)")


# ---------------------------------------------------------------------------------------------
# Looking inside (blender/inspect.py)

def _upd(self, context):
    inspect.apply(context)


def _upd_color(self, context):
    inspect.recolor(context)
    inspect.refresh_all(context)


def _upd_cells(self, context):
    """Showing the cells needs the direct view rebuilt (with its cells object)."""
    root = active_root(context)
    s = session.get(root.name) if root is not None else None
    if s is not None and scene.find_layer(root, "direct") is not None:
        layers.build_layer(root, "direct", s, context.scene.hbc)


class HBCInspectSettings(bpy.types.PropertyGroup):
    enabled: BoolProperty(name="Filters", default=True, update=_upd,
                          description="Apply the inspection filters to the cell-based layers")
    direct_cells: BoolProperty(name="All cells", default=False, update=_upd_cells,
                               description="Show every cell in the direct view (to look inside)")
    color_by_quality: BoolProperty(name="By quality", default=False, update=_upd_color,
                                   description="Colour the direct view's cells by scaled Jacobian (viridis)")
    plane: PointerProperty(name="Plane", type=bpy.types.Object, update=_upd,
                           description="Empty whose circle cuts (its local XZ plane); cells on its +Y side are hidden")
    slice: BoolProperty(name="Slice", default=False, update=_upd)
    flip: BoolProperty(name="Flip", default=False, update=_upd, description="Hide the other side")
    peel: IntProperty(name="Peel", default=0, min=0, soft_max=20, update=_upd,
                      description="Hide the cells fewer than this many layers from the boundary")
    show_hex: BoolProperty(name="Hex", default=True, update=_upd)
    show_tet: BoolProperty(name="Tet", default=True, update=_upd)
    show_prism: BoolProperty(name="Prism", default=True, update=_upd)
    show_pyramid: BoolProperty(name="Pyramid", default=True, update=_upd)
    show_polyhedron: BoolProperty(name="Polyhedron", default=True, update=_upd)
    filter_quality: BoolProperty(name="Quality range", default=False, update=_upd,
                                 description="Show only the cells whose scaled Jacobian is in [min, max]")
    quality_min: FloatProperty(name="Min", default=-1.0, min=-1.0, max=1.0, update=_upd)
    quality_max: FloatProperty(name="Max", default=1.0, min=-1.0, max=1.0, update=_upd)
    sheet_only: BoolProperty(name="Sheet only", default=False, update=_upd,
                             description="Show only the cells of the sheet picked in the sheet list")
    surface_above: IntProperty(name="Surface above", default=100000, min=0,
                               description="Meshes with more cells show only the surface of the kept cells in "
                                           "the direct view, rebuilt in C++ when a filter or the plane changes "
                                           "(fast for 10^6 cells); smaller ones hold every cell, filtered by "
                                           "geometry nodes")
    # Legend swatches: the colour map at LEGEND_VALUES (display only).
    for _i, _c in enumerate(IP.quality_colors(IP.LEGEND_VALUES)):
        __annotations__[f"legend_{_i}"] = FloatVectorProperty(
            name=f"{IP.LEGEND_VALUES[_i]:.2f}", subtype="COLOR", size=3, min=0.0, max=1.0,
            default=tuple(float(x) for x in _c[:3]))
    del _i, _c


# ---------------------------------------------------------------------------------------------
# The source path of an imported mesh

def _get_source(root):
    return root.get("hbc_source", "")


def _set_source(root, value):
    root["hbc_source"] = value
    session.drop(root.name)  # read again from the new path on the next build


def source_path_property():
    """Collection.hbc_path. The source path lives in the ID property "hbc_source" (it marks a
    collection as an imported mesh); this file-path view of it gives the panel a file browser to
    point the mesh at its file again. A get/set property stores nothing itself, so both stay one
    value in every Blender (5.0 keeps bpy.props values apart from dictionary-style ID properties)."""
    return StringProperty(
        name="Source", subtype="FILE_PATH", get=_get_source, set=_set_source,
        description="The mesh file the layers are built from (relative to the .blend when saved)")
