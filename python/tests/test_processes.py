"""The module among processes, signals and threads: fork-based process pools after a call, Ctrl-C
(SIGINT) during long calls, and thread counts out of range."""
import os
import pathlib
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import deformseg

# ---- fork-based process pools -------------------------------------------------------------------

# A parent that calls deformseg (its threads then ran here), then a fork-based pool whose workers
# call it too, get the animation through fork (a global of the parent) and return plain values.
# GNU OpenMP's thread pool, started by the parent's call, left each worker's first parallel loop
# waiting for ever; the pool runs in a child process group, killed when it takes too long, so
# that such a hang fails the test.
_POOL_SCRIPT = """
import multiprocessing, sys
from concurrent.futures import ProcessPoolExecutor
import deformseg
from conftest import grid_animation

animation = deformseg.Animation(*grid_animation(12, 12, 30))

def strain_total(threads):
    return float(deformseg.strain(animation, threads=threads).sum())

def self_similarity(k):
    return deformseg.similarity(animation, animation, significance=0).value

if __name__ == "__main__":
    in_parent = strain_total(2)
    fork = multiprocessing.get_context("fork")
    if sys.argv[1] == "ProcessPoolExecutor":
        with ProcessPoolExecutor(2, mp_context=fork) as pool:
            totals, values = list(pool.map(strain_total, [0, 1, 2, 0])), list(pool.map(self_similarity, range(2)))
    else:
        with fork.Pool(2) as pool:
            totals, values = pool.map(strain_total, [0, 1, 2, 0]), pool.map(self_similarity, range(2))
    print(totals == [in_parent] * 4, values)
"""


@pytest.mark.skipif(sys.platform != "linux", reason="fork is the default start method on Linux only")
@pytest.mark.parametrize("pool_kind", ["ProcessPoolExecutor", "multiprocessing.Pool"])
def test_a_fork_based_pool_runs_calls_after_a_call_in_the_parent(tmp_path, pool_kind):
    script = tmp_path / "pool.py"
    script.write_text(_POOL_SCRIPT)
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join([str(pathlib.Path(__file__).parent),
                                                               os.environ.get("PYTHONPATH", "")]))
    child = subprocess.Popen([sys.executable, str(script), pool_kind], env=environment, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = child.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        os.killpg(child.pid, signal.SIGKILL)
        child.communicate()
        pytest.fail(f"the {pool_kind} of forked workers did not return in 120 s")
    assert child.returncode == 0, err
    assert out.startswith("True [1.0, 1.0]"), out


# ---- Ctrl-C -------------------------------------------------------------------------------------

def _interrupted(call, after):
    """Runs call(), SIGINT sent to this process `after` seconds after it starts: (whether the call
    was interrupted before it returned, seconds from the signal to KeyboardInterrupt)."""
    sent = []

    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(after, interrupt)
    timer.start()
    returned = False
    try:
        call()
        returned = True
        time.sleep(10)  # the signal, if it came after the call, interrupts this
    except KeyboardInterrupt:
        latency = time.perf_counter() - sent[0]
    finally:
        timer.cancel()
    return not returned, latency


def _long_frame_folder(root, frames):
    """A folder of `frames` OBJ frames of a 10 201-vertex grid written with 17 digits (links to one
    file): reading it takes about 2 ms per frame per thread."""
    random = np.random.default_rng(3)
    y, x = np.mgrid[0:101, 0:101].astype(np.float64)
    xyz = np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], 1) + random.uniform(0, 0.5, (x.size, 3))
    index = np.arange(x.size).reshape(101, 101) + 1
    a, b, c, d = index[:-1, :-1].ravel(), index[:-1, 1:].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel()
    lines = [f"v {p[0]:.17f} {p[1]:.17f} {p[2]:.17f}" for p in xyz]
    lines += [f"f {i} {j} {k}" for i, j, k in np.concatenate([np.stack([a, b, d], 1), np.stack([a, d, c], 1)])]
    frame = root / "frame.obj.data"
    frame.write_text("\n".join(lines) + "\n")
    folder = root / "frames"
    folder.mkdir()
    for t in range(frames):
        (folder / f"f{t:05d}.obj").symlink_to(frame)
    return folder


