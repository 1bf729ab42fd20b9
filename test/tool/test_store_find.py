"""search --clip-index and find over a motion store: `search --clip-index I` is row I of knn-graph
(the same neighbours, values and pruning counts, each pair oriented as the matrix orients it);
`find QUERY --store S` gives the best windows over all the store's clips, a stored clip found whole
in itself and in its copy at 1, the lower index first."""

import re

import pytest

from conftest import fails, succeeds, synth

# Five small tubes moving differently, as frame folders (OBJ); "bend-again" copies "bend", so that
# values tie exactly.
SCHEDULES = {
    "bend": ["10:0", "10:90", "10:"],
    "twice": ["5:0", "5:60", "5:0", "5:60", "5:"],
    "slow": ["5:0", "20:45", "5:"],
    "bend-again": ["10:0", "10:90", "10:"],
    "still": ["8:0", "8:"],
}


@pytest.fixture(scope="session")
def scratch(scratch):
    """This file's own folder in the session's scratch: test_store.py, in the same session, writes
    tubes of the same names and a store of its own under the same names there."""
    folder = scratch / "store-find"
    folder.mkdir(exist_ok=True)
    return folder


@pytest.fixture(scope="session")
def clips(tool, scratch):
    """The tubes' folders, in a fixed order."""
    return [synth(tool, scratch, f"tube-{name}", "--format", "obj", "--rings", "10", "--sectors", "6",
                  "--schedule", *schedule, "--easing", "linear")[0]
            for name, schedule in SCHEDULES.items()]


@pytest.fixture(scope="session")
def store(tool, scratch, clips):
    """A store of the tubes, described once."""
    folder = scratch / "store"
    result = tool("describe", *clips, "--store", folder, "--json", "-").json()
    assert result["clips"] == len(clips)
    return folder


def ranked(values, indices):
    """(index, value) of `indices` by value descending, index ascending: the search's order."""
    return sorted(((i, values[i]) for i in indices), key=lambda p: (-p[1], p[0]))


@pytest.mark.parametrize("k", [1, 3, 10])
def test_search_clip_index_is_the_knn_graph_row(tool, store, clips, k):
    n = len(clips)
    arguments = [a for i in range(n) for a in ("--clip-index", str(i))]
    found = tool("search", "--store", store, *arguments, "-k", str(k), "--json", "-").json()["queries"]
    graph = tool("knn-graph", "--store", store, "-k", str(k), "--json", "-").json()
    matrix = tool("matrix", "--store", store, "--json", "-").json()["similarity"]
    assert [q["clip_index"] for q in found] == list(range(n))
    pruning = {key: 0 for key in graph["pruning"] if key != "pruned_share"}
    for i, query in enumerate(found):
        row = [(e["target"], e["value"]) for e in graph["edges"] if e["source"] == i]
        neighbours = [(m["index"], m["value"]) for m in query["neighbours"]]
        assert neighbours == row, i
        assert neighbours == ranked(matrix[i], [j for j in range(n) if j != i])[:k], i
        assert query["pruning"]["candidates"] == n - 1
        for key in pruning:
            pruning[key] += query["pruning"][key]
    # The graph's counts are the sum of its rows': those of the searches.
    assert pruning == {key: graph["pruning"][key] for key in pruning}


def test_search_clip_index_finds_its_copy_first(tool, store):
    (query,) = tool("search", "--store", store, "--clip-index", "3", "-k", "1", "--json", "-").json()["queries"]
    assert [(m["index"], m["value"]) for m in query["neighbours"]] == [(0, 1.0)]
    out = succeeds(tool("search", "--store", store, "--clip-index", "3", "-k", "1")).out
    assert out.startswith("query ") and "(4 candidates," in out and "  1  1.000  " in out, out


# ---- find QUERY --store S ------------------------------------------------------------------------

