"""describe, search, knn-graph, store info/verify, and matrix and evaluate over a motion store: the
store's values are those matrix and evaluate give from the files, bit for bit; unchanged clips are
skipped, changed ones described again at their index; a damaged store is named; a describe killed
half way leaves the store as it was."""

import csv as csv_module
import os
import shutil
import signal
import subprocess
import time

import pytest

from conftest import fails, matches_all, succeeds, synth

# Four small tubes moving differently, as frame folders (OBJ).
SCHEDULES = {
    "bend": ["10:0", "10:90", "10:"],
    "twice": ["5:0", "5:60", "5:0", "5:60", "5:"],
    "slow": ["5:0", "20:45", "5:"],
    "still": ["8:0", "8:"],
}


@pytest.fixture(scope="session")
def clips(tool, scratch):
    """The four tubes' folders, in a fixed order."""
    return [synth(tool, scratch, f"tube-{name}", "--format", "obj", "--rings", "10", "--sectors", "6",
                  "--schedule", *schedule, "--easing", "linear")[0]
            for name, schedule in SCHEDULES.items()]


def describe(tool, store, *inputs, extra=()):
    return tool("describe", *inputs, "--store", store, *extra, "--json", "-").json()


def store_info(tool, store):
    return tool("store", "info", store, "--json", "-").json()


def ranked(values, indices):
    """(index, value) of `indices` by value descending, index ascending: the search's order."""
    return sorted(((i, values[i]) for i in indices), key=lambda p: (-p[1], p[0]))


@pytest.fixture(scope="session")
def store(tool, scratch, clips):
    """A store of the four tubes, described once."""
    folder = scratch / "store"
    result = describe(tool, folder, *clips)
    assert len(result["described"]) == 4 and result["skipped"] == [] and result["clips"] == 4
    return folder


def test_search_equals_matrix(tool, store, clips):
    # The query first, then the store's clips in their order: row 0 is the query against each.
    matrix = tool("matrix", clips[1], *clips, "--json", "-").json()["similarity"]
    found = tool("search", clips[1], "--store", store, "-k", "10", "--json", "-").json()
    (query,) = found["queries"]
    expected = ranked({j - 1: matrix[0][j] for j in range(1, 5)}, range(4))
    assert [(n["index"], n["value"]) for n in query["neighbours"]] == expected
    assert [n["path"] for n in query["neighbours"]] == [str(clips[i].resolve()) for i, _ in expected]
    assert query["pruning"]["candidates"] == 4


def test_search_clip_index_leaves_itself_out(tool, store):
    matrix = tool("matrix", "--store", store, "--json", "-").json()["similarity"]
    found = tool("search", "--store", store, "--clip-index", "0", "-k", "2", "--json", "-").json()
    (query,) = found["queries"]
    assert query["clip_index"] == 0
    assert [(n["index"], n["value"]) for n in query["neighbours"]] == ranked(matrix[0], range(1, 4))[:2]


def test_search_text(tool, store, clips):
    out = succeeds(tool("search", clips[0], "--store", store, "-k", "2")).out
    assert out.startswith(f"query {clips[0]}") and f"  1  1.000  {clips[0].resolve()}" in out, out


def test_search_needs_a_query(tool, store):
    fails(tool("search", "--store", store), "search needs a query")
    fails(tool("search", "--store", store, "--clip-index", "9"), "--clip-index 9: the store holds 4 clips")


def test_matrix_store_equals_matrix_of_files(tool, store, clips):
    from_files = tool("matrix", *clips, "--json", "-").json()
    from_store = tool("matrix", "--store", store, "--json", "-").json()
    assert from_store["similarity"] == from_files["similarity"]
    assert from_store["inputs"] == [str(c.resolve()) for c in clips]


def test_matrix_store_or_inputs(tool, store, clips):
    fails(tool("matrix", *clips, "--store", store), "not both")
    fails(tool("matrix", "--store", store, "--policy", "histogram"), "a motion store holds the motion signatures")


