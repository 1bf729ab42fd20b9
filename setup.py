"""The build of the Python package for pip (pyproject.toml names setuptools as its backend).

The compiled extension deformseg._deformseg is the CMake target `_deformseg` (python/CMakeLists.txt):
build_ext configures the project with the Python module alone (no tests, examples or tool) for the
Python that runs pip, builds that target and copies it into the wheel beside the pure-Python files
of python/deformseg/. Only the target and what it links (the front end, frontend/) are compiled: no
tool, examples, tests or precompiled header.

Nothing is written into the source tree, which may be read-only: setuptools' build folder (the CMake
build among it) and its egg-info folder go to a temporary folder, removed when pip's build step ends,
or to DEFORMSEG_PIP_BUILD_DIR when set, a folder the user names and keeps, so that a second
`pip install .` recompiles only what changed.

Environment: CMAKE_ARGS, more arguments for CMake's configuration (`-DDEFORMSEG_ARCH=` for a
wheel that runs on any x86-64, `-DCMAKE_CXX_COMPILER=clang++`); CMAKE_BUILD_PARALLEL_LEVEL, the
number of compile jobs (default: every core); DEFORMSEG_CMAKE_BUILD_DIR, a build folder of this
project configured already with the Python module (-DDEFORMSEG_BUILD_PYTHON=ON) for the Python that
runs pip, whose target is built (nothing, when it is up to date) instead of configuring one here:
a build that makes the module anyway packages it without compiling it twice; DEFORMSEG_PIP_BUILD_DIR,
the folder for setuptools' and CMake's build files (default: a temporary folder, removed afterwards).
"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def build_base():
    """The folder setuptools builds in (its build/ and egg-info), CMake's build folder below it, and
    whether it is a temporary one to remove: never the source tree, so that a read-only checkout
    installs and a checkout is left as it was. pip runs this script once per build step (metadata,
    wheel), each in a process of its own, so a temporary folder lives for one step."""
    named = os.environ.get("DEFORMSEG_PIP_BUILD_DIR")
    if named:
        folder = pathlib.Path(named).expanduser().resolve()
        folder.mkdir(parents=True, exist_ok=True)
        return folder, False
    return pathlib.Path(tempfile.mkdtemp(prefix="deformseg-pip-build-")), True


def project_version():
    """The version of project(deformseg VERSION x.y.z) in CMakeLists.txt, the one source of it."""
    found = re.search(r"project\(deformseg VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if not found:
        raise RuntimeError("CMakeLists.txt: no 'project(deformseg VERSION x.y.z)' to take the version from")
    return found.group(1)


class CMakeExtension(Extension):
    """An extension that is a CMake target of this project rather than a list of sources."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        configured = os.environ.get("DEFORMSEG_CMAKE_BUILD_DIR")
        build = pathlib.Path(configured).resolve() if configured else pathlib.Path(self.build_temp).resolve() / "cmake"
        if not configured:
            configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                         f"-DPython_EXECUTABLE={sys.executable}", "-DDEFORMSEG_BUILD_PYTHON=ON",
                         "-DDEFORMSEG_BUILD_TESTS=OFF", "-DDEFORMSEG_BUILD_EXAMPLES=OFF", *pybind11_arguments(),
                         *shlex.split(os.environ.get("CMAKE_ARGS", ""))]
            subprocess.run(configure, check=True)
        jobs = [] if "CMAKE_BUILD_PARALLEL_LEVEL" in os.environ else ["--parallel", str(os.cpu_count() or 1)]
        subprocess.run(["cmake", "--build", str(build), "--target", ext.target, *jobs], check=True)
        built = build / "python" / "deformseg" / (ext.target + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():
            raise RuntimeError(f"{built}: CMake built no extension for this Python ({sys.executable})")
        destination = pathlib.Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, destination)


def pybind11_arguments():
    """pybind11's CMake files, when the pybind11 Python package is there (pip's build isolation
    installs it; Debian's python3-pybind11 has them too); else CMake searches for pybind11-dev's."""
    try:
        import pybind11
    except ImportError:
        return []
    return [f"-Dpybind11_DIR={pybind11.get_cmake_dir()}"]


def require_wheel_support():
    """Refuses, saying what to install, to build a wheel in a Python that cannot: setuptools before
    70.1 builds wheels through the `wheel` package, which `pip install --no-build-isolation` does
    not bring (a pyenv or python.org Python then fails with "invalid command 'bdist_wheel'"), already
    at pip's metadata step (`dist_info`, which runs bdist_wheel's options)."""
    if not {"bdist_wheel", "dist_info"} & set(sys.argv):
        return
    try:
        import setuptools.command.bdist_wheel  # noqa: F401 (setuptools 70.1 and later)
    except ImportError:
        try:
            import wheel  # noqa: F401
        except ImportError:
            sys.exit(f"deformseg: {sys.executable} has no 'wheel' package, which building the package without "
                     f"build isolation needs: run '{sys.executable} -m pip install wheel' first (on Debian's "
                     "/usr/bin/python3: apt-get install python3-wheel), or drop --no-build-isolation")


require_wheel_support()
BUILD_BASE, TEMPORARY = build_base()
try:
    # egg_base: egg_info writes deformseg.egg-info beside setup.py otherwise (pip's metadata step
    # names its own folder on the command line, which wins over these options).
    setup(
        version=project_version(),
        ext_modules=[CMakeExtension("deformseg._deformseg", target="_deformseg")],
        cmdclass={"build_ext": CMakeBuild},
        options={"build": {"build_base": str(BUILD_BASE)}, "egg_info": {"egg_base": str(BUILD_BASE)}},
    )
finally:
    # The wheel is in pip's own folder by now; the compiled objects are not needed again.
    if TEMPORARY:
        shutil.rmtree(BUILD_BASE, ignore_errors=True)
