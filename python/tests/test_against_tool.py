"""The module against the `deformseg` tool on the same inputs, end to end: identical numbers.

Both are made of one front end (frontend/: the parameters, the input rules, the dispatch), so
these tests no longer check every option of each command against its keyword: one case per
function, with the command-line forms every version of the tool takes (a single input with
--clip or FILE#CLIP, two inputs as FILE#CLIP). What the module does that the tool does not say is
tested in test_module.py and test_inputs.py."""
import numpy as np
import pytest

import deformseg


def clips(fox):
    return f"{fox}#Walk", f"{fox}#Run"


# ---- reading -----------------------------------------------------------------------------------

def test_read_animation_as_info_tubes(tool, tubes):
    for folder in tubes:
        info = tool("info", folder, "--json", "-")
        a = deformseg.read_animation(folder)
        assert (a.num_frames, a.num_vertices, a.num_faces) == (info["frames"], info["vertices"], info["triangles"])
        assert a.repair == info["repair"]
        box = info["bounding_box"]
        assert a.frames.reshape(-1, 3).min(axis=0).tolist() == box["min"]
        assert a.frames.reshape(-1, 3).max(axis=0).tolist() == box["max"]


def test_read_animation_as_info_gltf(tool, fox):
    for clip in ("Survey", "Walk", "Run"):
        info = tool("info", fox, "--clip", clip, "--json", "-")
        a = deformseg.read_animation(fox, clip=clip)
        assert (a.num_frames, a.num_vertices, a.num_faces) == (info["frames"], info["vertices"], info["triangles"])
        assert a.repair == info["repair"]
        assert a.frames.reshape(-1, 3).min(axis=0).tolist() == info["bounding_box"]["min"]
    unwelded = tool("info", fox, "--clip", "Walk", "--no-weld", "--json", "-")
    assert deformseg.read_animation(f"{fox}#Walk", weld=False).num_vertices == unwelded["vertices"]
    at_12 = tool("info", fox, "--clip", "Run", "--fps", "12", "--json", "-")
    assert deformseg.read_animation(fox, clip="Run", fps=12).num_frames == at_12["frames"]


# ---- strain ------------------------------------------------------------------------------------

STRAIN_OPTIONS = [
    ({}, []),
    ({"measure": "frobenius", "rest_frame": 5}, ["--measure", "frobenius", "--rest-frame", "5"]),
]


@pytest.mark.parametrize("keywords, arguments", STRAIN_OPTIONS)
def test_strain_as_tool(tool, tubes, tmp_path, csv_matrix, keywords, arguments):
    folder = tubes[1]
    summary = tool("strain", folder, "--out", tmp_path / "strain.csv", "--json", "-", *arguments)
    field = deformseg.strain(deformseg.read_animation(folder), **keywords)
    assert field.shape == (summary["frames"], summary["triangles"]) and field.dtype == np.float32
    assert np.array_equal(field, csv_matrix(tmp_path / "strain.csv", np.float32))
    for row, frame in zip(field, summary["per_frame"]):
        assert float(row.min()) == frame["min"] and float(row.max()) == frame["max"]
        assert float(np.cumsum(row, dtype=np.float64)[-1]) / row.size == frame["mean"]


# ---- temporal segmentation and frame distances -------------------------------------------------

def test_temporal_segmentation_and_frame_distances_as_tool(tool, tubes, tmp_path, csv_matrix):
    folder = tubes[1]
    document = tool("temporal", folder, "--metric", "l1", "--matrix", tmp_path / "d.csv", "--json", "-")
    a = deformseg.read_animation(folder)
    assert deformseg.temporal_segmentation(a, metric="l1") == [(s["first"], s["last"]) for s in document["segments"]]
    d = deformseg.frame_distances(a, metric="l1")
    assert d.dtype == np.float32 and d.shape[0] == d.shape[1]
    assert np.array_equal(d, csv_matrix(tmp_path / "d.csv", np.float32))


def test_temporal_segmentation_of_gltf_as_tool(tool, fox):
    document = tool("temporal", f"{fox}#Survey", "--json", "-")
    segments = deformseg.temporal_segmentation(deformseg.read_animation(fox, clip="Survey"))
    assert segments == [(s["first"], s["last"]) for s in document["segments"]]


# ---- evolving graph ----------------------------------------------------------------------------

