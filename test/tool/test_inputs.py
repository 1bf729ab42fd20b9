"""The input options, one set for every command that reads animations (the front end's table):
the same names everywhere, one --topology and one --clip for every input of a command, what each
command's JSON records of its inputs, and `--csv -` printing as `--json -` does."""

import csv
import io
import os
import shutil
import subprocess

import pytest

from conftest import fails, succeeds

INPUT_OPTIONS = ["--clip", "--fps", "--topology", "--triangulate", "--weld", "--no-weld", "--refuse-defects",
                 "--threads"]
READING_COMMANDS = ["info", "convert", "strain", "temporal", "spatiotemporal", "similarity", "matrix", "find", "view",
                    "evaluate"]


@pytest.mark.parametrize("command", READING_COMMANDS)
def test_every_command_takes_the_input_options(tool, command):
    out = succeeds(tool(command, "--help")).out
    for option in INPUT_OPTIONS:
        assert f"  {option} " in out, (command, option)


@pytest.mark.parametrize("option", ["--clip-a", "--clip-b", "--topology-a", "--topology-b"])
def test_no_per_input_options(tool, option):
    assert option not in succeeds(tool("similarity", "--help")).out


@pytest.fixture(scope="session")
def cache(tool, synth_obj, scratch):
    """The default tube as a point cache and its topology mesh."""
    folder = scratch / "cache"
    succeeds(tool("convert", synth_obj[0], folder, "--format", "pc2"))
    return folder / "synth-obj.pc2", folder / "synth-obj.obj"


# One --topology serves every point cache of a two-input command, as it does `matrix`'s.
def test_one_topology_for_both_inputs(tool, cache):
    pc2, topology = cache
    result = tool("similarity", pc2, pc2, "--topology", topology, "--significance", "0", "--json", "-").json()
    assert result["similarity"] == 1
    found = tool("find", pc2, pc2, "--topology", topology, "--json", "-").json()
    assert found["matches"][0]["first"] == 0


def test_point_cache_without_topology(tool, cache):
    fails(tool("similarity", cache[0], cache[0]), "topology")


# The JSON of every command that reads animations records what it read: file, clip and fps.
@pytest.mark.parametrize("command, extra", [
    ("strain", []), ("temporal", []), ("spatiotemporal", []), ("info", []),
    ("similarity", ["SECOND", "--significance", "0"]), ("matrix", ["SECOND"]), ("find", ["SECOND"]),
])
def test_json_records_its_sources(tool, synth_obj, command, extra):
    folder = str(synth_obj[0])
    arguments = [folder if a == "SECOND" else a for a in extra]
    document = tool(command, folder, *arguments, "--fps", "24", "--json", "-").json()
    expected = {"file": folder, "clip": None, "fps": 24}
    assert document["sources"] == [expected] * (2 if "SECOND" in extra else 1)


def test_spatiotemporal_records_its_input(tool, synth_obj):
    assert tool("spatiotemporal", synth_obj[0], "--json", "-").json()["input"] == str(synth_obj[0])


# `--csv -` prints the matrix in the summary's place, as `--json -` prints the JSON.
def test_matrix_csv_to_standard_output(tool, synth_obj, bend_once):
    a, b = str(synth_obj[0]), str(bend_once[0])
    out = succeeds(tool("matrix", a, b, "--csv", "-")).out
    rows = list(csv.reader(io.StringIO(out)))
    assert rows[0] == ["animation", a, b]
    assert [row[0] for row in rows[1:]] == [a, b] and float(rows[1][1]) == 1 and float(rows[2][2]) == 1
    assert rows[1][2] == rows[2][1]


def test_matrix_csv_to_a_file_is_whole(tool, synth_obj, bend_once, scratch):
    path = scratch / "matrix.csv"
    succeeds(tool("matrix", synth_obj[0], bend_once[0], "--csv", path))
    assert len(path.read_text().splitlines()) == 3
    assert not list(scratch.glob("matrix.csv.partial-*"))


# --weld is the glTF reader's default and --no-weld the frame files': each may be said anyway.
def test_weld_default_may_be_said(tool, synth_obj):
    plain = tool("info", synth_obj[0], "--json", "-").json()
    assert tool("info", synth_obj[0], "--no-weld", "--json", "-").json()["vertices"] == plain["vertices"]


def test_absurd_coordinates_are_warned_of_or_refused(tool, scratch, synth_obj):
    # Frame 4 of a copy of the tube has a vertex at 1e20: every path that reads it, whole (info),
    # frame by frame (similarity of frame folders) or into a store (describe), says where it is,
    # and --refuse-defects refuses it; the tube itself gets no warning.
    folder = scratch / "absurd"
    shutil.copytree(synth_obj[0], folder)
    frame = sorted(folder.glob("*.obj"))[4]
    lines = frame.read_text().splitlines()
    first_vertex = next(i for i, line in enumerate(lines) if line.startswith("v "))
    lines[first_vertex] = "v 1e20 0 0"
    frame.write_text("\n".join(lines) + "\n")
    where = "frame 4 vertex 0 lies 1e+20 from the frame's middle"
    assert "warning" not in succeeds(tool("info", synth_obj[0])).err
    run = succeeds(tool("info", folder))
    assert f"warning: {folder}: {where}" in run.err and "(in 1 frame(s)): corrupt coordinates?" in run.err
    fails(tool("info", folder, "--refuse-defects"), where, "corrupt coordinates")
    run = succeeds(tool("similarity", synth_obj[0], folder, "--significance", "0"))
    assert "each described frame by frame" in run.err and where in run.err
    fails(tool("similarity", synth_obj[0], folder, "--refuse-defects"), where)
    run = succeeds(tool("describe", folder, "--store", scratch / "store-absurd"))
    assert f"warning: {folder.resolve()}: {where}" in run.err
    fails(tool("describe", folder, "--store", scratch / "store-absurd-refused", "--refuse-defects"), where)


# A damaged file's bytes (E9, a Latin-1 e acute; 1B, a terminal's escape) reach the message as
# \xHH: standard error is printable UTF-8, whatever the file holds.
def test_damaged_file_bytes_are_escaped(scratch):
    damaged = scratch / "damaged.obj"
    damaged.write_bytes(b"v 0 0 0\nv 1 0 0\nv\xe9\x1b[2J 0 1 0\nf 1 2 3\n")
    run = subprocess.run([os.environ["DEFORMSEG_TOOL"], "info", str(damaged)], capture_output=True)
    assert run.returncode == 1, run
    assert b'damaged.obj:3: frame 0: unknown OBJ statement "v\\xE9\\x1B[2J"' in run.stderr, run.stderr
    assert b"\xe9" not in run.stderr and b"\x1b" not in run.stderr, run.stderr
    run.stderr.decode("utf-8")  # strict: no invalid sequence
