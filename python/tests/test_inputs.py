"""What each function accepts is what its stub and docstring say: evaluate's labels (motion names,
dicts, objects; bodies optional), paths as str or os.PathLike, sequences as lists or tuples, glTF
clips by name or index (and `clips`, which lists them), reference meshes with their rules."""
import json
import pathlib
import struct
from types import SimpleNamespace

import numpy as np
import pytest

import deformseg

# Four clips: two walks, a run, a jump; item 0's nearest other item is the other walk.
MATRIX = np.array([[1.0, 0.9, 0.2, 0.4],
                   [0.9, 1.0, 0.3, 0.1],
                   [0.2, 0.3, 1.0, 0.5],
                   [0.4, 0.1, 0.5, 1.0]])
MOTIONS = ["walk", "walk", "run", "jump"]


def assert_every_other_item_is_a_candidate(scores):
    # Each of the 4 items a query, its 3 others its candidates: 2 same-motion pairs (the walks,
    # once in each direction), 10 different-motion ones.
    assert scores.queries == 4 and scores.queries_without_candidate == 0
    assert (scores.same_pairs, scores.different_pairs) == (2, 10)
    assert [q["nearest"] for q in scores.per_query] == [1, 0, 3, 2]
    assert scores.nn_accuracy == 0.5  # the walks find each other; run and jump have no match
    assert scores.queries_without_relevant == 2 and scores.mean_average_precision == 1.0
    assert scores.roc_auc == 1.0  # 0.9 above every different-motion pair


def test_evaluate_without_bodies_makes_every_item_its_own_body():
    assert_every_other_item_is_a_candidate(deformseg.evaluate(MATRIX, [{"motion": m} for m in MOTIONS]))


def test_evaluate_takes_a_list_of_motion_names():
    assert_every_other_item_is_a_candidate(deformseg.evaluate(MATRIX, MOTIONS))
    assert_every_other_item_is_a_candidate(deformseg.evaluate(MATRIX, tuple(MOTIONS)))
    assert_every_other_item_is_a_candidate(deformseg.evaluate(MATRIX.tolist(), np.array(MOTIONS)))


def test_evaluate_takes_objects_with_a_motion():
    items = [SimpleNamespace(motion=m, body=None, rig=None) for m in MOTIONS]
    assert_every_other_item_is_a_candidate(deformseg.evaluate(MATRIX, items))


def test_evaluate_body_defaults_to_the_file_as_in_a_labels_file():
    # Items 0 and 2 from one file (one body): the walk's only candidates are then items 1 and 3.
    items = [{"motion": m, "file": f} for m, f in zip(MOTIONS, ["fox.glb", "knight.glb", "fox.glb", "mage.glb"])]
    scores = deformseg.evaluate(MATRIX, items)
    assert scores.queries == 4 and (scores.same_pairs, scores.different_pairs) == (2, 8)


def test_evaluate_with_bodies_keeps_them():
    # One body for all: no query has a candidate, which queries_without_candidate says.
    scores = deformseg.evaluate(MATRIX, [{"motion": m, "body": "fox"} for m in MOTIONS])
    assert scores.queries == 0 and scores.queries_without_candidate == 4 and scores.nn_accuracy is None
    # An item without a body beside items with one is a body of its own, whatever the others' names.
    items = [{"motion": "walk", "body": "item 1"}, {"motion": "walk"}, {"motion": "run", "body": "item 1"},
             {"motion": "jump", "body": ""}]
    assert deformseg.evaluate(MATRIX, items).same_pairs == 2


def test_evaluate_refuses_items_it_cannot_read_naming_them():
    with pytest.raises(TypeError, match=r"labels\[2\]: expected a motion name \(str\), a dict or an object "
                                        r"with a 'motion', got int"):
        deformseg.evaluate(MATRIX, ["walk", "walk", 3, "jump"])
    with pytest.raises(ValueError, match=r"labels\[1\]: no motion \(a name, or '-' for a distractor\)"):
        deformseg.evaluate(MATRIX, [{"motion": "walk"}, {"body": "fox"}, {"motion": "run"}, {"motion": "jump"}])
    with pytest.raises(ValueError, match=r"labels\[3\]: no motion"):
        deformseg.evaluate(MATRIX, ["walk", "walk", "run", ""])


