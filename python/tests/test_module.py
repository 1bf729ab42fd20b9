"""The module on its own: arrays in and out, what is copied, invariance, errors, the GIL, stubs."""
import ast
import pathlib
import resource
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import deformseg

PACKAGE = pathlib.Path(deformseg.__file__).parent


# ---- arrays in and out -------------------------------------------------------------------------

def test_animation_from_arrays(grid):
    faces, frames = grid(4, 5, 7)
    a = deformseg.Animation(faces, frames)
    assert (a.num_frames, a.num_vertices, a.num_faces) == (7, 30, 40)
    assert a.frames.shape == (7, 30, 3) and a.frames.dtype == np.float64
    assert np.array_equal(a.frames, frames) and np.array_equal(a.faces, faces)
    assert a.faces.dtype == np.uint32 and a.repair is None
    assert "7 frames" in repr(a)
    assert deformseg.__version__.count(".") == 2


def test_frames_and_faces_are_read_only_views_of_the_animation(grid):
    a = deformseg.Animation(*grid(3, 3, 4))
    first, second = a.frames, a.frames
    assert np.shares_memory(first, second)  # both views of the animation's own storage: no copy
    assert not first.flags.owndata and not first.flags.writeable and first.flags.c_contiguous
    assert np.shares_memory(a.faces, a.faces) and not a.faces.flags.writeable
    with pytest.raises(ValueError):
        first[0, 0, 0] = 1.0
    del a  # the view keeps the animation alive
    assert np.isfinite(first).all() and first.shape == (4, 16, 3)


def test_float32_and_strided_input_give_the_same_animation(grid):
    faces, frames = grid(3, 4, 5)
    reference = deformseg.Animation(faces, frames)
    as_float32 = deformseg.Animation(faces, frames.astype(np.float32))
    assert np.array_equal(as_float32.frames, frames.astype(np.float32).astype(np.float64))
    strided = np.asfortranarray(frames)
    assert not strided.flags.c_contiguous
    assert np.array_equal(deformseg.Animation(faces.astype(np.uint16), strided).frames, reference.frames)
    assert np.array_equal(deformseg.Animation(faces.tolist(), frames.tolist()).frames, reference.frames)


def test_the_frames_are_copied_once(tmp_path):
    # In a fresh interpreter: the peak resident memory grows by one copy of a 200 MB float64 input
    # (the library's own storage), not two, and by twice a float32 input (converted to float64).
    script = textwrap.dedent("""
        import resource, sys
        import numpy as np
        import deformseg
        dtype = np.dtype(sys.argv[1])
        frames = np.zeros((2000, 4200, 3), dtype=dtype)   # 200 MB as float64
        frames[:, :, 0] = np.arange(4200) % 70
        frames[:, :, 1] = np.arange(4200) // 70
        faces = np.array([[i, i + 1, i + 70] for i in range(60)], dtype=np.int64)
        frames += 0  # touch every page
        before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        a = deformseg.Animation(faces, frames)
        after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        print((after - before) * 1024 / (frames.size * 8))
    """)
    for dtype in ("float64", "float32"):
        done = subprocess.run([sys.executable, "-c", script, dtype], capture_output=True, text=True, check=True)
        growth = float(done.stdout)  # in units of the library's float64 storage
        assert 0.9 < growth < 1.3, (dtype, growth)


def test_strain_owns_its_array_without_copy(grid):
    a = deformseg.Animation(*grid(4, 4, 6))
    s = deformseg.strain(a)
    assert s.shape == (6, 32) and s.dtype == np.float32 and s.flags.c_contiguous
    assert s.base is not None and not s.flags.owndata  # the library's Strain_field, not a copy
    assert np.all(s[0] == 0) and np.all((s >= 0) & (s <= 1))


