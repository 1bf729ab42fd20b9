# Type stubs of the deformseg package (the compiled deformseg._deformseg and deformseg._graphs).
# Written by hand, kept in step by python/tests/test_stub.py, which checks it against the built
# package both ways: every public name and member, every parameter with its kind and default, and
# every Literal[...] against the front end's choices for that parameter (_deformseg._choices).
import os
from typing import Any, Callable, Iterator, List, Literal, Mapping, Optional, Protocol, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, "os.PathLike[str]"]
_Pairs = List[Tuple[int, int]]

__version__: str
EXACT_GED_MAX_EXPANDED: int

class InvalidInput(ValueError):
    file: Optional[str]
    line: Optional[int]
    frame: Optional[int]
    message: str

class SimilarityStopped(RuntimeError): ...

class Animation:
    def __init__(self, faces: npt.ArrayLike, frames: npt.ArrayLike, fps: float = 30.0) -> None: ...
    @property
    def frames(self) -> npt.NDArray[np.float64]: ...  # (T, V, 3), read-only view
    @property
    def faces(self) -> npt.NDArray[np.uint32]: ...  # (F, 3), read-only view
    @property
    def num_frames(self) -> int: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def fps(self) -> float: ...  # frames per second, set by the reader (every format) or the constructor
    @property
    def repair(self) -> Optional[dict[str, int]]: ...

def read_animation(
    path: _Path,
    clip: Union[str, int, None] = None,  # a name, or an index in the file (see clips)
    fps: float = 30.0,
    topology: Optional[_Path] = None,
    triangulate: bool = False,
    weld: Optional[bool] = None,
    refuse_defects: bool = False,
    threads: int = 0,
    body: Optional[_Path] = None,
) -> Animation: ...
# A glTF file's clips: dicts of name, index, start, end, duration, frames and channels.
def clips(path: _Path, fps: float = 30.0) -> List[dict[str, Any]]: ...
def strain(
    animation: Animation,
    *,
    reference: Literal["rest", "previous"] = "rest",
    rest_frame: int = 0,
    reference_mesh: Optional[_Path] = None,
    measure: Literal["max-principal", "green-lagrange", "frobenius", "area-ratio"] = "max-principal",
    normalize: Literal["gaussian", "none"] = "gaussian",
    sigma: Optional[float] = None,
    degenerate_tolerance: float = 1e-12,
    threads: int = 0,
) -> npt.NDArray[np.float32]: ...  # (T, F)
def frame_distances(
    animation: Animation,
    *,
    metric: Literal["euclidean", "l1", "cosine"] = "euclidean",
    rest_frame: int = 0,
    reference_mesh: Optional[_Path] = None,
    threads: int = 0,
) -> npt.NDArray[np.float32]: ...  # (T, T)
def temporal_segmentation(
    animation: Animation,
    *,
    method: Literal["optimal", "binary-split", "greedy", "barbic"] = "optimal",
    threshold: Optional[float] = None,
    absolute: bool = False,
    segments: Optional[int] = None,
    min_length: int = 1,
    metric: Literal["euclidean", "l1", "cosine"] = "euclidean",
    rest_frame: int = 0,
    reference_mesh: Optional[_Path] = None,
    threads: int = 0,
) -> _Pairs: ...

