"""The add-on's settings and results, kept on the scene (scene.deformseg) and in its preferences."""
import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty,
                       StringProperty)


class DeformsegPreferences(bpy.types.AddonPreferences):
    """Where the deformseg module is, when Blender's Python does not find it by itself."""
    bl_idname = __package__

    module_folder: StringProperty(
        name="deformseg module folder", subtype='DIR_PATH',
        description="The folder holding the deformseg package (a build folder's python/), added to Python's "
                    "path; empty when deformseg is installed where Blender's Python finds it")

    def draw(self, context):
        self.layout.prop(self, "module_folder")
        from . import module
        try:
            ds = module.load(module.bpy_path(self.module_folder))
            self.layout.label(text=f"deformseg {ds.__version__} found: {ds.__file__}", icon='CHECKMARK')
        except module.ModuleMissing as error:
            for line in _wrap(str(error)):
                self.layout.label(text=line, icon='ERROR')


def _wrap(text, width=90):
    """Splits a long message into lines a label can show."""
    lines, line = [], ""
    for word in text.split():
        if len(line) + len(word) > width:
            lines.append(line)
            line = ""
        line += word + " "
    return lines + [line]


class DeformsegNeighbour(bpy.types.PropertyGroup):
    """One clip the store search found."""
    path: StringProperty()
    clip: StringProperty()
    value: FloatProperty()


class DeformsegSettings(bpy.types.PropertyGroup):
    """The panel's settings and its last results."""
    # Look
    look_mode: EnumProperty(name="Colour by", items=[
        ('STRAIN', "Strain", "Normalised strain of each triangle against the first frame"),
        ('SEGMENTS', "Segments", "Spatio-temporal segmentation: each segment in a colour of its own, rigid "
                                 "triangles grey; key frames of the evolving graph as markers"),
        ('DEVIATION', "Deviation", "Normalised strain against a chosen frame: how far each triangle is from its "
                                   "shape then"),
    ])
    deviation_frame: IntProperty(name="From frame", description="The scene frame deviation is measured from")
    threshold: FloatProperty(name="Threshold", default=0.5, min=0.0, max=1.0,
                             description="A cell is deformed above this normalised strain")
    whole_character: BoolProperty(
        name="Whole character", default=True,
        description="Measure every mesh the character's armature moves (body, head, helmet, weapons) as one, as "
                    "the tool reads a character file; off: the active mesh alone")
    use_range: BoolProperty(name="Frame range", description="Sample these frames rather than the action's")
    frame_first: IntProperty(name="First", default=1)
    frame_last: IntProperty(name="Last", default=24)
    temporal_count: IntProperty(name="Temporal segments")
    key_frame_count: IntProperty(name="Key frames")
    # Compare
    compare_mode: EnumProperty(name="Compare", items=[
        ('OBJECTS', "Two objects", "The active object and the other selected one, each with its action"),
        ('ACTIONS', "Two actions", "The active object playing two actions"),
    ])
    action_a: PointerProperty(name="Action A", type=bpy.types.Action)
    action_b: PointerProperty(name="Action B", type=bpy.types.Action)
    similarity: FloatProperty(name="Similarity", precision=4)
    z_score: FloatProperty(name="z-score", precision=3)
    has_result: BoolProperty()
    alignment_length: IntProperty(name="Aligned pairs")
    object_a: PointerProperty(type=bpy.types.Object)
    object_b: PointerProperty(type=bpy.types.Object)
    # Find
    store_folder: StringProperty(name="Motion store", subtype='DIR_PATH',
                                 description="A deformseg motion store (made by `deformseg describe --store` "
                                             "or Describe below)")
    describe_input: StringProperty(name="Clips", subtype='FILE_PATH',
                                   description="A glTF file (every clip), an animation or a labels CSV to describe "
                                               "into the store")
    describe_fps: FloatProperty(name="fps", default=30.0, min=1.0, max=1000.0,
                                description="The rate clips are sampled at when described")
    k: IntProperty(name="k", default=5, min=1, max=100, description="Clips to list")
    onto_active: BoolProperty(name="Onto the active armature", default=True,
                              description="Put a loaded clip's action on the active armature when its bones "
                                          "have the clip's joints, rather than keeping the imported character")
    neighbours: CollectionProperty(type=DeformsegNeighbour)
    neighbour_index: IntProperty()
    status: StringProperty(name="Status")


classes = (DeformsegPreferences, DeformsegNeighbour, DeformsegSettings)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.Scene.deformseg = PointerProperty(type=DeformsegSettings)


def unregister():
    del bpy.types.Scene.deformseg
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