def test_find_in_store_finds_the_query_and_its_copy(tool, store, clips):
    frames = [c["frames"] for c in tool("store", "info", store, "--json", "-").json()["clips"]]
    result = tool("find", clips[0], "--store", store, "--count", "2", "--json", "-").json()
    assert result["store"] == str(store) and result["values"] == "descriptions as stored"
    # The query is clip 0, and clip 3 is its copy: both from their first frame, at 1, the lower index
    # first (the still frames at either end align at no cost with fewer or more of themselves).
    assert [(m["clip_index"], m["first"], m["similarity"]) for m in result["matches"]] == [(0, 0, 1.0), (3, 0, 1.0)]
    assert all(frames[0] // 2 <= m["last"] < frames[0] for m in result["matches"])
    assert [m["path"] for m in result["matches"]] == [str(clips[0].resolve()), str(clips[3].resolve())]
    for m in result["matches"]:
        assert m["alignment"][0] == [0, m["first"]] and m["alignment"][-1][1] == m["last"]


def test_find_in_store_ranks_over_all_clips(tool, store, clips):
    result = tool("find", clips[2], "--store", store, "--count", "10", "--json", "-").json()
    matches = result["matches"]
    values = [m["similarity"] for m in matches]
    assert values == sorted(values, reverse=True) and values[0] == 1.0 and matches[0]["clip_index"] == 2
    assert len({m["clip_index"] for m in matches}) > 1
    # Windows of one clip do not overlap.
    for clip in range(len(clips)):
        windows = sorted((m["first"], m["last"]) for m in matches if m["clip_index"] == clip)
        assert all(a[1] < b[0] for a, b in zip(windows, windows[1:])), windows


def test_find_in_store_text(tool, store, clips):
    out = succeeds(tool("find", clips[1], "--store", store, "--count", "1")).out
    assert out.startswith("clip 1  frames 0 to ") and f"similarity 1.000  {clips[1].resolve()}\n" in out, out


def test_find_in_store_takes_one_query(tool, store, clips):
    fails(tool("find", clips[0], clips[1], "--store", store), "find --store takes one input, the query, not 2")
    fails(tool("find", clips[0]), "find takes the query and the long animation, or the query and --store S")
    fails(tool("find", clips[0], "--store", store, "--count", "0"), "--count: must be a whole")


# The summary gives the pruned share to one decimal ("93.3 % pruned"), not a double's 17 digits;
# the JSON keeps every digit.
def test_knn_graph_summary_pruned_share(tool, store):
    run = succeeds(tool("knn-graph", "--store", store, "-k", "1"))
    share = re.search(r"\(([0-9.]+) % pruned before a full alignment\)", run.out)
    assert share and re.fullmatch(r"\d{1,3}\.\d", share.group(1)), run.describe()
    exact = tool("knn-graph", "--store", store, "-k", "1", "--json", "-").json()["pruning"]["pruned_share"]
    assert float(share.group(1)) == pytest.approx(100 * exact, abs=0.05)



# ---- a corrupted store ---------------------------------------------------------------------------

def test_a_flipped_byte_in_a_searched_clip_fails_naming_the_clip(tool, store, scratch):
    """Opening checks the structure; the first read of a clip's signatures checks its block, so a
    search that compares a damaged clip fails naming it rather than answering from it."""
    copy = scratch / "store-flipped"
    copy.mkdir()
    for f in store.iterdir():
        (copy / f.name).write_bytes(f.read_bytes())
    signatures = copy / "signatures-000001.npy"
    data = bytearray(signatures.read_bytes())
    data[data.index(b"\n", 12) + 1] ^= 0x01  # the first value of clip 0 ("bend"), past the .npy header
    signatures.write_bytes(bytes(data))
    named = ("clips-000001.npy: clip 0 (", "tube-bend", "its block's checksum does not match")
    fails(tool("search", "--store", copy, "--clip-index", "1", "-k", "4"), *named)
    fails(tool("matrix", "--store", copy), *named)
    fails(tool("store", "verify", copy), "signatures-000001.npy: its checksum does not match")  # every byte
    succeeds(tool("store", "info", copy))  # which reads no clip's rows
