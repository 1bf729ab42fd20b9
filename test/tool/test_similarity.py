"""similarity and matrix: an animation against itself gives 1 by every policy; the default policy
aligns by DTW and gives a z-score against shuffled copies; options that do not apply are refused
before anything is read."""

import re

import pytest

from conftest import fails, reads_nothing, succeeds, synth

# Each policy with the alignment it takes when none is given.
POLICIES = {"motion-signature": "dtw", "histogram": "smith-waterman", "self-similarity": "smith-waterman",
            "graph": "smith-waterman", "graph-characters": "dtw"}


@pytest.mark.parametrize("policy", POLICIES)
def test_similarity_self(tool, scratch, synth_obj, policy):
    png = scratch / f"similarity-{policy}.png"
    result = tool("similarity", synth_obj[0], synth_obj[0], "--policy", policy, "--png", png, "--json", "-").json()
    assert result["similarity"] == 1.0 and result["policy"] == policy
    assert result["alignment_policy"] == POLICIES[policy]
    assert isinstance(result["alignment"], list) and "labels_a" in result
    assert png.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


# The default policy aligns by DTW and gives a z-score against 20 shuffled copies; the graph
# policy none; --significance 1 is refused before anything is read.
def test_similarity_default(tool, synth_obj, bend_once):
    result = tool("similarity", synth_obj[0], bend_once[0], "--json", "-").json()
    assert result["policy"] == "motion-signature" and result["alignment_policy"] == "dtw"
    assert isinstance(result["z_score"], float) and result["shuffled_copies"] == 20


def test_similarity_z_score(tool, synth_obj, bend_once):
    out = succeeds(tool("similarity", synth_obj[0], bend_once[0], "--significance", "5", "--seed", "3")).out
    assert re.search(r"similarity +0\.[0-9]+", out), out
    assert re.search(r"z-score +-?[0-9.]+ \(against 5 frame-shuffled copies of B\)", out), out


@pytest.mark.parametrize("policy", ["graph", "graph-characters"])
def test_similarity_graph_no_z_score(tool, synth_obj, bend_once, policy):
    result = tool("similarity", synth_obj[0], bend_once[0], "--policy", policy, "--json", "-").json()
    assert result["z_score"] is None and result["shuffled_copies"] == 0


# The graph policy is the thesis' (Smith-Waterman); the variant tuned on characters aligns by DTW
# and segments otherwise, so the two differ on a bend against another.
def test_similarity_graph_policies(tool, synth_obj, bend_once):
    thesis = tool("similarity", synth_obj[0], bend_once[0], "--policy", "graph", "--json", "-").json()
    tuned = tool("similarity", synth_obj[0], bend_once[0], "--policy", "graph-characters", "--json", "-").json()
    assert thesis["alignment_policy"] == "smith-waterman" and tuned["alignment_policy"] == "dtw"
    assert thesis["similarity"] != tuned["similarity"]


# The graph policies' thresholds when none is given, as --threshold says: 0.5 for the thesis'
# method, 0.3 for the settings tuned on characters.
@pytest.mark.parametrize("policy,threshold", [("graph", "0.5"), ("graph-characters", "0.3")])
def test_similarity_graph_default_threshold(tool, synth_obj, bend_once, policy, threshold):
    given = tool("similarity", synth_obj[0], bend_once[0], "--policy", policy, "--threshold", threshold, "--json", "-")
    default = tool("similarity", synth_obj[0], bend_once[0], "--policy", policy, "--json", "-")
    assert given.json()["similarity"] == default.json()["similarity"]


def test_similarity_one_copy(tool, scratch):
    reads_nothing(fails(tool("similarity", scratch / "no-such-a", scratch / "no-such-b", "--significance", "1"),
                        "--significance needs 0 (none) or at least 2"))


def test_similarity_dtw(tool, synth_obj, bend_once):
    out = succeeds(tool("similarity", synth_obj[0], bend_once[0], "--alignment", "dtw")).out
    assert re.search(r"similarity +0\.[0-9]+", out) and "aligned" in out, out


def test_similarity_missing_input(tool, scratch, synth_obj):
    fails(tool("similarity", synth_obj[0], scratch / "no-such-folder"), "no-such-folder")


def test_similarity_unknown_policy(tool):
    fails(tool("similarity", "a", "b", "--policy", "magic"),
          "--policy: must be 'motion-signature', 'histogram', 'graph', 'self-similarity' or 'graph-characters', "
          "got 'magic'")


