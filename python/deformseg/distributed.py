"""A motion library on a Dask cluster: describe clips into a store, its similarity matrix, its
k-nearest-neighbour graph and searches, as tasks on ``dask.distributed`` workers.

Each function takes a ``distributed.Client`` (``client=None``: a ``LocalCluster`` of one worker
process per core, started for the call and closed after it) and gives exactly what the in-process
functions give, bit for bit, whatever the number of workers and the sizes of the tasks: a task is a
tile of the matrix (``MotionStore.matrix(rows=..., columns=...)``), a block of rows of the graph
(``MotionStore.knn_graph(rows=..., candidates=...)``), a block of queries, or a batch of clips to
describe. Workers open the store by its path, so the store and the clips' files must be where
every worker reads them (one machine, or a shared filesystem), and cache it per process.

Describing: the client plans which clips to describe (those the store lacks or holds changed),
each task describes a batch into a part store of its own, and the client, the one writer, merges
the parts into the store in the clips' order in one commit: the store is the one
``describe_to_store`` writes. A task rerun after a worker died writes a new part; the one its
future returns is merged.

The task keys start with ``deformseg-describe``, ``deformseg-matrix``, ``deformseg-knn`` and
``deformseg-search``, as the dashboard's task stream shows them; ``progress=True`` shows
``distributed.progress``. Chapter 15 of the manual gives the recipes for Slurm and Kubernetes and
how to size the tasks.
"""
import ast
import contextlib
import dataclasses
import functools
import itertools
import json
import math
import os
import shutil
import sys
import uuid

import numpy as np

try:
    import distributed as _dask
except ImportError as error:  # pragma: no cover - the message is the point
    raise ImportError("deformseg.distributed needs Dask's distributed package (Debian: python3-distributed, "
                      "pip: distributed)") from error

from . import _deformseg
from ._deformseg import InvalidInput

__all__ = ["KnnGraph", "TiledMatrix", "describe", "knn_graph", "matrix", "open_matrix", "search"]

_PRUNING = ("candidates", "pruned_by_summary", "pruned_by_rows", "abandoned", "aligned", "rows_aligned",
            "rows_abandoned")
_MATRIX_FORMAT = "deformseg-matrix-tiles"
_STOP = "stop"  # in a describe run's folder of parts: the run failed, tasks not yet started return


# ---- the cluster ---------------------------------------------------------------------------------

def _guarded_lines(tree):
    """The line ranges of the module-level ``if __name__ == "__main__":`` blocks of a parsed script."""
    for statement in tree.body:
        test = statement.test if isinstance(statement, ast.If) else None
        if (isinstance(test, ast.Compare) and isinstance(test.left, ast.Name) and test.left.id == "__name__"
                and len(test.comparators) == 1 and isinstance(test.comparators[0], ast.Constant)
                and test.comparators[0].value == "__main__"):
            yield statement.body[0].lineno, statement.end_lineno


def _script_line():
    """The script run as ``python SCRIPT`` and the line of its top level that led here, or None
    (an interactive session, a notebook, ``python -c``)."""
    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    frame = sys._getframe(1)
    while frame is not None and not (frame.f_globals is vars(main) and frame.f_code.co_name == "<module>"):
        frame = frame.f_back
    if frame is None or path is None or not os.path.isfile(path):
        return None
    return path, frame.f_lineno


def _require_main_guard():
    """Refuses to start worker processes from a script's top level outside of
    ``if __name__ == "__main__":``. Dask starts its workers with 'spawn': each imports the script
    again, which would start a cluster of its own, fail, and be restarted by its nanny without end."""
    where = _script_line()
    if where is None:
        return
    path, line = where
    try:
        with open(path, encoding="utf-8") as source:
            tree = ast.parse(source.read(), path)
    except (OSError, SyntaxError, UnicodeDecodeError):
        return  # a script we cannot read: nothing to say of it
    if not any(first <= line <= last for first, last in _guarded_lines(tree)):
        raise RuntimeError(f"{path}:{line}: deformseg.distributed starts worker processes, and each imports this "
                           "script again: put the script's work under 'if __name__ == \"__main__\":' (chapter 15 "
                           "of the manual), or pass a client of a cluster started elsewhere")


