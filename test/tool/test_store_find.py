"""search --clip-index and find over a motion store: `search --clip-index I` is row I of knn-graph
(the same neighbours, values and pruning counts, each pair oriented as the matrix orients it)."""

import pytest

from conftest import succeeds, synth

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
    assert out.startswith("query ") and "(4 candidates," in out and "  1  1.0  " in out, out
