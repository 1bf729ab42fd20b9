"""Exports glTF characters as FBX with Blender's own FBX exporter: the test-time reference of the
FBX reader on Blender's exports (test/blender_fbx.cmake runs it, test/io_fbx_blender.cpp compares).

Usage:
    blender -b --factory-startup --python-use-system-env --python export_fbx.py -- OUT FILE.glb@FPS[@X,Y,Z]...

Each FILE.glb is imported into an empty scene whose frame rate is FPS (the rate the file's keys are
on, so that every key lands on a frame and Blender's baking of it keeps it exactly), then written
as OUT/STEM.fbx. With X,Y,Z, the objects at the scene's root (the armature, unparented meshes) are
first scaled by X, Y and Z along the glTF file's axes, about the origin, and the file is
OUT/STEM-scaled.fbx: a character whose armature was scaled non-uniformly and never applied, whose
bones' bind matrices are sheared; Blender's frames are then the original's scaled so. Exits with 1,
naming the file, when one cannot be imported or exported.

The exporter's settings are its defaults (what a user who clicks Export gets), written out so that
a change of default does not change the reference, but two:
- key simplification is off (`bake_anim_simplify_factor` 0): at its default, 1, the exporter drops
  baked keys that its curve fitting deems redundant, and the frames between the keys left differ
  from the original's (Fox: 3.4e-4 to 1.6e-3 of the diagonal, Knight: up to 4.4e-3);
- "Force Start/End Keying" stays on, so that every clip keeps its first and last frames.
Left at their defaults, and what they mean for the comparison:
- axes: forward -Z, up Y (FBX's and glTF's Y-up), applied as a rotation of the root objects;
- scale: "All Local" (FBX_SCALE_NONE) with the unit scale applied: the file's unit is the
  centimetre (UnitScaleFactor 1) and the root objects are scaled by 100;
- "Apply Transform" (bake_space_transform) off: the exporter calls it experimental and "known
  broken with armatures/animations";
- "Add Leaf Bones" on: a bone with no child gets an extra "_end" bone, which nothing is bound to;
- primary and secondary bone axes Y and X: Blender's bone frame, which the exporter turns into
  FBX's by a fixed rotation of every bone;
- every action baked at every frame ("All Actions"), each as an animation stack named
  "ARMATURE|ACTION"; NLA strips too (the glTF importer stashes its actions on muted tracks, which
  the exporter skips).
"""
import os
import sys

import numpy

# Debian's Blender 3.4 glTF importer still uses numpy.bool, which NumPy 1.24 removed.
numpy.bool = bool

import bpy  # noqa: E402  (after the NumPy fix, which the importer needs when it is loaded)
import mathutils  # noqa: E402

EXPORT_SETTINGS = dict(
    use_selection=False,
    object_types={'ARMATURE', 'MESH'},
    axis_forward='-Z',
    axis_up='Y',
    global_scale=1.0,
    apply_unit_scale=True,
    apply_scale_options='FBX_SCALE_NONE',
    bake_space_transform=False,
    add_leaf_bones=True,
    primary_bone_axis='Y',
    secondary_bone_axis='X',
    use_armature_deform_only=False,
    armature_nodetype='NULL',
    bake_anim=True,
    bake_anim_use_all_bones=True,
    bake_anim_use_nla_strips=True,
    bake_anim_use_all_actions=True,
    bake_anim_force_startend_keying=True,
    bake_anim_step=1.0,
    bake_anim_simplify_factor=0.0,
)


def empty_scene(fps):
    """Starts from an empty scene: the factory scene's cube, camera and light would be exported."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = fps
    scene.render.fps_base = 1.0


def name_actions_as_clips():
    """Names each action as the glTF clip it came from: the importer names it CLIP_OBJECT and keeps
    it on an NLA track named CLIP, and the exporter names a stack OBJECT|ACTION."""
    for obj in bpy.data.objects:
        if obj.animation_data:
            for track in obj.animation_data.nla_tracks:
                for strip in track.strips:
                    strip.action.name = track.name


def scale_roots(x, y, z):
    """Scales the objects at the scene's root by x, y, z along glTF's axes: Blender's x, -z, y."""
    scale = mathutils.Matrix.Diagonal((x, z, y, 1.0))
    for obj in bpy.data.objects:
        if obj.parent is None:
            obj.matrix_world = scale @ obj.matrix_world


def export(gltf, fps, scale, out):
    empty_scene(fps)
    if bpy.ops.import_scene.gltf(filepath=gltf) != {'FINISHED'}:
        raise RuntimeError(f"Blender could not import {gltf}")
    name_actions_as_clips()
    stem = os.path.splitext(os.path.basename(gltf))[0]
    if scale:
        scale_roots(*scale)
        stem += "-scaled"
    target = os.path.join(out, stem + ".fbx")
    if bpy.ops.export_scene.fbx(filepath=target, **EXPORT_SETTINGS) != {'FINISHED'}:
        raise RuntimeError(f"Blender could not export {gltf} as FBX")
    print(f"export_fbx: {gltf} at {fps} fps{' scaled by ' + str(scale) if scale else ''} -> {target}", flush=True)


def main(arguments):
    out, characters = arguments[0], arguments[1:]
    os.makedirs(out, exist_ok=True)
    for character in characters:
        gltf, fps, *scale = character.split("@")
        export(gltf, int(fps), [float(s) for s in scale[0].split(",")] if scale else None, out)


if __name__ == "__main__":
    try:
        main(sys.argv[sys.argv.index("--") + 1:])
    except Exception as error:  # Blender exits with 0 after a script's exception: say it, exit 1
        print(f"export_fbx: {error}", file=sys.stderr, flush=True)
        sys.exit(1)
