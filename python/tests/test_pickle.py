"""Every result of the module pickles: a round trip gives back every field (NumPy arrays bit for
bit), through pickle, copy and a process pool started with 'spawn'; a bad state is refused clearly."""
import copy
import dataclasses
import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import deformseg

RESULT_TYPES = (deformseg.Animation, deformseg.Similarity, deformseg.MotionMatch, deformseg.RetrievalScores,
                deformseg.GedResult)


def fields(value):
    """Every public data attribute of `value`, by name (properties and read-only members alike)."""
    names = [name for name in dir(type(value)) if not name.startswith("_")]
    return {name: getattr(value, name) for name in names if not callable(getattr(value, name))}


def assert_same(restored, original):
    assert type(restored) is type(original)
    if isinstance(original, np.ndarray):  # the arrays functions return (views of the library's results)
        assert restored.dtype == original.dtype and restored.shape == original.shape
        assert restored.tobytes() == original.tobytes()
        return
    if dataclasses.is_dataclass(original):  # the evolving graph's classes: their == compares every field
        assert restored == original
        return
    expected, got = fields(original), fields(restored)
    assert expected and got.keys() == expected.keys()
    for name, value in expected.items():
        if isinstance(value, np.ndarray):
            assert got[name].dtype == value.dtype and got[name].shape == value.shape, name
            assert got[name].tobytes() == value.tobytes(), name  # bit-identical
        else:
            assert got[name] == value and type(got[name]) is type(value), name


def write_obj_frames(folder, frames=3):
    """A folder of OBJ frames of a square split in two triangles, one of them listed twice (a
    duplicate the reader drops), so that the animation read has a repair report to pickle."""
    folder.mkdir()
    for t in range(frames):
        z = 0.1 * t
        (folder / f"frame_{t:02}.obj").write_text(
            f"v 0 0 0\nv 1 0 {z}\nv 1 1 0\nv 0 1 {z}\nf 1 2 3\nf 1 3 4\nf 1 2 3\n")
    return folder


def ged_inputs():
    node = deformseg.Node
    g1 = deformseg.KeyFrame(0, 3, [node("rigid", None, 10, 0.5), node("deformed", 0, 4, 0.2),
                                   node("deformed", 1, 6, 0.3)], [(0, 1), (0, 2)])
    g2 = deformseg.KeyFrame(4, 9, [node("rigid", None, 12, 0.7), node("deformed", 2, 3, 0.3)], [(0, 1)])
    return g1, g2


def results(a, b, labels):
    """One result of each type, from two animations and the labels of four items: what a worker
    process computes and sends back."""
    matrix = np.array([[1, 0.9, 0.2, 0.4], [0.9, 1, 0.3, 0.1], [0.2, 0.3, 1, 0.5], [0.4, 0.1, 0.5, 1]])
    g1, g2 = ged_inputs()
    return {
        "animation": a,
        "similarity": deformseg.similarity(a, b, significance=4),
        "graph similarity": deformseg.similarity(a, b, policy="graph"),
        "matches": deformseg.find_motion(b, a, 2),
        "scores": deformseg.evaluate(matrix, labels),
        "exact ged": deformseg.ged(g1, g2),
        "lower ged": deformseg.ged(g1, g2, method="lower"),
        "evolving graph": deformseg.evolving_graph(a),
        "strain": deformseg.strain(a),
        "frame distances": deformseg.frame_distances(a),
        "matrix": deformseg.similarity_matrix([a, b]),
    }


LABELS = [{"motion": "walk", "body": "fox"}, {"motion": "walk", "body": "knight"},
          {"motion": "run", "body": "fox"}, {"motion": "jump", "body": "mage"}]


def every_result(grid, tmp_path):
    a = deformseg.Animation(*grid(5, 6, 24, seed=1))
    b = deformseg.Animation(*grid(5, 6, 12, seed=2))
    out = results(a, b, LABELS)
    out["animation read"] = deformseg.read_animation(write_obj_frames(tmp_path / "frames"))
    return out