def check_evolving_graph(graph, document):
    assert (graph.num_frames, graph.num_segments, len(graph)) == (
        document["frames"], document["segments"], len(document["key_frames"]))
    for key_frame, expected in zip(graph, document["key_frames"]):
        assert (key_frame.first, key_frame.last) == (expected["first"], expected["last"])
        assert [(n.kind, n.segment, n.triangles, n.area) for n in key_frame.nodes] == [
            (n["kind"], n["segment"], n["triangles"], n["area"]) for n in expected["nodes"]]
        assert sorted(key_frame.edges) == sorted(tuple(e) for e in expected["edges"])


def test_evolving_graph_as_tool(tool, tubes):
    folder = tubes[1]
    options = ["--threshold", "0.1", "--min-triangles", "4", "--min-frames", "1", "--max-island", "0"]
    document = tool("spatiotemporal", folder, "--json", "-", *options)
    graph = deformseg.evolving_graph(deformseg.read_animation(folder), threshold=0.1, min_triangles=4, min_frames=1,
                                     max_island=0)
    check_evolving_graph(graph, document)
    lasting = ["--min-area", "0.02", "--hysteresis", "0.4", "--contact-distance", "0", "--rigid-tolerance", "0"]
    document = tool("spatiotemporal", folder, "--json", "-", "--threshold", "0.1", *lasting)
    graph = deformseg.evolving_graph(deformseg.read_animation(folder), threshold=0.1, min_area=0.02, hysteresis=0.4,
                                     contact_distance=0, rigid_tolerance=0)
    check_evolving_graph(graph, document)


def test_evolving_graph_of_a_character_as_tool(tool, characters):
    knight = f"{characters / 'Knight.glb'}#Walking_A"
    document = tool("spatiotemporal", knight, "--json", "-", "--min-frames", "4")
    graph = deformseg.evolving_graph(deformseg.read_animation(knight), min_frames=4)
    check_evolving_graph(graph, document)
    assert max(len(k.nodes) for k in graph) <= 10  # its parts touch: not the 46 nodes of shared edges alone
    assert graph.face_segments is None  # not asked for


def test_face_segments_are_the_key_frames_segments(tool, characters):
    """Each triangle's segment in each frame: in every frame of a key frame, the segments present
    are exactly its deformed nodes'; the graph is the one made without them."""
    knight = deformseg.read_animation(f"{characters / 'Knight.glb'}#Walking_A")
    graph = deformseg.evolving_graph(knight, min_frames=4, face_segments=True)
    labels = graph.face_segments
    assert labels.shape == (knight.num_frames, knight.num_faces) and labels.dtype == np.int32
    assert labels.min() >= -1 and labels.max() < graph.num_segments and (labels == -1).any()
    for key in graph:
        deformed = {node.segment for node in key.nodes if node.segment is not None}
        for t in range(key.first, key.last + 1):
            assert set(np.unique(labels[t][labels[t] >= 0]).tolist()) == deformed, (key.first, t)
    assert graph == deformseg.evolving_graph(knight, min_frames=4)  # face_segments does not compare


# ---- similarity --------------------------------------------------------------------------------

def check_similarity(s, document):
    assert s.value == document["similarity"] and s.score == document["score"]
    assert s.alignment == [tuple(p) for p in document["alignment"]]
    assert s.labels_a == document["labels_a"] and s.labels_b == document["labels_b"]
    assert s.compared == document["compared"]
    assert s.z_score == document["z_score"] and s.shuffled_copies == document["shuffled_copies"]


def test_similarity_of_gltf_clips_as_tool(tool, fox):
    walk, run = clips(fox)
    document = tool("similarity", walk, run, "--json", "-")
    check_similarity(deformseg.similarity(deformseg.read_animation(walk), deformseg.read_animation(run)), document)
    options = ["--policy", "self-similarity", "--alignment", "dtw", "--significance", "5", "--seed", "7"]
    document = tool("similarity", walk, run, "--json", "-", *options)
    check_similarity(deformseg.similarity(deformseg.read_animation(walk), deformseg.read_animation(run),
                                          policy="self-similarity", alignment="dtw", significance=5, seed=7), document)


