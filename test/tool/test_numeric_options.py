"""Every numeric option of every command, fed -1, 0 and a huge value: each value outside the range
the option's help gives is refused as the command line is read, naming the option and its range;
each value inside it passes that check. The help of every numeric option gives its range, and a
count or an index never reaches below 0 or to infinity."""

import re

import pytest

from conftest import fails

# An option of CLI11's help: its spelling, then its type and the checks' descriptions after ':',
# a default after '=', ' ...' or ' x N' for several values; the help text follows after two spaces.
SPEC = re.compile(r"^(?:-[a-zA-Z], )?(-{1,2}[a-z][a-z-]*) (UINT|INT|FLOAT)\b")
RANGE = re.compile(r":in ([\[(])([^\s,]+), ([^\s\])]+)([\])])")
HUGE = {"UINT": "100000000000000000000", "INT": "100000000000000000000", "FLOAT": "1e300"}


def commands(tool):
    """Every command's words, sub-commands of sub-commands too (store info)."""
    found = []

    def walk(words):
        text = tool(*words, "--help").out
        subcommands = re.findall(r"^  ([a-z][a-z-]*)\s", text.split("Subcommands:")[1], re.M) if "Subcommands:" in text else []
        if words:
            found.append((words, text))
        for name in subcommands:
            walk(words + [name])

    walk([])
    return found


def numeric_options(tool):
    """(command words, option, type, range (low, high, low closed, high closed), values per use)."""
    options = []
    for words, text in commands(tool):
        for line in text.splitlines():
            spec = re.split(r"\s{2,}", line.strip())[0]
            m = SPEC.match(spec)
            if not m or m.group(1) == "--help":
                continue
            name, kind = m.group(1), m.group(2)
            described = RANGE.search(spec)
            assert described, f"{' '.join(words)} {name}: the help gives no range: {line.strip()}"
            bounds = (float(described.group(2)), float(described.group(3)), described.group(1) == "[",
                      described.group(4) == "]")
            repeat = re.search(r" x (\d+)$", spec)
            options.append((words, name, kind, bounds, int(repeat.group(1)) if repeat else 1))
    return options


def in_range(value, kind, bounds):
    low, high, low_closed, high_closed = bounds
    if kind != "FLOAT" and value != int(value):
        return False
    return (value >= low if low_closed else value > low) and (value <= high if high_closed else value < high)


def test_every_numeric_option_gives_its_range(tool):
    options = numeric_options(tool)
    assert len(options) >= 40, options  # every command's options were found
    for words, name, kind, (low, high, _, _), _ in options:
        if kind == "UINT":
            assert low >= 0, f"{' '.join(words)} {name}: a count or an index from {low}"
        if kind in ("UINT", "INT"):
            assert high < float("inf"), f"{' '.join(words)} {name}: a count or an index without a bound"


@pytest.mark.parametrize("value", ["-1", "0", "huge"])
def test_every_numeric_option_refuses_what_its_range_does_not_hold(tool, value):
    for words, name, kind, bounds, repeat in numeric_options(tool):
        given = HUGE[kind] if value == "huge" else value
        run = tool(*words, name, ",".join([given] * repeat))
        refusal = f"{name}: must be"
        if in_range(float(given), kind, bounds):
            assert refusal not in run.err, run.describe()
        else:
            fails(run, refusal, "got")
            assert "reading" not in run.output, run.describe()  # refused before any work
