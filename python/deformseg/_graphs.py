"""The evolving graph in Python: its key frames and nodes as small classes, networkx conversions,
and the graph edit distance on networkx graphs or key frames (``ged``)."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Iterator, List, Optional, Tuple, Union

from . import _deformseg

if TYPE_CHECKING:  # networkx is optional: only to_networkx and ged on networkx graphs need it
    import networkx
    import numpy


def _networkx() -> Any:
    try:
        import networkx
    except ImportError as error:  # pragma: no cover - depends on the machine
        raise ImportError("to_networkx needs networkx (Debian: python3-networkx; pip: networkx)") from error
    return networkx


@dataclass(frozen=True)
class Node:
    """One node of a key frame's graph: a spatial segment of its frames.

    kind: "rigid" (an edge-connected region of rigid triangles) or "deformed" (the triangles of
    one deformed spatio-temporal segment); segment: the segment id of a deformed node, None for a
    rigid one; triangles: its number of triangles and area: its share of the mesh's area in frame
    0, both means over the key frame's frames.
    """

    kind: str
    segment: Optional[int]
    triangles: int
    area: float

    @property
    def label(self) -> str:
        """The node's label as the tool writes it: "R" for rigid, "D<segment>" for deformed."""
        return "R" if self.kind == "rigid" else f"D{self.segment}"


@dataclass(frozen=True)
class KeyFrame:
    """An interval of frames with one segment graph: frames first..last (inclusive), its nodes
    (in the library's canonical order) and its edges (pairs u < v of node indices)."""

    first: int
    last: int
    nodes: List[Node] = field(default_factory=list)
    edges: List[Tuple[int, int]] = field(default_factory=list)

    @property
    def num_frames(self) -> int:
        """The number of frames it lasts, last - first + 1."""
        return self.last - self.first + 1

    def to_networkx(self) -> "networkx.Graph":
        """A networkx.Graph of the key frame: nodes 0..n-1 with the attributes kind, segment,
        triangles, area and label (what ``ged`` compares), the graph attributes first and last.
        Needs networkx. Complexity O(n + e)."""
        graph = _networkx().Graph(first=self.first, last=self.last)
        for i, node in enumerate(self.nodes):
            graph.add_node(i, kind=node.kind, segment=node.segment, triangles=node.triangles, area=node.area,
                           label=node.label)
        graph.add_edges_from(self.edges)
        return graph


@dataclass(frozen=True)
class EvolvingGraph:
    """The evolving graph of an animation (deformseg::spatiotemporal::Evolving_graph): its key frames in time order,
    which cover frames 0..num_frames-1 exactly once, and the number of spatio-temporal segments
    (deformed node ids are in [0, num_segments)). A sequence of KeyFrame. face_segments, when
    evolving_graph was asked for it: each triangle's segment in each frame, a (T, F) int32 array,
    -1 where the triangle is rigid (what the tool's ``spatiotemporal --mesh-dir`` colours)."""

    num_frames: int
    num_segments: int
    key_frames: List[KeyFrame] = field(default_factory=list)
    face_segments: Optional["numpy.ndarray"] = field(default=None, compare=False)

    def __len__(self) -> int:
        return len(self.key_frames)

    def __getitem__(self, index: int) -> KeyFrame:
        return self.key_frames[index]

    def __iter__(self) -> Iterator[KeyFrame]:
        return iter(self.key_frames)

    def key_frame_of(self, frame: int) -> int:
        """The index of the key frame that holds `frame`. Raises InvalidInput for a frame past the
        last. Complexity O(log K)."""
        if not 0 <= frame < self.num_frames:
            raise _deformseg.InvalidInput(
                f"frame {frame} asked of an evolving graph of {self.num_frames} frames")
        low, high = 0, len(self.key_frames)
        while high - low > 1:
            middle = (low + high) // 2
            if self.key_frames[middle].first <= frame:
                low = middle
            else:
                high = middle
        return low

    def to_networkx(self) -> List["networkx.Graph"]:
        """One networkx.Graph per key frame (KeyFrame.to_networkx), in time order. Needs networkx."""
        return [k.to_networkx() for k in self.key_frames]


