"""spatiotemporal: a tube bending once at constant speed gives R, R-D-R, R under a low threshold;
the JSON, the DOT files (which read back as labelled graphs) and the coloured meshes (which read
back as an animation)."""

import re

import pytest

from conftest import fails, reads_nothing, succeeds, synth


def test_spatiotemporal_json(tool, bend_once):
    graph = tool("spatiotemporal", bend_once[0], "--threshold", "0.01", "--json", "-").json()
    assert graph["frames"] == 31 and graph["segments"] == 1
    bending = [k for k in graph["key_frames"] if (k["first"], k["last"]) == (11, 20)]
    assert len(bending) == 1
    assert [node["kind"] for node in bending[0]["nodes"]].count("deformed") == 1


@pytest.fixture(scope="module")
def outputs(tool, scratch, bend_once):
    """spatiotemporal writing the key frames' DOT files and the coloured meshes."""
    return tool("spatiotemporal", bend_once[0], "--threshold", "0.01", "--dot", scratch / "bend-once-dot",
                "--mesh-dir", scratch / "bend-once-segments")


def test_spatiotemporal_outputs(outputs):
    out = succeeds(outputs).out
    assert re.search(r"key frames +3", out) and re.search(r"11-20 +D0 R R +2", out), outputs.describe()


def test_spatiotemporal_meshes_read_back(tool, scratch, outputs):
    succeeds(outputs)
    info = tool("info", scratch / "bend-once-segments", "--json", "-").json()
    assert (info["format"], info["frames"]) == ("ply", 31)


# The key frames' DOT files read back as labelled graphs: R against D0 - R - R is two node
# insertions and two edge insertions.
def test_ged_of_key_frames(tool, scratch, outputs):
    succeeds(outputs)
    dot = scratch / "bend-once-dot"
    result = tool("ged", dot / "key_frame_0000.dot", dot / "key_frame_0001.dot", "--method", "exact",
                  "--json", "-").json()
    assert result["distance"] == 4.0 and result["exact"] is True


def test_spatiotemporal_missing_input(tool, scratch):
    fails(tool("spatiotemporal", scratch / "no-such-folder"), "no-such-folder")


def test_spatiotemporal_bad_threshold(tool, bend_once):
    fails(tool("spatiotemporal", bend_once[0], "--threshold", "nan"), "threshold")


@pytest.mark.parametrize("bad", ["-1", "1.5"])
def test_spatiotemporal_threshold(tool, scratch, bad):
    reads_nothing(fails(tool("spatiotemporal", scratch / "no-such-tube", "--threshold", bad), "--threshold"))


def test_spatiotemporal_reference_mesh(tool, bend_once):
    run = succeeds(tool("spatiotemporal", bend_once[0], "--threshold", "0.01",
                        "--reference-mesh", bend_once[0] / "frame_0000.obj"))
    assert re.search(r"key frames +[1-9]", run.output), run.describe()


# A rest pose excludes the previous-pose reference.
def test_spatiotemporal_reference_mesh_previous(tool, scratch):
    reads_nothing(fails(tool("spatiotemporal", scratch / "no-such-tube", "--reference", "previous",
                             "--reference-mesh", "x.obj"),
                        "--reference-mesh is a rest pose: it excludes --reference previous"))


# The input is read frame by frame (frame files, point caches not welded), its coordinates never
# whole, or read whole (welded: welding compares every frame): the same segments, key frames and
# coloured meshes, byte for byte. The tubes have no coincident vertices, so welding changes nothing.
@pytest.mark.parametrize("reference", ["previous", "rest"])
def test_spatiotemporal_streamed_as_whole(tool, scratch, bend_once, reference):
    made = {}
    for way, options in (("streamed", []), ("whole", ["--weld"])):
        meshes = scratch / f"bend-once-{reference}-{way}"
        made[way] = tool("spatiotemporal", bend_once[0], "--threshold", "0.01", "--reference", reference, *options,
                         "--mesh-dir", meshes, "--json", "-").json(), meshes
    assert made["streamed"][0] == made["whole"][0]
    files = sorted(path.name for path in made["whole"][1].iterdir())
    assert len(files) == 31 and files == sorted(path.name for path in made["streamed"][1].iterdir())
    for name in files:
        assert (made["streamed"][1] / name).read_bytes() == (made["whole"][1] / name).read_bytes(), name


# A point cache of 16,450 vertices and 121 frames is read in chunks of 84 frames (32 MB of
# coordinates): the strain across the chunks' seam, against the frame before or frame 0, is the
# one of the animation read whole.
@pytest.mark.parametrize("reference", ["previous", "rest"])
def test_spatiotemporal_streamed_in_chunks(tool, scratch, reference):
    folder = scratch / "chunked-tube"
    if not (folder / "tube.pc2").exists():
        synth(tool, scratch, "chunked-tube", "--sectors", "64", "--rings", "256", "--format", "pc2",
              "--schedule", "30:0", "30:90", "30:", "30:0")
    cache = [folder / "tube.pc2", "--topology", folder / "tube.obj", "--reference", reference]
    streamed = tool("spatiotemporal", *cache, "--json", "-").json()
    whole = tool("spatiotemporal", *cache, "--weld", "--json", "-").json()
    assert streamed["frames"] == 121 and streamed["segments"] > 0
    assert streamed == whole