def test_similarity_matrix_as_tool(tool, fox):
    inputs = [f"{fox}#Survey", *clips(fox)]
    document = tool("matrix", *inputs, "--json", "-")
    animations = [deformseg.read_animation(i) for i in inputs]
    m = deformseg.similarity_matrix(animations)
    assert m.shape == (3, 3) and m.dtype == np.float64
    assert m.tolist() == document["similarity"]
    # Against a database: the rows' entries, whatever the split.
    assert deformseg.similarity_matrix(animations[:1], animations[1:]).tolist() == [document["similarity"][0][1:]]


def test_find_motion_as_tool(tool, fox):
    walk, _ = clips(fox)
    survey = f"{fox}#Survey"
    document = tool("find", walk, survey, "--count", "2", "--json", "-")
    matches = deformseg.find_motion(deformseg.read_animation(walk), deformseg.read_animation(survey), 2)
    assert [(m.first, m.last, m.value, m.alignment) for m in matches] == [
        (m["first"], m["last"], m["similarity"], [tuple(p) for p in m["alignment"]]) for m in document["matches"]]


def test_evaluate_as_tool(tool, characters, tmp_path):
    labels = tmp_path / "labels.csv"
    rows = [("Fox.glb", "Walk", "walk", "fox"), ("Fox.glb", "Run", "run", "fox"),
            ("Fox.glb", "Survey", "-", "fox"), ("Knight.glb", "Walking_A", "walk", "knight"),
            ("Knight.glb", "Running_A", "run", "knight")]
    labels.write_text("file,clip,motion,body\n" + "".join(
        f"{characters / f},{c},{m},{b}\n" for f, c, m, b in rows))
    document = tool("evaluate", labels, "--json", "-")
    items = deformseg.read_motion_labels(labels)
    assert [(i["clip"], i["motion"], i["body"]) for i in items] == [(c, m, b) for _, c, m, b in rows]
    animations = [deformseg.read_animation(i["file"], clip=i["clip"]) for i in items]
    m = deformseg.similarity_matrix(animations)
    assert m.tolist() == document["similarity"]
    scores = deformseg.evaluate(m, items)
    expected = document["scores"]
    for name in ("queries", "queries_without_relevant", "queries_without_candidate", "nn_accuracy",
                 "mean_average_precision", "roc_auc", "median_same", "median_different", "same_pairs",
                 "different_pairs", "labels", "confusion", "per_motion", "per_query"):
        assert getattr(scores, name) == expected[name], name


# ---- graph edit distance -----------------------------------------------------------------------

def write_dot(graph, path):
    lines = ["graph g {"]
    lines += [f'  n{i} [label="{data["label"]}"];' for i, (_, data) in enumerate(graph.nodes(data=True))]
    index = {node: i for i, node in enumerate(graph.nodes)}
    lines += [f"  n{index[u]} -- n{index[v]};" for u, v in graph.edges()]
    path.write_text("\n".join(lines + ["}"]) + "\n")


@pytest.mark.parametrize("method", ["exact", "bipartite", "lower"])
def test_ged_of_networkx_graphs_as_tool(tool, tmp_path, method):
    networkx = pytest.importorskip("networkx")
    g1 = networkx.Graph()
    g1.add_nodes_from([("a", {"label": "R"}), ("b", {"label": "D0"}), ("c", {"label": "R"}), ("d", {"label": "D1"})])
    g1.add_edges_from([("a", "b"), ("b", "c"), ("c", "d")])
    g2 = networkx.Graph()
    g2.add_nodes_from([(0, {"label": "R"}), (1, {"label": "D0"}), (2, {"label": "D1"})])
    g2.add_edges_from([(0, 1), (1, 2), (0, 2)])
    write_dot(g1, tmp_path / "a.dot")
    write_dot(g2, tmp_path / "b.dot")
    document = tool("ged", tmp_path / "a.dot", tmp_path / "b.dot", "--method", method, "--json", "-")
    r = deformseg.ged(g1, g2, method=method)
    assert (r.distance, r.exact, r.lower, r.upper) == (
        document["distance"], document["exact"], document["lower"], document["upper"])
    assert [[i, j] for i, j in enumerate(r.mapping)] == document["mapping"]


