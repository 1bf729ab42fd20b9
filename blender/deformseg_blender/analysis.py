"""The figures the panel shows, computed by the deformseg module from sampled frames: no bpy here,
so that the tests can call the same functions on frames read by deformseg itself."""
import numpy as np


def animation(ds, frames):
    """A deformseg.Animation of sampled Frames."""
    return ds.Animation(frames.faces, frames.positions, fps=frames.fps)


def strain(ds, anim, rest_frame=0):
    """Per-triangle normalised strain of every frame, (T, F) float32, against frame rest_frame
    (0: the first frame sampled), as `deformseg strain` gives it."""
    return ds.strain(anim, rest_frame=rest_frame)


def temporal_segments(ds, anim):
    """The temporal segments, a list of (first, last) frame indices, as `deformseg temporal`."""
    return [tuple(pair) for pair in ds.temporal_segmentation(anim)]


def evolving_graph(ds, anim, threshold=0.5, face_segments=False):
    """The evolving graph (key frames, their nodes), as `deformseg spatiotemporal`; with
    face_segments, also each triangle's segment in each frame (graph.face_segments, (T, F) int32,
    -1 rigid), as `deformseg spatiotemporal --mesh-dir` colours them."""
    return ds.evolving_graph(anim, threshold=threshold, face_segments=face_segments)


def compare(ds, a, b, significance=20):
    """The similarity of two animations: a deformseg.Similarity with its alignment and z-score
    (significance: the shuffled copies the z-score is measured against)."""
    return ds.similarity(a, b, significance=significance)


def search(ds, store_folder, anim, k=5):
    """The k clips of the motion store nearest to anim: a list of dicts (rank, index, name,
    path, clip, value), best first, as `deformseg search`."""
    store = ds.open_store(store_folder)
    return store.search(anim, k=min(k, len(store)))["neighbours"]


def key_frame_name(index, key_frame):
    """A timeline marker's name for a key frame: its number and its nodes' labels (R: rigid,
    D<n>: deformed segment n)."""
    labels = " ".join(node.label for node in key_frame.nodes)
    return f"K{index} {labels}"


# ---- colours -------------------------------------------------------------------------------------

# A perceptually ordered ramp (blue, cyan, yellow, red) for normalised strain in [0, 1].
_RAMP = np.array([[0.05, 0.15, 0.6], [0.1, 0.65, 0.85], [0.95, 0.9, 0.25], [0.85, 0.1, 0.05]])

# Distinct colours for segment labels; label -1 (rigid) is grey.
_PALETTE = np.array([[0.9, 0.3, 0.2], [0.2, 0.6, 0.9], [0.3, 0.8, 0.3], [0.95, 0.7, 0.1], [0.6, 0.3, 0.8],
                     [0.1, 0.8, 0.7], [0.9, 0.4, 0.7], [0.55, 0.45, 0.2]])
RIGID_GREY = np.array([0.55, 0.55, 0.55])


def ramp(values, low=0.0, high=1.0):
    """Colours (..., 4) of values on the strain ramp, low..high mapped onto it."""
    t = np.clip((np.asarray(values, dtype=np.float64) - low) / max(high - low, 1e-12), 0.0, 1.0)
    position = t * (len(_RAMP) - 1)
    lower = np.minimum(position.astype(int), len(_RAMP) - 2)
    mix = (position - lower)[..., None]
    rgb = _RAMP[lower] * (1 - mix) + _RAMP[lower + 1] * mix
    return np.concatenate([rgb, np.ones(rgb.shape[:-1] + (1,))], axis=-1)


def palette(labels):
    """Colours (..., 4) of integer labels: -1 grey, others from a repeating palette."""
    labels = np.asarray(labels)
    rgb = np.where((labels < 0)[..., None], RIGID_GREY, _PALETTE[np.maximum(labels, 0) % len(_PALETTE)])
    return np.concatenate([rgb, np.ones(rgb.shape[:-1] + (1,))], axis=-1)