def evolving_graph(animation: _deformseg.Animation, *, threshold: float = 0.5, reference: Optional[str] = None,
                   reference_mesh: Optional[Union[str, "os.PathLike[str]"]] = None, sigma: Optional[float] = None,
                   min_triangles: int = 10, min_frames: int = 6, max_island: int = 30, min_area: float = 0.0, hysteresis: float = 0.0,
                   contact_distance: float = 0.01, rigid_tolerance: float = 0.002,
                   face_segments: bool = False) -> EvolvingGraph:
    """The spatio-temporal segmentation of `animation` and the evolving graph of its key frames
    (deformseg::spatiotemporal::evolving_graph with Spatiotemporal_options; the tool's ``spatiotemporal``).

    threshold (default 0.5): a triangle-frame is deformed above this normalised strain, in [0, 1];
    reference: "previous" (the default; deformed while it moves) or "rest" (away from frame 0, or from
    `reference_mesh`, and the default with it); reference_mesh (default None): a mesh file with the
    animation's connectivity in a rest pose kept apart from the frames; sigma (default None: each
    animation's 95th percentile): the strain's Gaussian normalisation sigma, fixed for every animation;
    min_triangles (default 10) and min_frames (default 6): smaller or shorter segments become rigid;
    max_island (default 30): rigid islands of at most this many triangles inside one segment join
    it (0: none); min_area (default 0): segments whose largest slice covers less than this share of
    the area become rigid; hysteresis (default 0, in [0, 1)): cells above threshold x (1 - hysteresis)
    joined to a cell above the threshold are deformed too;
    contact_distance (default 0.01) and rigid_tolerance (default 0.002), shares of the rest pose's
    diagonal: separate parts that touch, or that move as one rigid body, are neighbours (0 and 0:
    shared edges only, the thesis; deformseg::spatiotemporal::part_links).
    face_segments (default False): also each triangle's segment in each frame
    (EvolvingGraph.face_segments, 4 T F bytes).
    Node areas are shares of the mesh's area in frame 0. Raises InvalidInput as the library does.
    Complexity O(T F) besides the strain's O(T F) and part_links'. Releases the GIL.
    """
    record = _deformseg._evolving_graph(animation, threshold, reference, reference_mesh, sigma, min_triangles,
                                        min_frames, max_island, min_area, hysteresis, contact_distance,
                                        rigid_tolerance, face_segments=face_segments)
    return EvolvingGraph(record["frames"], record["segments"], [
        KeyFrame(k["first"], k["last"], [Node(n["kind"], n["segment"], n["triangles"], n["area"]) for n in k["nodes"]],
                 [tuple(edge) for edge in k["edges"]])
        for k in record["key_frames"]], record.get("face_segments"))


GraphLike = Union[KeyFrame, "networkx.Graph"]


def _labels_and_edges(graph: GraphLike, name: str) -> Tuple[List[str], List[Tuple[int, int]]]:
    if isinstance(graph, KeyFrame):
        return [node.label for node in graph.nodes], list(graph.edges)
    if not hasattr(graph, "nodes") or not hasattr(graph, "edges"):
        raise TypeError(f"{name}: expected a KeyFrame or a networkx graph, got {type(graph).__name__}")
    if getattr(graph, "is_directed", lambda: False)():
        raise ValueError(f"{name}: a directed graph; the graph edit distance compares undirected ones")
    index = {node: i for i, node in enumerate(graph.nodes)}
    labels = []
    for node, data in graph.nodes(data=True):
        if "label" not in data:
            raise ValueError(f"{name}: node {node!r} has no 'label' attribute (its kind, compared by ==)")
        labels.append(str(data["label"]))
    edges = []
    for u, v in graph.edges():
        if u == v:
            raise ValueError(f"{name}: node {u!r} has a self-loop, which the graph edit distance does not take")
        edges.append((index[u], index[v]))
    return labels, edges


def ged(g1: GraphLike, g2: GraphLike, *, method: str = "exact",
        max_expanded: int = _deformseg.EXACT_GED_MAX_EXPANDED, max_seconds: float = 0.0) -> _deformseg.GedResult:
    """The graph edit distance between two labelled graphs under unit costs (ged::Unit_costs: a node
    or edge inserted or deleted costs 1, a node relabelled 1), as the tool's ``ged`` command.

    g1, g2: networkx undirected graphs whose nodes have a 'label' attribute (compared as strings),
    or KeyFrame objects of an evolving graph (labels "R" and "D<segment>"). method: "exact"
    (default; branch and bound, exact unless `max_expanded` partial mappings, default 200000, or
    `max_seconds` per pair, default 0: none, are reached, then bounds), "bipartite" (Riesen and
    Bunke's assignment approximation, an upper bound) or "lower" (an assignment lower bound).
    Returns a GedResult (distance, exact, lower, upper, mapping: node i of g1, in the order of
    g1.nodes, to a node index of g2, or -1). Complexity: exponential in the worst case for exact
    (bounded by max_expanded), O((n + m)^3) for bipartite and lower. Releases the GIL.
    """
    labels_a, edges_a = _labels_and_edges(g1, "g1")
    labels_b, edges_b = _labels_and_edges(g2, "g2")
    return _deformseg._ged(labels_a, edges_a, labels_b, edges_b, method, max_expanded, max_seconds)


__all__ = ["EvolvingGraph", "KeyFrame", "Node", "evolving_graph", "ged"]
