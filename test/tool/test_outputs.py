"""Every output is checked before any input is read (no "reading" on standard error): a FILE needs
its folder and must not be a folder; a DIR is created when missing, unless a file stands in the
way. The input is a real one, which the command would otherwise read and work on."""

import re

import pytest

from conftest import fails, reads_nothing


def refused(run, pattern):
    fails(run)
    reads_nothing(run)
    assert re.search(pattern, run.err), run.describe()


def test_strain_out_into_missing_folder(tool, scratch, synth_obj):
    refused(tool("strain", synth_obj[0], "--out", scratch / "no-such-folder" / "field.bin"),
            r"--out: cannot write [^\n]*no-such-folder/field.bin: the folder[^\n]*no-such-folder does not exist")


def test_strain_out_is_a_folder(tool, synth_obj):
    refused(tool("strain", synth_obj[0], "--out", synth_obj[0]), r"--out: cannot write [^\n]*synth-obj: it is a folder")


@pytest.mark.parametrize("command", ["strain", "spatiotemporal"])
def test_mesh_dir_below_a_file(tool, synth_obj, a_file, command):
    refused(tool(command, synth_obj[0], "--mesh-dir", a_file / "meshes"),
            r"--mesh-dir: cannot create the folder [^\n]*a-file/meshes: [^\n]*a-file is a file, not a folder")


def test_spatiotemporal_dot_is_a_file(tool, synth_obj, a_file):
    refused(tool("spatiotemporal", synth_obj[0], "--dot", a_file),
            r"--dot: cannot write into [^\n]*a-file: it is a file, not a folder")


def test_view_out_below_a_file(tool, synth_obj, a_file):
    refused(tool("view", synth_obj[0], "--out", a_file / "page"),
            r"--out: cannot create the folder [^\n]*a-file/page: [^\n]*a-file is a file, not a folder")


def test_convert_out_below_a_file(tool, synth_obj, a_file):
    refused(tool("convert", synth_obj[0], a_file / "frames"),
            r"out: cannot create the folder [^\n]*a-file/frames: [^\n]*a-file is a file, not a folder")