def test_evaluate_distractors_are_candidates_never_queries():
    scores = deformseg.evaluate(MATRIX, ["walk", "walk", "-", "-"])
    assert scores.queries == 2 and [q["nearest"] for q in scores.per_query] == [1, 0]


def test_paths_may_be_str_or_path_like(tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    for t in range(3):
        (folder / f"f{t}.obj").write_text(f"v 0 0 0\nv 1 0 {0.1 * t}\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n")
    by_path = deformseg.read_animation(pathlib.Path(folder))
    assert np.array_equal(by_path.frames, deformseg.read_animation(str(folder)).frames)
    labels = tmp_path / "labels.csv"
    labels.write_text("file,clip,motion\nframes,,walk\n")
    assert deformseg.read_motion_labels(labels) == deformseg.read_motion_labels(str(labels))
    rest = tmp_path / "rest.obj"
    rest.write_text((folder / "f0.obj").read_text())
    assert np.array_equal(deformseg.strain(by_path, reference_mesh=rest),
                          deformseg.strain(by_path, reference_mesh=str(rest)))


def test_sequences_may_be_lists_or_tuples(grid):
    animations = [deformseg.Animation(*grid(3, 3, 6, seed=k)) for k in range(3)]
    by_list = deformseg.similarity_matrix(animations, animations[:2])
    assert np.array_equal(deformseg.similarity_matrix(tuple(animations), tuple(animations[:2])), by_list)


# ---- glTF clips --------------------------------------------------------------------------------

def test_read_animation_needs_a_clip_of_a_file_of_several(fox):
    """A clip is named ("FILE.glb#CLIP" or clip=) for a file of several, as the tool asks; without
    one, the file's clips are listed where the first was read unsaid."""
    walk = deformseg.read_animation(f"{fox}#Walk")
    assert np.array_equal(walk.frames, deformseg.read_animation(fox, clip="Walk").frames)
    with pytest.raises(deformseg.InvalidInput, match=r"holds 3 clips: .*'Survey', 'Walk', 'Run'"):
        deformseg.read_animation(fox)
    with pytest.raises(deformseg.InvalidInput, match="the clip is given twice: after '#' and by clip"):
        deformseg.read_animation(f"{fox}#Walk", clip="Run")
    # Every clip of the file has its one mesh.
    survey, run = deformseg.read_animation(fox, clip="Survey"), deformseg.read_animation(fox, clip="Run")
    assert np.array_equal(survey.faces, run.faces) and np.array_equal(walk.faces, run.faces)


def test_a_clip_is_named_or_indexed(fox):
    """clip= takes a name or an index (an int, or its digits after '#'), 0 included."""
    survey = deformseg.read_animation(fox, clip="Survey")
    assert np.array_equal(deformseg.read_animation(fox, clip=0).frames, survey.frames)
    assert np.array_equal(deformseg.read_animation(fox, clip=2).frames, deformseg.read_animation(f"{fox}#Run").frames)
    walk = deformseg.read_animation(fox, clip="Walk")
    assert np.array_equal(deformseg.read_animation(f"{fox}#1").frames, walk.frames)
    with pytest.raises(deformseg.InvalidInput, match="clip must be a name or an index from 0, got -1"):
        deformseg.read_animation(fox, clip=-1)
    with pytest.raises(deformseg.InvalidInput, match=r"no clip '3'.*'Survey', 'Walk', 'Run'"):
        deformseg.read_animation(fox, clip=3)
    with pytest.raises(TypeError):
        deformseg.read_animation(fox, clip=1.0)


def test_clips_lists_a_gltf_files_clips(fox, tmp_path):
    clips = deformseg.clips(fox)
    assert [(c["name"], c["index"]) for c in clips] == [("Survey", 0), ("Walk", 1), ("Run", 2)]
    assert set(clips[0]) == {"name", "index", "start", "end", "duration", "frames", "channels"}
    for c in clips:
        assert c["duration"] == pytest.approx(c["end"] - c["start"]) and c["channels"] > 0
        assert c["frames"] == deformseg.read_animation(fox, clip=c["index"]).num_frames
    # The frames at another rate: those read at it.
    at_12 = deformseg.clips(pathlib.Path(fox), fps=12)
    assert at_12[2]["frames"] == deformseg.read_animation(fox, clip="Run", fps=12).num_frames < clips[2]["frames"]
    with pytest.raises(deformseg.InvalidInput, match=r"character files \(.glb, .gltf, .fbx, .dae, .bvh\) only") as error:
        deformseg.clips(tmp_path)
    assert error.value.file == str(tmp_path)
    with pytest.raises(deformseg.InvalidInput, match="fps"):
        deformseg.clips(fox, fps=0)


# ---- reference meshes --------------------------------------------------------------------------

def test_reference_mesh_errors_name_the_file_and_the_parameters(tubes, tmp_path):
    a = deformseg.read_animation(tubes[0])
    other = tmp_path / "triangle.obj"
    other.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(deformseg.InvalidInput, match="the reference mesh must have the connectivity") as error:
        deformseg.strain(a, reference_mesh=other)
    assert error.value.file == str(other)
    rest = tubes[0] / "frame_0000.ply"
    with pytest.raises(deformseg.InvalidInput, match="excludes reference='previous'"):
        deformseg.strain(a, reference_mesh=rest, reference="previous")
    with pytest.raises(deformseg.InvalidInput, match="excludes rest_frame"):
        deformseg.temporal_segmentation(a, reference_mesh=rest, rest_frame=3)
    with pytest.raises(deformseg.InvalidInput, match="excludes reference='previous'"):
        deformseg.evolving_graph(a, reference_mesh=rest, reference="previous")


def test_absurd_coordinates_warn_or_are_refused(tmp_path):
    # A 4 x 4 grid waving over 3 OBJ frames, frame 1's vertex 5 at 1e20: read with a UserWarning
    # naming the frame and the vertex, or refused with refuse_defects.
    points = [(i, j, 0.0) for i in range(4) for j in range(4)]
    faces = [(4 * i + j + 1, 4 * i + j + 2, 4 * i + j + 5) for i in range(3) for j in range(3)]
    faces += [(4 * i + j + 2, 4 * i + j + 6, 4 * i + j + 5) for i in range(3) for j in range(3)]
    for t in range(3):
        moved = [(x, y, 0.1 * t * x) for x, y, _ in points]
        if t == 1:
            moved[5] = (1e20, 0.0, 0.0)
        lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in moved] + [f"f {a} {b} {c}" for a, b, c in faces]
        (tmp_path / f"frame_{t}.obj").write_text("\n".join(lines) + "\n")
    with pytest.warns(UserWarning, match="frame 1 vertex 5 lies 1e\\+20 from the frame's middle"):
        animation = deformseg.read_animation(tmp_path)
    assert animation.num_frames == 3
    with pytest.raises(deformseg.InvalidInput, match="frame 1 vertex 5 lies 1e\\+20"):
        deformseg.read_animation(tmp_path, refuse_defects=True)


