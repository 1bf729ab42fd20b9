"""deformseg view: the pages written for one and two animations (and a glTF clip), opened from disk
in headless Chromium by test/viewer/check_page.py, screenshots at two frames; what is refused."""

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import fails, reads_nothing, succeeds

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
