"""find: a bend, hold and unbend (39 frames) looked for in a long, thicker tube that does it twice
(from frames 12 and 80, after half bends and holds): both windows found where they start, within
a frame, each window's frames described alone (measured: 12-56 and 80-124, 0.985 each; 15-49 and
83-117, 0.963, when the windows were valued inside the long animation)."""

import re

import pytest

from conftest import fails, reads_nothing, succeeds, synth


@pytest.fixture(scope="session")
def query(tool, scratch):
    return synth(tool, scratch, "find-query", "--schedule", "5:0", "10:90", "8:", "10:0", "5:")


@pytest.fixture(scope="session")
def long_tube(tool, scratch):
    return synth(tool, scratch, "find-long", "--radius", "0.16", "--schedule", "6:45", "6:0", "5:0", "10:90", "8:",
                 "10:0", "5:", "18:", "6:45", "6:0", "5:0", "10:90", "8:", "10:0", "5:", "10:")


def test_synth_find_query(query):
    assert query[1].json()["frames"] == 39


def test_synth_find_long(long_tube):
    assert long_tube[1].json()["frames"] == 129


def test_find_twice(tool, query, long_tube):
    out = succeeds(tool("find", query[0], long_tube[0], "--count", "2")).out
    assert re.search(r"frames 1[1-3] to [0-9]+  similarity 0\.9[5-9][0-9]\n", out), out
    assert re.search(r"frames (79|8[01]) to [0-9]+  similarity 0\.9[5-9][0-9]\n", out), out


# The query found in itself: the whole animation, exactly 1.
def test_find_itself(tool, query):
    run = succeeds(tool("find", query[0], query[0]))
    assert run.out.startswith("frames 0 to 38  similarity 1.000\n"), run.describe()
    assert not re.search(r"frames [1-9]", run.output), run.describe()


def test_find_json(tool, query, long_tube):
    result = tool("find", query[0], long_tube[0], "--json", "-").json()
    assert result["policy"] == "motion-signature" and result["matches"]
    assert all(isinstance(m["first"], int) and m["first"] >= 0 and isinstance(m["alignment"], list)
               for m in result["matches"])


def test_find_bad_count(tool, scratch):
    reads_nothing(fails(tool("find", scratch / "no-such-query", scratch / "no-such-long", "--count", "0"),
                        "--count: must be a whole number in [1, 1000000], got 0"))
