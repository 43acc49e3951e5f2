"""Every difference between the Blender versions the add-on supports (3.4 to 5.2), in one place.

Each function is checked by the add-on's tests in every Blender of the test matrix. Where an API
changed, the check is on what the running Blender offers (an attribute, a socket name) when that
is unambiguous, and on `bpy.app.version` otherwise; each branch names the release that changed it:

- 4.0: Principled BSDF sockets renamed and reordered (`Emission` -> `Emission Color`, emission
  strength default 0, `Specular` -> `Specular IOR Level`, ...): sockets are found by name only;
  node-group sockets through `ng.interface.new_socket`; `is_modifier` on geometry-node groups;
  `MeshPolygon.loop_total` read-only (derived from `loop_start`).
- 4.2: Object Info's Rotation output is a Rotation socket (was an Euler vector): turned vectors
  use Rotate Vector instead of Vector Rotate (checked on the socket's type).
- 4.2: `Material.blend_method` -> `surface_render_method`, `show_transparent_back` ->
  `use_transparency_overlap`; EEVEE is `BLENDER_EEVEE_NEXT` (until 4.5, `BLENDER_EEVEE` again
  from 5.0).
- 4.3: `Material.shadow_method` removed.
- 5.0: `bpy.data.materials.new()` gives a material whose node tree is empty and `use_nodes` is
  deprecated (always on): the nodes are built explicitly.
- 4.0: the corners' vertices are the `.corner_vert` attribute (MeshLoop.vertex_index reads it).
- Every version: `foreach_set` copies a buffer as a whole only when its item type is the
  property's: the vertex indices of 3.4's loops and edges (MLoop.v, MEdge.v1/v2) and the polygon
  starts and sizes are unsigned there, and an int32 array goes through a per-item path (16 M
  corners: 1.4 s against 0.08 s; 4 M loop starts 0.35 s against 0.02 s). From 4.0 `.corner_vert`
  takes int32 at full speed and uint32 slowly, while loop starts and edges still take uint32 fast
  (measured in 3.4, 4.2, 5.0 and 5.2): `set_corner_verts`, `set_corner_edges`, `set_polygons`,
  `set_edge_verts`.
- 5.0: an output's `image_settings.media_type` (IMAGE, VIDEO, ...) chooses which file formats
  exist: FFMPEG only after VIDEO (`video_output`, `image_output`); the sequencer's strips are
  `sequence_editor.strips` (4.4+; `sequences` removed in 5.0: `sequencer_strips`).
- 5.2: geometry-nodes modifier inputs are no longer ID properties (`mod["Socket_1"]` raises
  "id properties not supported"); they are `mod.properties.inputs.Socket_1.value`, used wherever
  the running Blender has it.
"""

from __future__ import annotations

import bpy
import numpy as np

VERSION = tuple(bpy.app.version)

#: Node-group sockets live in `ng.interface` (4.0+), not in `ng.inputs` / `ng.outputs`.
NODE_INTERFACE = VERSION >= (4, 0, 0)
#: EEVEE Next's material settings and engine id (4.2+).
EEVEE_NEXT = VERSION >= (4, 2, 0)

# Principled BSDF inputs by their 4.0+ names, with the name 3.x used for the same input.
_PRINCIPLED_OLD_NAMES = {
    "Emission Color": "Emission",
    "Specular IOR Level": "Specular",
    "Subsurface Weight": "Subsurface",
    "Transmission Weight": "Transmission",
    "Coat Weight": "Clearcoat",
    "Sheen Weight": "Sheen",
}


def eevee_engine() -> str:
    """The render engine id of EEVEE in this Blender."""
    return "BLENDER_EEVEE_NEXT" if (4, 2, 0) <= VERSION < (5, 0, 0) else "BLENDER_EEVEE"


def has_denoiser() -> bool:
    """Whether Cycles here was built with OpenImageDenoise (the bpy wheels are; Debian's 3.4 not)."""
    try:
        import _cycles  # Blender's Cycles module, present whenever Cycles is
    except ImportError:
        return False
    return bool(getattr(_cycles, "with_openimagedenoise", False))


# ---------------------------------------------------------------------------------------------
# Materials

