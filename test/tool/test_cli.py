"""The command line itself: the list of commands, each command's help, typos, the thread bound,
options that exclude each other."""

import re

import pytest

from conftest import GRAPHS, fails, succeeds


def test_help(tool):
    out = succeeds(tool("--help")).out
    for command in ("info", "synth", "strain", "temporal"):
        assert command in out


def test_info_help(tool):
    out = succeeds(tool("info", "--help")).out
    assert "--topology" in out and "--json" in out


def test_no_command(tool):
    fails(tool(), "subcommand")


def test_ged_listed(tool):
    assert "ged-matrix" in succeeds(tool("--help")).out


def test_evaluate_listed(tool):
    assert "evaluate" in succeeds(tool("--help")).out


# Each command's help names its options.
@pytest.mark.parametrize("command, options", [
    ("strain", ["--reference", "--measure", "--normalize", "--mesh-dir"]),
    ("temporal", ["--method", "--segments", "--png", "--matrix"]),
    ("spatiotemporal", ["--threshold", "--reference", "--dot", "--mesh-dir"]),
    ("ged", ["--method", "--max-expanded", "--json"]),
    ("similarity", ["--policy", "--alignment", "--png"]),
    ("matrix", ["--csv", "--png"]),
    ("evaluate", ["--policy", "--alignment", "--fps", "--json", "--png", "--threads", "--skip-unreadable",
                  "--per-query"]),
], ids=["strain", "temporal", "spatiotemporal", "ged", "similarity", "matrix", "evaluate"])
def test_help_of(tool, command, options):
    out = succeeds(tool(command, "--help")).out
    for option in options:
        assert option in out, option


# The histogram policy's values crowd near 1 (chapter 7's figures), which every command that takes
# --policy says, on the policy's line.
@pytest.mark.parametrize("command", ["similarity", "matrix", "evaluate"])
def test_help_histogram_near_1(tool, command):
    out = succeeds(tool(command, "--help")).out
    assert re.search(r"histogram: [^\n]*values crowd near 1[^\n]*read the z-score or a rank", out), out


# A typo gets the nearest command or option.
# The hint comes alone, not after CLI11's "A subcommand is required"; the status is 1, as every error's.
def test_typo_command(tool, synth_obj):
    run = fails(tool("inof", synth_obj[0]), "unknown command 'inof': did you mean 'info'?")
    assert run.status == 1 and "subcommand is required" not in run.output, run.describe()


def test_typo_option(tool, synth_obj):
    fails(tool("info", synth_obj[0], "--jsn", "x.json"), "unknown option '--jsn' of info: did you mean '--json'?")


def test_typo_option_far(tool, synth_obj):
    run = fails(tool("strain", synth_obj[0], "--colour-by-segment"), "unknown option '--colour-by-segment' of strain")
    assert "did you mean" not in run.output


# A thread count above the bound is refused when the command line is read, naming it (70000
# threads crashed the tool, 40000 ended in "libgomp: Thread creation failed"); the bound itself runs.
def test_threads_above_the_bound(tool, synth_obj):
    fails(tool("strain", synth_obj[0], "--threads", "70000"), "--threads: must be a whole number in [0, 1024], got 70000")


def test_threads_above_the_bound_ged_matrix(tool):
    fails(tool("ged-matrix", GRAPHS / "path.dot", GRAPHS / "ring.gv", "--threads", "40000"),
          "--threads: must be a whole number in [0, 1024], got 40000")


def test_threads_at_the_bound(tool, synth_obj):
    assert tool("strain", synth_obj[0], "--threads", "1024", "--json", "-").json()["frames"] == 41


def test_weld_excludes_no_weld(tool):
    fails(tool("info", "a.glb", "--weld", "--no-weld"), "excludes")


# Options that do not apply to the input are refused before anything is read.
def test_clip_without_gltf(tool, synth_obj):
    fails(tool("info", synth_obj[0], "--clip", "Walk"), "--clip applies to character files (glTF, FBX, Collada, BVH) only")


# A refusal as the command line is read ends with the status 1, as every other error: "cannot
# write" is CLI11's failed check (its own code, 105, said nothing more).
def test_refusals_exit_with_1(tool, synth_obj, scratch):
    run = fails(tool("info", synth_obj[0], "--json", scratch / "no-such-folder" / "x.json"), "cannot write")
    assert run.status == 1, run.describe()
    assert fails(tool("strain", synth_obj[0], "--fps", "0"), "--fps: must be in (0, 1000], got 0").status == 1