def test_strain_of_a_moved_and_scaled_copy_is_the_same(grid):
    faces, frames = grid(6, 8, 10, seed=3)
    angle = 0.7
    rotation = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
    rotation = rotation @ np.array([[1, 0, 0], [0, np.cos(1.1), -np.sin(1.1)], [0, np.sin(1.1), np.cos(1.1)]])
    moved = 3.5 * frames @ rotation.T + np.array([10.0, -4.0, 2.5])
    for keywords in ({}, {"reference": "previous"}, {"measure": "green-lagrange", "normalize": "none"}):
        original = deformseg.strain(deformseg.Animation(faces, frames), **keywords)
        copy = deformseg.strain(deformseg.Animation(faces, moved), **keywords)
        assert np.allclose(original, copy, rtol=1e-4, atol=1e-5), keywords
    assert deformseg.temporal_segmentation(deformseg.Animation(faces, frames)) == \
        deformseg.temporal_segmentation(deformseg.Animation(faces, moved))


def test_similarity_of_an_animation_with_itself_is_1(grid):
    a = deformseg.Animation(*grid(4, 6, 12))
    s = deformseg.similarity(a, a)
    assert s.value == pytest.approx(1.0) and s.alignment[0] == (0, 0)
    m = deformseg.similarity_matrix([a, a])
    assert m.shape == (2, 2) and np.allclose(m, 1.0)


def test_explain_says_where_two_motions_differ_and_bands_describe_otherwise(grid):
    faces, frames = grid(4, 6, 24)
    a = deformseg.Animation(faces, frames)
    b = deformseg.Animation(faces, frames * np.array([1.0, 1.0, 2.0]))  # the same wave, twice as high
    s = deformseg.similarity(a, b, bands=2, up="+z", explain=True)
    channels = s.explanation["channels"]
    assert len(channels) == 2 * 4 * 2 * 2 and s.explanation["pairs"] == len(s.alignment)
    assert sum(c["share"] for c in channels) == pytest.approx(1.0)
    assert {c["band"] for c in channels} == {0, 1} and {c["kind"] for c in channels} == {"speed", "vertical_rate"}
    assert deformseg.similarity(a, b).explanation is None
    assert all(c["share"] == 0 for c in deformseg.similarity(a, a, explain=True).explanation["channels"])
    banded = deformseg.similarity(a, b, bands=2, up="+z").value
    assert banded == s.value and banded != deformseg.similarity(a, b, up="+z").value
    assert deformseg.similarity_matrix([a, b], bands=2, up="+z")[0, 1] == banded
    with pytest.raises(deformseg.InvalidInput, match="explain applies to the motion-signature policy only"):
        deformseg.similarity(a, b, policy="histogram", explain=True)
    with pytest.raises(deformseg.InvalidInput, match="bands 2 needs an up direction, not up='none'"):
        deformseg.similarity(a, b, bands=2, up="none")


def test_a_mirror_image_is_alike_but_for_sides(grid):
    faces, frames = grid(4, 6, 24)
    a = deformseg.Animation(faces, frames)
    mirror = deformseg.Animation(faces, frames * np.array([-1.0, 1.0, 1.0]))
    assert deformseg.similarity(a, mirror).value == 1.0
    apart = deformseg.similarity(a, mirror, sides="+x", explain=True)
    assert apart.value < 1.0 and {c["side"] for c in apart.explanation["channels"]} == {-1, 1}
    with pytest.raises(deformseg.InvalidInput, match="sides"):
        deformseg.similarity(a, mirror, sides="left")


def test_the_frame_rate_is_the_animations_and_the_same_motion_at_half_the_rate_is_the_same(grid):
    faces, frames = grid(4, 6, 61)
    a = deformseg.Animation(faces, frames)
    half = deformseg.Animation(faces, frames[::2], fps=15)
    assert (a.fps, half.fps) == (30.0, 15.0)
    # The same motion sampled at 15 fps: the same motion; the same frames played at 60: a faster one.
    same = deformseg.similarity(half, a).value
    faster = deformseg.similarity(deformseg.Animation(faces, frames, fps=60), a).value
    assert same >= 0.99 and faster < same - 0.02, (same, faster)
    with pytest.raises(deformseg.InvalidInput, match="fps"):
        deformseg.Animation(faces, frames, fps=0)


