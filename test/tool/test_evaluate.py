"""evaluate: two motions (bend once, bend twice) on two tubes (thin, thick) and a distractor bending
another joint; each motion's nearest neighbour is the same motion on the other tube, so every
figure is 1 (by DTW, one different pair of 16 outranks a same pair: AUC 15/16). The labels files
are written beside the tubes."""

import re

import pytest

from conftest import fails, succeeds

THICK = ["--radius", "0.15", "--rings", "30", "--sectors", "12"]
TUBES = {
    "bend-thin": ["--schedule", "5:0", "10:90", "8:"],
    "bend-thick": THICK + ["--schedule", "5:0", "10:90", "8:"],
    "twice-thin": ["--schedule", "5:0", "5:90", "4:", "5:0", "5:90", "4:", "5:0"],
    "twice-thick": THICK + ["--schedule", "5:0", "5:90", "4:", "5:0", "5:90", "4:", "5:0"],
    "other": ["--joints", "0.3", "--schedule", "3:0", "12:-40", "6:"],
}
# The same labels as a spreadsheet exports them: a byte order mark, every field quoted, CRLF.
QUOTED = ('\ufeff"file","clip","motion","body"\r\n"bend-thin","","bend","thin"\r\n"twice-thin","","twice","thin"\r\n'
          '"bend-thick","","bend","thick"\r\n"twice-thick","","twice","thick"\r\n')
LABEL_FILES = {
    "labels.csv": "file,clip,motion,body\nbend-thin,,bend,thin\ntwice-thin,,twice,thin\n"
                  "bend-thick,,bend,thick\ntwice-thick,,twice,thick\nother,,-,other\n",
    "quoted.csv": QUOTED,
    # A pose of one frame among them: no motion to describe.
    "pose.csv": "file,clip,motion,body\nbend-thin,,bend,thin\nbend-thick,,bend,thick\n"
                "bend-thin/frame_0003.obj,,bend,pose\n",
    "missing.csv": "file,clip,motion\nbend-thin,,bend\nno-such-tube,,bend\n",
    "bad.csv": "file,clip,motion,colour\n",
}


@pytest.fixture(scope="session")
def tubes(tool, scratch):
    """The five tubes and the label files, in scratch/evaluate: name -> run of synth."""
    folder = scratch / "evaluate"
    runs = {name: tool("synth", folder / name, *args, "--json", "-") for name, args in TUBES.items()}
    for name, text in LABEL_FILES.items():
        (folder / name).write_bytes(text.encode("utf-8"))
    return folder, runs


@pytest.mark.parametrize("tube", list(TUBES))
def test_evaluate_synth(tubes, tube):
    assert "frames" in tubes[1][tube].json()


@pytest.fixture(scope="session")
def evaluate_tubes(tool, tubes):
    folder = tubes[0]
    return tool("evaluate", folder / "labels.csv", "--png", folder / "matrix.png", "--threads", "2")


def test_evaluate_tubes(evaluate_tubes):
    run = succeeds(evaluate_tubes)
    for pattern in (r"items +5\n", r"queries +4\n", r"NN accuracy +1.000\n", r"mAP +1.000\n", r"ROC-AUC +1.000\n",
                    r"median same +0\.[0-9]+ \(4 pairs\)", r"median different +0\.[0-9]+ \(8 pairs\)",
                    r"bend +2 / 2", r"twice +2 / 2", r"confusion", r"bend +\. +2 +\.\n", r"twice +\. +\. +2\n"):
        assert re.search(pattern, run.out), f"{pattern}\n{run.describe()}"
    # Each phase counted on its own: the 5 descriptions, then the 5 x 6 / 2 comparisons.
    assert re.search(r"described 5 animations in [0-9.]+ s\n", run.err), run.describe()
    assert "matrix: 15 of 15 comparisons" in run.err and " steps" not in run.err, run.describe()


