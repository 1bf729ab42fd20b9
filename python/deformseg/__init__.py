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


_copyreg.pickle(type(strain), _reduce_builtin)

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
