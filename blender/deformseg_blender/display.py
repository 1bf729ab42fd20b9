"""What the add-on leaves in the scene: a colour attribute that follows the timeline, timeline
markers, an alignment curve, an NLA track that plays a second object in step.

A field (a value per polygon per frame) is kept on the mesh as ID properties, so that it is
saved with the .blend file, and a frame-change handler writes the current frame's colours into
the mesh's colour attribute ATTRIBUTE (corner domain, what Workbench and EEVEE display) and its
values into the face attribute VALUE_ATTRIBUTE.
"""
import uuid

import bpy
import numpy as np
from bpy.app.handlers import persistent

from . import analysis

ATTRIBUTE = "deformseg"
VALUE_ATTRIBUTE = "deformseg_value"
FIELD = "deformseg_field"          # the values, T x P floats, frame-major
FIELD_FRAMES = "deformseg_frames"  # the scene frame of each row
FIELD_KIND = "deformseg_kind"      # "strain" (a ramp over [0, 1]) or "labels" (a palette)
FIELD_TOKEN = "deformseg_token"    # which field this is, to tell a cached one from the mesh's own
MARKERS = "deformseg_markers"      # names of the markers the add-on made, on the scene

# Fields read back from ID properties once per mesh (a handler runs at every frame change).
_cache = {}


def polygon_field(frames, values, part, polygon_count):
    """The rows of a (T, F) per-triangle field for object `part` of frames.objects, as (T, P) per
    polygon of its mesh: the largest value of a polygon's triangles (a quad is two triangles);
    polygons without a triangle get 0."""
    mine = frames.triangle_object == part
    polygons = frames.triangle_polygon[mine]
    field = np.full((values.shape[0], polygon_count), -np.inf)
    for t in range(values.shape[0]):
        np.maximum.at(field[t], polygons, values[t][mine])
    field[np.isinf(field)] = 0.0
    return field


def set_fields(frames, values, kind):
    """Shows a (T, F) per-triangle field on every object the frames were sampled from."""
    for part, name in enumerate(frames.objects):
        obj = bpy.data.objects[name]
        set_field(obj, polygon_field(frames, values, part, len(obj.data.polygons)), frames.frame_numbers, kind)


def set_field(obj, field, frame_numbers, kind):
    """Keeps a (T, P) field on obj's mesh and shows the current frame's colours."""
    mesh = obj.data
    mesh[FIELD] = field.astype(np.float32).ravel()
    mesh[FIELD_FRAMES] = list(frame_numbers)
    mesh[FIELD_KIND] = kind
    mesh[FIELD_TOKEN] = token = uuid.uuid4().hex
    _cache[mesh.name_full] = (token, (field.astype(np.float32), list(frame_numbers), kind))
    if ATTRIBUTE not in mesh.color_attributes:
        mesh.color_attributes.new(ATTRIBUTE, 'FLOAT_COLOR', 'CORNER')
    if VALUE_ATTRIBUTE not in mesh.attributes:
        mesh.attributes.new(VALUE_ATTRIBUTE, 'FLOAT', 'FACE')
    mesh.color_attributes.active_color = mesh.color_attributes[ATTRIBUTE]
    update_object(obj, bpy.context.scene.frame_current)


def _field_of(mesh):
    """The field kept on a mesh, from the cache, or from its ID properties when the cache holds
    another field (an undo, another file) or none."""
    if FIELD not in mesh:
        return None
    token, field = _cache.get(mesh.name_full, (None, None))
    if token != mesh.get(FIELD_TOKEN):
        frames = list(mesh[FIELD_FRAMES])
        values = np.array(mesh[FIELD], dtype=np.float32).reshape(len(frames), -1)
        field = (values, frames, mesh[FIELD_KIND])
        _cache[mesh.name_full] = (mesh.get(FIELD_TOKEN), field)
    return field


def update_object(obj, frame):
    """Writes the field's row for scene frame `frame` (the nearest sampled frame) into the mesh."""
    mesh = obj.data
    field = _field_of(mesh)
    if field is None or ATTRIBUTE not in mesh.color_attributes:
        return
    values, frames, kind = field
    row = values[int(np.argmin(np.abs(np.asarray(frames) - frame)))]
    if row.shape[0] != len(mesh.polygons):
        return  # the mesh was edited since: its field no longer applies
    colours = analysis.palette(row.astype(int)) if kind == "labels" else analysis.ramp(row)
    loop_totals = np.empty(len(mesh.polygons), dtype=np.int64)
    mesh.polygons.foreach_get("loop_total", loop_totals)
    # Polygons' loops are consecutive, in polygon order: each corner takes its polygon's colour.
    corner_colours = np.repeat(colours, loop_totals, axis=0).astype(np.float32)
    mesh.color_attributes[ATTRIBUTE].data.foreach_set("color", corner_colours.ravel())
    mesh.attributes[VALUE_ATTRIBUTE].data.foreach_set("value", row)
    mesh.update()


@persistent
def on_frame_change(scene, depsgraph=None):
    """Follows the timeline: every object of the scene with a field shows the current frame."""
    for obj in scene.objects:
        if obj.type == 'MESH' and FIELD in obj.data:
            update_object(obj, scene.frame_current)