# The bound the tests allow, generous for a loaded 2-core machine; on an idle one the interruption
# comes within about 20 to 30 ms (the library checks every 20 ms). Before the check, the signal
# waited for the end of the call: seconds here.
_LATENCY_BOUND = 1.0


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT is sent with os.kill")
@pytest.mark.parametrize("threads", [1, 2])
def test_ctrl_c_interrupts_a_long_read(tmp_path, threads):
    folder = _long_frame_folder(tmp_path, 1500)  # about 3 s on one thread
    interrupted, latency = _interrupted(lambda: deformseg.read_animation(folder, threads=threads), 0.3)
    assert interrupted and latency < _LATENCY_BOUND, latency
    assert deformseg.read_animation(folder, threads=threads).frames.shape[0] == 1500  # usable after it


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT is sent with os.kill")
def test_ctrl_c_interrupts_a_long_graph_matrix(characters):
    labelled = deformseg.read_motion_labels(characters / "motions.csv")[:40]
    animations = [deformseg.read_animation(characters / c["file"], clip=c["clip"]) for c in labelled]
    # 820 pairs of key-frame graphs: about 4 s on two threads
    interrupted, latency = _interrupted(lambda: deformseg.similarity_matrix(animations, policy="graph"), 0.3)
    assert interrupted and latency < _LATENCY_BOUND, latency


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT is sent with os.kill")
def test_ctrl_c_interrupts_a_long_exact_graph_edit_distance():
    nx = pytest.importorskip("networkx")
    # Two dense 20-node graphs of one label: the search runs to its 200 000 expansions, seconds.
    g1, g2 = (nx.gnp_random_graph(20, 0.5, seed=seed) for seed in (1, 2))
    for g in (g1, g2):
        nx.set_node_attributes(g, "a", "label")
    interrupted, latency = _interrupted(lambda: deformseg.ged(g1, g2), 0.3)
    assert interrupted and latency < _LATENCY_BOUND, latency


def test_a_signal_handler_that_does_not_raise_lets_the_call_finish(grid):
    calls = []
    before = signal.signal(signal.SIGINT, lambda number, frame: calls.append(number))
    try:
        animations = [deformseg.Animation(*grid(6, 6, 30, seed=k)) for k in range(6)]
        timer = threading.Timer(0.05, lambda: os.kill(os.getpid(), signal.SIGINT))
        timer.start()
        m = deformseg.similarity_matrix(animations, policy="graph")
        timer.join()
        time.sleep(0.05)
    finally:
        signal.signal(signal.SIGINT, before)
    assert calls == [signal.SIGINT] and m.shape == (6, 6)


# ---- thread counts ------------------------------------------------------------------------------

@pytest.mark.parametrize("threads", [30000, 1025, -1])
def test_a_thread_count_out_of_range_is_refused_naming_it(grid, threads):
    a = deformseg.Animation(*grid(4, 4, 6))
    message = f"threads must be a whole number in \\[0, 1024\\], got {threads}"
    with pytest.raises(deformseg.InvalidInput, match=message):
        deformseg.strain(a, threads=threads)
    with pytest.raises(deformseg.InvalidInput, match=message):
        deformseg.frame_distances(a, threads=threads)
    with pytest.raises(deformseg.InvalidInput, match=message):
        deformseg.read_animation(pathlib.Path("no-such-folder"), threads=threads)


def test_results_are_the_same_on_1_2_and_7_threads(grid):
    a = deformseg.Animation(*grid(10, 12, 40))
    strains = [deformseg.strain(a, threads=t) for t in (1, 2, 7)]
    distances = [deformseg.frame_distances(a, threads=t) for t in (1, 2, 7)]
    assert all(np.array_equal(s, strains[0]) for s in strains)
    assert all(np.array_equal(d, distances[0]) for d in distances)


def test_the_default_follows_deformseg_num_threads(grid, tmp_path):
    # A fresh interpreter, whose environment sets the default: the results are the same, and a
    # value that is not a count is refused naming it.
    script = ("import deformseg, numpy as np; from conftest import grid_animation as g; "
              "a = deformseg.Animation(*g(6, 6, 12)); print(float(deformseg.strain(a).sum()))")
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join([str(pathlib.Path(__file__).parent),
                                                               os.environ.get("PYTHONPATH", "")]))
    outputs = []
    for value in ("1", "3"):
        done = subprocess.run([sys.executable, "-c", script], env=dict(environment, DEFORMSEG_NUM_THREADS=value),
                              capture_output=True, text=True, timeout=120, check=True)
        outputs.append(done.stdout)
    assert outputs[0] == outputs[1]
    done = subprocess.run([sys.executable, "-c", script], env=dict(environment, DEFORMSEG_NUM_THREADS="many"),
                          capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode != 0 and "DEFORMSEG_NUM_THREADS is 'many'" in done.stderr