def assert_same_results(restored, original):
    assert restored.keys() == original.keys()
    for key, value in original.items():
        if isinstance(value, list):
            assert len(restored[key]) == len(value) >= 1, key
            for r, v in zip(restored[key], value):
                assert_same(r, v)
        else:
            assert_same(restored[key], value)


def test_every_result_type_is_covered(grid, tmp_path):
    made = every_result(grid, tmp_path)
    covered = {type(v[0] if isinstance(v, list) else v) for v in made.values()}
    assert covered == set(RESULT_TYPES) | {deformseg.EvolvingGraph, np.ndarray}
    assert made["evolving graph"].key_frames and made["evolving graph"].key_frames[0].nodes
    assert made["animation read"].repair["duplicate_triangles"] == 1  # a repair report to carry
    assert made["similarity"].z_score is not None and made["graph similarity"].labels_a
    assert made["lower ged"].upper is None and made["exact ged"].exact
    assert any(q["first_relevant_rank"] is None for q in made["scores"].per_query)  # None inside lists


@pytest.mark.parametrize("protocol", [2, pickle.DEFAULT_PROTOCOL, pickle.HIGHEST_PROTOCOL])
def test_every_result_round_trips_through_pickle(grid, tmp_path, protocol):
    original = every_result(grid, tmp_path)
    assert_same_results(pickle.loads(pickle.dumps(original, protocol=protocol)), original)


def test_copies_are_equal_and_independent(grid, tmp_path):
    original = every_result(grid, tmp_path)
    assert_same_results(copy.deepcopy(original), original)
    a = original["animation"]
    copied = copy.copy(a)
    assert copied is not a and not np.shares_memory(copied.frames, a.frames)
    assert_same(copied, a)


def test_a_restored_animation_gives_the_same_results(grid):
    a = deformseg.Animation(*grid(5, 6, 24, seed=1))
    b = pickle.loads(pickle.dumps(a))
    assert np.array_equal(deformseg.strain(b), deformseg.strain(a))
    assert deformseg.similarity(a, b).value == 1.0


def test_a_gltf_clip_round_trips(fox):
    a = deformseg.read_animation(fox, clip="Walk")
    assert a.repair is not None
    assert_same(pickle.loads(pickle.dumps(a, protocol=pickle.HIGHEST_PROTOCOL)), a)


def test_results_come_back_from_a_spawned_process_pool(grid, tmp_path):
    # Animations go to the workers pickled, results come back pickled; both equal those computed here.
    a = deformseg.Animation(*grid(5, 6, 24, seed=1))
    b = deformseg.Animation(*grid(5, 6, 12, seed=2))
    read = deformseg.read_animation(write_obj_frames(tmp_path / "frames"))
    expected = results(a, b, LABELS)
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as pool:
        came_back = list(pool.map(results, [a, a], [b, b], [LABELS, LABELS]))
        echoed = pool.submit(copy.copy, read).result()  # a read animation there and back
        missing = pool.submit(deformseg.read_animation, str(tmp_path / "missing.obj"))
        with pytest.raises(deformseg.InvalidInput) as error:  # errors come back too, with their parts
            missing.result()
    for restored in came_back:
        assert_same_results(restored, expected)
    assert_same(echoed, read)
    assert error.value.file == str(tmp_path / "missing.obj")


def test_functions_pickle_by_name_and_go_to_a_spawned_pool(grid):
    compiled = [deformseg.strain, deformseg.read_animation, deformseg.similarity, deformseg.evaluate]
    for function in compiled + [deformseg.ged, deformseg.evolving_graph]:
        assert pickle.loads(pickle.dumps(function)) is function
    assert pickle.loads(pickle.dumps(len)) is len  # other built-in functions as before
    animations = [deformseg.Animation(*grid(4, 4, 8, seed=k)) for k in range(3)]
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as pool:
        strains = list(pool.map(deformseg.strain, animations))
    assert all(s.tobytes() == deformseg.strain(a).tobytes() for s, a in zip(strains, animations))