def test_evaluate_figure_written(tubes, evaluate_tubes):
    succeeds(evaluate_tubes)
    assert (tubes[0] / "matrix.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


# Each query's line: its nearest candidate is the same motion on the other tube.
def test_evaluate_tubes_per_query(tool, tubes):
    out = succeeds(tool("evaluate", tubes[0] / "labels.csv", "--per-query")).out
    assert "per query" in out
    assert re.search(r"\n  bend-thin \(bend\): bend-thick \(bend\) 0\.[0-9]+; first bend at 1\n", out), out
    assert re.search(r"\n  twice-thick \(twice\): twice-thin \(twice\) 0\.[0-9]+; first twice at 1\n", out), out


def test_evaluate_quoted_labels(tool, tubes):
    out = succeeds(tool("evaluate", tubes[0] / "quoted.csv")).out
    for pattern in (r"items +4\n", r"queries +4\n", r"NN accuracy +1.000\n", r"bend +2 / 2", r"twice +2 / 2"):
        assert re.search(pattern, out), f"{pattern}\n{out}"


def test_evaluate_pose(tool, tubes):
    run = fails(tool("evaluate", tubes[0] / "pose.csv"))
    assert re.search(r"error: [^\n]*frame_0003.obj: motion_signatures: an animation of 1 frame\(s\); a motion needs "
                     r"at least 2 \(--skip-unreadable leaves it out\)", run.err), run.describe()


def test_evaluate_pose_skipped(tool, tubes):
    run = succeeds(tool("evaluate", tubes[0] / "pose.csv", "--skip-unreadable"))
    assert re.search(r"skipped [^\n]*frame_0003.obj: motion_signatures: an animation of 1 frame", run.output)
    # The count says how many were described and how many left out; the comparisons, of those kept.
    assert re.search(r"described 2 of 3 animations in [0-9.]+ s \(1 left out\)", run.err), run.describe()
    assert "matrix: 3 of 3 comparisons" in run.err and "of 9" not in run.err, run.describe()
    for pattern in (r"items +2\n", r"queries +2\n", r"NN accuracy +1.000\n"):
        assert re.search(pattern, run.out), f"{pattern}\n{run.describe()}"


def test_evaluate_tubes_json(tool, tubes):
    run = tool("evaluate", tubes[0] / "labels.csv", "--alignment", "dtw", "--json", "-")
    result = run.json()
    scores = result["scores"]
    assert (scores["nn_accuracy"], scores["roc_auc"], scores["mean_average_precision"]) == (1.0, 1.0, 1.0)
    assert scores["labels"] == ["-", "bend", "twice"]
    assert result["policy"] == "motion-signature" and result["alignment_policy"] == "dtw"
    assert isinstance(result["similarity"], list) and "seconds" in result
    first = scores["per_query"][0]
    assert first["average_precision"] == 1.0 and first["first_relevant_rank"] == 1
    assert "NN accuracy" not in run.output


# Strain histograms, the default before, rank one different pair above a same one: AUC 15/16.
def test_evaluate_tubes_json_histogram(tool, tubes):
    result = tool("evaluate", tubes[0] / "labels.csv", "--policy", "histogram", "--alignment", "dtw",
                  "--json", "-").json()
    assert result["scores"]["roc_auc"] == 0.9375
    assert result["policy"] == "histogram" and result["alignment_policy"] == "dtw"


# The thesis' graph policy runs too (its figures on these tubes are lower: not pinned).
def test_evaluate_graph(tool, tubes):
    result = tool("evaluate", tubes[0] / "labels.csv", "--policy", "graph", "--json", "-").json()
    assert result["policy"] == "graph"
    assert result["scores"]["queries"] == 4 and result["scores"]["same_pairs"] == 4


def test_evaluate_missing_clip(tool, tubes):
    # The error names the labels file's row, then the input it could not read.
    run = fails(tool("evaluate", tubes[0] / "missing.csv"))
    assert re.search(r"deformseg: error: [^\n]*missing.csv:3: [^\n]*no-such-tube", run.err), run.describe()


def test_evaluate_skip_unreadable(tool, tubes):
    # One clip left: the scores are printed, all "none", and the run fails, saying why.
    run = fails(tool("evaluate", tubes[0] / "missing.csv", "--skip-unreadable"),
                "nothing evaluated: no clip has a candidate of another body to rank")
    assert re.search(r"skipped [^\n]*missing.csv:3: [^\n]*no-such-tube", run.output), run.describe()
    for pattern in (r"items +1\n", r"queries +0\n", r"NN accuracy +none"):
        assert re.search(pattern, run.out), f"{pattern}\n{run.describe()}"


def test_evaluate_every_row_unreadable(tool, tubes):
    labels = tubes[0] / "unreadable.csv"
    labels.write_text("file,clip,motion\nno-such-tube,,bend\nnor-this-one,,twice\n")
    fails(tool("evaluate", labels, "--skip-unreadable"), "nothing evaluated: every row was unreadable (2)")


def test_evaluate_names_the_row_of_a_missing_clip(tool, tubes, characters):
    # A clip the file lacks: the labels file's row first, then the file's own words.
    labels = tubes[0] / "badclip.csv"
    labels.write_text(f"file,clip,motion\n{characters / 'Fox.glb'},Wlak,walk\n{characters / 'Fox.glb'},Run,run\n")
    fails(tool("evaluate", labels), f"{labels}:2: {characters / 'Fox.glb'}: no clip 'Wlak'")


def test_evaluate_bad_labels(tool, tubes):
    run = fails(tool("evaluate", tubes[0] / "bad.csv"))
    assert re.search(r"deformseg: error: [^\n]*bad.csv:1: unknown column 'colour'", run.err), run.describe()


def test_evaluate_no_labels(tool, tubes):
    run = fails(tool("evaluate", tubes[0] / "no-such.csv"))
    assert re.search(r"deformseg: error: [^\n]*no-such.csv: cannot open", run.err), run.describe()