def test_knn_graph_equals_brute_force(tool, scratch, store):
    matrix = tool("matrix", "--store", store, "--json", "-").json()["similarity"]
    graph = tool("knn-graph", "--store", store, "-k", "2", "--json", "-").json()
    edges = [(e["source"], e["target"], e["rank"], e["value"]) for e in graph["edges"]]
    expected = [(i, j, r + 1, v) for i in range(4)
                for r, (j, v) in enumerate(ranked(matrix[i], [j for j in range(4) if j != i])[:2])]
    assert edges == expected
    csv = scratch / "edges.csv"
    succeeds(tool("knn-graph", "--store", store, "-k", "2", "--csv", csv))
    lines = csv.read_text().splitlines()
    assert lines[0] == "source,target,rank,value,source_name,target_name" and len(lines) == 9
    rows = list(csv_module.reader(lines[1:]))
    assert [tuple(map(float, row[:4])) for row in rows] == [tuple(map(float, e)) for e in edges]
    names = [c["name"] for c in graph["clips"]]
    assert [(row[4], row[5]) for row in rows] == [(names[e[0]], names[e[1]]) for e in edges]


def test_describe_again_skips_everything(tool, store, clips):
    result = describe(tool, store, *clips)
    assert result["described"] == [] and result["redescribed"] == [] and len(result["skipped"]) == 4


def test_changed_clip_described_again_at_its_index(tool, scratch, clips):
    folder = scratch / "store-changed"
    copies = []
    for k, clip in enumerate(clips[:3]):
        copies.append(scratch / f"copy-{k}")
        shutil.copytree(clip, copies[-1])
    describe(tool, folder, *copies)
    before = store_info(tool, folder)
    frame = sorted(copies[1].iterdir())[0]
    stamp = frame.stat()
    os.utime(frame, ns=(stamp.st_atime_ns, stamp.st_mtime_ns + 1_000_000_000))  # touched
    result = describe(tool, folder, *copies)
    assert result["redescribed"] == [str(copies[1].resolve())] and len(result["skipped"]) == 2
    after = store_info(tool, folder)
    assert [c["path"] for c in after["clips"]] == [c["path"] for c in before["clips"]]
    assert after["clips"][1]["source_mtime_ns"] != before["clips"][1]["source_mtime_ns"]
    # --hash: the clips described without a hash are described again once, then only a change counts.
    assert len(describe(tool, folder, *copies, extra=["--hash"])["redescribed"]) == 3
    os.utime(frame, ns=(stamp.st_atime_ns, stamp.st_mtime_ns + 2_000_000_000))
    assert len(describe(tool, folder, *copies, extra=["--hash"])["skipped"]) == 3
    shutil.copy(sorted(clips[3].iterdir())[0], frame)  # another frame's geometry: changed bytes
    result = describe(tool, folder, *copies, extra=["--hash"])
    assert result["redescribed"] == [str(copies[1].resolve())]
    # A new clip comes at the end.
    result = describe(tool, folder, *copies, clips[3])
    assert result["described"] == [str(clips[3].resolve())] and result["clips"] == 4


def broken_copy(scratch, clip, name="broken"):
    """A copy of the frame folder `clip` whose fourth frame cannot be read."""
    broken = scratch / name
    shutil.copytree(clip, broken)
    sorted(broken.iterdir())[3].write_text("v 1 2\n")
    return broken


def test_unreadable_clip_leaves_the_store(tool, scratch, store, clips):
    manifest = (store / "store.json").read_bytes()
    broken = broken_copy(scratch, clips[0])
    fails(tool("describe", *clips, broken, "--store", store), "broken", "--skip-unreadable")
    assert (store / "store.json").read_bytes() == manifest


def test_a_run_that_produces_nothing_fails(tool, scratch, clips):
    # Every input unreadable: the run says so on one line and exits 1, whatever --skip-unreadable.
    broken = [broken_copy(scratch, clips[k], f"nothing-{k}") for k in range(2)]
    folder = scratch / "store-nothing"
    run = fails(tool("describe", *broken, "--store", folder, "--skip-unreadable"),
                "deformseg: error: ", "nothing described: every input was unreadable (2)")
    assert "unreadable   2" in run.out
    # A store of no clip has no graph to give, as it has no neighbour to search.
    fails(tool("knn-graph", "--store", folder, "-k", "1"), "the store holds no clip")
    # Unchanged clips skipped are a store that holds them: not a failure.
    succeeds(tool("describe", clips[0], "--store", scratch / "store-again"))
    succeeds(tool("describe", clips[0], "--store", scratch / "store-again"))