@contextlib.contextmanager
def _client_of(client):
    """`client`, or a LocalCluster of one single-threaded worker process per core for the call,
    refused from a script's top level without the ``__main__`` guard (`_require_main_guard`)."""
    if client is not None:
        yield client
        return
    _require_main_guard()
    with _dask.LocalCluster(n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True,
                            dashboard_address=":0") as cluster, _dask.Client(cluster) as local:
        yield local


def _threads(client):
    """The worker threads of the cluster, at least 1."""
    return max(1, sum(client.nthreads().values()))


def _run(client, futures, progress, stop=None):
    """The futures' results in their order. On the first error, it is raised after the others are
    cancelled, or, with `stop`, after `stop()` and every task has ended (a task already running
    cannot be cancelled: `stop` tells those not yet started to return at once, so that nothing
    writes after the caller cleans up)."""
    if progress:
        _dask.progress(futures)
    try:
        return client.gather(futures)
    except BaseException:
        if stop is None:
            client.cancel(futures)
        else:
            stop()
            _dask.wait(futures)
        raise


def _keys(kind, count):
    """Task keys `deformseg-KIND-RUN-I`: named for the dashboard, unique to the run."""
    run = uuid.uuid4().hex[:12]
    return [f"deformseg-{kind}-{run}-{i}" for i in range(count)]


def _blocks(n, size):
    """The ranges of `size` clips (the last one shorter) that cover n clips."""
    return [range(b, min(n, b + size)) for b in range(0, n, size)]


def _checked_size(value, name):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ValueError(f"{name} must be a positive integer or None, got {value!r}")
    return value


# ---- the store, on the workers -------------------------------------------------------------------

def _folder_of(store):
    """A store (a MotionStore or its folder) as an absolute folder, which every worker can open."""
    folder = store.folder if isinstance(store, _deformseg.MotionStore) else os.fspath(store)
    return os.path.abspath(folder)


@functools.lru_cache(maxsize=4)
def _opened(folder, stamp):
    del stamp  # part of the key: a store committed again since is opened again
    return _deformseg.open_store(folder)


def _store(folder, generation):
    """The store in `folder`, opened once per worker process and commit; refused when it is no longer
    the generation the run started on."""
    manifest = os.stat(os.path.join(folder, "store.json"))
    store = _opened(folder, (manifest.st_mtime_ns, manifest.st_size, manifest.st_ino))
    if store.generation != generation:
        raise InvalidInput(f"{folder}: the store was appended to during the run (generation {store.generation}, "
                           f"the run started at {generation}); run it again")
    return store


def _opened_on_client(store):
    folder = _folder_of(store)
    opened = _deformseg.open_store(folder)
    return folder, opened


# ---- describing ----------------------------------------------------------------------------------

def _describe_on_bodies(clips, part, options):
    """Describes `clips`, (input, body) pairs, into the store `part` in their order: each run of
    clips on one body by one describe_to_store (a body is an option of all its inputs)."""
    for body, run in itertools.groupby(clips, key=lambda clip: clip[1]):
        on_body = dict(options, body=body) if body else {k: v for k, v in options.items() if k != "body"}
        _deformseg.describe_to_store([clip for clip, _ in run], part, threads=1, **on_body)


def _describe_batch(clips, root, options, on_error):
    """Task: describes clips `clips` (dicts of name, input and body) into a new part store below
    `root`; returns (its folder or None, the clips that could not be described with their errors,
    when `on_error` is 'skip')."""
    if os.path.exists(os.path.join(root, _STOP)):  # the run failed: nothing more to write
        return None, []
    part = os.path.join(root, uuid.uuid4().hex)
    try:
        _describe_on_bodies([(c["input"], c["body"]) for c in clips], part, options)
        return part, []
    except InvalidInput:
        if on_error == "raise":
            shutil.rmtree(part, ignore_errors=True)
            raise
    shutil.rmtree(part, ignore_errors=True)  # what it committed before the bad clip: made again below
    failed = []
    for clip in clips:
        try:
            _describe_on_bodies([(clip["input"], clip["body"])], part, options)
        except InvalidInput as error:
            failed.append({"name": clip["name"], "error": str(error)})
    return (part if len(failed) < len(clips) else None), failed


