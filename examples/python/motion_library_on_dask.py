"""A motion library on a Dask cluster (deformseg.distributed), notebook style: two shared
characters described into a store by the workers, the store's similarity matrix written by tiles
and read back a block at a time, its k-nearest-neighbour graph, and a search, each equal to the
in-process result.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/motion_library_on_dask.py ../shared/data/characters

The tests run it (CTest `python.example_dask`); without the characters or Dask's distributed
package it exits with status 77, which CTest reports as skipped. On a cluster, replace the
LocalCluster by `Client(scheduler_file=...)` (chapter 15).
"""
import pathlib
import sys
import tempfile

import numpy as np

import deformseg

try:
    from distributed import Client, LocalCluster

    from deformseg import distributed as dd
except ImportError:
    dd = None


def main():
    characters = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "../shared/data/characters")
    if not (characters / "Fox.glb").exists():
        print(f"{characters}/Fox.glb not found: run from the repository with ../shared/data beside it")
        return 77
    if dd is None:
        print("Dask's distributed package is not installed (Debian: python3-distributed)")
        return 77
    with tempfile.TemporaryDirectory(prefix="deformseg-dask-") as scratch:
        return run(characters, pathlib.Path(scratch))


def run(characters, work):
    inputs = [characters / "Fox.glb", characters / "RobotExpressive.glb"]
    # %% A cluster of two single-threaded worker processes on this machine.
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster, Client(cluster) as client:
        # %% Describe: batches of clips on the workers, each into a part store; the client merges them.
        report = dd.describe(inputs, work / "store", client, clips_per_task=4)
        print(f"described {len(report['described'])} clips into {report['clips']}; failed: {report['failed']}")
        store = deformseg.open_store(work / "store")

        # %% The matrix, by tiles of 5 x 5 clips written by the workers, never gathered whole.
        tiled = dd.matrix(store, client, out=work / "matrix", tile=5)
        print(tiled)
        print("Fox's Walk against its Run:", tiled[1, 2], "- rows 0-2 of column 10:", tiled[0:3, 10])
        same_matrix = np.array_equal(np.asarray(tiled), store.matrix())

        # %% The k-nearest-neighbour graph by blocks of 4 rows, and searches by blocks of queries.
        graph = dd.knn_graph(store, 3, client, rows_per_task=4)
        walk = store.index_of(str((characters / "Fox.glb").resolve()), "Walk")
        print("nearest to Fox's Walk:", [store.names[i].rsplit("/", 1)[-1] for i in graph.index[walk]])
        print(f"pairs aligned: {graph.pruning['aligned']} of {graph.pruning['candidates']}")
        same_graph = all(list(graph.index[i][graph.index[i] >= 0]) == [n["index"] for n in row["neighbours"]]
                         for i, row in enumerate(store.knn_graph(3)))
        query = f"{characters / 'RobotExpressive.glb'}#Running"
        found = dd.search([query], store, 3, client)[0]
        print("nearest to the robot's Running:", [n["name"].rsplit("/", 1)[-1] for n in found["neighbours"]])
    print("equal to the in-process results:", same_matrix and same_graph)
    return 0 if same_matrix and same_graph else 1


if __name__ == "__main__":  # workers start by importing this file: the run is behind this guard
    sys.exit(main())
