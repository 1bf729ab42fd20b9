"""Loading a clip the store search found: its file imported by Blender's own importer (glTF, FBX),
the clip's action played on the imported armature, or on the active armature when its bones have
the clip's joints (the imported objects are then removed)."""
import os

import bpy

from . import animated


def _import(path):
    """Imports a character file; returns the objects it added."""
    before = set(bpy.data.objects)
    extension = os.path.splitext(path)[1].lower()
    if extension in (".glb", ".gltf"):
        result = bpy.ops.import_scene.gltf(filepath=path)
    elif extension == ".fbx":
        result = bpy.ops.import_scene.fbx(filepath=path)
    else:
        raise ValueError(f"{os.path.basename(path)}: only glTF and FBX clips can be loaded into Blender")
    if result != {'FINISHED'}:
        raise RuntimeError(f"Blender could not import {path}")
    return [obj for obj in bpy.data.objects if obj not in before]


def _clip_action(clip, armature, actions):
    """The action of `clip` among the imported actions: glTF's importer keeps each clip on an NLA
    track named as the clip; FBX's names its actions ARMATURE|CLIP."""
    data = armature.animation_data
    for track in (data.nla_tracks if data else []):
        if track.name == clip and track.strips:
            return track.strips[0].action
    for action in actions:
        if action.name == clip or action.name.endswith("|" + clip):
            return action
    return data.action if data and not clip else None


def load(context, path, clip, onto_active):
    """Loads `clip` of the file at `path`; returns what it did, in words."""
    active = context.object
    target = active if active is not None and active.type == 'ARMATURE' else None
    if target is None and active is not None and active.type == 'MESH':
        owner = animated.animation_owner(active)
        target = owner if getattr(owner, "type", None) == 'ARMATURE' else None
    actions_before = set(bpy.data.actions)
    added = _import(path)
    new_actions = [a for a in bpy.data.actions if a not in actions_before]
    armatures = [obj for obj in added if obj.type == 'ARMATURE']
    if not armatures:
        raise ValueError(f"{os.path.basename(path)} has no armature to play {clip or 'its clip'} on")
    action = _clip_action(clip, armatures[0], new_actions)
    if action is None:
        raise ValueError(f"{os.path.basename(path)} has no clip {clip!r}")
    start, end = action.frame_range
    context.scene.frame_start, context.scene.frame_end = int(start), int(round(end))
    if onto_active and target is not None and animated.bone_names(action) <= set(target.data.bones.keys()):
        target.animation_data_create().action = action
        action.use_fake_user = True  # it outlives the imported armature
        for obj in added:
            bpy.data.objects.remove(obj)
        return f"{clip or action.name} put on {target.name}"
    armatures[0].animation_data.action = action
    return f"{os.path.basename(path)} imported, playing {clip or action.name}"