def test_ged_of_key_frames_as_tool(tool, tubes, tmp_path):
    folder = tubes[1]
    options = ["--threshold", "0.05", "--reference", "rest"]
    tool("spatiotemporal", folder, "--dot", tmp_path, *options)
    graph = deformseg.evolving_graph(deformseg.read_animation(folder), threshold=0.05, reference="rest")
    dots = sorted(tmp_path.glob("*.dot"))
    assert len(dots) == len(graph) >= 2
    for k in (1, len(graph) - 1):
        document = tool("ged", dots[0], dots[k], "--json", "-")
        r = deformseg.ged(graph[0], graph[k])
        assert (r.distance, r.exact) == (document["distance"], document["exact"])
        nx = pytest.importorskip("networkx")
        assert deformseg.ged(graph[0].to_networkx(), graph[k].to_networkx()).distance == r.distance
        assert isinstance(graph.to_networkx()[k], nx.Graph)


def test_point_cache_with_topology_as_tool(tool, tmp_path, csv_matrix):
    cache = tmp_path / "cache"
    tool("synth", cache, "--format", "pc2", "--schedule", "3:0", "8:60", "8:0")
    pc2 = next(cache.glob("*.pc2"))
    topology = cache / "tube.obj"
    info = tool("info", pc2, "--topology", topology, "--json", "-")
    a = deformseg.read_animation(pc2, topology=topology)
    assert (a.num_frames, a.num_vertices, a.num_faces) == (info["frames"], info["vertices"], info["triangles"])
    tool("strain", pc2, "--topology", topology, "--out", tmp_path / "strain.csv")
    assert np.array_equal(deformseg.strain(a), csv_matrix(tmp_path / "strain.csv", np.float32))
    with pytest.raises(deformseg.InvalidInput, match="needs a topology mesh"):
        deformseg.read_animation(pc2)


def test_reference_mesh_as_tool(tool, tubes, tmp_path, csv_matrix):
    # A rest pose kept apart from the frames: here the tube's frame 10, given as a mesh file.
    folder = tubes[1]
    rest = folder / "frame_0010.ply"
    a = deformseg.read_animation(folder)
    tool("strain", folder, "--reference-mesh", rest, "--measure", "frobenius", "--out", tmp_path / "s.csv")
    assert np.array_equal(deformseg.strain(a, reference_mesh=rest, measure="frobenius"),
                          csv_matrix(tmp_path / "s.csv", np.float32))
    document = tool("temporal", folder, "--reference-mesh", rest, "--matrix", tmp_path / "d.csv", "--json", "-")
    assert deformseg.temporal_segmentation(a, reference_mesh=rest) == [
        (s["first"], s["last"]) for s in document["segments"]]
    assert np.array_equal(deformseg.frame_distances(a, reference_mesh=rest), csv_matrix(tmp_path / "d.csv", np.float32))
    document = tool("spatiotemporal", folder, "--reference-mesh", rest, "--threshold", "0.1", "--json", "-")
    check_evolving_graph(deformseg.evolving_graph(a, reference_mesh=rest, threshold=0.1), document)


# ---- FBX and Collada characters ------------------------------------------------------------------

@pytest.fixture(scope="session")
def fbx_collada(characters):
    folder = characters.parent / "fbx-collada"
    if not (folder / "quat_man.fbx").exists():
        pytest.skip(f"{folder} not found: the shared FBX and Collada characters are not beside the repository")
    return folder


def test_fbx_and_collada_read_as_tool(tool, fbx_collada):
    man, max_walk, maya_walk = (fbx_collada / "quat_man.fbx", fbx_collada / "astroboy_walk_max.dae",
                                fbx_collada / "astroboy_walk_maya.dae")
    listed = deformseg.clips(man, fps=24)
    assert [c["name"] for c in listed] == [c["name"] for c in tool("info", f"{man}#0", "--json", "-")["gltf"]["clips"]]
    punch = next(c for c in listed if c["name"].endswith("|Punch"))
    assert punch["frames"] == 25 and punch["index"] == 5
    animation = deformseg.read_animation(f"{man}#{punch['name']}", fps=24)
    info = tool("info", f"{man}#{punch['name']}", "--fps", "24", "--json", "-")
    assert (animation.num_frames, animation.num_vertices) == (info["frames"], info["vertices"]) == (25, 791)
    with pytest.raises(deformseg.InvalidInput, match="holds 9 clips: name the one to read"):
        deformseg.read_animation(man)
    document = tool("similarity", max_walk, maya_walk, "--json", "-")
    s = deformseg.similarity(deformseg.read_animation(max_walk), deformseg.read_animation(maya_walk))
    check_similarity(s, document)
    assert s.value >= 0.9
