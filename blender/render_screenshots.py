"""Renders the manual's pictures of the add-on (doc/images/blender_*.png), headless, with Workbench:
the Fox walking coloured by strain, running coloured by spatio-temporal segment, and walking in step beside its run.

Usage, from the repository's root, with the Python module built:
    PYTHONPATH=build/python blender -b --factory-startup --python-use-system-env \\
        --python blender/render_screenshots.py -- ../shared/data/characters/Fox.glb doc/images

The add-on is loaded from this folder (blender/deformseg_blender), as in development; the
pictures are small 8-bit PNGs (a few tens of KB), rendered at 24 fps, the Fox's key rate.
"""
import os
import sys

import numpy

numpy.bool = bool  # Debian's Blender 3.4 glTF importer needs it (NumPy 1.24 removed the alias)

import bpy  # noqa: E402
import mathutils  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import deformseg_blender  # noqa: E402

WIDTH, HEIGHT = 400, 240


def scene_with_fox(fox):
    """An empty scene at 24 fps with the Fox, and the add-on registered."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    deformseg_blender.register()
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = 24, 1.0
    return import_fox(fox)


def import_fox(fox):
    before = set(bpy.data.objects)
    bpy.ops.import_scene.gltf(filepath=fox)
    added = [o for o in bpy.data.objects if o not in before]
    return next(o for o in added if o.type == 'MESH'), next(o for o in added if o.type == 'ARMATURE')


def play(armature, clip):
    """Plays a glTF clip (the importer keeps each on an NLA track named as the clip)."""
    armature.animation_data.action = next(t.strips[0].action for t in armature.animation_data.nla_tracks
                                          if t.name == clip)


def select(*objects):
    bpy.ops.object.select_all(action='DESELECT')
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]


def camera_on(objects, frame):
    """An orthographic camera from the character's left, framing the objects at `frame`."""
    scene = bpy.context.scene
    scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    corners = [obj.matrix_world @ mathutils.Vector(c) for obj in objects
               for c in obj.evaluated_get(depsgraph).bound_box]
    low = mathutils.Vector([min(c[i] for c in corners) for i in range(3)])
    high = mathutils.Vector([max(c[i] for c in corners) for i in range(3)])
    centre, size = (low + high) / 2, high - low
    camera = bpy.data.objects.get("camera") or bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    if camera.name not in scene.collection.objects:
        scene.collection.objects.link(camera)
    camera.data.type = 'ORTHO'
    camera.data.ortho_scale = max(size.y, size.z * WIDTH / HEIGHT) * 1.1
    camera.location = centre + mathutils.Vector((size.length * 2, 0, 0))
    camera.rotation_euler = (1.5708, 0.0, 1.5708)  # looking along -x
    camera.data.clip_end = size.length * 5
    scene.camera = camera


def render(path):
    """Workbench, flat studio light, the colour attribute shown; a small 8-bit PNG."""
    scene = bpy.context.scene
    scene.render.engine = 'BLENDER_WORKBENCH'
    if scene.world is None:  # a light grey background rather than the empty scene's black
        scene.world = bpy.data.worlds.new("background")
    scene.world.color = (0.8, 0.8, 0.8)
    scene.display.shading.light = 'STUDIO'
    scene.display.shading.color_type = 'VERTEX'
    scene.display.shading.show_cavity = False
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.image_settings.file_format = 'PNG'
    scene.render.image_settings.color_mode = 'RGB'
    scene.render.image_settings.color_depth = '8'
    scene.render.image_settings.compression = 100
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    print(f"render_screenshots: {path}", flush=True)


def main(fox, out):
    os.makedirs(out, exist_ok=True)
    body, armature = scene_with_fox(fox)
    play(armature, "Walk")
    select(body)
    bpy.ops.deformseg.look(mode='STRAIN')
    camera_on([body], 9)
    bpy.context.scene.frame_set(9)
    render(os.path.join(out, "blender_strain.png"))

    play(armature, "Run")  # the run deforms more of the body than the walk
    bpy.context.scene.deformseg.threshold = 0.25  # more of the run counts as deformed: more segments
    bpy.ops.deformseg.look(mode='SEGMENTS')
    labels = numpy.array(body.data["deformseg_field"]).reshape(len(body.data["deformseg_frames"]), -1)
    segments = [len(numpy.unique(row[row >= 0])) for row in labels]
    bpy.context.scene.frame_set(int(numpy.argmax(segments)))  # the frame of the most segments
    render(os.path.join(out, "blender_segments.png"))

    play(armature, "Walk")
    # A second Fox running, set beside the first, played in step with its walk.
    other, other_armature = import_fox(fox)
    other_armature.location.y -= 170
    play(other_armature, "Run")
    for obj in (body, other):
        select(obj)
        bpy.ops.deformseg.look(mode='STRAIN')
    settings = bpy.context.scene.deformseg
    settings.compare_mode = 'OBJECTS'
    select(body, other)
    bpy.ops.deformseg.compare()
    bpy.ops.deformseg.play_in_step()
    alignment = bpy.data.objects.get("deformseg alignment")
    if alignment is not None:
        alignment.hide_render = True
    camera_on([body, other], 9)
    bpy.context.scene.frame_set(9)
    render(os.path.join(out, "blender_compare.png"))


if __name__ == "__main__":
    try:
        main(*sys.argv[sys.argv.index("--") + 1:][:2])
    except Exception:  # Blender exits with 0 after a script's exception: say it, exit 1
        import traceback
        traceback.print_exc()
        sys.exit(1)
