"""What each function accepts is what its stub and docstring say: evaluate's labels (motion names,
dicts, objects; bodies optional), paths as str or os.PathLike, sequences as lists or tuples."""
import pathlib
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
