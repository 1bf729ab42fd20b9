"""File and clip names as they come: a POSIX file name is any bytes, and Latin-1 names are common
in motion libraries. The store keeps them escaped as UTF-8 (a byte of no UTF-8 sequence as \\xHH, a
backslash doubled: store::escaped_name), finds them again by that, and every JSON output names them
so; no command ends in a JSON exception."""

import json
import os
import shutil
import subprocess
import time

import pytest

LATIN1_KNIGHT = os.fsdecode(b"Kn\xe9ight.glb")  # the byte E9, Latin-1's e acute: no UTF-8
LATIN1_BODY = os.fsdecode(b"B\xe4rbarian.glb")  # E4, a umlaut


def run_bytes(*args):
    """Runs the tool with `args` (str, os.PathLike; names of any bytes), its outputs kept as bytes:
    a name of Latin-1 bytes in a progress line is no text of any one encoding."""
    program = os.environ.get("DEFORMSEG_TOOL")
    if not program:
        pytest.fail("DEFORMSEG_TOOL is not set: run these tests through CTest")
    return subprocess.run([program, *map(os.fspath, args)], capture_output=True, timeout=600)


def json_of(*args):
    """The JSON the tool writes to standard output (`--json -`), after it succeeded."""
    completed = run_bytes(*args, "--json", "-")
    assert completed.returncode == 0, completed.stderr.decode(errors="backslashreplace")
    assert b"json.exception" not in completed.stderr
    return json.loads(completed.stdout.decode("utf-8"))


@pytest.fixture(scope="module")
def latin1(characters, tmp_path_factory):
    """A folder holding the Knight and the Barbarian under Latin-1 names."""
    folder = tmp_path_factory.mktemp("latin1")
    if not (characters / "Knight.glb").is_file():
        pytest.skip("the shared characters are not here")
    shutil.copyfile(characters / "Knight.glb", folder / LATIN1_KNIGHT)
    shutil.copyfile(characters / "Barbarian.glb", folder / LATIN1_BODY)
    return folder.resolve()


def kept(path):
    """The store's text for `path`, ASCII but for Latin-1 bytes (the scratch folder's name, and the
    names above): each byte above 7F as \\xHH."""
    return "".join(chr(b) if b < 0x80 else f"\\x{b:02X}" for b in os.fsencode(path))


def strings(value):
    """Every string of a JSON value."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for item in value.values():
            yield from strings(item)
    elif isinstance(value, list):
        for item in value:
            yield from strings(item)


def test_a_latin1_clip_on_a_latin1_body_is_stored_escaped_and_found_again(latin1, tmp_path):
    knight, body = latin1 / LATIN1_KNIGHT, latin1 / LATIN1_BODY
    store = tmp_path / "S"
    name = f"{kept(knight)}#Idle on {kept(body)}"
    report = json_of("describe", f"{knight}#Idle", "--body", body, "--store", store)
    assert report["described"] == [name]
    (record,) = json_of("store", "info", store)["clips"]
    assert (record["path"], record["clip"], record["body"]) == (kept(knight), "Idle", kept(body))
    assert record["input_options"]["body"] == kept(body) and record["topology_path"] == kept(body)
    assert json_of("describe", f"{knight}#Idle", "--body", body, "--store", store)["skipped"] == [name]
    os.utime(body, ns=(time.time_ns(), time.time_ns() + 10**9))  # the body file changed: described again
    assert json_of("describe", f"{knight}#Idle", "--body", body, "--store", store)["redescribed"] == [name]
    found = json_of("search", f"{latin1 / LATIN1_BODY}#Idle", "--store", store, "-k", "1")["queries"][0]
    assert found["query"] == f"{kept(body)}#Idle"
    assert (found["neighbours"][0]["name"], found["neighbours"][0]["value"]) == (name, 1.0)


def test_labels_of_latin1_files_describe_and_evaluate_from_the_store(latin1, characters, tmp_path):
    labels = tmp_path / "labels.csv"
    rows = [(latin1 / LATIN1_KNIGHT, "Idle", "idle"), (latin1 / LATIN1_BODY, "Idle", "idle"),
            (latin1 / LATIN1_KNIGHT, "Walking_A", "walk"), (characters / "Barbarian.glb", "Walking_A", "walk")]
    labels.write_bytes(b"file,clip,motion\n" + b"".join(os.fsencode(f) + f",{c},{m}\n".encode() for f, c, m in rows))
    store = tmp_path / "S"
    described = json_of("describe", labels, "--store", store)["described"]
    assert described[:2] == [f"{kept(latin1 / LATIN1_KNIGHT)}#Idle", f"{kept(latin1 / LATIN1_KNIGHT)}#Walking_A"]
    from_files = json_of("evaluate", labels)
    from_store = json_of("evaluate", labels, "--store", store)
    assert from_store["scores"] == from_files["scores"] and from_store["similarity"] == from_files["similarity"]
    assert from_store["inputs"][0]["file"] == kept(latin1 / LATIN1_KNIGHT)
    graph = json_of("knn-graph", "--store", store, "-k", "1")
    assert graph["clips"][0]["path"] == kept(latin1 / LATIN1_KNIGHT)


def test_json_outputs_name_latin1_inputs_escaped(latin1):
    knight = latin1 / LATIN1_KNIGHT
    matrix = json_of("matrix", f"{knight}#Idle", f"{knight}#Walking_A")
    assert matrix["inputs"] == [f"{kept(knight)}#Idle", f"{kept(knight)}#Walking_A"]
    assert [source["file"] for source in matrix["sources"]] == [kept(knight)] * 2
    assert any(kept(knight) in text for text in strings(json_of("info", f"{knight}#Idle")))


def test_an_unreadable_latin1_file_is_left_out_named(latin1, tmp_path):
    broken = latin1 / os.fsdecode(b"Br\xf6ken.glb")
    broken.write_bytes(b"glTF not really")
    report = json_of("describe", broken, f"{latin1 / LATIN1_KNIGHT}#Idle", "--store", tmp_path / "S",
                     "--skip-unreadable")
    assert len(report["described"]) == 1
    (line,) = report["unreadable"]
    assert line.startswith(kept(broken) + ": ")
    failed = run_bytes("describe", broken, "--store", tmp_path / "S2", "--json", "-")
    assert failed.returncode > 0 and b"json.exception" not in failed.stderr
    assert os.fsencode(broken) in failed.stderr  # the error names the file as it is
