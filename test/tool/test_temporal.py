"""temporal: a tube that holds three poses, 20 frames each, with 4-frame transitions (frames
20-23 and 43-46): the boundaries fall in the transitions, by every method."""

import json
import re

import pytest

from conftest import fails, reads_nothing, succeeds

IN_FIRST_TRANSITION = range(20, 24)
IN_SECOND_TRANSITION = range(43, 47)


def segment_firsts(result):
    return [segment["first"] for segment in result["segments"]]


def test_temporal_three_segments(tool, three_poses):
    result = tool("temporal", three_poses[0], "--segments", "3", "--json", "-").json()
    assert result["frames"] == 66 and result["method"] == "optimal"
    first, second, third = segment_firsts(result)
    assert first == 0 and second in IN_FIRST_TRANSITION and third in IN_SECOND_TRANSITION
    assert result["segments"][-1]["last"] == 65


@pytest.mark.parametrize("method", ["binary-split", "greedy", "barbic"])
def test_temporal(tool, three_poses, method):
    firsts = segment_firsts(tool("temporal", three_poses[0], "--method", method, "--json", "-").json())
    assert any(f in IN_FIRST_TRANSITION for f in firsts) and any(f in IN_SECOND_TRANSITION for f in firsts)
    assert all(f == 0 or f in IN_FIRST_TRANSITION or f in IN_SECOND_TRANSITION for f in firsts), firsts


@pytest.fixture(scope="module")
def temporal_figure(tool, scratch, three_poses):
    return tool("temporal", three_poses[0], "--png", scratch / "temporal.png", "--matrix", scratch / "temporal.csv")


def test_temporal_figure(temporal_figure):
    assert re.search(r"66 frames, [3-5] segments", succeeds(temporal_figure).output), temporal_figure.describe()


def test_temporal_figure_written(scratch, temporal_figure):
    succeeds(temporal_figure)
    assert (scratch / "temporal.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    rows = (scratch / "temporal.csv").read_text().splitlines()
    assert len(rows) == 66 and all(len(row.split(",")) == 66 for row in rows)


def test_temporal_segments_need_optimal(tool, three_poses):
    fails(tool("temporal", three_poses[0], "--method", "greedy", "--segments", "3"),
          "deformseg: error: --segments asks for --method optimal")


def test_temporal_too_many_segments(tool, three_poses):
    fails(tool("temporal", three_poses[0], "--segments", "67"), "cannot make 67 segments")


def test_temporal_segments_not_optimal(tool, scratch):
    reads_nothing(fails(tool("temporal", scratch / "no-such-tube", "--segments", "4", "--method", "greedy"),
                        "--segments asks for --method optimal"))


# The summary stays on standard output when the JSON goes to a file.
def test_temporal_json_file_keeps_summary(tool, scratch, three_poses):
    run = succeeds(tool("temporal", three_poses[0], "--segments", "3", "--json", scratch / "temporal.json"))
    assert "66 frames, 3 segments" in run.out
    assert len(segment_firsts(json.loads((scratch / "temporal.json").read_text()))) == 3


def test_temporal_reference_mesh(tool, three_poses):
    run = succeeds(tool("temporal", three_poses[0], "--segments", "3",
                        "--reference-mesh", three_poses[0] / "frame_0000.obj"))
    assert "66 frames, 3 segments" in run.output


def test_json_into_missing_folder(tool, scratch):
    run = fails(tool("temporal", scratch / "no-such-tube", "--json", scratch / "no-such-folder" / "x.json"))
    assert re.search(r"cannot write [^\n]*no-such-folder/x.json: the folder [^\n]*no-such-folder does not exist",
                     run.err), run.describe()
    reads_nothing(run)
