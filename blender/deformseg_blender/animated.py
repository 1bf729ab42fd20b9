"""Which datablock animates a mesh, which action it plays, and over which frames."""
import math
from contextlib import contextmanager

import bpy


def _deforms(armature, obj):
    """Whether armature moves the mesh object obj: by an Armature modifier, or as its parent
    (an object parented to the armature or to one of its bones: a sword in a hand)."""
    return obj.parent == armature or any(m.type == 'ARMATURE' and m.object == armature for m in obj.modifiers)


def mesh_of(obj):
    """The mesh to measure for the active object: the object itself when it is a mesh; for an
    armature (a click on a character often selects it), the largest mesh it deforms."""
    if obj is None:
        return None
    if obj.type == 'MESH':
        return obj
    if obj.type == 'ARMATURE':
        meshes = [o for o in bpy.context.scene.objects if o.type == 'MESH' and _deforms(obj, o)]
        return max(meshes, key=lambda o: len(o.data.vertices), default=None)
    return None


def character_meshes(obj, whole=True):
    """The mesh objects measured as one for the active object: with `whole`, every mesh of the
    scene its armature moves (body, head, helmet, weapons), by name, as the tool reads every mesh
    of a character file; else, or without an armature, the one mesh (mesh_of)."""
    mesh = mesh_of(obj)
    if mesh is None:
        return []
    armature = obj if obj.type == 'ARMATURE' else animation_owner(mesh)
    if not whole or not isinstance(armature, bpy.types.Object) or armature.type != 'ARMATURE':
        return [mesh]
    meshes = [o for o in bpy.context.scene.objects if o.type == 'MESH' and _deforms(armature, o)]
    return sorted(meshes, key=lambda o: o.name)


def animation_owner(obj):
    """The datablock whose action moves obj's mesh: the armature of its Armature modifier (a
    skinned character) or its parent armature, else its shape keys when they are animated, else
    the object itself."""
    for modifier in obj.modifiers:
        if modifier.type == 'ARMATURE' and modifier.object is not None:
            return modifier.object
    if obj.parent is not None and obj.parent.type == 'ARMATURE':  # a prop on a bone: a sword in a hand
        return obj.parent
    keys = obj.data.shape_keys if obj.type == 'MESH' else None
    if keys is not None and keys.animation_data is not None:
        return keys
    return obj


def active_action(obj):
    """The action obj plays now (on its animation owner), or None."""
    data = animation_owner(obj).animation_data
    return data.action if data else None


def action_frames(action):
    """The whole frames an action covers: its first key's frame to its last, rounded outwards."""
    first, last = action.frame_range
    return list(range(int(math.floor(first)), int(math.ceil(last)) + 1))


def frames_to_sample(scene, settings, obj, action=None):
    """The scene frames to sample: the range the user gives, else the action's, else the
    scene's frame range."""
    if settings.use_range:
        return list(range(settings.frame_first, settings.frame_last + 1))
    action = action or active_action(obj)
    if action is not None:
        return action_frames(action)
    return list(range(scene.frame_start, scene.frame_end + 1))


@contextmanager
def playing(obj, action):
    """Plays `action` on obj's animation owner for the block's time, then puts back the one it
    played (for comparing one object's two actions). None: leaves the object as it is."""
    if action is None:
        yield
        return
    owner = animation_owner(obj)
    data = owner.animation_data or owner.animation_data_create()
    previous = data.action
    data.action = action
    try:
        yield
    finally:
        data.action = previous


def bone_names(action):
    """The bones an action's channels move (pose.bones["NAME"]...)."""
    names = set()
    for curve in action.fcurves:
        path = curve.data_path
        if path.startswith('pose.bones["'):
            names.add(path.split('"')[1])
    return names


def duplicate_character(context, obj, offset):
    """A copy of the character obj belongs to, moved by `offset` (a vector), that can play an
    action of its own: its armature and every mesh object it moves are copied (their data
    shared), or for shape keys the mesh with its data (the keys are the mesh data's). Returns the
    copy of obj."""
    owner = animation_owner(obj)
    collection = context.scene.collection

    def copy_of(original):
        copy = original.copy()
        copy.name = original.name + " (B)"
        collection.objects.link(copy)
        return copy

    if isinstance(owner, bpy.types.Key) or owner is obj:
        copy = copy_of(obj)
        if isinstance(owner, bpy.types.Key):
            copy.data = obj.data.copy()
            copy.data.shape_keys.animation_data_create()
        copy.location = copy.location + offset
        return copy
    armature = copy_of(owner)  # the meshes follow it: parented to it, or deformed by it
    copies = {}
    for mesh in character_meshes(obj):
        copy = copies[mesh.name] = copy_of(mesh)
        for modifier in copy.modifiers:
            if modifier.type == 'ARMATURE' and modifier.object == owner:
                modifier.object = armature
        if copy.parent == owner:
            copy.parent = armature
        elif copy.parent is None:  # deformed but not parented: moved with the armature by hand
            copy.location = copy.location + offset
    armature.location = armature.location + offset
    return copies[obj.name]
