"""The tool's start: the shared libraries it loads before any work. Assimp (FBX, Collada and BVH
files), with what it needs (zlib, minizip), is opened on the first such file read, not at start
(src/io/assimp_import.cpp); the libraries the loader opens are listed by glibc's LD_DEBUG=files."""

import os
import re
import subprocess
from pathlib import Path

import pytest

# The readers' fuzzing seed of three joints and three frames: a file that makes the tool open Assimp.
BVH = Path(__file__).resolve().parents[1] / "fuzz" / "seeds" / "bvh" / "three_joints.bvh"


def loaded_libraries(*args):
    """The tool's run with `args`, and the file names of the libraries the loader opened for it."""
    program = os.environ.get("DEFORMSEG_TOOL")
    if not program:
        pytest.fail("DEFORMSEG_TOOL is not set: run these tests through CTest, or set it to the built tool")
    environment = dict(os.environ, LD_DEBUG="files")
    run = subprocess.run([program, *map(str, args)], capture_output=True, text=True, env=environment, timeout=600)
    names = {os.path.basename(name) for name in re.findall(r"\bfile=(\S+)", run.stderr)}
    return run, names


def test_version_loads_no_assimp():
    run, names = loaded_libraries("--version")
    assert run.returncode == 0, run.stderr[-2000:]
    assert names, "LD_DEBUG=files listed no library: not glibc's loader?"
    assert not [name for name in names if name.startswith(("libassimp", "libminizip"))], sorted(names)


def test_reading_bvh_loads_assimp_then():
    run, names = loaded_libraries("info", BVH)
    assert run.returncode == 0, run.stderr[-2000:]
    assert re.search(r"frames +7\n", run.stdout), run.stdout  # 3 at 10 fps, sampled at 30
    assert [name for name in names if name.startswith("libassimp")], sorted(names)
