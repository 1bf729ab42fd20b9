"""deformseg for Blender: colour an animated character by strain or segments, compare two motions,
find the clips of a motion store that move alike, from the 3D view's sidebar (tab deformseg).

The work is done by the deformseg Python module (chapter 12 of the manual), which the add-on finds
in Blender's Python path or in the folder its preferences give. Manual: doc/chapters/16_blender.md.
"""

bl_info = {
    "name": "deformseg",
    "author": "deformseg developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D View > Sidebar > deformseg",
    "description": "Strain, segments and motion similarity of deforming meshes (the deformseg module)",
    "category": "Animation",
}

import warnings  # noqa: E402

import bpy  # noqa: E402
import numpy  # noqa: E402

# Debian's Blender 3.4 glTF importer uses numpy.bool, which NumPy 1.24 removed: the add-on imports
# glTF clips it finds (Find), so it puts the alias back for the importer. (Asking NumPy 1.24 for
# the name warns that it will come back as NumPy's own boolean.)
with warnings.catch_warnings():
    warnings.simplefilter("ignore", FutureWarning)
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

from . import display, operators, panel, properties  # noqa: E402

_modules = (properties, operators, panel)


def register():
    for m in _modules:
        m.register()
    bpy.app.handlers.frame_change_post.append(display.on_frame_change)
    bpy.app.handlers.load_post.append(display.on_load)


def unregister():
    for handler, handlers in ((display.on_frame_change, bpy.app.handlers.frame_change_post),
                              (display.on_load, bpy.app.handlers.load_post)):
        if handler in handlers:
            handlers.remove(handler)
    for m in reversed(_modules):
        m.unregister()
