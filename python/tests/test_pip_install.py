"""`pip install .` (the README's first route) builds the package from a copy of the source tree and
installs it into a scratch virtual environment, offline (`--no-build-isolation --no-index`: the
build tools and NumPy are the system's); the installed package imports from outside the tree and
gives the results of the package under test. pip leaves the source tree as it was: the copy is made
read-only before pip runs (a non-root pip cannot write in it at all) and its listing (names, sizes,
times, modes) compared before and after (which proves it for root, whom modes do not stop); setup.py's
temporary build folder is gone afterwards.

CTest runs it as a test of its own (`python.pip_install`, label `pip`), with the extension built in
the tests' own build folder (DEFORMSEG_CMAKE_BUILD_DIR, setup.py): pip's build runs the CMake target
there, up to date, rather than compiling the module a second time; without that variable, pip
configures and compiles as a user's `pip install` does."""
import os
import pathlib
import shutil
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import deformseg

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def source_copy(destination):
    """The source tree without its build folders and Git data, as a fresh clone has it."""
    def ignored(folder, names):
        return [n for n in names if pathlib.Path(folder) == REPOSITORY and (n.startswith("build") or n == ".git")]
    shutil.copytree(REPOSITORY, destination, ignore=ignored)
    return destination


def listing(tree):
    """Every file and folder below `tree` with its size, modification time and mode: what a write in
    the tree (a new file or folder, a changed or removed one) changes."""
    entries = {}
    for path in [tree, *tree.rglob("*")]:
        status = path.lstat()
        entries[str(path.relative_to(tree))] = (status.st_size, status.st_mtime_ns, status.st_mode)
    return entries


def set_writable(tree, writable):
    """Adds or removes the owner's, group's and others' write permission of everything below `tree`."""
    for path in [tree, *tree.rglob("*")]:
        if not path.is_symlink():
            mode = path.stat().st_mode
            path.chmod(mode | 0o200 if writable else mode & ~0o222)


def test_pip_install_builds_an_importable_package(tmp_path, grid):
    cmake = os.environ.get("DEFORMSEG_CMAKE")
    if not cmake:
        pytest.skip("DEFORMSEG_CMAKE is set by CTest (python.pip_install), which gives pip its cmake and build folder")
    source = source_copy(tmp_path / "source")
    # TMPDIR: setup.py's temporary build folder goes there, so that the test sees it removed.
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    environment = dict(os.environ, PATH=os.pathsep.join([str(pathlib.Path(cmake).parent), os.environ["PATH"]]),
                       TMPDIR=str(temporary))
    environment.pop("PYTHONPATH", None)  # the package under test must not hide the installed one
    environment.pop("DEFORMSEG_PIP_BUILD_DIR", None)  # the default, a temporary folder, is what is tested
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", venv], check=True)
    python = venv / "bin" / "python"
    set_writable(source, False)
    before = listing(source)
    try:
        done = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", "."],
                              cwd=source, env=environment, capture_output=True, text=True)
        after = listing(source)
    finally:
        set_writable(source, True)  # for pytest's removal of tmp_path
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-4000:]
    written = sorted(name for name in before.keys() | after.keys() if before.get(name) != after.get(name))
    assert not written, f"pip install wrote into the source tree: {written[:20]}"
    assert not list(temporary.glob("deformseg-pip-build-*")), "setup.py left its temporary build folder"

    faces, frames = grid(4, 5, 9)
    np.save(tmp_path / "faces.npy", faces)
    np.save(tmp_path / "frames.npy", frames)
    script = textwrap.dedent("""
        import importlib.metadata, pathlib, sys
        import numpy as np
        import deformseg
        a = deformseg.Animation(np.load("faces.npy"), np.load("frames.npy"))
        np.save("strain.npy", deformseg.strain(a))
        package = pathlib.Path(deformseg.__file__).parent
        print(package)
        print(importlib.metadata.version("deformseg"), deformseg.__version__)
        print(" ".join(sorted(p.name for p in package.iterdir() if p.name != "__pycache__")))
        print(deformseg.temporal_segmentation(a))
        """)
    done = subprocess.run([python, "-c", script], cwd=tmp_path, env=environment, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    package, versions, files, segments = done.stdout.strip().splitlines()
    assert pathlib.Path(package).is_relative_to(venv), package  # installed, not the tree's
    assert versions == f"{deformseg.__version__} {deformseg.__version__}"
    assert {"__init__.py", "__init__.pyi", "_graphs.py", "store_format.py", "py.typed"} <= set(files.split())
    assert any(f.startswith("_deformseg.") and f.endswith(".so") for f in files.split()), files
    a = deformseg.Animation(faces, frames)
    assert np.array_equal(np.load(tmp_path / "strain.npy"), deformseg.strain(a))
    assert segments == str(deformseg.temporal_segmentation(a))
