"""deformseg view: the pages written for one and two animations (and a glTF clip), opened from disk
in headless Chromium by test/viewer/check_page.py, screenshots at two frames; what is refused."""

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import fails, reads_nothing, succeeds, synth

CHECK_PAGE = Path(__file__).parent.parent / "viewer" / "check_page.py"


def check_page(page, first, second):
    """check_page.py on `page` at frames `first` and `second` (skipped without Chromium)."""
    chromium = os.environ.get("DEFORMSEG_CHROMIUM")
    if not chromium:
        pytest.skip("Chromium not found (Debian: chromium)")
    checked = subprocess.run([sys.executable, CHECK_PAGE, chromium, page, str(first), str(second)],
                             capture_output=True, text=True, timeout=600)
    assert checked.returncode == 0, checked.stdout + checked.stderr


@pytest.fixture(scope="module")
def view_tube(tool, scratch, bend_once):
    return scratch / "view-tube", tool("view", bend_once[0], "--out", scratch / "view-tube")


@pytest.fixture(scope="module")
def view_two(tool, scratch, bend_once, synth_obj):
    return scratch / "view-two", tool("view", bend_once[0], synth_obj[0], "--color", "segments",
                                      "--out", scratch / "view-two")


@pytest.fixture(scope="module")
def view_fox(tool, scratch, characters):
    return scratch / "view-fox", tool("view", f"{characters}/Fox.glb#Walk", "--color", "previous-strain",
                                      "--out", scratch / "view-fox")


def test_view_tube(view_tube):
    assert re.search(r"open [^\n]*view-tube/index.html", succeeds(view_tube[1]).output), view_tube[1].describe()


def test_view_two_tubes(view_two):
    assert "aligning the two animations" in succeeds(view_two[1]).output, view_two[1].describe()


def test_view_fox(view_fox):
    assert re.search(r"open [^\n]*view-fox/index.html", succeeds(view_fox[1]).output), view_fox[1].describe()


def test_view_clip_suffix(tool, scratch, characters):
    run = succeeds(tool("view", f"{characters}/Fox.glb#Run", "--out", scratch / "view-fox-run"))
    assert re.search(r"open [^\n]*view-fox-run/index.html", run.output), run.describe()


def test_view_bad_color(tool, scratch):
    reads_nothing(fails(tool("view", scratch / "no-such-tube", "--out", scratch / "view-bad", "--color", "stripes"),
                        "--color"))


def test_view_three_inputs(tool, scratch):
    reads_nothing(fails(tool("view", scratch / "a", scratch / "b", scratch / "c", "--out", scratch / "view-bad"),
                        "inputs: At Most 2 required but received 3"))


# The written pages play in a browser (formerly the CTest entries viewer.view-*).
def test_viewer_page_tube(view_tube):
    succeeds(view_tube[1])
    check_page(view_tube[0], 0, 20)


def test_viewer_page_two(view_two):
    succeeds(view_two[1])
    check_page(view_two[0], 0, 25)


def test_viewer_page_fox(view_fox):
    succeeds(view_fox[1])
    check_page(view_fox[0], 0, 10)


def page_data(page):
    """The page's data (data.js) as JSON."""
    text = (page / "data.js").read_text()
    return json.loads(text[text.index("=") + 1:text.rindex(";")])


# A long take of a large mesh: a tube of 32,898 vertices and 281 frames (a 111 MB point cache),
# 9.2 million vertex positions, more than the page's budget of 24 million coordinates holds.
@pytest.fixture(scope="module")
def long_tube(tool, scratch):
    folder, _ = synth(tool, scratch, "long-tube", "--sectors", "128", "--rings", "256", "--format", "pc2",
                      "--schedule", "70:0", "70:90", "70:", "70:0")
    return [folder / "tube.pc2", "--topology", folder / "tube.obj"]


# view reads the long take frame by frame, keeps the frames it shows, and says what it chose: as
# many frames as the budget holds (24,000,000 / (3 x 32,898) = 243), at a frame rate lowered to
# match, and how to choose otherwise.
def test_view_long_take_within_budget(tool, scratch, long_tube):
    page = scratch / "view-long"
    run = succeeds(tool("view", *long_tube, "--color", "none", "--out", page))
    assert re.search(r"showing 243 of 281 frames \(one in 1\.16\), at 25\.9 fps: the page holds at most "
                     r"24000000 coordinates .*; --max-frames chooses", run.err), run.describe()
    assert "warning" not in run.err, run.describe()
    animation = page_data(page)["animations"][0]
    assert animation["frames"] == 243 and animation["vertices"] == 32898
    assert animation["frame_numbers"][:3] == [0, 1, 2] and animation["frame_numbers"][-1] == 280


# --max-frames overrides the budget, with a warning when the page grows past it.
def test_view_long_take_max_frames(tool, scratch, long_tube):
    page = scratch / "view-long-all"
    run = succeeds(tool("view", *long_tube, "--color", "none", "--max-frames", "281", "--out", page))
    assert "showing all 281 frames, at 30 fps" in run.err, run.describe()
    assert re.search(r"warning: .*: 281 frames of 32898 vertices make a page of about \d+ MB, more than a browser "
                     r"holds well \(24000000 coordinates in all\); a smaller --max-frames shows fewer", run.err), \
        run.describe()
    assert page_data(page)["animations"][0]["frames"] == 281


# A short take is shown whole, as before the budget; a smaller --max-frames samples it evenly, the
# page playing at the frame rate the sample keeps.
def test_view_short_take(tool, scratch, bend_once, view_tube):
    assert "showing all 31 frames, at 30 fps" in succeeds(view_tube[1]).err, view_tube[1].describe()
    assert page_data(view_tube[0])["animations"][0]["frames"] == 31
    page = scratch / "view-tube-ten"
    run = succeeds(tool("view", bend_once[0], "--max-frames", "10", "--out", page))
    assert "showing 10 of 31 frames (one in 3.33), at 9 fps" in run.err, run.describe()
    assert "warning" not in run.err, run.describe()
    data = page_data(page)
    assert data["animations"][0]["frame_numbers"] == [0, 3, 7, 10, 13, 17, 20, 23, 27, 30]
    assert data["fps"] == pytest.approx(9)


# Frame files welded are read whole (welding compares every frame), then sampled as a stream is.
def test_view_welded_frames_sampled(tool, scratch, bend_once):
    page = scratch / "view-tube-welded"
    run = succeeds(tool("view", bend_once[0], "--weld", "--max-frames", "10", "--out", page))
    assert "showing 10 of 31 frames" in run.err, run.describe()
    assert page_data(page)["animations"][0]["frame_numbers"] == [0, 3, 7, 10, 13, 17, 20, 23, 27, 30]