def principled_input(bsdf, name: str):
    """A Principled BSDF input by its 4.0+ name (also found under its 3.x name), never by index."""
    sock = bsdf.inputs.get(name)
    if sock is None and name in _PRINCIPLED_OLD_NAMES:
        sock = bsdf.inputs.get(_PRINCIPLED_OLD_NAMES[name])
    if sock is None:
        raise KeyError(f"Principled BSDF has no input {name!r} in Blender {bpy.app.version_string}")
    return sock


def new_node_material(name: str):
    """A new material with a Principled BSDF wired to a Material Output; returns (material,
    node tree, bsdf). Built explicitly: 5.0's new materials start with an empty node tree."""
    mat = bpy.data.materials.new(name)
    if VERSION < (5, 0, 0):
        mat.use_nodes = True
    nt = mat.node_tree
    bsdf = next((n for n in nt.nodes if n.type == "BSDF_PRINCIPLED"), None)
    out = next((n for n in nt.nodes if n.type == "OUTPUT_MATERIAL"), None)
    if bsdf is None:
        bsdf = nt.nodes.new("ShaderNodeBsdfPrincipled")
        bsdf.location = (-300, 0)
    if out is None:
        out = nt.nodes.new("ShaderNodeOutputMaterial")
        out.location = (100, 0)
    if not out.inputs["Surface"].is_linked:
        nt.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    # No emission whatever the version's default (3.x: black colour, 4.0+: strength 0).
    if "Emission Strength" in bsdf.inputs:
        bsdf.inputs["Emission Strength"].default_value = 0.0
    return mat, nt, bsdf


def world_use_nodes(world):
    """Turns on the world's node tree where that is still a setting (before 5.0)."""
    if VERSION < (5, 0, 0):
        world.use_nodes = True
    return world.node_tree


def set_blend(mat, transparent: bool):
    """Alpha blending for a see-through material, opaque otherwise, in EEVEE and the viewport."""
    if EEVEE_NEXT:
        mat.surface_render_method = "BLENDED" if transparent else "DITHERED"
        if hasattr(mat, "use_transparency_overlap"):
            mat.use_transparency_overlap = False
    else:
        mat.blend_method = "BLEND" if transparent else "OPAQUE"
        if transparent and hasattr(mat, "shadow_method"):  # removed in 4.3
            mat.shadow_method = "NONE"
        if hasattr(mat, "show_transparent_back"):
            mat.show_transparent_back = False


def set_viewport_color(mat, rgba):
    """The colour Solid mode shows for the material (`diffuse_color`, RGBA)."""
    mat.diffuse_color = tuple(float(c) for c in rgba[:4]) if len(rgba) >= 4 else tuple(rgba[:3]) + (1.0,)


# ---------------------------------------------------------------------------------------------
# Geometry nodes

def group_socket(ng, in_out: str, socket_type: str, name: str):
    """Adds an input or output socket to a node group."""
    if NODE_INTERFACE:
        return ng.interface.new_socket(name, in_out=in_out, socket_type=socket_type)
    return (ng.inputs if in_out == "INPUT" else ng.outputs).new(socket_type, name)


def mark_modifier_group(ng):
    """Geometry-node groups are offered as modifiers only when flagged so (4.0+)."""
    if hasattr(ng, "is_modifier"):
        ng.is_modifier = True


def rotate_by_object_rotation(ng, vector, rotation):
    """A node output: `vector` (a constant) turned by Object Info's Rotation output. 3.x-4.x give an
    Euler vector (Vector Rotate, Euler XYZ); where the output is a Rotation socket (4.2+), the
    Rotate Vector node takes it as it is."""
    if getattr(rotation, "type", "VECTOR") == "ROTATION":
        node = ng.nodes.new("FunctionNodeRotateVector")
        node.inputs["Vector"].default_value = vector
    else:
        node = ng.nodes.new("ShaderNodeVectorRotate")
        node.rotation_type = "EULER_XYZ"
        node.inputs["Vector"].default_value = vector
    ng.links.new(rotation, node.inputs["Rotation"])
    return node.outputs["Vector"]


def _input_identifier(ng, name: str) -> str:
    if NODE_INTERFACE:
        return next(s.identifier for s in ng.interface.items_tree
                    if getattr(s, "item_type", "SOCKET") == "SOCKET"
                    and getattr(s, "in_out", None) == "INPUT" and s.name == name)
    return ng.inputs[name].identifier


