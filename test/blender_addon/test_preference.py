"""The add-on as a new user sets it up: installed from its zip in a Blender whose Python does not
find deformseg, it refuses saying where to point it; once its preference "deformseg module folder"
names the module's folder, it colours a shape-keyed mesh by strain.

Usage (test/blender_addon/run.cmake runs it, without PYTHONPATH):
    blender -b --factory-startup --python-exit-code 1 --python test_preference.py -- ADDON.zip MODULE_DIR
"""
import sys

import addon_utils
import bpy
import numpy as np

ZIP, MODULE_DIR = sys.argv[sys.argv.index("--") + 1:][:2]
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)


def shape_keyed_cube():
    """A cube whose top stretches by a shape key keyed from 0 to 1 over frames 1 to 5."""
    bpy.ops.mesh.primitive_cube_add()
    cube = bpy.context.object
    cube.shape_key_add(name="Basis")
    stretch = cube.shape_key_add(name="stretch")
    for point in stretch.data:
        if point.co.z > 0:
            point.co.x *= 2.0
    for frame, value in ((1, 0.0), (5, 1.0)):
        stretch.value = value
        stretch.keyframe_insert("value", frame=frame)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, 5
    return cube


def look():
    try:  # an operator that reports an error raises it in a script
        return bpy.ops.deformseg.look(mode='STRAIN')
    except RuntimeError:
        return {'CANCELLED'}


def main():
    check(bpy.ops.preferences.addon_install(filepath=ZIP) == {'FINISHED'}, "the add-on installs from its zip")
    addon_utils.enable("deformseg_blender", default_set=True)
    check("deformseg_blender" in bpy.context.preferences.addons, "and is enabled")
    cube = shape_keyed_cube()
    settings = bpy.context.scene.deformseg
    check(look() == {'CANCELLED'} and "deformseg module folder" in settings.status,
          f"without the module it says where to point it: {settings.status}")
    bpy.context.preferences.addons["deformseg_blender"].preferences.module_folder = MODULE_DIR
    check(look() == {'FINISHED'}, f"with the preference set it colours the cube: {settings.status}")
    field = np.array(cube.data["deformseg_field"]).reshape(5, -1)
    check(field.shape == (5, 6) and field[0].max() == 0 and field[4].max() > 0,
          "its shape-key animation's strain: none at the first frame, some at the last")
    print(f"blender_addon preference: {'FAILED: ' + '; '.join(failures) if failures else 'passed'}", flush=True)
    if failures:
        sys.exit(1)


if __name__ == "__main__":
    try:
        main()
    except Exception:  # Blender exits with 0 after a script's exception: say it, exit 1
        import traceback
        traceback.print_exc()
        sys.stdout.flush()
        sys.exit(1)
