"""deformseg.distributed on a LocalCluster of two worker processes: every result equals the
in-process one, bit for bit, for tasks of 1, 3 and 7 clips (so that edge tiles occur), and the
described store equals describe_to_store's byte for byte; a worker killed in the middle of a run
changes nothing; the scheduler-file recipe, started as separate processes on the loopback
address, works and shuts down; an unreadable clip names its file and is skipped or stops the run,
the store left valid. CTest runs this file as a test of its own, with a time budget; without
Dask's distributed package it is reported as skipped, with the reason."""
import filecmp
import os
import pathlib
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

distributed = pytest.importorskip("distributed", reason="Dask's distributed package is not installed "
                                  "(Debian: python3-distributed)")
import cloudpickle  # noqa: E402 (Dask's own dependency)

import deformseg  # noqa: E402
from deformseg import distributed as dd  # noqa: E402

# The worker plugin below is defined here, a module the workers cannot import: send it by value.
cloudpickle.register_pickle_by_value(sys.modules[__name__])

SIZES = (1, 3, 7)


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, distributed.Client(cluster) as c:
        yield c


@pytest.fixture(scope="module")
def inputs(characters):
    """Two small characters: 17 clips."""
    return [str(characters / "Fox.glb"), str(characters / "RobotExpressive.glb")]


@pytest.fixture(scope="module")
def reference(inputs, tmp_path_factory):
    """The store describe_to_store writes in process, opened, with its matrix and graph."""
    folder = tmp_path_factory.mktemp("reference") / "S"
    deformseg.describe_to_store(inputs, folder)
    store = deformseg.open_store(folder)
    return store, store.matrix(), store.knn_graph(4)


def same_files(a, b):
    """The store folders hold the same files, byte for byte (the lock file aside)."""
    names = sorted(set(os.listdir(a)) - {"lock"})
    assert names == sorted(set(os.listdir(b)) - {"lock"})
    return all(filecmp.cmp(pathlib.Path(a) / n, pathlib.Path(b) / n, shallow=False) for n in names)


def graph_equals(graph, expected):
    """A KnnGraph's arrays equal MotionStore.knn_graph's lists, index for index, value for value."""
    for i, row in enumerate(expected):
        found = [(int(x), float(v)) for x, v in zip(graph.index[i], graph.value[i]) if x >= 0]
        if found != [(n["index"], n["value"]) for n in row["neighbours"]]:
            return False
    return True


class KillOnce(distributed.WorkerPlugin):
    """Kills its worker process (SIGKILL, as the kernel's OOM killer does) when it starts the
    `after`-th task of a run whose keys start with `prefix`, once per marker file."""

    def __init__(self, prefix, after, marker):
        self.prefix, self.after, self.marker, self.started = prefix, after, marker, 0

    def transition(self, key, start, finish, **kwargs):
        if finish != "executing" or not str(key).startswith(self.prefix):
            return
        self.started += 1
        if self.started >= self.after and not os.path.exists(self.marker):
            pathlib.Path(self.marker).touch()
            os.kill(os.getpid(), signal.SIGKILL)


@pytest.fixture
def kill_once(client, tmp_path):
    """Registers KillOnce(prefix, after) on the workers; returns the marker that says it fired."""
    marker = tmp_path / "killed"

    def register(prefix, after):
        client.register_worker_plugin(KillOnce(prefix, after, str(marker)), name="kill-once")
        return marker

    yield register
    client.unregister_worker_plugin("kill-once")
    client.wait_for_workers(2, timeout=60)


# ---- equal to the in-process results ------------------------------------------------------------

@pytest.mark.parametrize("size", SIZES)
def test_describe_writes_the_store_describe_to_store_writes(client, inputs, reference, tmp_path, size):
    report = dd.describe(inputs, tmp_path / "S", client, clips_per_task=size)
    store = reference[0]
    assert report["described"] == store.names and report["failed"] == [] and report["clips"] == len(store)
    assert same_files(store.folder, tmp_path / "S")
    assert [p.name for p in tmp_path.iterdir()] == ["S"]  # the part stores removed
    again = dd.describe(inputs, tmp_path / "S", client, clips_per_task=size)
    assert again["skipped"] == store.names and again["described"] == [] and same_files(store.folder, tmp_path / "S")


def test_describe_plays_each_clip_on_its_body(client, characters, tmp_path):
    # A labels CSV of one clip on two bodies: the workers play each clip on its row's body, and the
    # store is describe_to_store's, byte for byte.
    knight, barbarian = characters / "Knight.glb", characters / "Barbarian.glb"
    labels = tmp_path / "labels.csv"
    labels.write_text(f"file,clip,motion,body_file\n{knight},Idle,idle,{barbarian}\n{knight},Idle,idle,\n"
                      f"{knight},Walking_A,walk,{barbarian}\n")
    expected = deformseg.describe_to_store(labels, tmp_path / "reference")
    report = dd.describe(labels, tmp_path / "S", client, clips_per_task=2)
    assert report["described"] == expected["described"] and report["failed"] == []
    assert same_files(tmp_path / "reference", tmp_path / "S")