def test_similarity_threshold_not_graph(tool, scratch):
    reads_nothing(fails(tool("similarity", scratch / "no-such-a", scratch / "no-such-b", "--threshold", "0.1"),
                        "threshold applies to the graph policies only, not to the motion-signature policy"))


@pytest.mark.parametrize("up", ["none", "+z"])
def test_similarity_up(tool, synth_obj, up):
    assert tool("similarity", synth_obj[0], synth_obj[0], "--up", up, "--json", "-").json()["similarity"] == 1.0


def test_similarity_up_not_signature(tool, scratch):
    reads_nothing(fails(tool("similarity", scratch / "no-such-a", scratch / "no-such-b", "--policy", "histogram",
                             "--up", "none"),
                        "up applies to the motion-signature policy only, not to the histogram policy"))


def test_similarity_up_unknown(tool, scratch):
    reads_nothing(fails(tool("similarity", scratch / "no-such-a", scratch / "no-such-b", "--up", "w"), "--up"))


# --explain: the channels' shares sum to 1 and the text lists the largest; a motion and itself
# differ nowhere; refused for another policy before anything is read.
def test_similarity_explain(tool, synth_obj, bend_once):
    run = succeeds(tool("similarity", synth_obj[0], bend_once[0], "--explain", "--bands", "2", "--up", "+z",
                        "--json", "-"))
    explanation = run.json()["explanation"]
    channels = explanation["channels"]
    assert len(channels) == 2 * 4 * 2 * 2 and explanation["pairs"] > 0
    assert abs(sum(c["share"] for c in channels) - 1) < 1e-9
    assert {c["band"] for c in channels} == {0, 1} and {c["half"] for c in channels} == {"lower", "upper"}
    text = succeeds(tool("similarity", synth_obj[0], bend_once[0], "--explain", "--bands", "2", "--up", "+z")).out
    lines = [line for line in text.splitlines() if "% " in line]
    assert len(lines) == 6 and re.search(r"height band [12] of 2, counted from the ground", lines[0]), text
    itself = tool("similarity", synth_obj[0], synth_obj[0], "--explain", "--json", "-").json()["explanation"]
    assert all(c["share"] == 0 and c["mean_difference"] == 0 for c in itself["channels"])
    assert tool("similarity", synth_obj[0], bend_once[0], "--json", "-").json()["explanation"] is None


def test_similarity_explain_not_signature(tool, scratch):
    reads_nothing(fails(tool("similarity", scratch / "no-such-a", scratch / "no-such-b", "--policy", "histogram",
                             "--explain"),
                        "--explain applies to the motion-signature policy only, not to the histogram policy"))


# --bands: another description (a value of its own), 1 the default; refused without an up direction,
# for another policy, and out of its range, before anything is read.
def test_similarity_bands(tool, scratch, synth_obj, bend_once):
    def value(*options):
        return tool("similarity", synth_obj[0], bend_once[0], *options, "--json", "-").json()["similarity"]

    assert value("--bands", "1") == value()
    assert value("--bands", "3", "--up", "+z") != value("--up", "+z")
    assert tool("similarity", synth_obj[0], synth_obj[0], "--bands", "4", "--json", "-").json()["similarity"] == 1.0
    missing = (scratch / "no-such-a", scratch / "no-such-b")
    reads_nothing(fails(tool("similarity", *missing, "--bands", "2", "--up", "none"),
                        "--bands 2 needs an up direction, not --up none"))
    reads_nothing(fails(tool("similarity", *missing, "--bands", "2", "--policy", "graph"),
                        "--bands applies to the motion-signature policy only, not to the graph policy"))
    reads_nothing(fails(tool("similarity", *missing, "--bands", "0"), "--bands"))
    reads_nothing(fails(tool("similarity", *missing, "--bands", "65"), "--bands"))


# A motion and its mirror image: alike by default (distributions over the whole surface), apart with
# --sides, which keeps the two sides of the body apart; --sides refused for another policy.
def mirrored_frames(folder, to):
    """The OBJ frames of `folder` mirrored across x = 0, into `to`."""
    to.mkdir(exist_ok=True)
    for frame in sorted(folder.glob("*.obj")):
        lines = []
        for line in frame.read_text().splitlines():
            if line.startswith("v "):
                _, x, y, z = line.split()
                line = f"v {-float(x)!r} {y} {z}"
            lines.append(line)
        (to / frame.name).write_text("\n".join(lines) + "\n")


