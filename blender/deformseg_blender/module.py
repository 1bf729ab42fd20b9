"""Finding the deformseg Python module from inside Blender.

Blender runs its own Python. Debian's Blender 3.4 runs Debian's Python 3.11, the one the module
is built for, so the module is found when it is installed there (`cmake --install BUILD
--component python --prefix /usr`), when Blender is started with `--python-use-system-env` and
PYTHONPATH names a build folder's python/, or when the add-on's preference "deformseg module
folder" names that folder (added to sys.path here).
"""
import importlib
import sys

MISSING = ("the deformseg Python module was not found: set \"deformseg module folder\" in Edit > Preferences > "
           "Add-ons > deformseg to the folder holding the deformseg package (a build folder's python/, e.g. "
           "~/deformseg/build/python), or start Blender with --python-use-system-env and PYTHONPATH naming it")


class ModuleMissing(ImportError):
    """deformseg cannot be imported; the message says where to point the add-on."""


def load(folder=""):
    """Imports deformseg, from `folder` first when one is given. Raises ModuleMissing, saying
    what was tried, when it cannot be imported (not built, or built for another Python)."""
    if folder and folder not in sys.path:
        sys.path.insert(0, folder)
    try:
        return importlib.import_module("deformseg")
    except ImportError as error:
        version = f"{sys.version_info.major}.{sys.version_info.minor}"
        raise ModuleMissing(f"{MISSING} (Blender's Python is {version}; the import said: {error})") from error


def load_from_preferences(context):
    """Imports deformseg with the folder the add-on's preferences give."""
    addon = context.preferences.addons.get(__package__)
    folder = addon.preferences.module_folder if addon else ""
    return load(bpy_path(folder))


def bpy_path(path):
    """An absolute path from a Blender path ('//' relative to the .blend file)."""
    if not path:
        return ""
    import bpy
    return bpy.path.abspath(path)