def copies_of(scratch, clips, name, count):
    """`count` copies of the four tubes' folders, in turn: as many clips to describe."""
    folders = []
    for k in range(count):
        folders.append(scratch / f"{name}-{k}")
        if not folders[-1].exists():
            shutil.copytree(clips[k % 4], folders[-1])
    return folders


def stored_names(tool, folder):
    return [clip["path"] for clip in store_info(tool, folder)["clips"]]


def test_bad_input_in_the_middle_keeps_every_other_clip(tool, scratch, clips):
    # 100 clips with an unreadable one after the 70th: the run stops there with the 70 before it
    # committed (64 at the first commit, 6 when it stops); --skip-unreadable then adds the 30 after
    # it, each once.
    inputs = copies_of(scratch, clips, "middle", 100)
    inputs.insert(70, broken_copy(scratch, clips[1], "middle-broken"))
    folder = scratch / "store-middle"
    fails(tool("describe", *inputs, "--store", folder, "--threads", "2"), "middle-broken",
          "the 70 clip(s) described before it are in the store")
    expected = [str(f.resolve()) for f in inputs]
    assert stored_names(tool, folder) == expected[:70]
    result = tool("describe", *inputs, "--store", folder, "--skip-unreadable", "--json", "-")
    assert "left out " + str(inputs[70].resolve()) in result.err
    report = result.json()
    assert len(report["skipped"]) == 70 and len(report["described"]) == 30 and report["clips"] == 100
    assert [line.split(": ")[0] for line in report["unreadable"]] == [expected[70]]
    assert stored_names(tool, folder) == expected[:70] + expected[71:]
    succeeds(tool("store", "verify", folder))


def test_describe_reports_each_clip(tool, scratch, clips):
    run = succeeds(tool("describe", *clips, "--store", scratch / "store-progress"))
    for done in range(1, 5):
        matches_all(run.err, rf"described {done} of 4: .*tube-\w+ \(\d+ frames\); [\d.]+ clips/s, \d+ frames/s, "
                             r"about \d+ (s|min \d+ s) left")


