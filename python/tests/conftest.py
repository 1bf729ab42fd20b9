"""Fixtures of the Python module's tests.

The tests compare the module with the `deformseg` tool on the same inputs, so they need the tool:
its path in DEFORMSEG_TOOL (CTest sets it when the examples are built). The shared real
animations are found in DEFORMSEG_DATA_DIR (default: ../shared/data beside the repository).
Without either, the tests that need it are skipped, with the reason.
"""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import deformseg

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def tool_path():
    path = os.environ.get("DEFORMSEG_TOOL")
    return path if path and os.access(path, os.X_OK) else None


def data_dir():
    return pathlib.Path(os.environ.get("DEFORMSEG_DATA_DIR", REPOSITORY.parent / "shared" / "data"))


@pytest.fixture(scope="session")
def tool():
    """A function that runs the tool with its arguments and returns its standard output; as JSON
    when `--json -` is among them."""
    path = tool_path()
    if path is None:
        pytest.skip("DEFORMSEG_TOOL does not name the deformseg tool (build with -DDEFORMSEG_BUILD_EXAMPLES=ON)")

    def run(*arguments):
        arguments = [str(a) for a in arguments]
        done = subprocess.run([path, *arguments], capture_output=True, text=True, check=False)
        if done.returncode != 0:
            raise AssertionError(f"deformseg {' '.join(arguments)} failed: {done.stderr}")
        return json.loads(done.stdout) if "--json" in arguments and "-" in arguments else done.stdout

    return run


@pytest.fixture(scope="session")
def fox():
    """The shared Fox character (three clips: Survey, Walk, Run)."""
    path = data_dir() / "characters" / "Fox.glb"
    if not path.exists():
        pytest.skip(f"{path} not found: the shared data is not beside the repository")
    return path


@pytest.fixture(scope="session")
def characters(fox):
    return fox.parent


@pytest.fixture(scope="session")
def tubes(tool, tmp_path_factory):
    """Two synthetic tubes written by `deformseg synth` as PLY frames: one bending at its middle
    joint, one at two joints in turn, faster."""
    root = tmp_path_factory.mktemp("tubes")
    one, two = root / "one", root / "two"
    tool("synth", one, "--format", "ply", "--schedule", "4:0", "12:80", "6:", "12:0")
    tool("synth", two, "--format", "ply", "--joints", "0.3,0.7", "--schedule", "3:0,0", "8:70,0", "8:70,70",
         "8:0,0")
    return one, two


def grid_animation(rows, columns, frames, seed=0, dtype=np.float64):
    """A flat grid of (rows + 1) x (columns + 1) vertices and 2 rows columns triangles, waving in
    z: (faces, frames) arrays for deformseg.Animation."""
    y, x = np.mgrid[0:rows + 1, 0:columns + 1].astype(np.float64)
    index = np.arange((rows + 1) * (columns + 1)).reshape(rows + 1, columns + 1)
    a, b, c, d = index[:-1, :-1].ravel(), index[:-1, 1:].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel()
    faces = np.concatenate([np.stack([a, b, d], 1), np.stack([a, d, c], 1)]).astype(np.int64)
    random = np.random.default_rng(seed)
    phase = random.uniform(0, 2 * np.pi)
    positions = np.empty((frames, x.size, 3), dtype=dtype)
    for t in range(frames):
        z = 0.3 * np.sin(0.5 * x + 0.2 * t + phase) * np.cos(0.3 * y - 0.1 * t)
        positions[t] = np.stack([x.ravel(), y.ravel(), z.ravel()], 1)
    return faces, positions


@pytest.fixture
def grid():
    return grid_animation


def read_csv_matrix(path, dtype):
    """A CSV of numbers the tool wrote (shortest round-trip representation) as an array."""
    return np.loadtxt(path, delimiter=",", dtype=dtype, ndmin=2)


@pytest.fixture
def csv_matrix():
    return read_csv_matrix


assert deformseg.Animation  # the module under test is importable