def _plan(inputs, folder, on_error, options):
    """The clips to describe (_describe_plan's dict) and the inputs that cannot be planned (a glTF
    file that cannot be parsed, a missing file), with on_error 'skip': planned one by one, the
    others then planned together, so that the order is describe_to_store's for them."""
    try:
        return _deformseg._describe_plan(inputs, folder, **options), []
    except InvalidInput as first_error:
        if on_error == "raise":
            raise
        paths = [inputs] if isinstance(inputs, (str, os.PathLike)) else list(inputs)
        good, failed = [], []
        for path in paths:
            try:
                _deformseg._describe_plan([path], folder, **options)
                good.append(path)
            except InvalidInput as error:
                failed.append({"name": os.fspath(path), "error": str(error)})
        if not good:
            raise first_error
        return _deformseg._describe_plan(good, folder, **options), failed


def describe(inputs, store, client=None, *, clips_per_task=None, on_error="raise", parts=None, progress=False,
             hash=False, **options):
    """Describes clips into the motion store in the folder `store` on the cluster, as
    describe_to_store(inputs, store, hash=hash, **options) does: the same store, byte for byte.

    inputs, options (fps, topology, triangulate, weld, refuse_defects, clip, body, up, bands,
    sides) and hash are describe_to_store's; the clips to describe are planned on the client (new
    and changed ones, unchanged ones skipped; a clip on each of its bodies, a labels row's on its
    body_file), described in batches of `clips_per_task` (default: about four batches per worker
    thread, at most 32 clips) each into a part store of its own below `parts` (default
    a hidden folder beside the store, removed after), then merged into the store by the client, the
    one writer, in one commit. on_error: 'raise' (default) stops at the first clip (or input) that
    cannot be read or described, raising InvalidInput naming its file, and leaves the store as it
    was; 'skip' leaves such clips and inputs out and lists them. Returns describe_to_store's dict,
    with 'failed': a list of dicts of name (the clip, or the input that could not be listed) and
    error.
    """
    if on_error not in ("raise", "skip"):
        raise ValueError(f"on_error must be 'raise' or 'skip', got {on_error!r}")
    clips_per_task = _checked_size(clips_per_task, "clips_per_task")
    if "threads" in options:
        raise TypeError("describe: the workers' threads are the cluster's (each task describes on one)")
    folder = _folder_of(store)
    plan, failed = _plan(inputs, folder, on_error, dict(options, hash=hash))
    worker_options = {name: value for name, value in options.items() if name != "clip"}
    worker_options["hash"] = hash
    clips = [{"name": name, "input": clip, "body": body}  # a clip's body is apart from its input
             for name, clip, body in zip(plan["describe"], plan["inputs"], plan["bodies"])]
    root = os.path.join(os.path.abspath(parts) if parts else os.path.dirname(folder),
                        f".{os.path.basename(folder)}.parts-{uuid.uuid4().hex[:12]}")
    merged = {"clips": plan["clips"], "described": [], "redescribed": []}
    try:
        if clips:
            with _client_of(client) as c:
                size = clips_per_task or max(1, min(32, math.ceil(len(clips) / (4 * _threads(c)))))
                batches = [clips[b:b + size] for b in range(0, len(clips), size)]
                keys = _keys("describe", len(batches))
                os.makedirs(root)
                futures = [c.submit(_describe_batch, batch, root, worker_options, on_error, key=key)
                           for batch, key in zip(batches, keys)]
                results = _run(c, futures, progress, stop=lambda: open(os.path.join(root, _STOP), "w").close())
            for _, batch_failed in results:
                failed += batch_failed
            merged = _deformseg._merge_stores(folder, [part for part, _ in results if part is not None])
    finally:
        shutil.rmtree(root, ignore_errors=True)
    return {"store": folder, "clips": merged["clips"], "described": merged["described"],
            "redescribed": merged["redescribed"], "skipped": plan["skipped"],
            "poses_left_out": plan["poses_left_out"], "failed": failed}


# ---- the matrix, by tiles ------------------------------------------------------------------------

def _tile_name(rows, columns):
    return f"tile-{rows.start:09d}-{columns.start:09d}.npy"


def _matrix_tile(folder, generation, rows, columns, out):
    """Task: the tile of `rows` and `columns`, saved into `out` whole or not at all."""
    values = _store(folder, generation).matrix(rows=rows, columns=columns, threads=1)
    name = _tile_name(rows, columns)
    partial = os.path.join(out, f".{name}.{uuid.uuid4().hex}")
    with open(partial, "wb") as f:
        np.save(f, values)
    os.replace(partial, os.path.join(out, name))
    return name


