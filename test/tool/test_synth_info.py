"""synth writes tubes in every format; info reads them back with the right counts."""

import re

import pytest

from conftest import fails, reads_nothing, succeeds, synth

FORMATS = ["obj", "ply", "pc2", "mdd"]


@pytest.fixture(scope="session")
def tubes(tool, scratch):
    """The default tube written in each format: format -> (folder, run of synth)."""
    return {format: synth(tool, scratch, f"synth-{format}", "--format", format) for format in FORMATS}


def input_of(tubes, format):
    """The input naming the tube of `format`: its folder, or its cache and its topology."""
    folder = tubes[format][0]
    if format in ("pc2", "mdd"):
        return [folder / f"tube.{format}", "--topology", folder / "tube.obj"]
    return [folder]


@pytest.mark.parametrize("format", FORMATS)
def test_synth(tubes, format):
    assert tubes[format][1].json()["frames"] == 41


# Each format the tool writes reads back with the right counts: 41 frames of the default tube.
@pytest.mark.parametrize("format", FORMATS)
def test_info(tool, tubes, format):
    info = tool("info", *input_of(tubes, format), "--json", "-").json()
    assert info["format"] == format
    assert (info["frames"], info["vertices"], info["triangles"]) == (41, 786, 1568)


# The summary prints the bounding box to 6 significant digits, not a double's 17
# (-0.10103061890839388); the JSON keeps every digit.
def test_info_summary_figures(tool, tubes):
    run = succeeds(tool("info", *input_of(tubes, "obj")))
    box = re.search(r"^bounding box  \[(.*)\] to \[(.*)\]$", run.out, re.M)
    assert box, run.describe()
    coordinates = [c for corner in box.groups() for c in corner.split(", ")]
    assert len(coordinates) == 6 and coordinates[0] == "-0.101031", run.describe()
    assert all(len(re.sub(r"[-.]|e.*", "", c).lstrip("0")) <= 6 for c in coordinates), run.describe()
    exact = tool("info", *input_of(tubes, "obj"), "--json", "-").json()["bounding_box"]["min"]
    assert [float(c) for c in coordinates[:3]] == pytest.approx(exact, rel=1e-5)


# info reads one frame at a time (the bounding box accumulated frame by frame) where it can, and
# reads welded frame files whole, which compare every frame: both say the same of the same tube,
# to the digit. The tube has no coincident vertices, so welding changes nothing.
def test_info_streamed_as_whole(tool, tubes):
    streamed = succeeds(tool("info", *input_of(tubes, "obj")))
    whole = succeeds(tool("info", *input_of(tubes, "obj"), "--weld"))
    assert streamed.out == whole.out, streamed.describe() + whole.describe()
    streamed_json = tool("info", *input_of(tubes, "obj"), "--json", "-").json()
    whole_json = tool("info", *input_of(tubes, "obj"), "--weld", "--json", "-").json()
    assert streamed_json == whole_json


# The memory info gives is what the animation takes read whole (as most commands read it): its
# coordinates as doubles, 12 + 4 bytes a triangle and 4 a vertex, computed from the counts; the
# help says so.
@pytest.mark.parametrize("format", FORMATS)
def test_info_memory_of_the_whole_animation(tool, tubes, format):
    info = tool("info", *input_of(tubes, format), "--json", "-").json()
    frames, vertices, triangles = info["frames"], info["vertices"], info["triangles"]
    assert info["memory_bytes"] == 3 * vertices * frames * 8 + 16 * triangles + 4 * vertices
    assert "what the animation takes read whole" in " ".join(succeeds(tool("info", "--help")).out.split())


def test_synth_two_joints(synth_two):
    made = synth_two[1].json()
    assert made["frames"] == 16 and made["triangles"] == 304


def test_synth_three_poses(three_poses):
    assert three_poses[1].json()["frames"] == 66


def test_synth_bend_once(bend_once):
    assert bend_once[1].json()["frames"] == 31


def test_synth_bad_schedule(tool, scratch):
    fails(tool("synth", scratch / "synth-bad", "--schedule", "10:x"), "deformseg: error: --schedule: 'x'")


def test_synth_wrong_angle_count(tool, scratch):
    fails(tool("synth", scratch / "synth-bad", "--schedule", "10:1,2"), "phase 0: needs")


def test_synth_out_below_a_file(tool, a_file):
    run = fails(tool("synth", a_file / "tube"), "out: cannot create the folder ",
                f"{a_file}/tube: ", f"{a_file} is a file, not a folder")
    assert "writing" not in run.output


# One clear line and a non-zero exit on bad input.
def test_info_missing(tool, scratch):
    run = fails(tool("info", scratch / "no-such-folder"))
    assert re.search(r"deformseg: error: [^\n]*no-such-folder", run.err), run.describe()


def test_info_cache_without_topology(tool, tubes):
    fails(tool("info", tubes["pc2"][0] / "tube.pc2"), "needs a topology mesh (.obj, .off or .ply): give it with --topology")


def test_synth_too_big_for_memory(tool, scratch):
    run = fails(tool("synth", scratch / "synth-huge", "--sectors", "10000", "--rings", "10000"),
                "deformseg: error: a tube of 100010002 vertices", "fewer sectors, rings or frames")
    assert "bad_alloc" not in run.err


def test_version(tool):
    run = succeeds(tool("--version"))
    assert re.fullmatch(r"deformseg \d+\.\d+\.\d+\n", run.out), run.describe()


# The one rule of what a command prints: the summary on standard output, with --json FILE as well.
def test_info_json_file_keeps_summary(tool, synth_obj, scratch):
    run = succeeds(tool("info", synth_obj[0], "--json", scratch / "info.json"))
    assert re.search(r"frames +41\n", run.out), run.describe()
    assert '"frames"' not in run.output


# info --files: the frames in the order read (natural order: frame_2 before frame_10).
def test_info_files(tool, synth_obj):
    out = succeeds(tool("info", synth_obj[0], "--files")).out
    lines = out.splitlines()
    header = next(i for i, line in enumerate(lines) if line.startswith("files"))
    assert lines[header].split() == ["files", "frame:", "file,", "in", "the", "order", "read"]
    listed = [line.split() for line in lines[header + 1:header + 42]]
    assert [entry[0] for entry in listed] == [f"{i}:" for i in range(41)]
    assert listed[0][1].endswith("frame_0000.obj") and listed[40][1].endswith("frame_0040.obj")


def test_info_files_json(tool, synth_obj):
    files = tool("info", synth_obj[0], "--files", "--json", "-").json()["files"]
    assert files[0].endswith("frame_0000.obj")


def test_info_files_of_cache(tool, tubes):
    folder = tubes["pc2"][0]
    run = fails(tool("info", folder / "tube.pc2", "--topology", folder / "tube.obj", "--files"),
                "--files lists the frame files of a folder or glob; this input is one pc2 file")
    reads_nothing(run)