@persistent
def on_load(_):
    """A new file: the cache of the previous file's fields no longer applies."""
    _cache.clear()


def clear_field(obj):
    """Takes the field and its attributes off obj's mesh."""
    mesh = obj.data
    for key in (FIELD, FIELD_FRAMES, FIELD_KIND, FIELD_TOKEN):
        if key in mesh:
            del mesh[key]
    _cache.pop(mesh.name_full, None)
    for name in (ATTRIBUTE, VALUE_ATTRIBUTE):
        if name in mesh.attributes:
            mesh.attributes.remove(mesh.attributes[name])


def show_colours(context):
    """Puts the 3D views' solid shading on the colour attribute, so the colours show at once."""
    screen = context.screen
    for area in (screen.areas if screen else []):
        if area.type == 'VIEW_3D':
            for space in area.spaces:
                if space.type == 'VIEW_3D':
                    space.shading.color_type = 'VERTEX'


# ---- markers ---------------------------------------------------------------------------------------

def set_markers(scene, named_frames, group):
    """Replaces the add-on's markers of `group` ("temporal", "keys", "alignment") by
    (name, frame) pairs; markers the user made are left alone."""
    made = dict(scene.get(MARKERS, {}))
    for name in made.get(group, []):
        marker = scene.timeline_markers.get(name)
        if marker is not None:
            scene.timeline_markers.remove(marker)
    names = []
    for name, frame in named_frames:
        names.append(scene.timeline_markers.new(name, frame=int(frame)).name)
    made[group] = names
    scene[MARKERS] = made


def temporal_markers(segments, frame_numbers):
    """Markers at the first frame of each temporal segment: 'S<n> <first>-<last>' in scene frames."""
    return [(f"S{n} {frame_numbers[first]}-{frame_numbers[last]}", frame_numbers[first])
            for n, (first, last) in enumerate(segments)]


def key_frame_markers(graph, frame_numbers):
    """Markers at the first frame of each key frame of the evolving graph, named by its nodes."""
    return [(analysis.key_frame_name(n, key), frame_numbers[key.first]) for n, key in enumerate(graph.key_frames)]


# ---- comparison ------------------------------------------------------------------------------------

CURVE_NAME = "deformseg alignment"


def alignment_curve(context, pairs, frames_a, frames_b, scale=0.05):
    """A poly curve through the aligned frames (frame of A along x, frame of B along y, `scale`
    units a frame), in a new or reused object named CURVE_NAME: the warping path drawn."""
    curve = bpy.data.curves.get(CURVE_NAME) or bpy.data.curves.new(CURVE_NAME, 'CURVE')
    curve.splines.clear()
    curve.dimensions = '3D'
    curve.bevel_depth = scale * 0.2
    spline = curve.splines.new('POLY')
    spline.points.add(len(pairs) - 1)
    points = [(frames_a[i] * scale, frames_b[j] * scale, 0.0, 1.0) for i, j in pairs]
    spline.points.foreach_set("co", np.array(points, dtype=np.float32).ravel())
    obj = bpy.data.objects.get(CURVE_NAME)
    if obj is None:
        obj = bpy.data.objects.new(CURVE_NAME, curve)
        context.scene.collection.objects.link(obj)
    return obj


def alignment_markers(pairs, frames_a, frames_b, every=5):
    """Markers on A's frames saying the frame of B aligned with them ('A12=B15'), one every
    `every` aligned pairs, so the timeline stays readable."""
    return [(f"A{frames_a[i]}=B{frames_b[j]}", frames_a[i]) for n, (i, j) in enumerate(pairs) if n % every == 0]


STEP_TRACK = "deformseg in step"


def play_in_step(owner_b, action_b, pairs, frames_a, frames_b):
    """Plays action_b on owner_b in step with A: an NLA strip whose evaluated time is keyed, at
    each scene frame of A, to the frame of B aligned with it (strip_time animated). The active
    action is kept aside in the strip's track so stop_in_step can put it back."""
    data = owner_b.animation_data or owner_b.animation_data_create()
    stop_in_step(owner_b)
    track = data.nla_tracks.new()
    track.name = STEP_TRACK
    strip = track.strips.new(action_b.name, int(action_b.frame_range[0]), action_b)
    strip.use_animated_time = True
    first_of = {}
    for i, j in pairs:
        first_of.setdefault(i, j)
    for i, j in sorted(first_of.items()):
        strip.strip_time = frames_b[j]
        strip.keyframe_insert("strip_time", frame=frames_a[i])
    owner_b["deformseg_action"] = data.action.name if data.action else ""
    data.action = None


def stop_in_step(owner_b):
    """Removes the in-step track and puts the active action back."""
    data = owner_b.animation_data
    if data is None:
        return
    track = data.nla_tracks.get(STEP_TRACK)
    if track is not None:
        data.nla_tracks.remove(track)
        name = owner_b.get("deformseg_action", "")
        if name and name in bpy.data.actions:
            data.action = bpy.data.actions[name]