def _default_tile(store, threads):
    """The clips per side of tiles of about a second (an aligned pair of rows takes some 15 ns on a
    2020s core), and at least four tasks per worker thread."""
    n = len(store)
    if n == 0:
        return 1
    rows = np.mean([store.signatures(i).shape[0] for i in range(0, n, max(1, n // 256))])
    by_time = max(1, int(math.sqrt(1.0 / (15e-9 * rows * rows))))
    by_tasks = max(1, math.ceil(n / math.ceil(math.sqrt(8 * threads))))
    return min(by_time, by_tasks)


def _clear_matrix_folder(out):
    """Makes `out` ready for a new matrix: created when missing, an earlier matrix's files removed
    (its manifest first, so that no manifest ever names tiles of two runs); refuses other files."""
    os.makedirs(out, exist_ok=True)
    entries = sorted(os.listdir(out))
    others = [e for e in entries if e != "matrix.json" and not e.startswith(("tile-", ".tile-", ".matrix.json."))]
    if others:
        raise InvalidInput(f"{out}: the folder holds files that are not a matrix's ({', '.join(others[:3])}); "
                           "name an empty folder or an earlier matrix's")
    for entry in sorted(entries, key=lambda e: e != "matrix.json"):
        os.remove(os.path.join(out, entry))


def matrix(store, client=None, *, out, tile=None, progress=False):
    """The similarity of every pair of the store's clips, as MotionStore.matrix() gives it, bit for
    bit, computed by tiles on the cluster and written by the workers into the folder `out` (made
    when missing; an earlier matrix there is replaced): one .npy file per tile on or above the
    diagonal, and matrix.json, written last, listing them. Never gathered on the client: read it
    with the returned TiledMatrix (or open_matrix(out) later). tile (default: tiles of about a
    second and at least four tasks per worker thread): the clips per side of a tile.
    """
    tile = _checked_size(tile, "tile")
    folder, opened = _opened_on_client(store)
    n, generation = len(opened), opened.generation
    out = os.path.abspath(os.fspath(out))
    _clear_matrix_folder(out)
    with _client_of(client) as c:
        size = tile or _default_tile(opened, _threads(c))
        blocks = _blocks(n, size)
        pairs = [(r, c_) for i, r in enumerate(blocks) for c_ in blocks[i:]]
        futures = [c.submit(_matrix_tile, folder, generation, r, c_, out, key=key)
                   for (r, c_), key in zip(pairs, _keys("matrix", len(pairs)))]
        names = _run(c, futures, progress)
    manifest = {"format": _MATRIX_FORMAT, "version": 1, "store": folder, "generation": generation, "clips": n,
                "tile": size, "tiles": [[r.start, c_.start, name] for (r, c_), name in zip(pairs, names)]}
    partial = os.path.join(out, f".matrix.json.{uuid.uuid4().hex}")
    with open(partial, "w") as f:
        json.dump(manifest, f, indent=1)
        f.flush()
        os.fsync(f.fileno())
    os.replace(partial, os.path.join(out, "matrix.json"))
    return TiledMatrix(out)


class TiledMatrix:
    """A similarity matrix written by tiles (matrix(..., out=F)), read a block at a time: m[rows,
    columns] with slices (of step 1) or integers gives a NumPy array, assembled from the tiles it
    crosses (those below the diagonal as their mirrors' transposes); np.asarray(m) the whole
    matrix. Tiles are memory-mapped, so a block reads only its bytes."""

    def __init__(self, folder):
        self.folder = os.path.abspath(os.fspath(folder))
        path = os.path.join(self.folder, "matrix.json")
        try:
            with open(path) as f:
                manifest = json.load(f)
        except FileNotFoundError:
            raise InvalidInput(f"{path}: no matrix here (matrix.json is written last: the run did not finish)")
        except (OSError, ValueError) as error:
            raise InvalidInput(f"{path}: not a matrix's manifest: {error}") from None
        if not isinstance(manifest, dict) or manifest.get("format") != _MATRIX_FORMAT or manifest.get("version") != 1:
            raise InvalidInput(f"{path}: not a version 1 {_MATRIX_FORMAT} manifest")
        self.store, self.generation = manifest["store"], manifest["generation"]
        self.tile, n = manifest["tile"], manifest["clips"]
        self.shape = (n, n)
        self._files = {(r, c): name for r, c, name in manifest["tiles"]}

    def __repr__(self):
        return f"<deformseg.distributed.TiledMatrix {self.folder}: {self.shape[0]} clips, tiles of {self.tile}>"

    def _tile(self, r, c):
        """The tile whose first row is r and first column c (or its mirror's transpose)."""
        if r <= c:
            return np.load(os.path.join(self.folder, self._files[(r, c)]), mmap_mode="r")
        return self._tile(c, r).T

    def _range(self, key, name):
        n = self.shape[0]
        if isinstance(key, (int, np.integer)):
            if not -n <= key < n:
                raise IndexError(f"{name} {key} is out of range for {n} clips")
            key = int(key) % n
            return range(key, key + 1), True
        if isinstance(key, slice) and key.step in (None, 1):
            return range(*key.indices(n))[:], False
        raise TypeError(f"{name}: expected an integer or a slice of step 1, got {key!r}")

    def __getitem__(self, key):
        rows, columns = key if isinstance(key, tuple) else (key, slice(None))
        (rows, drop_row), (columns, drop_column) = self._range(rows, "row"), self._range(columns, "column")
        out = np.empty((len(rows), len(columns)))
        t = self.tile
        for r in range(rows.start // t * t, rows.stop, t) if len(rows) else ():
            for c in range(columns.start // t * t, columns.stop, t) if len(columns) else ():
                r0, r1 = max(r, rows.start), min(r + t, rows.stop)
                c0, c1 = max(c, columns.start), min(c + t, columns.stop)
                out[r0 - rows.start:r1 - rows.start, c0 - columns.start:c1 - columns.start] = \
                    self._tile(r, c)[r0 - r:r1 - r, c0 - c:c1 - c]
        if drop_row:
            out = out[0]
        if drop_column:
            out = out[..., 0]
        return out

    def __array__(self, dtype=None):
        whole = self[:, :]
        return whole if dtype is None else whole.astype(dtype)


def open_matrix(folder):
    """The matrix that matrix(..., out=folder) wrote, as a TiledMatrix. Raises InvalidInput naming
    the manifest when the folder holds none (the run did not finish) or not one of this format."""
    return TiledMatrix(folder)


# ---- the k-nearest-neighbour graph and searches --------------------------------------------------

@dataclasses.dataclass
class KnnGraph:
    """Every clip's k nearest other clips, as arrays: index[i] the clips' indices, value[i] their
    values (MotionStore.knn_graph's, bit for bit), best first, ties by index; rows with fewer than k
    (a store of k clips or fewer) padded with -1 and NaN. pruning: the counts of all the searches,
    summed (with blocks of candidates, each block's search prunes on its own)."""
    index: np.ndarray
    value: np.ndarray
    pruning: dict

    def __len__(self):
        return len(self.index)


def _arrays(found, k):
    """Searches' results (dicts as search gives) as (index, value, counts) arrays, padded to k."""
    index = np.full((len(found), k), -1, dtype=np.int64)
    value = np.full((len(found), k), np.nan)
    for row, result in enumerate(found):
        for column, neighbour in enumerate(result["neighbours"]):
            index[row, column], value[row, column] = neighbour["index"], neighbour["value"]
    counts = np.array([[result["pruning"][name] for name in _PRUNING] for result in found], dtype=np.int64)
    return index, value, counts.reshape(len(found), len(_PRUNING))


def _knn_block(folder, generation, k, rows, candidates):
    """Task: the rows `rows` of the graph among `candidates`, as arrays."""
    found = _store(folder, generation).knn_graph(k, rows=rows, candidates=candidates, threads=1)
    return _arrays(found, k)


def _merge(parts, k):
    """Per row, the k best of the parts' neighbours (found among disjoint candidates): value
    descending, then index ascending, as merge_nearest ranks; the counts summed."""
    index = np.concatenate([p[0] for p in parts], axis=1)
    value = np.concatenate([p[1] for p in parts], axis=1)
    missing = index < 0
    order = np.lexsort((np.where(missing, np.iinfo(np.int64).max, index), np.where(missing, np.inf, -value)))[:, :k]
    return np.take_along_axis(index, order, axis=1), np.take_along_axis(value, order, axis=1), sum(p[2] for p in parts)


def _pruning(counts):
    total = {name: int(v) for name, v in zip(_PRUNING, counts.sum(axis=0))}
    total["pruned_share"] = (total["candidates"] - total["aligned"]) / total["candidates"] if total["candidates"] else 0.0
    return total


def _default_rows(n, threads):
    """Rows per task of about two seconds (a search costs some 3 microseconds per clip of the store:
    0.26 s of one core at 100,000 clips) and at least eight tasks per worker thread."""
    by_time = max(1, int(2.0 / (3e-6 * max(n, 1))))
    return max(1, min(by_time, math.ceil(n / (8 * threads))))


def knn_graph(store, k=10, client=None, *, rows_per_task=None, candidates_per_task=None, progress=False):
    """Every clip's k nearest other clips, as MotionStore.knn_graph(k) gives them (neighbours and
    values bit for bit), computed on the cluster by blocks of `rows_per_task` rows (default: tasks
    of about two seconds, at least eight per worker thread), each searched among all the clips, or, with
    `candidates_per_task`, among blocks of that many (the searches of a row merged on the client:
    more tasks, less pruning). Returns a KnnGraph of arrays; the counts equal the in-process
    graph's without candidate blocks."""
    if k < 1:
        raise ValueError("k must be at least 1")
    rows_per_task = _checked_size(rows_per_task, "rows_per_task")
    candidates_per_task = _checked_size(candidates_per_task, "candidates_per_task")
    folder, opened = _opened_on_client(store)
    n, generation = len(opened), opened.generation
    with _client_of(client) as c:
        size = rows_per_task or _default_rows(n, _threads(c))
        row_blocks = _blocks(n, size)
        candidate_blocks = _blocks(n, candidates_per_task) if candidates_per_task else [None]
        work = [(r, b) for r in row_blocks for b in candidate_blocks]
        futures = [c.submit(_knn_block, folder, generation, k, r, b, key=key)
                   for (r, b), key in zip(work, _keys("knn", len(work)))]
        results = _run(c, futures, progress)
    per_row_block = [results[i:i + len(candidate_blocks)] for i in range(0, len(results), len(candidate_blocks))]
    merged = [parts[0] if len(parts) == 1 else _merge(parts, k) for parts in per_row_block]
    if not merged:
        return KnnGraph(np.empty((0, k), np.int64), np.empty((0, k)), _pruning(np.zeros((0, len(_PRUNING)))))
    return KnnGraph(np.concatenate([m[0] for m in merged]), np.concatenate([m[1] for m in merged]),
                    _pruning(np.concatenate([m[2] for m in merged])))


def _search_block(folder, generation, queries, k):
    """Task: each query (a description, or a path read_animation reads) searched in the store."""
    store = _store(folder, generation)
    return [store.search(q if isinstance(q, np.ndarray) else _deformseg.read_animation(q), k, threads=1)
            for q in queries]


def search(queries, store, k=10, client=None, *, queries_per_task=None, progress=False):
    """Each query's k nearest clips of the store, as MotionStore.search(query, k) gives them (a
    list of its dicts, in the queries' order, counts included), searched on the cluster in blocks
    of `queries_per_task` (default: about four blocks per worker thread). A query is an Animation,
    described on the client (MotionStore.describe: a description is small to send), or a path (with
    #CLIP) that read_animation reads with its defaults on the worker."""
    if k < 1:
        raise ValueError("k must be at least 1")
    queries_per_task = _checked_size(queries_per_task, "queries_per_task")
    queries = list(queries)
    for i, q in enumerate(queries):
        if not isinstance(q, (_deformseg.Animation, str, os.PathLike)):
            raise TypeError(f"queries[{i}]: expected an Animation or a path, got {type(q).__name__}")
    folder, opened = _opened_on_client(store)
    with _client_of(client) as c:
        size = queries_per_task or max(1, math.ceil(len(queries) / (4 * _threads(c))))
        keys = _keys("search", math.ceil(len(queries) / size))
        futures = []
        for b, key in zip(range(0, len(queries), size), keys):  # a block sent as soon as it is described
            block = [opened.describe(q) if isinstance(q, _deformseg.Animation) else os.path.abspath(os.fspath(q))
                     for q in queries[b:b + size]]
            futures.append(c.submit(_search_block, folder, opened.generation, block, k, key=key))
        return [found for block in _run(c, futures, progress) for found in block]
