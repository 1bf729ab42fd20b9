"""convert writes each frame format, which reads back as the animation."""

import re

import pytest

from conftest import succeeds

FORMATS = ["off", "ply"]


@pytest.fixture(scope="module")
def converted(tool, scratch, synth_obj):
    """The default tube converted to each format: format -> (folder, run of convert)."""
    runs = {}
    for format in FORMATS:
        folder = scratch / f"convert-{format}"
        runs[format] = (folder, tool("convert", synth_obj[0], folder, "--format", format, "--json", "-"))
    return runs


@pytest.mark.parametrize("format", FORMATS)
def test_convert(converted, format):
    result = converted[format][1].json()
    assert result["frames"] == 41
    assert result["files"][-1].endswith(f"frame_0040.{format}")


@pytest.mark.parametrize("format", FORMATS)
def test_convert_reads_back(tool, converted, format):
    info = tool("info", converted[format][0], "--json", "-").json()
    assert (info["format"], info["frames"], info["vertices"]) == (format, 41, 786)


def test_convert_summary(tool, scratch, synth_obj):
    out = succeeds(tool("convert", synth_obj[0], scratch / "convert-summary", "--format", "off")).out
    assert re.search(r"frames +41\n", out), out
    assert re.search(r"files +41: [^\n]*frame_0000.off \.\.\. [^\n]*frame_0040.off\n", out), out
