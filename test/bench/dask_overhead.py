"""deformseg.distributed against the in-process functions on the same cores, run by hand:

    PYTHONPATH=build/python /usr/bin/python3 test/bench/dask_overhead.py [--copies 3,4,6] [--work DIR]
        [--k 10] [--queries 40]

A library of more than 1,000 clips is made from the shared characters: `--copies` copies of their
glTF files in DIR (default a scratch folder), copy i described at its own frame rate (30, 24, 40,
20, 60, 36, ...), so that copies are different clips. For each size, the store is described in
process, then the matrix, the k-nearest-neighbour graph and the searches of `--queries` clips
are timed in process on 1 and 2 threads and on a LocalCluster of 1 and 2 single-threaded worker
processes (started beforehand, not timed); the ratio is Dask's time to the in-process time on as
many cores. Describing is timed on 1 thread and on the cluster at the first size only. Every result is checked
equal to the in-process one.
"""
import argparse
import csv
import glob
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import deformseg
from deformseg import distributed as dd

RATES = (30, 24, 40, 20, 60, 36, 48, 15, 25, 50, 45, 32)


def timed(function, *args, **kwargs):
    start = time.perf_counter()
    result = function(*args, **kwargs)
    return time.perf_counter() - start, result


def make_copies(data, work, copies):
    """Copy i of the characters' glTF files, in work/copy-i; returns [(files, fps)]."""
    files = sorted(glob.glob(str(data / "characters" / "*.glb")))
    made = []
    for i in range(copies):
        folder = work / f"copy-{i}"
        folder.mkdir(exist_ok=True)
        for f in files:
            if not (folder / Path(f).name).exists():
                shutil.copyfile(f, folder / Path(f).name)
        made.append(([str(folder / Path(f).name) for f in files], RATES[i % len(RATES)]))
    return made


def describe_in_process(copies, folder, threads=2):
    start = time.perf_counter()
    for files, fps in copies:
        deformseg.describe_to_store(files, folder, fps=fps, threads=threads)
    return time.perf_counter() - start


def describe_on_cluster(copies, folder, client):
    start = time.perf_counter()
    for files, fps in copies:
        dd.describe(files, folder, client, fps=fps)
    return time.perf_counter() - start


def query_files_of(data, count):
    """The first `count` clips of the shared motions.csv, as FILE#CLIP."""
    with open(data / "characters" / "motions.csv", newline="") as f:
        rows = list(csv.DictReader(f))[:count]
    return [f"{data / 'characters' / r['file']}#{r['clip']}" for r in rows]


def graph_equals(graph, expected):
    return all([(int(x), float(v)) for x, v in zip(graph.index[i], graph.value[i]) if x >= 0]
               == [(n["index"], n["value"]) for n in row["neighbours"]] for i, row in enumerate(expected))


def line(what, n, base, cluster):
    ratios = ", ".join(f"{w} worker{'s' * (w > 1)} {cluster[w]:.2f} s (x{cluster[w] / base[w]:.3f})" for w in sorted(cluster))
    inside = ", ".join(f"{t} thread{'s' * (t > 1)} {base[t]:.2f} s" for t in sorted(base))
    print(f"{n:6d} clips, {what}: in process {inside}; Dask {ratios}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--copies", default="3,4,6")
    parser.add_argument("--work")
    parser.add_argument("--k", type=int, default=10)
    parser.add_argument("--queries", type=int, default=40)
    arguments = parser.parse_args()
    data = Path(os.environ.get("DEFORMSEG_DATA_DIR", Path(__file__).resolve().parents[3] / "shared" / "data"))
    work = Path(arguments.work or tempfile.mkdtemp(prefix="deformseg-dask-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    import distributed
    sizes = [int(c) for c in arguments.copies.split(",")]
    copies = make_copies(data, work, max(sizes))
    query_files = query_files_of(data, arguments.queries)
    queries = [deformseg.read_animation(q) for q in query_files]
    clusters = {}
    for workers in (1, 2):
        start = time.perf_counter()
        cluster = distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                           dashboard_address=":0")
        clusters[workers] = (cluster, distributed.Client(cluster))
        print(f"LocalCluster of {workers} worker(s) started in {time.perf_counter() - start:.2f} s", flush=True)
    try:
        for index, count in enumerate(sizes):
            folder = work / f"store-{count}"
            shutil.rmtree(folder, ignore_errors=True)
            described = describe_in_process(copies[:count], folder)
            store = deformseg.open_store(folder)
            n = len(store)
            if index == 0:
                base, cluster = {2: described}, {}
                shutil.rmtree(work / "store-1-thread", ignore_errors=True)
                base[1] = describe_in_process(copies[:count], work / "store-1-thread", threads=1)
                for w, (_, client) in clusters.items():
                    other = work / f"store-{count}-dask-{w}"
                    shutil.rmtree(other, ignore_errors=True)
                    cluster[w] = describe_on_cluster(copies[:count], other, client)
                    assert sorted(os.listdir(other)) == sorted(os.listdir(folder))
                line("describe", n, base, cluster)

            base, cluster, expected = {}, {}, None
            for t in (1, 2):
                base[t], expected = timed(store.matrix, threads=t)
            for w, (_, client) in clusters.items():
                cluster[w], tiled = timed(dd.matrix, store, client, out=work / "matrix")
                assert np.array_equal(np.asarray(tiled), expected)
            line(f"matrix (tiles of {tiled.tile})", n, base, cluster)

            for t in (1, 2):
                base[t], expected = timed(store.knn_graph, arguments.k, threads=t)
            for w, (_, client) in clusters.items():
                cluster[w], graph = timed(dd.knn_graph, store, arguments.k, client)
                assert graph_equals(graph, expected)
            aligned = graph.pruning["aligned"] / graph.pruning["candidates"]
            line(f"knn graph, k = {arguments.k} ({100 * aligned:.2f} % of pairs aligned)", n, base, cluster)

            for t in (1, 2):
                base[t], expected = timed(lambda: [store.search(q, arguments.k, threads=t) for q in queries])
            for w, (_, client) in clusters.items():
                cluster[w], found = timed(dd.search, queries, store, arguments.k, client)
                assert found == expected
            line(f"{len(queries)} searches of Animations", n, base, cluster)
            for t in (1, 2):
                base[t], expected = timed(lambda: [store.search(deformseg.read_animation(q), arguments.k, threads=t)
                                                   for q in query_files])
            for w, (_, client) in clusters.items():
                cluster[w], found = timed(dd.search, query_files, store, arguments.k, client)
                assert found == expected
            line(f"{len(queries)} searches of files (read where searched)", n, base, cluster)
            del store
            shutil.rmtree(folder)
    finally:
        for cluster, client in clusters.values():
            client.close()
            cluster.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
