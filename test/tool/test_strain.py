"""strain: the summary, the field file, the coloured meshes (which read back as an animation), the
strip of frames, the reference mesh, and what is refused."""

import re

import pytest

from conftest import fails, succeeds


def test_strain_summary(tool, synth_obj):
    strain = tool("strain", synth_obj[0], "--measure", "green-lagrange", "--json", "-").json()
    assert (strain["frames"], strain["triangles"], strain["degenerate_count"]) == (41, 1568, 0)
    assert strain["measure"] == "green-lagrange"
    assert isinstance(strain["sigma"], float) and strain["sigma"] > 0


# The summary prints sigma to 6 significant digits ("0.872746"), not a double's 17.
def test_strain_summary_sigma_digits(tool, synth_obj):
    run = succeeds(tool("strain", synth_obj[0]))
    sigma = re.search(r"^sigma +(\S+)$", run.out, re.M)
    assert sigma and re.fullmatch(r"0\.\d{1,6}", sigma.group(1)), run.describe()
    exact = tool("strain", synth_obj[0], "--json", "-").json()["sigma"]
    assert float(sigma.group(1)) == pytest.approx(exact, rel=1e-5)


@pytest.fixture(scope="module")
def strain_outputs(tool, scratch, synth_obj):
    """strain writing the field file and the coloured meshes."""
    return tool("strain", synth_obj[0], "--reference", "previous", "--normalize", "none",
                "--out", scratch / "strain-field.bin", "--mesh-dir", scratch / "strain-meshes")


def test_strain_outputs(scratch, strain_outputs):
    out = succeeds(strain_outputs).out
    assert re.search(r"sigma +null", out) and re.search(r"frame +min +max +mean", out), out
    assert (scratch / "strain-field.bin").stat().st_size > 0
    # Every strain with six decimals: frame 0 of the previous-pose strain is 0, not 4e-41.
    rows = re.findall(r"^\d+  (\S+)  (\S+)  (\S+)$", out, re.M)
    assert len(rows) == 41 and rows[0] == ("0.000000",) * 3, out
    assert all(re.fullmatch(r"\d+\.\d{6}", value) for row in rows for value in row), out


def test_strain_meshes_read_back(tool, scratch, strain_outputs):
    succeeds(strain_outputs)
    info = tool("info", scratch / "strain-meshes", "--json", "-").json()
    assert (info["format"], info["frames"], info["triangles"]) == ("ply", 41, 1568)


def test_strain_unknown_measure(tool, synth_obj):
    fails(tool("strain", synth_obj[0], "--measure", "stretchiness"), "--measure")


def test_strain_sigma_without_gaussian(tool, synth_obj):
    fails(tool("strain", synth_obj[0], "--normalize", "none", "--sigma", "0.1"), "deformseg: error: --sigma asks for")


def test_strain_rest_frame_out_of_range(tool, synth_obj):
    fails(tool("strain", synth_obj[0], "--rest-frame", "41"), "rest frame 41 out of range")


# --reference-mesh: the tube's straight frame kept apart gives frame 0 no strain; a mesh of other
# connectivity is refused, naming it.
def test_strain_reference_mesh(tool, synth_obj):
    reference = synth_obj[0] / "frame_0000.obj"
    strain = tool("strain", synth_obj[0], "--reference-mesh", reference, "--json", "-").json()
    assert strain["reference_mesh"].endswith("frame_0000.obj")
    first = strain["per_frame"][0]
    assert first["frame"] == 0 and 0 <= first["max"] < 1e-9


def test_strain_reference_mesh_mismatch(tool, synth_obj, synth_two):
    run = fails(tool("strain", synth_obj[0], "--reference-mesh", synth_two[0] / "frame_0000.obj"))
    assert re.search(r"deformseg: error: [^\n]*synth-two/frame_0000.obj[^\n]*reference mesh", run.err), run.describe()


# strain --png: a strip of frames coloured by strain.
@pytest.fixture(scope="module")
def strain_png(tool, scratch, synth_obj):
    return tool("strain", synth_obj[0], "--png", scratch / "strain.png", "--png-frames", "0,20,40")


def test_strain_png(strain_png):
    assert "drawing 3 frames coloured by strain" in succeeds(strain_png).output


def test_strain_png_written(scratch, strain_png):
    succeeds(strain_png)
    assert (scratch / "strain.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


def test_strain_png_frame_past_end(tool, scratch, synth_obj):
    fails(tool("strain", synth_obj[0], "--png", scratch / "strain-bad.png", "--png-frames", "41"),
          "--png-frames: frame 41 is past the last, 40")


# A missing DIR, parents and all, is created.
def test_strain_mesh_dir_into_missing_folders(tool, scratch, synth_obj):
    run = succeeds(tool("strain", synth_obj[0], "--mesh-dir", scratch / "new-folder" / "meshes"))
    assert re.search(r"writing 41 coloured meshes to [^\n]*new-folder/meshes", run.output), run.describe()
    assert len(list((scratch / "new-folder" / "meshes").iterdir())) == 41


# An unquoted glob: extra inputs to a single-input command are refused with a hint to quote it.
def test_strain_unquoted_glob(tool, synth_obj):
    fails(tool("strain", synth_obj[0] / "frame_0000.obj", synth_obj[0] / "frame_0001.obj"), "a glob must be quoted")
