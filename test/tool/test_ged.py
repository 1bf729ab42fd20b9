"""ged and ged-matrix between user graphs (test/tool/graphs: a path x-y-x in DOT, a triangle x-y-z
in GraphML, a ring x-y-x-y in .gv): path-triangle 2, path-ring 3, triangle-ring 5 (bound 3)."""

import json
import re

from conftest import GRAPHS, fails, succeeds

PATH = GRAPHS / "path.dot"
TRIANGLE = GRAPHS / "triangle.graphml"
RING = GRAPHS / "ring.gv"


def test_ged_exact(tool):
    result = tool("ged", PATH, TRIANGLE, "--json", "-").json()
    assert result["distance"] == 2.0 and result["exact"] is True
    assert result["lower"] == 2.0 and result["upper"] == 2.0
    assert result["mapping"][0] == [0, 0]


def test_ged_exact_ring(tool):
    result = tool("ged", TRIANGLE, RING, "--json", "-").json()
    assert result["distance"] == 5.0 and result["exact"] is True and result["nodes"] == [3, 4]


def test_ged_bipartite(tool):
    result = tool("ged", PATH, RING, "--method", "bipartite", "--json", "-").json()
    assert result["distance"] == 3.0 and result["exact"] is False and result["upper"] == 3.0


def test_ged_lower(tool):
    result = tool("ged", TRIANGLE, RING, "--method", "lower", "--json", "-").json()
    assert result["distance"] == 3.0 and result["lower"] == 3.0
    assert result["upper"] is None and result["mapping"] == []


def test_ged_limit(tool):
    result = tool("ged", TRIANGLE, RING, "--max-expanded", "0", "--json", "-").json()
    assert result["exact"] is False and result["lower"] == 3.0 and result["upper"] == 5.0


# The one rule of outputs: the summary on standard output, the JSON in the file as well.
def test_ged_json_file(tool, scratch):
    run = succeeds(tool("ged", RING, PATH, "--json", scratch / "ged.json"))
    assert re.search(r"distance +3 \(exact\)\n", run.out) and re.search(r"mapping +0->0 1->deleted", run.out), run.out
    assert '"distance"' not in run.output


def test_ged_json_written(tool, scratch):
    succeeds(tool("ged", RING, PATH, "--json", scratch / "ged.json"))
    assert json.loads((scratch / "ged.json").read_text())["distance"] == 3.0


def test_ged_matrix(tool):
    out = succeeds(tool("ged-matrix", PATH, TRIANGLE, RING, "--csv", "-")).out
    assert "0,2,3\n2,0,5\n3,5,0\n" in out


def test_ged_matrix_json(tool):
    result = tool("ged-matrix", PATH, TRIANGLE, "--threads", "2", "--json", "-").json()
    assert result["exact"] is True
    assert result["distance"] == [[0.0, 2.0], [2.0, 0.0]]
    assert [name.endswith(end) for name, end in zip(result["files"], ["path.dot", "triangle.graphml"])] == [True, True]


def test_ged_matrix_summary(tool):
    out = succeeds(tool("ged-matrix", PATH, TRIANGLE)).out
    assert "graph edit distances (exact, exact)" in out
    assert re.search(r"1  [^\n]*triangle.graphml\n   2 0\n", out), out


def test_ged_missing(tool):
    run = fails(tool("ged", PATH, GRAPHS / "no-such-graph.dot"))
    assert re.search(r"deformseg: error: [^\n]*no-such-graph.dot: cannot open", run.err), run.describe()


def test_ged_unlabelled(tool):
    run = fails(tool("ged-matrix", PATH, GRAPHS / "unlabelled.dot"))
    assert re.search(r"deformseg: error: [^\n]*unlabelled.dot: node 'b' has no 'label' attribute", run.err), \
        run.describe()


def test_ged_unknown_method(tool):
    fails(tool("ged", PATH, RING, "--method", "fastest"), "--method")