def _modifier_socket(mod, ident):
    """5.2+: the modifier's interface accessor `mod.properties.inputs.<identifier>` (an object
    with `.value`); None where inputs are still ID properties of the modifier (`mod[identifier]`)."""
    inputs = getattr(getattr(mod, "properties", None), "inputs", None)
    return getattr(inputs, ident, None) if inputs is not None else None


def set_modifier_input(mod, name: str, value):
    """Sets the geometry-nodes modifier input called `name` (the group's socket name)."""
    ident = _input_identifier(mod.node_group, name)
    sock = _modifier_socket(mod, ident)
    if sock is not None:
        sock.value = value
    else:
        mod[ident] = value


def get_modifier_input(mod, name: str):
    ident = _input_identifier(mod.node_group, name)
    sock = _modifier_socket(mod, ident)
    return sock.value if sock is not None else mod[ident]


# ---------------------------------------------------------------------------------------------
# Meshes

def _indices(values, dtype):
    return np.ascontiguousarray(values, dtype).ravel()


def set_polygons(me, loop_starts, face_sizes):
    """Polygon loop starts (and, before 4.0, loop totals: later they follow from the starts)."""
    me.polygons.foreach_set("loop_start", _indices(loop_starts, np.uint32))
    if VERSION < (4, 0, 0):
        me.polygons.foreach_set("loop_total", _indices(face_sizes, np.uint32))


def _set_corner_values(me, attribute, loop_property, values):
    """From 4.0 a corner map is a signed attribute (`.corner_vert`, `.corner_edge`); before, an
    unsigned loop property. foreach_set copies a buffer whole only in the property's own type."""
    attr = me.attributes.get(attribute)
    if attr is not None:
        attr.data.foreach_set("value", _indices(values, np.int32))
    else:
        me.loops.foreach_set(loop_property, _indices(values, np.uint32))


def set_corner_verts(me, corner_verts):
    """The vertex of every corner (loop) of a mesh whose loops were just added."""
    _set_corner_values(me, ".corner_vert", "vertex_index", corner_verts)


def set_corner_edges(me, corner_edges):
    """The edge of every corner (to the next corner of its face) of a mesh whose edges are set."""
    _set_corner_values(me, ".corner_edge", "edge_index", corner_edges)


def set_edge_verts(me, edges):
    """The two vertices of every edge of a mesh whose edges were just added ((m, 2) or flat)."""
    me.edges.foreach_set("vertices", _indices(edges, np.uint32))


def make_active_color(me, attr):
    """Makes a colour attribute the one Solid > Attribute and the renderers show."""
    try:
        me.color_attributes.active_color = attr
        me.color_attributes.render_color_index = me.color_attributes.active_color_index
    except (AttributeError, TypeError):
        pass


# ---------------------------------------------------------------------------------------------
# Context

def temp_override(context=None, **kwargs):
    """`context.temp_override(...)` (dict overrides are gone since 4.0)."""
    return (context or bpy.context).temp_override(**kwargs)


def view3d_spaces(context=None):
    """The 3D View spaces of the current window manager's screens (none in background mode)."""
    wm = (context or bpy.context).window_manager
    for window in getattr(wm, "windows", []):
        for area in window.screen.areas:
            if area.type == "VIEW_3D":
                for space in area.spaces:
                    if space.type == "VIEW_3D":
                        yield space


def solid_shading(shading):
    """The add-on's Solid settings on a View3DShading (a 3D View's, or the scene's display one
    that Workbench renders with): colours from the objects' active colour attribute. The enum is
    still "VERTEX" in 5.x (labelled "Attribute" since 3.2)."""
    shading.color_type = "VERTEX"


def show_attribute_colors(context=None):
    """Solid mode of every open 3D View shows the objects' active colour attribute (the layers'
    colours) instead of the materials' single viewport colour."""
    for space in view3d_spaces(context):
        if space.shading.type == "SOLID":
            solid_shading(space.shading)


