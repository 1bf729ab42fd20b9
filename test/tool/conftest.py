"""Shared pieces of the deformseg tool's tests: the tool run as a user runs it, and the inputs that
several tests read, made once per pytest session (a session is one test file: CTest runs each
file on its own, in a scratch folder of its own given by --basetemp).

The environment, set by CTest (test/tool/CMakeLists.txt):
  DEFORMSEG_TOOL           the tool's binary (required)
  DEFORMSEG_DATA_DIR       the shared real animations; the tests that read them skip without it
  DEFORMSEG_FIRST_PROGRAM  examples/first_program (built with the tool)
  DEFORMSEG_CHROMIUM       Chromium, which opens the pages `view` writes (skipped without it)
"""

import json
import os
import re
import subprocess
import tarfile
from dataclasses import dataclass
from pathlib import Path

import pytest

GRAPHS = Path(__file__).parent / "graphs"


@dataclass
class Run:
    """A finished run: its exit status, standard output and standard error."""

    args: list
    status: int
    out: str
    err: str

    @property
    def output(self):
        """Standard output and error together, as a user sees them."""
        return self.out + self.err

    def json(self):
        """Standard output read as JSON (`--json -`); the run must have succeeded."""
        assert self.status == 0, self.describe()
        return json.loads(self.out)

    def describe(self):
        command = " ".join(map(str, self.args))
        return f"{command}\nexit status {self.status}\n--- stdout\n{self.out}--- stderr\n{self.err}"


def run_program(program, *args):
    completed = subprocess.run([program, *map(str, args)], capture_output=True, text=True, timeout=1800)
    return Run([program, *args], completed.returncode, completed.stdout, completed.stderr)


def succeeds(run):
    """`run`, after asserting that it exited with status 0."""
    assert run.status == 0, run.describe()
    return run


def fails(run, *messages):
    """`run`, after asserting that it exited with a non-zero status, that it did not crash (no
    "terminate", no "Aborted") and that its standard error holds every one of `messages`."""
    assert run.status != 0, run.describe()
    assert run.status > 0, run.describe()  # a signal (a crash) gives a negative status
    for message in messages:
        assert message in run.err, f"missing {message!r}\n{run.describe()}"
    assert "terminate" not in run.output and "Aborted" not in run.output, run.describe()
    return run


def matches_all(text, *patterns):
    """Asserts that every regular expression of `patterns` matches somewhere in `text`."""
    for pattern in patterns:
        assert re.search(pattern, text), f"{pattern}\n{text}"


def reads_nothing(run):
    """`run`, after asserting that it refused its options before reading any input."""
    assert "reading" not in run.output, run.describe()
    return run


@pytest.fixture(scope="session")
def tool():
    """tool(*args): runs deformseg with `args` and returns the `Run`."""
    program = os.environ.get("DEFORMSEG_TOOL")
    if not program:
        pytest.fail("DEFORMSEG_TOOL is not set: run these tests through CTest, or set it to the built tool")
    return lambda *args: run_program(program, *args)


@pytest.fixture(scope="session")
def scratch(tmp_path_factory):
    """The session's scratch folder (below --basetemp)."""
    return tmp_path_factory.getbasetemp()


@pytest.fixture(scope="session")
def data_dir():
    """The shared real animations; the test skips without them."""
    folder = Path(os.environ.get("DEFORMSEG_DATA_DIR", ""))
    if not os.environ.get("DEFORMSEG_DATA_DIR") or not folder.is_dir():
        pytest.skip("the shared data (DEFORMSEG_DATA_DIR) is not here")
    return folder


@pytest.fixture(scope="session")
def characters(data_dir):
    """The shared glTF characters."""
    return data_dir / "characters"


@pytest.fixture(scope="session")
def motions(characters):
    """The shared evaluation's labels: 362 clips of 7 bodies."""
    labels = characters / "motions.csv"
    if not labels.is_file():
        pytest.skip(f"{labels} is not here")
    return labels


def synth(tool, scratch, name, *args):
    """The tube `synth` writes into scratch/name with `args`; returns the folder and the run."""
    folder = scratch / name
    run = succeeds(tool("synth", folder, *args, "--json", "-"))
    return folder, run


# The synthetic inputs: each fixture gives (folder, run of synth).
@pytest.fixture(scope="session")
def synth_obj(tool, scratch):
    """The default tube: 41 frames of 786 vertices, 1568 triangles, as OBJ files."""
    return synth(tool, scratch, "synth-obj", "--format", "obj")


@pytest.fixture(scope="session")
def synth_two(tool, scratch):
    """Two joints, a custom schedule (16 frames), 18 rings of 8 sectors (304 triangles), placed."""
    return synth(tool, scratch, "synth-two", "--joints", "0.3,0.7", "--rings", "18", "--sectors", "8",
                 "--schedule", "5:45,0", "5:45,-30", "5:0,0", "--scale", "3", "--rotate", "1,0,0,30",
                 "--translate", "5,6,7")


@pytest.fixture(scope="session")
def three_poses(tool, scratch):
    """Three poses, 20 frames each, with 4-frame transitions (frames 20-23 and 43-46): 66 frames."""
    return synth(tool, scratch, "three-poses", "--joints", "0.3,0.7",
                 "--schedule", "19:", "4:90,0", "19:", "4:0,90", "19:")


@pytest.fixture(scope="session")
def bend_once(tool, scratch):
    """A tube bending once at constant speed: 31 frames."""
    return synth(tool, scratch, "bend-once", "--schedule", "10:0", "10:90", "10:", "--easing", "linear")


@pytest.fixture(scope="session")
def a_file(scratch):
    """A file where a folder is asked for."""
    path = scratch / "a-file"
    path.write_text("not a folder\n")
    return path


def unpack(archive, into):
    into.mkdir(parents=True, exist_ok=True)
    with tarfile.open(archive) as tar:
        tar.extractall(into)


@pytest.fixture(scope="session")
def real_data(data_dir, scratch):
    """The horse gallop, the samba and the cat poses, unpacked into scratch/data."""
    folder = scratch / "data"
    unpack(data_dir / "horse-gallop" / "horse-gallop.tar.xz", folder)
    unpack(data_dir / "samba" / "samba.tar.xz", folder)
    unpack(data_dir / "cat-lion-poses" / "cat-poses.tgz", folder)
    return folder