def test_killed_describe_keeps_what_it_committed(tool, scratch, clips):
    # Killed after its first commit (64 clips): those stay, and a second run describes the rest.
    folder = scratch / "store-killed-later"
    inputs = copies_of(scratch, clips, "later", 400)
    process = subprocess.Popen([os.environ["DEFORMSEG_TOOL"], "describe", *map(str, inputs), "--store", str(folder),
                                "--threads", "1"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        while process.poll() is None and not (folder / "store.json").exists():
            time.sleep(0.002)  # polling, not an assertion
        assert process.poll() is None, "the describe ended before its first commit"
        process.send_signal(signal.SIGKILL)
    finally:
        process.wait()
    kept = stored_names(tool, folder)
    assert len(kept) % 64 == 0 and 64 <= len(kept) < 400
    assert kept == [str(f.resolve()) for f in inputs[: len(kept)]]
    result = describe(tool, folder, *inputs)
    assert len(result["skipped"]) == len(kept) and len(result["described"]) == 400 - len(kept)
    assert stored_names(tool, folder) == [str(f.resolve()) for f in inputs]
    succeeds(tool("store", "verify", folder))


def store_files(folder):
    """Every file of a store (but its lock) by name, with its bytes."""
    return {f.name: f.read_bytes() for f in folder.iterdir() if f.name != "lock"}


@pytest.fixture(scope="session")
def caches(tool, scratch):
    """Two PC2 tubes of one mesh moving differently, and that mesh (their topology)."""
    folders = [synth(tool, scratch, f"cache-{k}", "--format", "pc2", "--rings", "10", "--sectors", "6",
                     "--schedule", *schedule)[0] for k, schedule in enumerate([["6:0", "6:70", "6:"],
                                                                               ["4:0", "9:40", "3:"]])]
    return [folder / "tube.pc2" for folder in folders], folders[0] / "tube.obj"


def describe_both(tool, folder, frames, caches, extra=()):
    """Describes the frame folders, then the point caches with their topology, into `folder`."""
    describe(tool, folder, *frames, extra=extra)
    return describe(tool, folder, *caches[0], extra=["--topology", caches[1], *extra])


def test_describe_threads_give_the_same_store(tool, scratch, clips, caches):
    # More clips than a batch (32), of two formats: every file of the store, clip table and
    # manifest included, is the same described on 1 thread or on 2.
    many = []
    for k in range(36):
        many.append(scratch / f"threads-{k}")
        shutil.copytree(clips[k % 4], many[-1])
    stores = [scratch / f"store-threads-{n}" for n in (1, 2)]
    for n, folder in zip((1, 2), stores):
        assert describe_both(tool, folder, [*many, *clips], caches, extra=["--threads", str(n)])["clips"] == 42
    one, two = store_files(stores[0]), store_files(stores[1])
    assert sorted(one) == sorted(two) and any(name.startswith("signatures-") for name in one)
    assert [name for name in one if one[name] != two[name]] == []


def test_describe_streamed_equals_read_whole(tool, scratch, clips, caches):
    # Frames and point caches are read frame by frame, unless welded (then read whole); the tubes
    # have no vertices to weld: the signatures, frames and summaries are the same bytes either way,
    # and matrix --store gives matrix's values from the files.
    streamed, whole = scratch / "store-streamed", scratch / "store-whole"
    describe_both(tool, streamed, clips, caches)
    describe_both(tool, whole, clips, caches, extra=["--weld"])
    one, two = store_files(streamed), store_files(whole)
    data = [name for name in one if name.startswith(("signatures-", "frames-", "summaries-"))]
    assert len(data) == 6 and [name for name in data if one[name] != two[name]] == []
    assert all(one[name] != two[name] for name in one if name.startswith("clips-"))  # the weld option recorded
    cached = scratch / "store-caches"
    describe(tool, cached, *caches[0], extra=["--topology", caches[1]])
    from_files = tool("matrix", *caches[0], "--topology", caches[1], "--json", "-").json()["similarity"]
    assert tool("matrix", "--store", cached, "--json", "-").json()["similarity"] == from_files


def test_describe_errors_name_the_clip(tool, scratch, clips, caches):
    # A frame that cannot be read is named once, by its file and frame; a folder of one frame, by
    # the folder, and a point cache without topology, as when read whole.
    broken = scratch / "broken-stream"
    shutil.copytree(clips[1], broken)
    frame = sorted(broken.iterdir())[5]
    frame.write_text("v 1 2\n")
    run = fails(tool("describe", broken, "--store", scratch / "store-errors"), f"{frame}:", "frame 5")
    (error,) = [line for line in run.err.splitlines() if "error:" in line]
    assert error.count(str(broken)) == 1, run.err
    single = scratch / "one-frame"
    single.mkdir()
    shutil.copy(sorted(clips[0].iterdir())[0], single)
    fails(tool("describe", single, "--store", scratch / "store-errors"), str(single.resolve()),
          "an animation of 1 frame: a motion needs at least 2")
    fails(tool("describe", caches[0][0], "--store", scratch / "store-errors"),
          f"{caches[0][0]}: a .pc2 point cache needs a topology mesh")
    assert not (scratch / "store-errors" / "store.json").exists()


@pytest.mark.parametrize("command", ["describe", "search"])
def test_input_options(tool, command):
    out = succeeds(tool(command, "--help")).out
    for option in ["--clip", "--fps", "--topology", "--triangulate", "--weld", "--no-weld", "--refuse-defects",
                   "--threads"]:
        assert f"  {option} " in out, (command, option)


def test_store_info(tool, store):
    info = store_info(tool, store)
    assert len(info["clips"]) == 4 and info["description"]["policy"] == "motion-signature"
    assert info["description"]["up"] == [0.0, 1.0, 0.0] and info["description"]["width"] == info["width"] == 64
    assert info["summary_layout"] == {"kind": "motion-summary", "chunks": 4}


# A store described with --bands 3 says so, and searches, the matrix and evaluate use its bands:
# the search equals the banded matrix of the files; other bands asked are refused naming the store.
def test_store_of_height_bands(tool, scratch, clips):
    folder = scratch / "store-bands"
    assert len(describe(tool, folder, *clips, extra=("--bands", "3", "--up", "+z"))["described"]) == 4
    info = store_info(tool, folder)
    assert info["description"]["bands"] == 3 and info["width"] == 3 * 64
    matrix = tool("matrix", clips[1], *clips, "--bands", "3", "--up", "+z", "--json", "-").json()["similarity"]
    (query,) = tool("search", clips[1], "--store", folder, "-k", "10", "--json", "-").json()["queries"]
    expected = ranked({j - 1: matrix[0][j] for j in range(1, 5)}, range(4))
    assert [(n["index"], n["value"]) for n in query["neighbours"]] == expected
    assert tool("matrix", "--store", folder, "--json", "-").json()["similarity"] == \
        [row[1:] for row in matrix[1:]]
    fails(tool("matrix", "--store", folder, "--bands", "1"), "--bands 1 differs from the store's 3")
    fails(tool("describe", *clips, "--store", folder), "described with other options")


# A store described with --sides records them; other sides asked are refused naming the store.
def test_store_of_sides(tool, scratch, clips):
    folder = scratch / "store-sides"
    assert len(describe(tool, folder, *clips, extra=("--sides", "+x"))["described"]) == 4
    info = store_info(tool, folder)
    assert info["description"]["sides"] == [1.0, 0.0, 0.0] and info["width"] == 2 * 64
    matrix = tool("matrix", *clips, "--sides", "+x", "--json", "-").json()["similarity"]
    assert tool("matrix", "--store", folder, "--sides", "+x", "--json", "-").json()["similarity"] == matrix
    fails(tool("matrix", "--store", folder, "--sides", "-x"), "--sides -x differs from the store's sides")


def test_store_verify_names_the_damaged_file(tool, scratch, store):
    assert "ok: 4 clips" in succeeds(tool("store", "verify", store)).out
    damaged = scratch / "store-damaged"
    shutil.copytree(store, damaged)
    (data,) = [f for f in damaged.iterdir() if f.name.startswith("signatures-")]
    content = bytearray(data.read_bytes())
    content[-5] ^= 0x40
    data.write_bytes(bytes(content))
    fails(tool("store", "verify", damaged), data.name)


def test_store_verify_not_a_store(tool, scratch):
    fails(tool("store", "verify", scratch / "no-such-store"), "no-such-store")


def data_files(folder):
    """The names of the store's data files and tables, written or being written (.partial)."""
    kinds = ("signatures-", "frames-", "summaries-", "clips-", "strings-", "store.json.partial")
    return {f.name for f in folder.iterdir() if f.name.startswith(kinds)}


def test_killed_describe_leaves_the_store(tool, scratch, clips):
    folder = scratch / "store-killed"
    describe(tool, folder, clips[0])
    manifest = (folder / "store.json").read_bytes()
    info = store_info(tool, folder)
    listed = data_files(folder)
    many = []
    for k in range(40):  # many clips: the describe is still running when its first new file appears
        many.append(scratch / f"many-{k}")
        shutil.copytree(clips[k % 4], many[-1])
    process = subprocess.Popen([os.environ["DEFORMSEG_TOOL"], "describe", *map(str, many), "--store", str(folder)],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        while process.poll() is None and data_files(folder) <= listed:
            time.sleep(0.002)  # polling, not an assertion
        assert process.poll() is None, "the describe ended before a new file appeared"
        process.send_signal(signal.SIGKILL)
    finally:
        process.wait()
    assert process.returncode == -signal.SIGKILL
    assert (folder / "store.json").read_bytes() == manifest
    assert store_info(tool, folder) == info
    result = describe(tool, folder, *many)
    assert len(result["described"]) == 40 and result["clips"] == 41


def write_labels(path, rows):
    path.write_text("file,clip,motion\n" + "".join(f"{file},{clip},{motion}\n" for file, clip, motion in rows))
    return path


def evaluate_figures(run):
    result = run.json()
    return result["scores"], result["similarity"]


def test_evaluate_store_equals_evaluate_of_files(tool, scratch, clips):
    labels = write_labels(scratch / "labels.csv", [(c, "", m) for c, m in zip(clips, ["a", "a", "b", "b"])])
    folder = scratch / "store-labels"
    assert len(describe(tool, folder, labels)["described"]) == 4
    from_files = evaluate_figures(tool("evaluate", labels, "--json", "-"))
    from_store = evaluate_figures(tool("evaluate", labels, "--store", folder, "--json", "-"))
    assert from_store == from_files


def test_evaluate_store_missing_clip(tool, scratch, clips):
    labels = write_labels(scratch / "labels-2.csv", [(c, "", m) for c, m in zip(clips, ["a", "a", "b", "b"])])
    folder = scratch / "store-partial"
    describe(tool, folder, *clips[:2])
    fails(tool("evaluate", labels, "--store", folder), "2 missing", f"deformseg describe {labels} --store {folder}")


def test_evaluate_store_shared_characters(tool, scratch, characters):
    # Interleaved: evaluate reads each file's rows together, and the store's matrix follows that order.
    rows = [("Knight.glb", "Walking_A", "walk"), ("Mage.glb", "Walking_A", "walk"),
            ("Knight.glb", "Running_A", "run"), ("Mage.glb", "Running_A", "run")]
    if not all((characters / f).is_file() for f, _, _ in rows):
        pytest.skip("the shared characters are not all here")
    labels = write_labels(scratch / "characters.csv", [(characters / f, c, m) for f, c, m in rows])
    folder = scratch / "store-characters"
    assert len(describe(tool, folder, labels)["described"]) == 4
    from_files = evaluate_figures(tool("evaluate", labels, "--json", "-"))
    from_store = evaluate_figures(tool("evaluate", labels, "--store", folder, "--json", "-"))
    assert from_store == from_files
    # Every clip of a glTF file when none is named: the Knight's clips include the two above.
    knight = describe(tool, folder, characters / "Knight.glb")
    assert len(knight["skipped"]) == 2 and len(knight["described"]) > 2
    assert knight["poses_left_out"] and all(p.startswith(str((characters / "Knight.glb").resolve()) + "#")
                                            for p in knight["poses_left_out"])


def test_evaluate_store_changed_clip(tool, scratch, clips):
    copies = []
    for k, clip in enumerate(clips):
        copies.append(scratch / f"evaluated-{k}")
        shutil.copytree(clip, copies[-1])
    labels = write_labels(scratch / "labels-3.csv", [(c, "", m) for c, m in zip(copies, ["a", "a", "b", "b"])])
    folder = scratch / "store-stale"
    describe(tool, folder, labels)
    frame = sorted(copies[2].iterdir())[0]
    shutil.copy(sorted(clips[0].iterdir())[0], frame)  # changed bytes, size and time
    fails(tool("evaluate", labels, "--store", folder), "1 changed since described", str(copies[2].resolve()))
    assert describe(tool, folder, labels)["redescribed"] == [str(copies[2].resolve())]
    succeeds(tool("evaluate", labels, "--store", folder))


def test_describe_labels_with_body_files(tool, scratch, characters):
    # A labels row's body_file is the body its clip plays on: the Knight's Idle on the Barbarian's
    # body is the Barbarian's Idle, its Walking_A on the Rogue's the Rogue's; each record names its body.
    knight, barbarian, rogue = (characters / f"{name}.glb" for name in ("Knight", "Barbarian", "Rogue"))
    labels = scratch / "labels-bodies.csv"
    labels.write_text(f"file,clip,motion,body_file\n{knight},Idle,idle,{barbarian}\n"
                      f"{knight},Walking_A,walk,{rogue}\n")
    folder = scratch / "store-body-files"
    assert len(describe(tool, folder, labels)["described"]) == 2
    bodies = {record["clip"]: record["input_options"]["body"] for record in store_info(tool, folder)["clips"]}
    assert bodies == {"Idle": str(barbarian.resolve()), "Walking_A": str(rogue.resolve())}
    for query, clip in [(f"{barbarian}#Idle", "Idle"), (f"{rogue}#Walking_A", "Walking_A")]:
        found = tool("search", query, "--store", folder, "-k", "1", "--json", "-").json()["queries"][0]["neighbours"][0]
        assert found["value"] == 1.0 and found["clip"] == clip
    assert describe(tool, folder, labels)["skipped"] == [f"{knight.resolve()}#Idle on {barbarian.resolve()}",
                                                         f"{knight.resolve()}#Walking_A on {rogue.resolve()}"]


def test_one_clip_on_two_bodies_is_two_clips(tool, scratch, characters):
    # The Knight's clips played on the Barbarian's body and on its own, a row per body, as a library
    # of animation-only clips lists them: each clip once per body in the store, found, searched,
    # evaluated and reported with its body.
    knight, barbarian = characters / "Knight.glb", scratch / "two-bodies-Barbarian.glb"
    shutil.copyfile(characters / "Barbarian.glb", barbarian)
    rows = [(knight, "Idle", "idle", barbarian), (knight, "Idle", "idle", knight),
            (knight, "Walking_A", "walk", barbarian), (knight, "Walking_A", "walk", knight),
            (characters / "Barbarian.glb", "Idle", "idle", "")]
    labels = scratch / "labels-two-bodies.csv"
    labels.write_text("file,clip,motion,body_file\n" + "".join(f"{f},{c},{m},{b}\n" for f, c, m, b in rows))
    folder = scratch / "store-two-bodies"
    on = {body: f" on {body.resolve()}" for body in (knight, barbarian)}
    described = describe(tool, folder, labels)["described"]
    assert described == [f"{knight.resolve()}#{clip}{on[body]}" for _, clip, _, body in rows[:4]] + \
        [f"{(characters / 'Barbarian.glb').resolve()}#Idle"]
    clips = store_info(tool, folder)["clips"]
    assert [(c["clip"], c["body"]) for c in clips] == [(clip, str(body.resolve()) if body else "")
                                                       for _, clip, _, body in rows]
    # The Barbarian's Idle is the Knight's Idle on the Barbarian's body: found first, at 1, named with it.
    found = tool("search", f"{characters / 'Barbarian.glb'}#Idle", "--store", folder, "-k", "5", "--json", "-")
    neighbours = found.json()["queries"][0]["neighbours"]
    assert len(neighbours) == 5
    assert {(n["clip"], n["body"]) for n in neighbours} == {(c["clip"], c["body"]) for c in clips}
    best = [n for n in neighbours if n["value"] == 1.0]
    assert {(n["path"], n["clip"], n["body"]) for n in best} >= {(str(knight.resolve()), "Idle", str(barbarian.resolve()))}
    text = succeeds(tool("search", f"{characters / 'Barbarian.glb'}#Idle", "--store", folder, "-k", "5")).output
    assert f"{knight.resolve()}#Idle{on[barbarian]}" in text and f"{knight.resolve()}#Idle{on[knight]}" in text
    # evaluate --store compares the five, as evaluate of the files does.
    from_files = evaluate_figures(tool("evaluate", labels, "--json", "-"))
    from_store = evaluate_figures(tool("evaluate", labels, "--store", folder, "--json", "-"))
    assert from_store == from_files
    graph = tool("knn-graph", "--store", folder, "-k", "1", "--json", "-").json()
    assert [c["body"] for c in graph["clips"]] == [c["body"] for c in clips]
    assert {e["source_body"] for e in graph["edges"]} == {c["body"] for c in clips}
    edges = succeeds(tool("knn-graph", "--store", folder, "-k", "1", "--csv", "-")).output
    assert f"{knight.resolve()}#Walking_A{on[barbarian]}" in edges
    # Unchanged, skipped; the Barbarian's body touched, only the clips played on it described again.
    assert len(describe(tool, folder, labels)["skipped"]) == 5
    os.utime(barbarian, ns=(time.time_ns(), time.time_ns() + 10**9))
    assert describe(tool, folder, labels)["redescribed"] == [f"{knight.resolve()}#{clip}{on[barbarian]}"
                                                             for clip in ("Idle", "Walking_A")]
    succeeds(tool("evaluate", labels, "--store", folder))


def test_describe_with_a_body(tool, scratch, characters):
    # The Knight's Idle on the Barbarian's body is the Barbarian's Idle: found at 1; the store
    # records the body, and a body changed since describes the clip again.
    body = scratch / "body-Barbarian.glb"
    shutil.copyfile(characters / "Barbarian.glb", body)
    folder = scratch / "store-body"
    clip = f"{characters / 'Knight.glb'}#Idle"
    assert len(describe(tool, folder, clip, extra=["--body", body])["described"]) == 1
    (record,) = store_info(tool, folder)["clips"]
    assert record["input_options"]["body"] == str(body.resolve())
    found = tool("search", f"{characters / 'Barbarian.glb'}#Idle", "--store", folder, "-k", "1", "--json", "-")
    assert found.json()["queries"][0]["neighbours"][0]["value"] == 1.0
    assert record["body"] == str(body.resolve())
    named = f"{record['path']}#Idle on {body.resolve()}"
    assert describe(tool, folder, clip, extra=["--body", body])["skipped"] == [named]
    os.utime(body, ns=(time.time_ns(), time.time_ns() + 10**9))
    assert describe(tool, folder, clip, extra=["--body", body])["redescribed"] == [named]