def view3d_regions(context):
    """(window, area, region) of every 3D viewport's main region (none in background mode)."""
    wm = context.window_manager
    for window in getattr(wm, "windows", []):
        for area in window.screen.areas:
            if area.type != "VIEW_3D":
                continue
            for region in area.regions:
                if region.type == "WINDOW":
                    yield window, area, region


def frame_objects(context, objects) -> bool:
    """Selects `objects` (the first active) and frames them in every 3D viewport. False when
    there is no viewport to frame in (background mode). context.temp_override exists from 3.2 on."""
    context.view_layer.update()  # objects linked in this same operator join the view layer here
    objects = [ob for ob in objects if ob.name in context.view_layer.objects]
    if not objects:
        return False
    for ob in context.view_layer.objects:
        if ob.select_get():
            ob.select_set(False)
    for ob in objects:
        ob.select_set(True)
    context.view_layer.objects.active = objects[0]
    regions = list(view3d_regions(context))
    for window, area, region in regions:
        with context.temp_override(window=window, area=area, region=region):
            bpy.ops.view3d.view_selected()
    return bool(regions)


def redraw_status(context) -> bool:
    """Draws the window now, so the status bar and the progress counter show a step of a long
    operator while it still runs (Blender redraws only after an operator returns). Nothing to draw
    in background mode (False). `wm.redraw_timer` is the one call that draws from inside an
    operator in every supported version."""
    if bpy.app.background or not getattr(context.window_manager, "windows", None):
        return False
    try:
        bpy.ops.wm.redraw_timer(type="DRAW_WIN_SWAP", iterations=1)
    except RuntimeError:  # no window to draw in this context
        return False
    return True


def frame_edit_selection(context) -> bool:
    """Frames the selected elements of the mesh in edit mode in every 3D viewport."""
    regions = list(view3d_regions(context))
    for window, area, region in regions:
        with context.temp_override(window=window, area=area, region=region):
            bpy.ops.view3d.view_selected()
    return bool(regions)


def layer_exporter(fmt: str):
    """(operator, keywords) of Blender's exporter of selected objects, keeping Blender's axes
    (Z up) so the file has the coordinates the scene shows."""
    axes = {"forward_axis": "Y", "up_axis": "Z"}
    if fmt == "OBJ":  # the C++ OBJ exporter, from 3.2 on
        return bpy.ops.wm.obj_export, dict(export_selected_objects=True, export_materials=False, **axes)
    if "ply_export" in dir(bpy.ops.wm):  # the C++ PLY exporter, from 3.6 on
        return bpy.ops.wm.ply_export, dict(export_selected_objects=True, ascii_format=False, **axes)
    # Blender 3.4/3.5: the io_mesh_ply add-on (enabled in the factory settings).
    return bpy.ops.export_mesh.ply, dict(use_selection=True, axis_forward="Y", axis_up="Z")


# ---------------------------------------------------------------------------------------------
# Render output

def image_output(scene):
    """Renders of `scene` go to 8-bit RGB PNG files."""
    im = scene.render.image_settings
    if hasattr(im, "media_type"):  # 5.0
        im.media_type = "IMAGE"
    im.file_format = "PNG"
    im.color_mode = "RGB"
    im.color_depth = "8"


def video_output(scene, container: str):
    """Renders of `scene` go to one video through Blender's own FFmpeg: `mp4` (H.264) or `webm`
    (VP9), no audio, constant quality."""
    im = scene.render.image_settings
    if hasattr(im, "media_type"):  # 5.0: FFMPEG is only offered for VIDEO
        im.media_type = "VIDEO"
    im.file_format = "FFMPEG"
    im.color_mode = "RGB"
    ff = scene.render.ffmpeg
    mp4 = container == "mp4"
    ff.format = "MPEG4" if mp4 else "WEBM"
    ff.codec = "H264" if mp4 else "WEBM"  # WEBM: VP9
    ff.constant_rate_factor = "MEDIUM"
    ff.ffmpeg_preset = "GOOD"
    ff.gopsize = max(1, int(scene.render.fps))
    ff.audio_codec = "NONE"


def sequencer_strips(scene):
    """The strips collection of the scene's sequencer (made if missing)."""
    ed = scene.sequence_editor or scene.sequence_editor_create()
    return ed.strips if hasattr(ed, "strips") else ed.sequences
