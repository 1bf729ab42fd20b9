"""deformseg: segmentation and motion similarity of deforming meshes, from NumPy.

A thin, typed layer over the C++ library's default types (``Surface_mesh_animation``, float32
strains): the compiled functions come from ``deformseg._deformseg``; the evolving graph's classes,
their networkx conversion and ``ged`` on graphs are pure Python (``deformseg._graphs``). Option
names, defaults, checks and errors are those of the front end the ``deformseg`` tool is made of; every long call
releases the GIL and stops on Ctrl-C (``KeyboardInterrupt``), and no thread of the library lives
between calls, so fork-based process pools work after any call. Every result pickles, and so do the
functions (by name), so that both go to and come back from worker processes.
"""
import copyreg as _copyreg

from ._deformseg import (
    EXACT_GED_MAX_EXPANDED,
    Animation,
    GedResult,
    InvalidInput,
    MotionMatch,
    MotionStore,
    RetrievalScores,
    Similarity,
    SimilarityStopped,
    clips,
    describe_to_store,
    evaluate,
    find_motion,
    frame_distances,
    merge_nearest,
    open_store,
    read_animation,
    read_motion_labels,
    similarity,
    similarity_matrix,
    strain,
    temporal_segmentation,
    __version__,
)
from . import _deformseg
from ._graphs import EvolvingGraph, KeyFrame, Node, evolving_graph, ged


def _reduce_builtin(function):
    """Pickles the compiled functions by name, as Python functions are: pybind11 before 3.0 makes
    a capsule their __self__, which pickle cannot save (so `pool.map(deformseg.strain, ...)`
    failed). Any other built-in function is reduced as Python reduces it."""
    if getattr(function, "__module__", None) == _deformseg.__name__:
        return function.__name__  # a global: pickle finds it as deformseg._deformseg.<name>
    return function.__reduce__()


def _reduce_method(method):
    """Pickles a method as its class holds it (`type(store).search`, which `pool.map` takes) as
    that class's attribute: pybind11 wraps the methods of the compiled classes in `instancemethod`
    objects, which pickle cannot save. A bound method (`store.search`) pickles as Python's do."""
    name = method.__func__.__name__
    for owner in (Animation, GedResult, MotionMatch, MotionStore, RetrievalScores, Similarity):
        if owner.__dict__.get(name) is method:
            return getattr, (owner, name)
    raise TypeError(f"cannot pickle the method {name!r}: it is no compiled class's of deformseg")


_copyreg.pickle(type(strain), _reduce_builtin)
_copyreg.pickle(type(MotionStore.__dict__["search"]), _reduce_method)

__all__ = [
    "Animation",
    "EvolvingGraph",
    "EXACT_GED_MAX_EXPANDED",
    "GedResult",
    "InvalidInput",
    "KeyFrame",
    "MotionMatch",
    "MotionStore",
    "Node",
    "RetrievalScores",
    "Similarity",
    "SimilarityStopped",
    "clips",
    "describe_to_store",
    "evaluate",
    "evolving_graph",
    "find_motion",
    "frame_distances",
    "ged",
    "merge_nearest",
    "open_store",
    "read_animation",
    "read_motion_labels",
    "similarity",
    "similarity_matrix",
    "strain",
    "temporal_segmentation",
]