def test_clips_played_on_another_body(characters):
    # body=: the Knight's clips on the Barbarian's body (one rig, byte-identical clips) are the
    # Barbarian's own; a body for frames is refused, by its keyword.
    knight, barbarian = characters / "Knight.glb", characters / "Barbarian.glb"
    bound = deformseg.read_animation(knight, clip="Idle", body=barbarian)
    own = deformseg.read_animation(barbarian, clip="Idle")
    assert np.array_equal(np.asarray(bound.frames), np.asarray(own.frames))
    with pytest.raises(deformseg.InvalidInput, match="moves nothing of the body"):
        deformseg.read_animation(characters / "Fox.glb", clip="Walk", body=knight)


def test_a_clip_that_moves_few_joints_of_its_body_warns(characters, tmp_path):
    # The fox's walk reduced to its head's channel: on the fox, it moves 1 of its 24 joints.
    fox = characters / "Fox.glb"
    data = fox.read_bytes()
    length = struct.unpack_from("<I", data, 12)[0]
    document = json.loads(data[20:20 + length])
    names = [node.get("name", "") for node in document["nodes"]]
    for clip in document["animations"]:
        clip["channels"] = [c for c in clip["channels"] if names[c["target"]["node"]] == "b_Head_05"]
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + data[20 + length:]
    head = tmp_path / "fox-head.glb"
    head.write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)
    with pytest.warns(UserWarning, match="moves 1 of the 24 joints of the body"):
        deformseg.read_animation(head, clip="Walk", body=fox)