class MotionStore:
    def __len__(self) -> int: ...
    @property
    def folder(self) -> str: ...
    @property
    def generation(self) -> int: ...
    @property
    def width(self) -> int: ...
    @property
    def description(self) -> dict[str, Any]: ...  # the options the clips were described with
    @property
    def names(self) -> List[str]: ...  # "FILE" or "FILE#CLIP"
    @property
    def records(self) -> List[dict[str, Any]]: ...  # index, name, path, clip, frames, fps, rows, ...
    def index_of(self, path: _Path, clip: str = "", body: _Path = "") -> Optional[int]: ...
    def signatures(self, i: int) -> npt.NDArray[np.float32]: ...  # (R, W), read-only view of the mapping
    def frames(self, i: int) -> npt.NDArray[np.uint32]: ...  # (R,), read-only view
    # A dict: neighbours (dicts of rank, index, name, path, clip, value) and pruning (the counts).
    # candidates, rows, columns: a block of the store's clips, range(begin, end); None: all.
    def describe(self, query: Animation) -> npt.NDArray[np.float32]: ...  # (R, W), Fortran order
    def search(  # query: an Animation or its description by describe
        self,
        query: Union[Animation, npt.NDArray[np.float32]],
        k: int = 10,
        *,
        candidates: Optional[range] = None,
        threads: int = 0,
    ) -> dict[str, Any]: ...
    def nearest_to_clip(
        self, i: int, k: int = 10, *, candidates: Optional[range] = None, threads: int = 0
    ) -> dict[str, Any]: ...
    def knn_graph(  # per clip of rows, as search
        self, k: int = 10, *, rows: Optional[range] = None, candidates: Optional[range] = None, threads: int = 0
    ) -> List[dict[str, Any]]: ...
    def find(  # windows: index, name, path, clip, first, last, value, alignment
        self, query: Animation, count: int = 3, *, shortest: float = 0.5, threads: int = 0
    ) -> List[dict[str, Any]]: ...
    def matrix(
        self,
        *,
        rows: Optional[range] = None,
        columns: Optional[range] = None,
        progress: Optional[Callable[[int, int], Optional[bool]]] = None,
        threads: int = 0,
    ) -> npt.NDArray[np.float64]: ...  # (N, N), or the tile (len(rows), len(columns))

def open_store(folder: _Path, verify: Literal["structure", "checksums"] = "structure") -> MotionStore: ...
# One query's searches among disjoint blocks of clips, merged: a dict as MotionStore.search gives.
def merge_nearest(parts: Sequence[dict[str, Any]], k: int = 10) -> dict[str, Any]: ...
# A dict: store, clips, described, redescribed, skipped (lists of clip names) and poses_left_out.
def describe_to_store(
    inputs: Union[_Path, Sequence[_Path]],  # animations, glTF files (every clip), labels CSVs
    store: _Path,
    *,
    clip: Union[str, int, None] = None,
    fps: float = 30.0,
    topology: Optional[_Path] = None,
    triangulate: bool = False,
    weld: Optional[bool] = None,
    refuse_defects: bool = False,
    threads: int = 0,
    body: Optional[_Path] = None,
    up: Optional[Literal["+x", "-x", "+y", "-y", "+z", "-z", "none"]] = None,
    bands: Optional[int] = None,
    sides: Optional[Literal["+x", "-x", "+y", "-y", "+z", "-z"]] = None,
    hash: bool = False,
    skip_unreadable: bool = False,
) -> dict[str, Any]: ...

class Node:
    kind: str
    segment: Optional[int]
    triangles: int
    area: float
    def __init__(self, kind: str, segment: Optional[int], triangles: int, area: float) -> None: ...
    @property
    def label(self) -> str: ...

class KeyFrame:
    first: int
    last: int
    nodes: List[Node]
    edges: _Pairs
    def __init__(self, first: int, last: int, nodes: List[Node] = ..., edges: _Pairs = ...) -> None: ...
    @property
    def num_frames(self) -> int: ...
    def to_networkx(self) -> Any: ...  # networkx.Graph

class EvolvingGraph:
    num_frames: int
    num_segments: int
    key_frames: List[KeyFrame]
    face_segments: Optional[npt.NDArray[np.int32]]  # (T, F), -1 rigid; with evolving_graph(face_segments=True)
    def __init__(
        self,
        num_frames: int,
        num_segments: int,
        key_frames: List[KeyFrame] = ...,
        face_segments: Optional[npt.NDArray[np.int32]] = ...,
    ) -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: int) -> KeyFrame: ...
    def __iter__(self) -> Iterator[KeyFrame]: ...
    def key_frame_of(self, frame: int) -> int: ...
    def to_networkx(self) -> List[Any]: ...  # networkx.Graph per key frame

def evolving_graph(
    animation: Animation,
    *,
    threshold: float = 0.5,
    reference: Optional[Literal["previous", "rest"]] = None,
    reference_mesh: Optional[_Path] = None,
    sigma: Optional[float] = None,
    min_triangles: int = 10,
    min_frames: int = 6,
    max_island: int = 30,
    min_area: float = 0.0,
    hysteresis: float = 0.0,
    contact_distance: float = 0.01,
    rigid_tolerance: float = 0.002,
    face_segments: bool = False,
) -> EvolvingGraph: ...

