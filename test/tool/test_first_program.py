"""The README's first program (examples/first_program.cpp) on two clips of two characters, as the
README runs it."""

import os
import re

import pytest

from conftest import fails, run_program, succeeds


@pytest.fixture(scope="session")
def first_program():
    # The program of the examples' group that holds it, and the argument that names it there.
    program = os.environ.get("DEFORMSEG_FIRST_PROGRAM")
    name = os.environ.get("DEFORMSEG_FIRST_PROGRAM_ARGUMENT")
    if not program or not name:
        pytest.fail("DEFORMSEG_FIRST_PROGRAM(_ARGUMENT) is not set: run these tests through CTest")
    return lambda *args: run_program(program, name, *args)


def test_first_program_clips(first_program, characters):
    run = succeeds(first_program(f"{characters}/Knight.glb#Walking_A", f"{characters}/Mage.glb#Walking_B"))
    assert "A: 33 frames of 6952 triangles\n" in run.output
    assert re.search(r"similarity of A and B: 0\.[0-9]+\n", run.output), run.describe()


def test_first_program_needs_clip(first_program, characters):
    run = fails(first_program(characters / "Knight.glb", characters / "Mage.glb"))
    assert re.search(r"error: [^\n]*Knight.glb: the file holds 76 clips: name the one to read", run.err), run.describe()