def test_similarity_sides_tell_a_mirror_image(tool, scratch, synth_obj):
    mirror = scratch / "synth-obj-mirrored"
    mirrored_frames(synth_obj[0], mirror)
    def value(*options):
        return tool("similarity", synth_obj[0], mirror, *options, "--json", "-").json()["similarity"]

    assert value() == 1.0 and value("--bands", "3") == 1.0
    assert value("--sides", "+x") < 0.99  # 0.981: the tube bends towards +x, its mirror image towards -x
    assert tool("similarity", synth_obj[0], synth_obj[0], "--sides", "+x", "--json", "-").json()["similarity"] == 1.0
    reads_nothing(fails(tool("similarity", scratch / "no-such-a", scratch / "no-such-b", "--sides", "+x",
                             "--policy", "self-similarity"),
                        "--sides applies to the motion-signature policy only, not to the self-similarity policy"))
    reads_nothing(fails(tool("similarity", scratch / "no-such-a", scratch / "no-such-b", "--sides", "left"),
                        "--sides"))


def test_matrix_csv(tool, scratch, synth_obj, bend_once):
    run = succeeds(tool("matrix", synth_obj[0], bend_once[0], synth_obj[0], "--csv", scratch / "matrix.csv",
                        "--png", scratch / "matrix.png", "--json", "-"))
    matrix = run.json()["similarity"]
    assert len(matrix) == 3 and all(len(row) == 3 for row in matrix)
    assert [matrix[i][i] for i in range(3)] == [1.0, 1.0, 1.0] and matrix[0][2] == 1.0
    assert "described 3 animations" in run.err and "matrix: 6 of 6 comparisons" in run.err
    header, *rows = (scratch / "matrix.csv").read_text().splitlines()
    assert header.startswith("animation,") and len(rows) == 3
    assert (scratch / "matrix.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


def test_matrix_one_input(tool, synth_obj):
    fails(tool("matrix", synth_obj[0]), "inputs")


# An unquoted glob: one-frame inputs are refused with the cause.
def test_matrix_unquoted_glob(tool, synth_obj):
    fails(tool("matrix", synth_obj[0] / "frame_0000.obj", synth_obj[0] / "frame_0001.obj"),
          "an animation of 1 frame: a motion needs at least 2 (an unquoted glob")


# Frame sequences and point caches are described frame by frame (the progress says so); read whole
# (--weld: welding compares every frame; the tubes have nothing to weld) they give the same report
# to the last byte, path and z-score included.
def test_similarity_streamed_equals_read_whole(tool, scratch, synth_obj, bend_once):
    caches = [synth(tool, scratch, f"similarity-cache-{k}", "--format", "pc2", "--schedule", *schedule)[0]
              for k, schedule in enumerate([["6:0", "6:70", "6:"], ["4:0", "9:40", "3:"]])]
    pairs = [([synth_obj[0], bend_once[0]], []),
             ([caches[0] / "tube.pc2", caches[1] / "tube.pc2"], ["--topology", caches[0] / "tube.obj"])]
    for inputs, options in pairs:
        streamed = succeeds(tool("similarity", *inputs, *options, "--significance", "4", "--json", "-"))
        whole = succeeds(tool("similarity", *inputs, *options, "--significance", "4", "--weld", "--json", "-"))
        assert "frame by frame" in streamed.err and "frame by frame" not in whole.err
        assert streamed.out == whole.out
        assert len(streamed.json()["alignment"]) > 0


# --threads reaches every loop of a comparison, the policy's own included: with the environment's
# count unreadable, one thread compares by every policy (a loop left on the environment's count
# fails), the same as on two; the environment's count is read only when --threads asks for it.
@pytest.mark.parametrize("policy", POLICIES)
def test_similarity_threads_reach_the_policy(tool, synth_obj, bend_once, policy, monkeypatch):
    args = ["similarity", synth_obj[0], bend_once[0], "--policy", policy, "--json", "-"]
    two = succeeds(tool(*args, "--threads", "2")).json()
    monkeypatch.setenv("DEFORMSEG_NUM_THREADS", "many")
    one = succeeds(tool(*args, "--threads", "1")).json()
    assert one["similarity"] == two["similarity"] and one["alignment"] == two["alignment"]
    assert one.get("z_score") == two.get("z_score")
    fails(tool(*args), "DEFORMSEG_NUM_THREADS is 'many'")