class Similarity:
    @property
    def value(self) -> float: ...
    @property
    def score(self) -> float: ...
    @property
    def alignment(self) -> _Pairs: ...
    @property
    def labels_a(self) -> List[int]: ...
    @property
    def labels_b(self) -> List[int]: ...
    @property
    def compared(self) -> str: ...
    @property
    def z_score(self) -> Optional[float]: ...
    @property
    def shuffled_copies(self) -> int: ...
    @property
    def explanation(self) -> Optional[dict[str, Any]]: ...  # with explain=True: pairs, channels

def similarity(
    a: Animation,
    b: Animation,
    *,
    policy: Literal["motion-signature", "histogram", "graph", "self-similarity", "graph-characters"] = "motion-signature",
    alignment: Optional[Literal["smith-waterman", "dtw", "subsequence-dtw"]] = None,
    threshold: Optional[float] = None,
    up: Optional[Literal["+x", "-x", "+y", "-y", "+z", "-z", "none"]] = None,
    bands: Optional[int] = None,
    sides: Optional[Literal["+x", "-x", "+y", "-y", "+z", "-z"]] = None,
    significance: Optional[int] = None,
    seed: int = 1,
    explain: bool = False,
    threads: int = 0,
) -> Similarity: ...
def similarity_matrix(
    animations: Union[Sequence[Animation], MotionStore],  # a store: its clips as described, no database
    database: Optional[Sequence[Animation]] = None,
    *,
    policy: Literal["motion-signature", "histogram", "graph", "self-similarity", "graph-characters"] = "motion-signature",
    alignment: Optional[Literal["smith-waterman", "dtw", "subsequence-dtw"]] = None,
    threshold: Optional[float] = None,
    up: Optional[Literal["+x", "-x", "+y", "-y", "+z", "-z", "none"]] = None,
    bands: Optional[int] = None,
    sides: Optional[Literal["+x", "-x", "+y", "-y", "+z", "-z"]] = None,
    progress: Optional[Callable[[int, int], Optional[bool]]] = None,
    threads: int = 0,
) -> npt.NDArray[np.float64]: ...  # (N, N), or (Q, D) with a database

class MotionMatch:
    @property
    def first(self) -> int: ...
    @property
    def last(self) -> int: ...
    @property
    def value(self) -> float: ...  # the query against the window's frames described alone; 1 for a copy
    @property
    def alignment(self) -> _Pairs: ...

def find_motion(query: Animation, long_animation: Animation, count: int = 3, *, shortest: float = 0.5) -> List[MotionMatch]: ...

class RetrievalScores:
    queries: int
    queries_without_relevant: int
    queries_without_candidate: int
    nn_accuracy: Optional[float]
    mean_average_precision: Optional[float]
    roc_auc: Optional[float]
    median_same: Optional[float]
    median_different: Optional[float]
    same_pairs: int
    different_pairs: int
    labels: List[str]
    confusion: List[List[int]]
    @property
    def per_motion(self) -> List[dict[str, Any]]: ...
    @property
    def per_query(self) -> List[dict[str, Any]]: ...

class _Labelled(Protocol):  # an object with a motion; body, rig, clip and file are read when present
    motion: str

# A motion name, a dict (motion, and optionally body, rig, clip, file) or an object with a motion.
_Label = Union[str, Mapping[str, Optional[str]], _Labelled]

# With a MotionStore: labels is the path of a labels CSV, its clips looked up in the store.
def evaluate(
    similarity: Union[npt.ArrayLike, MotionStore], labels: Union[Sequence[_Label], _Path]
) -> RetrievalScores: ...
def read_motion_labels(path: _Path) -> List[dict[str, str]]: ...

class GedResult:
    distance: float
    exact: bool
    lower: float
    mapping: List[int]
    @property
    def upper(self) -> Optional[float]: ...

def ged(
    g1: Any, g2: Any, *, method: str = "exact", max_expanded: int = ..., max_seconds: float = 0.0
) -> GedResult: ...  # g1, g2: networkx.Graph or KeyFrame

__all__: List[str]