def test_find_motion_finds_a_copy_at_its_frames_with_value_1(grid):
    faces, frames = grid(4, 6, 12)
    louder = frames[:, :, :] * np.array([1.0, 1.0, 3.0])  # the same wave, three times as high
    still = np.repeat(frames[:1], 10, axis=0)
    long_animation = deformseg.Animation(faces, np.concatenate([louder[::-1], frames, still, louder]))
    match = deformseg.find_motion(deformseg.Animation(faces, frames), long_animation)[0]
    assert (match.first, match.last, match.value) == (12, 23, 1.0)
    assert match.alignment[0] == (0, 12) and match.alignment[-1] == (11, 23)
    # Three windows by default, as the tool's `find` and MotionStore.find (it was one).
    matches = deformseg.find_motion(deformseg.Animation(faces, frames), long_animation)
    assert len(matches) == 3 and (matches[0].first, matches[0].last) == (12, 23)
    assert [(m.first, m.last) for m in matches] == [
        (m.first, m.last) for m in deformseg.find_motion(deformseg.Animation(faces, frames), long_animation, 3)]


# ---- errors ------------------------------------------------------------------------------------

@pytest.mark.parametrize("frames, message", [
    (np.zeros((2, 9, 2)), r"frames: expected shape \(T, V, 3\).*got \(2, 9, 2\)"),
    (np.zeros((9, 3)), r"frames: expected shape \(T, V, 3\).*got \(9, 3\)"),
    (np.zeros((0, 9, 3)), r"got \(0, 9, 3\)"),
])
def test_frames_of_the_wrong_shape_are_refused(frames, message):
    with pytest.raises(ValueError, match=message):
        deformseg.Animation(np.array([[0, 1, 2]]), frames)


@pytest.mark.parametrize("dtype", [np.int64, np.complex128, np.float16, object])
def test_frames_of_the_wrong_dtype_are_refused(dtype):
    with pytest.raises(TypeError, match="frames: expected a float32 or float64 array"):
        deformseg.Animation(np.array([[0, 1, 2]]), np.zeros((2, 3, 3), dtype=dtype))


def test_faces_of_the_wrong_shape_dtype_or_range_are_refused(grid):
    faces, frames = grid(2, 2, 3)
    with pytest.raises(ValueError, match=r"faces: expected shape \(F, 3\).*got \(8, 2\)"):
        deformseg.Animation(faces[:, :2], frames)
    with pytest.raises(TypeError, match="faces: expected an integer array"):
        deformseg.Animation(faces.astype(np.float64), frames)
    bad = faces.copy()
    bad[3, 1] = 9
    with pytest.raises(deformseg.InvalidInput, match=r"triangle 3 has vertex index 9 out of range \[0, 9\)"):
        deformseg.Animation(bad, frames)
    bad[3, 1] = -1
    with pytest.raises(deformseg.InvalidInput, match="vertex index -1"):
        deformseg.Animation(bad, frames)
    # The same -1 in an unsigned array, as NumPy wraps it: named as what it was.
    with pytest.raises(deformseg.InvalidInput,
                       match=r"vertex index 4294967295 \(-1 stored as an unsigned 32-bit integer\?\) out of range"):
        deformseg.Animation(bad.astype(np.uint32), frames)
    with pytest.raises(deformseg.InvalidInput, match=r"vertex index 9 out of range"):
        deformseg.Animation(np.where(bad < 0, 9, bad).astype(np.uint16), frames)


def test_invalid_input_is_a_value_error_naming_the_frame(grid):
    faces, frames = grid(2, 2, 4)
    frames[2, 5, 1] = np.nan
    with pytest.raises(deformseg.InvalidInput, match="frame 2: vertex 5 has a non-finite coordinate") as error:
        deformseg.Animation(faces, frames)
    assert isinstance(error.value, ValueError)
    assert (error.value.frame, error.value.file, error.value.line) == (2, None, None)