@pytest.mark.parametrize("size", SIZES)
def test_the_matrix_by_tiles_is_the_matrix(client, reference, tmp_path, size):
    store, expected, _ = reference
    tiled = dd.matrix(store, client, out=tmp_path / "M", tile=size)
    assert np.array_equal(np.asarray(tiled), expected)
    n = len(store)
    assert tiled.shape == (n, n) and tiled.tile == size
    assert np.array_equal(tiled[2:9, 5:n], expected[2:9, 5:n]) and np.array_equal(tiled[-1], expected[-1])
    assert tiled[3, 4] == expected[3, 4]
    tiles = sorted(p.name for p in (tmp_path / "M").iterdir() if p.name.startswith("tile-"))
    blocks = -(-n // size)
    assert len(tiles) == blocks * (blocks + 1) // 2  # on and above the diagonal only
    assert np.array_equal(np.asarray(dd.open_matrix(tmp_path / "M")), expected)


@pytest.mark.parametrize("size", SIZES)
def test_the_knn_graph_by_blocks_is_the_graph(client, reference, size):
    store, _, expected = reference
    by_rows = dd.knn_graph(store, 4, client, rows_per_task=size)
    assert graph_equals(by_rows, expected)
    counts = {name: sum(row["pruning"][name] for row in expected) for name in expected[0]["pruning"]}
    counts["pruned_share"] = 1 - counts["aligned"] / counts["candidates"]
    assert by_rows.pruning == pytest.approx(counts)  # the same searches
    by_tiles = dd.knn_graph(store, 4, client, rows_per_task=size, candidates_per_task=size)
    assert graph_equals(by_tiles, expected)
    assert by_tiles.pruning["candidates"] == len(store) * (len(store) - 1)


@pytest.mark.parametrize("size", SIZES)
def test_searches_on_the_cluster_are_the_store_searches(client, reference, fox, size):
    store = reference[0]
    queries = [deformseg.read_animation(fox, clip="Walk"), f"{fox}#Run", f"{fox}#Survey",
               deformseg.read_animation(fox, clip="Run", fps=24)]
    found = dd.search(queries, store, 5, client, queries_per_task=size)
    animations = [q if isinstance(q, deformseg.Animation) else deformseg.read_animation(q) for q in queries]
    assert found == [store.search(q, 5) for q in animations]


def test_without_a_client_a_local_cluster_is_started_for_the_call(reference):
    store, _, expected = reference
    assert graph_equals(dd.knn_graph(store, 4), expected)


def test_a_script_without_the_main_guard_is_refused_at_once(reference, tmp_path):
    # Saved as a script and run, its workers would import it again and start clusters of their own
    # without end: the call refuses before starting any, naming the script's line.
    store, _, _ = reference
    script = tmp_path / "unguarded.py"
    script.write_text(f"from deformseg import distributed\n\ndistributed.knn_graph({str(store.folder)!r}, 4)\n")
    started = time.monotonic()
    done = subprocess.run([sys.executable, script], capture_output=True, text=True, timeout=300)
    assert done.returncode != 0 and time.monotonic() - started < 60, done.stderr[-2000:]
    assert f"{script}:3: deformseg.distributed starts worker processes" in done.stderr, done.stderr[-2000:]
    assert "if __name__ == \"__main__\":" in done.stderr and "Traceback" in done.stderr
    assert "nanny" not in done.stderr.lower(), done.stderr[-2000:]  # no worker was started


def test_progress_shows_dask_s_bar(client, reference, capsys):
    store, _, expected = reference
    assert graph_equals(dd.knn_graph(store, 4, client, rows_per_task=2, progress=True), expected)
    assert "100% Completed" in capsys.readouterr().out


# ---- faults ---------------------------------------------------------------------------------------

def test_a_worker_killed_during_the_matrix_changes_nothing(client, reference, kill_once, tmp_path):
    store, expected, _ = reference
    marker = kill_once("deformseg-matrix", after=20)
    tiled = dd.matrix(store, client, out=tmp_path / "M", tile=1)
    assert marker.exists()  # it was killed
    assert np.array_equal(np.asarray(tiled), expected)


def test_a_worker_killed_while_describing_changes_nothing(client, inputs, reference, kill_once, tmp_path):
    marker = kill_once("deformseg-describe", after=3)
    report = dd.describe(inputs, tmp_path / "S", client, clips_per_task=2)
    assert marker.exists()
    assert report["described"] == reference[0].names
    assert same_files(reference[0].folder, tmp_path / "S")


def write_frames(folder, broken=False):
    """A tetrahedron stretched over four OBJ frames; with `broken`, frame 2 has a vertex of two
    coordinates."""
    folder.mkdir()
    for f in range(4):
        s = 1 + 0.2 * f
        vertex = "v 1 2" if broken and f == 2 else f"v 0 0 {s}"
        (folder / f"frame{f}.obj").write_text(f"v 0 0 0\nv 1 0 0\nv 0 1 0\n{vertex}\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n")
    return folder


def test_an_unreadable_clip_stops_the_run_or_is_skipped(client, fox, tmp_path):
    good, bad = write_frames(tmp_path / "good"), write_frames(tmp_path / "bad", broken=True)
    truncated = tmp_path / "truncated.glb"
    truncated.write_bytes(fox.read_bytes()[:5000])
    inputs = [f"{fox}#Walk", str(good), str(bad), f"{fox}#Run"]
    folder = tmp_path / "S"
    deformseg.describe_to_store(f"{fox}#Survey", folder)
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    with pytest.raises(deformseg.InvalidInput, match=r"bad/frame2\.obj:4: frame 2: a v line needs 3 coordinates"):
        dd.describe(inputs, folder, client, clips_per_task=1)
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before  # as it was
    assert sorted(p.name for p in tmp_path.iterdir()) == ["S", "bad", "good", "truncated.glb"]  # no part left

    with pytest.raises(deformseg.InvalidInput, match="truncated.glb"):
        dd.describe([*inputs, truncated], folder, client)  # found by the plan, on the client

    report = dd.describe([*inputs, truncated], folder, client, clips_per_task=3, on_error="skip")
    assert [f["name"] for f in report["failed"]] == [str(truncated), str(bad.resolve())]
    assert "truncated.glb" in report["failed"][0]["error"] and "frame2.obj" in report["failed"][1]["error"]
    assert report["described"] == [f"{fox.resolve()}#Walk", f"{fox.resolve()}#Run", str(good.resolve())]
    store = deformseg.open_store(folder, verify="checksums")
    assert len(store) == 4 and store.index_of(str(bad.resolve())) is None
    expected = tmp_path / "expected"
    deformseg.describe_to_store([f"{fox}#Survey"], expected)
    deformseg.describe_to_store([f"{fox}#Walk", str(good), f"{fox}#Run"], expected)
    assert np.array_equal(store.matrix(), deformseg.open_store(expected).matrix())  # a file's clips together


def test_a_store_appended_to_during_a_run_is_refused_by_the_tasks(client, fox, tmp_path):
    folder = tmp_path / "S"
    deformseg.describe_to_store(f"{fox}#Walk", folder)
    generation = deformseg.open_store(folder).generation
    deformseg.describe_to_store(f"{fox}#Run", folder)  # as if another process appended meanwhile
    future = client.submit(dd._knn_block, str(folder), generation, 1, range(0, 1), None)
    with pytest.raises(deformseg.InvalidInput, match=f"appended to during the run .generation {generation + 1}"):
        future.result()
    with pytest.raises(deformseg.InvalidInput, match="matrix.json: no matrix here"):
        dd.open_matrix(tmp_path)
    (tmp_path / "M").mkdir()
    (tmp_path / "M" / "notes.txt").write_text("mine")
    with pytest.raises(deformseg.InvalidInput, match=r"holds files that are not a matrix's \(notes.txt\)"):
        dd.matrix(folder, client, out=tmp_path / "M")
    assert (tmp_path / "M" / "notes.txt").read_text() == "mine"


# ---- the scheduler-file recipe ---------------------------------------------------------------------

def test_the_scheduler_file_recipe_on_the_loopback_address(reference, tmp_path):
    store, expected, graph = reference
    scheduler_file = tmp_path / "scheduler.json"
    common = ["--scheduler-file", str(scheduler_file), "--no-dashboard"]
    scheduler = subprocess.Popen(["dask", "scheduler", "--host", "127.0.0.1", *common],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    workers = []
    try:
        deadline = time.monotonic() + 60
        while not scheduler_file.exists():
            assert time.monotonic() < deadline and scheduler.poll() is None, "the scheduler did not start"
            time.sleep(0.1)
        workers = [subprocess.Popen(["dask", "worker", "--nthreads", "1", "--host", "127.0.0.1", *common],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) for _ in range(2)]
        with distributed.Client(scheduler_file=str(scheduler_file)) as c:
            c.wait_for_workers(2, timeout=60)
            assert all(address.startswith("tcp://127.0.0.1:") for address in c.scheduler_info()["workers"])
            assert graph_equals(dd.knn_graph(store, 4, c, rows_per_task=3), graph)
            assert np.array_equal(np.asarray(dd.matrix(store, c, out=tmp_path / "M", tile=7)), expected)
            c.shutdown()
        for process in [scheduler, *workers]:
            process.wait(timeout=60)
    finally:
        for process in [scheduler, *workers]:
            if process.poll() is None:
                process.kill()
                process.wait()