# The methods of the compiled classes pickle too, as their class's attribute: a process pool takes
# `type(store).search` (pybind11's `instancemethod`, which pickle could not save).
def test_methods_pickle_and_go_to_a_spawned_pool(tmp_path):
    methods = [(owner, name, method) for owner in (deformseg.Animation, deformseg.MotionStore, deformseg.Similarity)
               for name, method in vars(owner).items() if type(method).__name__ == "instancemethod"]
    assert len(methods) >= 10
    for owner, name, method in methods:
        assert pickle.loads(pickle.dumps(method)) is getattr(owner, name)
    folders = [write_obj_frames(tmp_path / f"frames{k}", frames=4 + k) for k in range(3)]
    deformseg.describe_to_store([str(f) for f in folders], str(tmp_path / "clips.store"))
    store = deformseg.open_store(tmp_path / "clips.store")
    query = deformseg.read_animation(folders[1])
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as pool:
        found = list(pool.map(type(store).search, [store, store], [query, query], [2, 3]))
        bound = pool.submit(store.knn_graph, 1).result()
    assert found == [store.search(query, 2), store.search(query, 3)]
    assert bound == store.knn_graph(1)


def new_of(type_):
    return type_.__new__(type_)


@pytest.mark.parametrize("type_", RESULT_TYPES)
def test_a_bad_state_is_refused_naming_the_class(type_, grid):
    good = {deformseg.Animation: lambda: deformseg.Animation(*grid(2, 2, 3)),
            deformseg.Similarity: lambda: deformseg.similarity(*[deformseg.Animation(*grid(2, 2, 3))] * 2),
            deformseg.MotionMatch: lambda: deformseg.find_motion(*[deformseg.Animation(*grid(2, 2, 6))] * 2)[0],
            deformseg.RetrievalScores: lambda: deformseg.evaluate(np.eye(2), LABELS[:2]),
            deformseg.GedResult: lambda: deformseg.ged(*ged_inputs())}[type_]().__getstate__()
    assert isinstance(good, tuple) and good[0] == 1  # versioned
    name = f"deformseg.{type_.__name__}: cannot restore a pickled state"
    for bad, reason in [((2,) + good[1:], "state version 2, this deformseg reads version 1"),
                        (good[:-1], f"got {len(good) - 1} items"),
                        (list(good), "got a list"),
                        (good[:1] + ("text",) + good[2:], "field '")]:
        with pytest.raises(ValueError, match="^" + name) as error:
            new_of(type_).__setstate__(bad)
        assert reason in str(error.value), (bad, str(error.value))


def test_an_animation_keeps_its_frame_rate(grid):
    restored = pickle.loads(pickle.dumps(deformseg.Animation(*grid(2, 2, 3), fps=24.0)))
    assert restored.fps == 24.0


def test_every_repair_count_comes_back_under_its_name(grid, tmp_path):
    faces, frames = deformseg.Animation(*grid(2, 2, 3)).__getstate__()[1:3]
    names = list(deformseg.read_animation(write_obj_frames(tmp_path / "frames")).repair)
    assert len(names) == 14
    counts = {name: k + 1 for k, name in enumerate(names)}  # every count another value
    restored = new_of(deformseg.Animation)
    restored.__setstate__((1, faces, frames, 30.0, counts))
    assert restored.repair == counts and list(restored.repair) == names


def test_an_animation_state_is_checked_as_its_arrays_are(grid):
    faces, frames, fps, repair = deformseg.Animation(*grid(2, 2, 3)).__getstate__()[1:]
    bad_faces = np.array(faces)
    bad_faces[0, 0] = 99
    with pytest.raises(deformseg.InvalidInput, match="out of range"):
        new_of(deformseg.Animation).__setstate__((1, bad_faces, frames, fps, repair))
    with pytest.raises(ValueError, match="field 'repair' has no count 'input_vertices'"):
        new_of(deformseg.Animation).__setstate__((1, faces, frames, fps, {}))
    with pytest.raises(ValueError, match="field 'frames' is not an array of float64"):
        new_of(deformseg.Animation).__setstate__((1, faces, frames.astype(np.float32), fps, repair))
    with pytest.raises(deformseg.InvalidInput, match="fps must be positive"):
        new_of(deformseg.Animation).__setstate__((1, faces, frames, 0.0, repair))