def test_invalid_input_names_the_file_and_line(tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    (folder / "0.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    (folder / "1.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n")
    with pytest.raises(deformseg.InvalidInput) as error:
        deformseg.read_animation(folder)
    assert error.value.file == str(folder / "1.obj") and error.value.line == 3
    assert str(error.value).startswith(f"{folder / '1.obj'}:3: ")


def test_options_are_checked_as_the_tool_checks_them(grid, tmp_path):
    a = deformseg.Animation(*grid(3, 3, 5))
    cases = [
        (lambda: deformseg.strain(a, measure="max"), "measure must be"),
        (lambda: deformseg.strain(a, normalize="none", sigma=0.1), "sigma asks for normalize='gaussian'"),
        (lambda: deformseg.strain(a, reference="previous", rest_frame=2), "rest_frame asks for reference='rest'"),
        (lambda: deformseg.strain(a, rest_frame=5), "frame 5"),
        (lambda: deformseg.temporal_segmentation(a, method="greedy", segments=2), "segments asks for method='optimal'"),
        (lambda: deformseg.similarity(a, a, policy="signatures"), r"policy must be .*, got 'signatures'"),
        (lambda: deformseg.similarity(a, a, alignment="lcss"), r"alignment must be .*, got 'lcss'"),
        (lambda: deformseg.similarity(a, a, threshold=0.3), "threshold applies to the graph policies only"),
        (lambda: deformseg.similarity(a, a, policy="histogram", up="+z"), "up applies to the motion-signature"),
        (lambda: deformseg.similarity_matrix([a, a], up="z"), r"up must be .*, got 'z'"),
        (lambda: deformseg.similarity(a, a, significance=1), "at least 2 shuffled copies"),
        (lambda: deformseg.find_motion(a, a, 0), r"count must be a whole number in \[1, 1000000\], got 0"),
        (lambda: deformseg.find_motion(a, a, -1), r"count must be a whole number in \[1, 1000000\], got -1"),
        (lambda: deformseg.find_motion(a, a, shortest=0), r"shortest must be in \(0, 1\], got 0"),
        (lambda: deformseg.similarity(a, a, significance=-1), r"significance must be a whole number in \[0, 10000\]"),
        (lambda: deformseg.similarity(a, a, significance=10**12), r"got 1000000000000$"),
        (lambda: deformseg.similarity(a, a, seed=-1), r"seed must be a whole number in \[0, 4294967295\]"),
        (lambda: deformseg.similarity(a, a, policy="graph", threshold=2), r"threshold must be in \[0, 1\], got 2"),
        (lambda: deformseg.strain(a, rest_frame=-1), r"rest_frame must be a whole number in \[0, 1000000000\]"),
        (lambda: deformseg.strain(a, sigma=0), r"sigma must be in \(0, inf\), got 0"),
        (lambda: deformseg.temporal_segmentation(a, segments=-1), r"segments must be a whole number in \[1, "),
        (lambda: deformseg.temporal_segmentation(a, min_length=0), r"min_length must be a whole number in \[1, "),
        (lambda: deformseg.evolving_graph(a, min_frames=-1), r"min_frames must be a whole number in \[0, "),
        (lambda: deformseg.evolving_graph(a, hysteresis=1), r"hysteresis must be in \[0, 1\), got 1"),
        (lambda: deformseg.read_animation(tmp_path, threads=-1), r"threads must be a whole number in \[0, 1024\]"),
        (lambda: deformseg.read_animation(tmp_path, fps=0), r"^fps must be in \(0, 1000\], got 0$"),
        (lambda: deformseg.ged(deformseg.KeyFrame(0, 0), deformseg.KeyFrame(0, 0), max_expanded=-1),
         r"max_expanded must be a whole number in \[0, "),
        (lambda: deformseg.read_animation(tmp_path, clip="Walk"),
         r"clip applies to character files \(glTF, FBX, Collada, BVH\) only"),
        (lambda: deformseg.ged(deformseg.KeyFrame(0, 0), deformseg.KeyFrame(0, 0), method="fast"), "method must be"),
    ]
    for call, message in cases:
        with pytest.raises(deformseg.InvalidInput, match=message):
            call()
    with pytest.raises(TypeError, match=r"animations\[1\]: expected an Animation, got int"):
        deformseg.similarity_matrix([a, 3])


def test_ged_refuses_graphs_without_labels():
    networkx = pytest.importorskip("networkx")
    g = networkx.path_graph(3)
    with pytest.raises(ValueError, match="node 0 has no 'label' attribute"):
        deformseg.ged(g, g)
    with pytest.raises(ValueError, match="directed"):
        deformseg.ged(networkx.DiGraph(), networkx.DiGraph())


# ---- progress and the GIL ----------------------------------------------------------------------

def test_similarity_matrix_reports_progress_and_stops(grid):
    animations = [deformseg.Animation(*grid(3, 4, 8 + k, seed=k)) for k in range(3)]
    steps = []
    m = deformseg.similarity_matrix(animations, progress=lambda done, total: steps.append((done, total)))
    assert steps[-1] == (9, 9) and (3, 9) in steps and m.shape == (3, 3)
    with pytest.raises(deformseg.SimilarityStopped):
        deformseg.similarity_matrix(animations, progress=lambda done, total: False)

    def failing(done, total):
        raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback"):
        deformseg.similarity_matrix(animations, progress=failing)


def test_similarity_matrix_on_any_number_of_threads_is_the_same(grid):
    animations = [deformseg.Animation(*grid(3, 4, 8 + k, seed=k)) for k in range(4)]
    for policy in ("motion-signature", "histogram", "self-similarity"):
        one = deformseg.similarity_matrix(animations, policy=policy, threads=1)
        assert np.array_equal(one, deformseg.similarity_matrix(animations, policy=policy, threads=2))
        assert np.array_equal(one[:2, 1:], deformseg.similarity_matrix(animations[:2], animations[1:],
                                                                         policy=policy, threads=2))
    with pytest.raises(deformseg.InvalidInput, match=r"threads must be a whole number in \[0, "):
        deformseg.similarity_matrix(animations, threads=-1)


def test_similarity_on_any_number_of_threads_is_the_same(grid):
    a, b = (deformseg.Animation(*grid(3, 4, 10 + k, seed=k)) for k in range(2))
    for policy in ("motion-signature", "histogram", "graph"):
        one = deformseg.similarity(a, b, policy=policy, threads=1)
        two = deformseg.similarity(a, b, policy=policy, threads=2)
        assert (one.value, one.alignment, one.z_score) == (two.value, two.alignment, two.z_score)
    with pytest.raises(deformseg.InvalidInput, match=r"threads must be a whole number in \[0, "):
        deformseg.similarity(a, b, threads=-1)


def test_similarity_matrix_names_a_pose_of_one_frame(grid):
    faces, frames = grid(3, 4, 8)
    animations = [deformseg.Animation(faces, frames), deformseg.Animation(faces, frames[:1])]
    with pytest.raises(deformseg.InvalidInput, match=r"^animations\[1\]: an animation of 1 frame: a motion needs"):
        deformseg.similarity_matrix(animations)
    with pytest.raises(deformseg.InvalidInput, match=r"^database\[1\]: an animation of 1 frame"):
        deformseg.similarity_matrix(animations[:1], animations)


def test_long_calls_release_the_gil(grid):
    # A 600-frame animation of 20 000 triangles: its frame distances, on one thread, take about half
    # a second, during which a Python thread keeps counting. Were the GIL held, the
    # thread could count for at most about one switch interval (5 ms) before the call took it.
    a = deformseg.Animation(*grid(100, 100, 600))
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1

    thread = threading.Thread(target=count)
    thread.start()
    try:
        time.sleep(0.2)  # the counting rate with the main thread asleep
        start, began = counter[0], time.perf_counter()
        time.sleep(0.2)
        rate = (counter[0] - start) / (time.perf_counter() - began)
        start, began = counter[0], time.perf_counter()
        deformseg.frame_distances(a, threads=1)
        seconds = time.perf_counter() - began
        during = counter[0] - start
    finally:
        stop.set()
        thread.join()
    held_at_most = 2 * rate * sys.getswitchinterval()
    assert seconds > 10 * sys.getswitchinterval(), seconds
    assert during > 4 * held_at_most, (during, held_at_most, seconds)


# ---- stubs and docstrings ----------------------------------------------------------------------

def test_every_public_name_is_in_the_stub_and_documented():
    stub = ast.parse((PACKAGE / "__init__.pyi").read_text())
    stubbed = {node.name for node in stub.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    stubbed |= {target.id for node in stub.body if isinstance(node, (ast.Assign, ast.AnnAssign))
                for target in (node.targets if isinstance(node, ast.Assign) else [node.target])
                if isinstance(target, ast.Name)}
    assert set(deformseg.__all__) <= stubbed, set(deformseg.__all__) - stubbed
    assert (PACKAGE / "py.typed").exists()
    for name in deformseg.__all__:
        value = getattr(deformseg, name)
        if callable(value):
            assert value.__doc__ and len(value.__doc__) > 40, name


def test_functions_document_shapes_defaults_and_complexity():
    for name in deformseg.__all__:
        value = getattr(deformseg, name)
        if callable(value) and not isinstance(value, type):
            assert "Complexity" in value.__doc__, name
    for name in ("strain", "frame_distances", "temporal_segmentation", "evolving_graph", "similarity",
                 "similarity_matrix", "find_motion", "ged", "read_animation"):
        assert "default" in getattr(deformseg, name).__doc__.lower(), name
    for name in ("strain", "frame_distances", "similarity_matrix", "Animation"):
        assert "(T, " in getattr(deformseg, name).__doc__ or "(N, N)" in getattr(deformseg, name).__doc__, name


def test_results_do_not_depend_on_threads_or_on_concurrent_calls(grid):
    from concurrent.futures import ThreadPoolExecutor
    animations = [deformseg.Animation(*grid(6, 6, 20, seed=k)) for k in range(4)]
    one = [deformseg.strain(a, threads=1) for a in animations]
    assert all(np.array_equal(deformseg.strain(a, threads=2), s) for a, s in zip(animations, one))
    alone = [deformseg.similarity(animations[0], b).value for b in animations]
    with ThreadPoolExecutor(4) as pool:  # the GIL released, calls run at once on shared animations
        strains = list(pool.map(deformseg.strain, animations))
        together = list(pool.map(lambda b: deformseg.similarity(animations[0], b).value, animations))
    assert all(np.array_equal(s, t) for s, t in zip(one, strains)) and together == alone


def parameter_names(function):
    """The parameter names of a function: from inspect, or from the signature line pybind11 puts
    first in a compiled function's docstring."""
    import inspect
    try:
        return [p for p in inspect.signature(function).parameters]
    except ValueError:
        line = function.__doc__.splitlines()[0]
        inside, depth, names, current = line[line.index("(") + 1:], 0, [], ""
        for character in inside:
            if character in "([":
                depth += 1
            elif character in ")]":
                if depth == 0:
                    break
                depth -= 1
            if character == "," and depth == 0:
                names.append(current)
                current = ""
            else:
                current += character
        names.append(current)
        return [n.split(":")[0].strip() for n in names if n.strip() and n.strip() != "*"]


def test_the_stub_gives_every_function_its_parameters():
    stub = ast.parse((PACKAGE / "__init__.pyi").read_text())
    for node in stub.body:
        if isinstance(node, ast.FunctionDef):
            arguments = node.args
            stubbed = [a.arg for a in arguments.args + arguments.kwonlyargs]
            assert stubbed == parameter_names(getattr(deformseg, node.name)), node.name
