"""Descriptions of motion tried against the studio and the body (issue 57), run by hand:

    cmake --build build-bench --target described_matrix
    PYTHONPATH=build/python /usr/bin/python3 test/bench/retrieval_descriptions.py \\
        [--matrix build-bench/test/bench/described_matrix] [--cache DIR] [NAME ...]

Each labelled clip of the shared characters (characters/motions.csv, a group per rig) and of the
motion library (library/labels.csv, a group per pack; the cute fish apart) is read as `deformseg
evaluate` reads it (30 fps, welded, repaired) and kept in DIR (default: deformseg-descriptions in
the system's temporary folder) for the next run. Each description NAME (default: all, in the order
below) is computed here in NumPy, frame by frame, with the library's rules (lags of 1, 4, 16 and
128 frames, cut at the clip's ends; the area-weighted quantiles at (q + 1/2) / k of the weight; the
logarithms, floor, asinh and vertical weight of the default), then compared as the default policy
compares motion signatures (its kernel, DTW and normalisation: `described_matrix`), and each group's
queries scored against their whole set with the evaluation's rules. A fixed description chooses
nothing, so each group's figures are those of a group left out. `default` reproduces the library's
default (`deformseg evaluate`'s figures to the last digit); `bands-3` and `bands-4` the option
`bands`; `vertical-W` the default with vertical rates weighted W (0.2 in the default); `axes-W` the
default and speeds across and along the body (x and z), weighted W. `learned-S` maps the default's
rows by a metric learned, without labels, from copies of the other sets' clips (played 0.8x and
1.25x, their motion scaled 0.75 and 1.25): the inverse square root of the copies' row differences'
covariance, shrunk towards the identity by S. Two rows re-rank the default's matrix instead, reading
no label: `body-centred` takes from each similarity the query's mean similarity to the candidate's
body (the body's offset), `hubs` half the candidate's mean similarity to its 10 nearest clips of
other bodies.

Eleven rows match body regions before comparing them (issue 57's last direction). `limbs-R` cuts the
first frame's pose into the trunk (within R RMS radii of the centroid) and the limbs beyond it by their
offset's largest component: legs (down), arms (across), head (up), front and back (z), the legs'
and the arms' halves either side of the centroid, the one that moves more first.
`bands-N-inner-outer` halves each of N height bands at its median distance from the vertical
axis. `motion-parts-K` clusters the vertices of each clip by their frame-to-frame displacements
(the centroid's out; k-means, K parts) and orders the parts by their rest height, then their
distance from the axis. Five rows match each pair's parts instead: `matched-motion-parts-K` (the
parts of `motion-parts-K`) and `matched-rest-parts-K` (k-means of the first pose's positions) give
each part's place, its rest centroid's offset from the body's in the pose's extent along each axis,
and `described_matrix --regions` assigns each pair's parts to each other by place before comparing.
Each region's 4 area-weighted quantiles are side by side. Four rows
normalise 4 height bands by the clip's own period (the strongest autocorrelation of its surface
speed over lags of 6 frames to half the clip, kept above 0.5): `bands-4-per-cycle-C` plays the
clip so that a period lasts C frames, `bands-4-rows-per-cycle-C` only interpolates its rows to
that length. `mean-A+B...` averages the similarity matrices of the descriptions A, B, ... (a
fusion of their values, each pair compared under each).
"""
import argparse
import json
import os
import struct
import subprocess
import sys
import tempfile
from multiprocessing import Pool
from pathlib import Path

import numpy as np

import deformseg

LAGS = (1, 4, 16, 128)  # frames at 30 fps
FPS = 30.0
FLOOR, VERTICAL_UNIT, VERTICAL_WEIGHT = 3e-3, 9e-3, 0.2
DATA = Path(os.environ.get("DEFORMSEG_DATA_DIR", Path(__file__).resolve().parents[3] / "shared" / "data"))


# ---- the clips ---------------------------------------------------------------------------------

def read_sets(cache):
    """[(set name, [clip dict])]: the characters, the library without the cute fish, the cute fish.
    Each clip: file, clip, motion, rig, body, group, and path (its positions and faces, cached)."""
    sources = {"characters": (DATA / "characters" / "motions.csv", lambda r: r["rig"]),
               "library": (DATA / "library" / "labels.csv", lambda r: r["body"].split("/")[0])}
    clips = {}
    for name, (csv, group_of) in sources.items():
        folder = cache / name
        folder.mkdir(parents=True, exist_ok=True)
        clips[name] = []
        for k, row in enumerate(deformseg.read_motion_labels(csv)):
            path = folder / f"{k}.npz"
            if not path.exists():
                try:
                    a = deformseg.read_animation(row["file"], clip=row["clip"], fps=FPS)
                except deformseg.InvalidInput:
                    continue  # as --skip-unreadable
                np.savez(path, positions=np.asarray(a.frames, dtype=np.float32), faces=np.asarray(a.faces))
            clips[name].append(dict(row, body=row["body"] or row["file"], group=group_of(row), path=str(path)))
    fish = "cute_fish_pack"
    return [("characters", clips["characters"]),
            ("library without the cute fish", [c for c in clips["library"] if c["group"] != fish]),
            ("the cute fish", [c for c in clips["library"] if c["group"] == fish])]


# ---- the descriptions --------------------------------------------------------------------------

def area_weights(first, faces):
    e1, e2 = first[faces[:, 1]] - first[faces[:, 0]], first[faces[:, 2]] - first[faces[:, 0]]
    area = 0.5 * np.linalg.norm(np.cross(e1, e2), axis=1)
    w = np.zeros(len(first))
    for j in range(3):
        np.add.at(w, faces[:, j], area / 3)
    return w / w.sum() if w.sum() > 0 else np.full(len(first), 1 / len(first))


def rms_radius(p, w):
    centroid = np.einsum("tvi,v->ti", p, w)
    return np.sqrt(np.mean(((p - centroid[:, None]) ** 2).sum(-1) @ w))


def quantiles(values, w, k):
    """Per row of `values` (T, V): the smallest value whose cumulative weight reaches (q + 1/2) / k."""
    order = np.argsort(values, axis=1, kind="stable")
    cumulative = np.cumsum(w[order], axis=1)
    cumulative /= cumulative[:, -1:]
    at = np.stack([np.argmax(cumulative >= (q + 0.5) / k - 1e-12, axis=1) for q in range(k)], 1)
    return np.take_along_axis(np.take_along_axis(values, order, 1), at, 1)


def displacements(p, lag, unit):
    t = np.arange(len(p))
    return (p[np.minimum(t + lag, len(p) - 1)] - p[np.maximum(t - lag, 0)]) * unit / (2 * lag / FPS)


def rows(p, regions, unit, k=8, transform=None, vertical_weight=VERTICAL_WEIGHT):
    """Per lag, each region's (a vertex weighting's) speed quantiles, then its vertical rates'."""
    speeds, verticals = [], []
    for lag in LAGS:
        d = displacements(p, lag, unit)
        if transform:
            d = transform(d, lag)
        for w in regions:
            on = w > 0
            speeds.append(np.log(np.maximum(quantiles(np.linalg.norm(d[:, on], axis=2), w[on], k), FLOOR)))
            verticals.append(np.sqrt(vertical_weight) * np.arcsinh(quantiles(d[:, on, 1], w[on], k) / VERTICAL_UNIT))
    return np.hstack(speeds + verticals)


def axis_speeds(p, w, unit, weight):
    """The default's rows, then per lag the quantiles of the speeds across the body (x, either way)
    and along it (z, either way), as logarithms weighted by `weight`: a run and a strafe apart."""
    along = []
    for axis in (0, 2):
        for lag in LAGS:
            d = np.abs(displacements(p, lag, unit)[:, :, axis])
            along.append(np.sqrt(weight) * np.log(np.maximum(quantiles(d, w, 8), FLOOR)))
    return np.hstack([rows(p, [w], unit)] + along)


def cut(values, count):
    """Each value's band of `count` equal ones between the values' least and greatest."""
    u = (values - values.min()) / max(values.max() - values.min(), 1e-300)
    return np.minimum((u * count).astype(int), count - 1)


def regions_of(labels, w, count):
    """A weighting per label of `count`, each summing to 1; an empty label takes the whole surface's."""
    out = []
    for label in range(count):
        part = np.where(labels == label, w, 0.0)
        out.append(part / part.sum() if part.sum() > 0 else w)
    return out


def describe(name, p, faces):
    w = area_weights(p[0], faces)
    radius = rms_radius(p, w)
    height, depth, side = p[0][:, 1], p[0][:, 2], p[0][:, 0]
    if name == "default":
        return rows(p, [w], 1 / radius)
    if name == "bands-3x2-front-back":
        return rows(p, regions_of(cut(height, 3) * 2 + cut(depth, 2), w, 6), 1 / radius)
    if name == "bands-3-left-right":
        return left_right_sorted(p, w, radius, side >= side @ w, cut(height, 3))
    if name == "bands-3-equal-weights":
        return rows(p, [sum(regions_of(cut(height, 3), w, 3)) / 3], 1 / radius)
    if name == "vertex-weights":
        return rows(p, [np.full(len(w), 1 / len(w))], 1 / radius)
    if name.startswith("vertical-"):
        return rows(p, [w], 1 / radius, vertical_weight=float(name[9:]))
    if name.startswith("axes-"):
        return axis_speeds(p, w, 1 / radius, float(name[5:]))
    if name == "height-unit":
        return rows(p, [w], 1 / (height.max() - height.min()))
    if name in ("local", "local-and-travel"):
        return local(p, w, radius, name == "local-and-travel")
    if name.startswith("amplitude-"):
        return amplitude_relative(p, w, radius, cut(height, 3), float(name[10:]))
    if name in ("bands-3-and-alternation", "bands-3-and-return"):
        structure = alternation(p, w, height, side) if name.endswith("alternation") else homecoming(p, w, radius)
        banded = rows(p, regions_of(cut(height, 3), w, 3), 1 / radius)
        return np.hstack([banded, np.full((len(p), 1), (8.0 if name.endswith("alternation") else 4.0) * structure)])
    if name.startswith("bands-") and name.endswith("-inner-outer"):
        return inner_outer(p, w, radius, int(name[6:-12]))
    if name.startswith("bands-4-") and "per-cycle-" in name:
        return per_cycle(p, w, radius, int(name.rsplit("-", 1)[1]), "rows-per-cycle" in name)
    if name.startswith("bands-"):
        return rows(p, regions_of(cut(height, int(name[6:])), w, int(name[6:])), 1 / radius)
    if name.startswith("limbs-"):
        return limbs(p, w, radius, float(name[6:]))
    if name.startswith("motion-parts-"):
        return motion_parts(p, w, radius, int(name[13:]))
    if name.startswith("matched-"):
        return matched_parts(p, w, radius, name[8:].startswith("motion"), int(name.rsplit("-", 1)[1]))
    raise SystemExit(f"unknown description {name}")


def local(p, w, radius, travel):
    """Each displacement less the centroid's (the body's travel out); with `travel`, the centroid's
    speed and vertical rate as one more region of one vertex."""
    speeds, verticals = [], []
    for lag in LAGS:
        d = displacements(p, lag, 1 / radius)
        centroid = np.einsum("tvi,v->ti", d, w)
        d = d - centroid[:, None]
        speeds.append(np.log(np.maximum(quantiles(np.linalg.norm(d, axis=2), w, 8), FLOOR)))
        verticals.append(np.sqrt(VERTICAL_WEIGHT) * np.arcsinh(quantiles(d[:, :, 1], w, 8) / VERTICAL_UNIT))
        if travel:
            speeds.append(np.log(np.maximum(np.linalg.norm(centroid, axis=1), FLOOR))[:, None])
            verticals.append(np.sqrt(VERTICAL_WEIGHT) * np.arcsinh(centroid[:, 1:2] / VERTICAL_UNIT))
    return np.hstack(speeds + verticals)


def amplitude_relative(p, w, radius, bands, keep):
    """3 height bands, every rate of a lag divided by the clip's typical speed at that lag (the
    exponential of its area-weighted mean log speed over the clip) to the power 1 - keep."""
    levels = {lag: np.exp(np.mean(np.log(np.maximum(np.linalg.norm(displacements(p, lag, 1 / radius), axis=2),
                                                      FLOOR)) @ w)) for lag in LAGS}
    return rows(p, regions_of(bands, w, 3), 1 / radius, transform=lambda d, lag: d / levels[lag] ** (1 - keep))


def left_right_sorted(p, w, radius, right, bands):
    """3 height bands, each cut into its halves either side of the centroid across x; the half that
    moves more over the clip first, so that a motion and its mirror image match."""
    labels = bands * 2 + right.astype(int)
    described = rows(p, regions_of(labels, w, 6), 1 / radius, k=4)
    blocks = described.reshape(len(described), 2, len(LAGS), 3, 2, 4)
    for band in range(3):
        if blocks[:, 0, :, band, 1].mean() > blocks[:, 0, :, band, 0].mean():
            blocks[:, :, :, band] = blocks[:, :, :, band, ::-1].copy()
    return blocks.reshape(len(described), -1)


def alternation(p, w, height, side):
    """How the two lateral halves of the lower body rise and fall together over the clip: the
    correlation of their vertical velocities (a walk's legs alternate: below 0)."""
    low = cut(height, 2) == 0
    halves = [low & (side < side @ w), low & (side >= side @ w)]
    if any(w[h].sum() <= 0 for h in halves):
        return 0.0
    rises = [np.diff(p[:, h, 1], axis=0) @ (w[h] / w[h].sum()) for h in halves]
    if min(r.std() for r in rises) < 1e-12:
        return 0.0
    return float(np.corrcoef(*rises)[0, 1])


def homecoming(p, w, radius):
    """How far the clip ends from its first pose, in RMS radii, as a logarithm (a loop comes back)."""
    return float(np.log(max(np.sqrt(((p[-1] - p[0]) ** 2).sum(-1) @ w) / radius, 1e-3)))


# ---- body regions matched before they are compared ---------------------------------------------

def moving_first(p, w, labels, pairs):
    """`labels` with each pair's two labels swapped where the second's surface moves more over the
    clip (area-weighted mean speed at lag 4), so that a motion and its mirror image match."""
    speed = np.linalg.norm(displacements(p, 4, 1.0), axis=2).mean(0) * w
    out = labels.copy()
    for a, b in pairs:
        if speed[labels == b].sum() / max(w[labels == b].sum(), 1e-300) > \
                speed[labels == a].sum() / max(w[labels == a].sum(), 1e-300):
            out[labels == a], out[labels == b] = b, a
    return out


def limb_labels(first, w, radius, reach):
    """Regions of the rest pose that correspond across bodies: 0 the trunk (within `reach` RMS radii
    of the centroid), else by the offset's largest component: 1 and 2 down (legs, x below or above
    the centroid), 3 and 4 across (arms, wings, fins), 5 up (head), 6 forward (z), 7 backward (tail)."""
    o = (first - w @ first) / radius
    side = (o[:, 0] >= 0).astype(int)
    direction = np.argmax(np.stack([-o[:, 1], np.abs(o[:, 0]), o[:, 1], o[:, 2], -o[:, 2]], 1), 1)
    labels = np.choose(direction, [1 + side, 3 + side] + [np.full(len(o), label) for label in (5, 6, 7)])
    labels[np.linalg.norm(o, axis=1) < reach] = 0
    return labels


def limbs(p, w, radius, reach):
    """The 8 limb regions' rows side by side (4 quantiles each), of each pair of legs and of arms
    the one that moves more first; an empty region takes the whole surface's rows."""
    labels = moving_first(p, w, limb_labels(p[0], w, radius, reach), [(1, 2), (3, 4)])
    return rows(p, regions_of(labels, w, 8), 1 / radius, k=4)


def inner_outer(p, w, radius, count):
    """`count` height bands, each halved at its area-weighted median horizontal distance from the
    vertical axis through the rest centroid: trunk and head inside, arms, hands and tails outside."""
    first = p[0]
    centre = w @ first
    distance = np.hypot(first[:, 0] - centre[0], first[:, 2] - centre[2])
    bands, outer = cut(first[:, 1], count), np.zeros(len(w), dtype=int)
    for band in range(count):
        on = bands == band
        if w[on].sum() > 0:
            outer[on] = distance[on] > quantiles(distance[on][None], w[on], 1)[0, 0]
    return rows(p, regions_of(bands * 2 + outer, w, 2 * count), 1 / radius, k=4)


def kmeans(x, w, count, iterations=25):
    """Labels of area-weighted k-means of the rows of `x` from a k-means++ start of seed 0."""
    rng = np.random.default_rng(0)
    centres = [x[rng.choice(len(x), p=w / w.sum())]]
    nearest = ((x - centres[0]) ** 2).sum(1)
    for _ in range(1, count):
        chance = w * nearest
        centres.append(x[rng.choice(len(x), p=chance / chance.sum())] if chance.sum() > 0 else x[0])
        nearest = np.minimum(nearest, ((x - centres[-1]) ** 2).sum(1))
    centres = np.array(centres)
    for _ in range(iterations):
        labels = np.argmin((x ** 2).sum(1)[:, None] - 2 * x @ centres.T + (centres ** 2).sum(1)[None], 1)
        for j in range(count):
            if w[labels == j].sum() > 0:
                centres[j] = w[labels == j] @ x[labels == j] / w[labels == j].sum()
    return labels


def motion_parts(p, w, radius, count):
    """Near-rigid parts of the clip: vertices clustered (k-means, `count`) by their frame-to-frame
    displacements less the centroid's, in RMS radii; the parts ordered by their rest centroid's
    height (in 2 `count` equal bands), then its distance from the vertical axis; each part's rows
    side by side (4 quantiles)."""
    steps = np.diff(p, axis=0) / radius
    steps -= np.einsum("tvi,v->ti", steps, w)[:, None]
    labels = kmeans(steps.transpose(1, 0, 2).reshape(len(w), -1), w, count)
    first, centre = p[0], w @ p[0]
    centroids = np.array([w[labels == j] @ first[labels == j] / w[labels == j].sum()
                          if w[labels == j].sum() > 0 else centre for j in range(count)])
    span = max(np.ptp(first[:, 1]), 1e-300)
    level = np.floor((centroids[:, 1] - first[:, 1].min()) / span * 2 * count)
    distance = np.hypot(centroids[:, 0] - centre[0], centroids[:, 2] - centre[2])
    rank = np.empty(count, dtype=int)
    rank[np.lexsort((distance, level))] = np.arange(count)
    return rows(p, regions_of(rank[labels], w, count), 1 / radius, k=4)


def matched_parts(p, w, radius, by_motion, count):
    """`count` parts of the clip, from its motion (as `motion_parts`) or from its first pose (k-means of
    the rest positions, each axis in the pose's extent along it), each part's rows side by side (4
    quantiles), and each part's place: its rest centroid's offset from the body's, each axis in the
    pose's extent. `described_matrix --regions` matches each pair's parts by place before comparing."""
    first = p[0]
    extent = np.maximum(np.ptp(first, axis=0), 1e-300)
    offsets = (first - w @ first) / extent
    if by_motion:
        steps = np.diff(p, axis=0) / radius
        steps -= np.einsum("tvi,v->ti", steps, w)[:, None]
        labels = kmeans(steps.transpose(1, 0, 2).reshape(len(w), -1), w, count)
    else:
        labels = kmeans(offsets, w, count)
    places = np.array([w[labels == j] @ offsets[labels == j] / w[labels == j].sum()
                       if w[labels == j].sum() > 0 else np.zeros(3) for j in range(count)])
    return rows(p, regions_of(labels, w, count), 1 / radius, k=4), places


def dominant_period(p, w, shortest=6, least=0.5):
    """The clip's period in frames: the lag in [shortest, T/2] where the autocorrelation of its
    surface speed (area-weighted mean over vertices, frame to frame) is greatest, if above `least`;
    else None (a death, a hit: no cycle)."""
    speed = np.linalg.norm(np.diff(p, axis=0), axis=2) @ w
    speed = speed - speed.mean()
    best, period = least, None
    for lag in range(shortest, len(speed) // 2 + 1):
        a, b = speed[:-lag], speed[lag:]
        norm = np.sqrt((a @ a) * (b @ b))
        if norm > 0 and a @ b / norm > best:
            best, period = a @ b / norm, lag
    return period


def per_cycle(p, w, radius, cycle, rows_only):
    """4 height bands' rows with the clip played so that its period (`dominant_period`) lasts
    `cycle` frames (speeds then per cycle, not per second), or with only its rows interpolated in
    time to that length (`rows_only`: speeds per second); a clip without a period as it is."""
    period, banded = dominant_period(p, w), regions_of(cut(p[0][:, 1], 4), w, 4)
    if period is None:
        return rows(p, banded, 1 / radius)
    if not rows_only:
        return rows(resampled(p, period / cycle)[0], banded, 1 / radius)
    described = rows(p, banded, 1 / radius)
    times = np.arange(0, len(described) - 1 + 1e-9, period / cycle)
    i = np.minimum(np.floor(times).astype(int), max(len(described) - 2, 0))
    f = (times - i)[:, None]
    return (1 - f) * described[i] + f * described[np.minimum(i + 1, len(described) - 1)]


# ---- a metric learned from augmented copies -----------------------------------------------------

def resampled(p, speed):
    """`p` played `speed` times as fast (positions interpolated linearly), and the original's time
    of each of its frames."""
    times = np.arange(0, len(p) - 1 + 1e-9, speed)
    i = np.minimum(np.floor(times).astype(int), max(len(p) - 2, 0))
    f = (times - i)[:, None, None]
    return (1 - f) * p[i] + f * p[np.minimum(i + 1, len(p) - 1)], times


def copies_of(p):
    """A clip's four copies, each a copy of the same motion, and the original's time of each of
    their frames: played 0.8x and 1.25x, and its motion scaled 0.75 and 1.25 from its first pose
    (each vertex's path about where it starts)."""
    for speed in (0.8, 1.25):
        yield resampled(p, speed)
    for scale in (0.75, 1.25):
        yield p[:1] + scale * (p - p[:1]), np.arange(len(p))


def augmented(path):
    """A clip's default rows and the differences of its copies' rows (`copies_of`) from them, row by
    row along the time they share."""
    z = np.load(path)
    p, faces = z["positions"].astype(np.float64), z["faces"]
    original = describe("default", p, faces)
    return original, np.vstack([describe("default", copy, faces) - original[np.rint(times).astype(int)]
                                for copy, times in copies_of(p)])


def learned_map(training, shrink):
    """The map (N + shrink tr(N)/W I)^(-1/2), N the mean outer product of `training`'s copy
    differences, scaled so that the mean squared distance of random pairs of its rows stays."""
    differences = np.vstack([d for _, d in training])
    nuisance = differences.T @ differences / len(differences)
    values, vectors = np.linalg.eigh(nuisance + shrink * np.trace(nuisance) / len(nuisance) * np.eye(len(nuisance)))
    m = vectors @ np.diag(values ** -0.5) @ vectors.T
    rows_ = np.vstack([r for r, _ in training])
    pairs = rows_[np.random.default_rng(0).choice(len(rows_), 4000)]
    gap = pairs[:2000] - pairs[2000:]
    return m * np.sqrt((gap ** 2).sum(1).mean() / ((gap @ m) ** 2).sum(1).mean())


def learned_matrices(sets, pool, program, shrink):
    """Each set's rows mapped by the map learned on the other sets' copies (the characters' on the
    library's and the cute fish's, and so on): no clip of a set teaches its own map."""
    described_sets = [pool.map(augmented, [c["path"] for c in clips], chunksize=4) for _, clips in sets]
    matrices = []
    for k, described_set in enumerate(described_sets):
        m = learned_map([d for j, other in enumerate(described_sets) if j != k for d in other], shrink)
        matrices.append(similarity_matrix([rows_ @ m for rows_, _ in described_set], program))
    return matrices


DESCRIPTIONS = ["default", "bands-3", "bands-4", "bands-3x2-front-back", "bands-3-left-right",
                "bands-3-equal-weights", "vertex-weights", "height-unit", "local", "local-and-travel",
                "amplitude-0", "amplitude-0.5", "bands-3-and-alternation", "bands-3-and-return",
                "vertical-0.6", "axes-0.25", "limbs-1", "limbs-1.5", "bands-3-inner-outer",
                "bands-4-inner-outer", "motion-parts-6", "motion-parts-8", "bands-4-per-cycle-12",
                "bands-4-per-cycle-16", "bands-4-per-cycle-24", "bands-4-rows-per-cycle-16",
                "matched-rest-parts-4", "matched-rest-parts-6", "matched-rest-parts-8", "matched-motion-parts-6",
                "matched-motion-parts-8"]
LEARNED = ["learned-1", "learned-3"]
RERANKINGS = ["body-centred", "hubs"]
FUSED = ["mean-default+bands-4", "mean-default+bands-4-per-cycle-12", "mean-default+bands-4+bands-4-per-cycle-12"]


def described(job):
    name, path = job
    z = np.load(path)
    return describe(name, z["positions"].astype(np.float64), z["faces"])


# ---- the matrix and the figures ----------------------------------------------------------------

def similarity_matrix(descriptions, program):
    """The matrix of `descriptions`, each its rows, or its rows and its regions' places (matched per pair)."""
    with tempfile.TemporaryDirectory() as folder:
        rows_path, matrix_path = os.path.join(folder, "rows"), os.path.join(folder, "matrix")
        regions_path = os.path.join(folder, "regions")
        matched = isinstance(descriptions[0], tuple)
        with open(rows_path, "wb") as f:
            f.write(struct.pack("<Q", len(descriptions)))
            for d in descriptions:
                d = np.ascontiguousarray(d[0] if matched else d, dtype=np.float32)
                f.write(struct.pack("<QQ", *d.shape) + d.tobytes())
        if matched:
            with open(regions_path, "wb") as f:
                for _, places in descriptions:
                    f.write(struct.pack("<Q", len(places)) + np.ascontiguousarray(places, dtype=np.float64).tobytes())
        subprocess.run([program, rows_path, matrix_path] + (["--regions", regions_path] if matched else []), check=True)
        n = len(descriptions)
        return np.fromfile(matrix_path, dtype=np.float64).reshape(n, n, order="F")


def is_candidate(query, other):
    if other["body"] == query["body"]:
        return False
    return not (query["rig"] and other["rig"] == query["rig"] and other["clip"] == query["clip"])


def scores(m, clips, queries):
    """Queries, NN accuracy, mAP and ROC-AUC of `queries` (indices) against every clip, as
    evaluate_retrieval scores them (candidates by decreasing similarity, ties to the lower index)."""
    hits, precisions, same, different, n = 0, [], [], [], 0
    for q in queries:
        motion = clips[q]["motion"]
        if motion == "-":
            continue
        candidates = [c for c in range(len(clips)) if c != q and is_candidate(clips[q], clips[c])]
        if not candidates:
            continue
        n += 1
        ranking = sorted(candidates, key=lambda c: (-m[q, c], c))
        relevant = [clips[c]["motion"] == motion for c in ranking]
        hits += relevant[0]
        found = np.cumsum(relevant)
        if found[-1]:
            precisions.append(np.mean([found[r] / (r + 1) for r in range(len(ranking)) if relevant[r]]))
        for c, is_relevant in zip(ranking, relevant):
            (same if is_relevant else different).append(m[q, c])
    same, different = np.sort(same), np.sort(different)
    below = np.searchsorted(different, same, "left")
    ties = np.searchsorted(different, same, "right") - below
    auc = (below + 0.5 * ties).sum() / (len(same) * len(different)) if len(same) and len(different) else None
    return n, hits / n if n else None, np.mean(precisions) if precisions else None, auc


def text(s):
    return f"{s[0]:4d} " + " ".join("  -  " if x is None else f"{x:.3f}" for x in s[1:])


def body_centred(m, clips):
    out = m.copy()
    for body in {c["body"] for c in clips}:
        of_body = [i for i, c in enumerate(clips) if c["body"] == body]
        out[:, of_body] -= m[:, of_body].mean(axis=1, keepdims=True)
    return out


def hubs(m, clips):
    nearest = np.array([np.sort([m[c, j] for j in range(len(clips)) if clips[j]["body"] != clips[c]["body"]])[-10:]
                        .mean() for c in range(len(clips))])
    return m - 0.5 * nearest[None, :]


def report(name, sets, matrices):
    print(f"{name}: queries NN mAP ROC-AUC")
    for (set_name, clips), m in zip(sets, matrices):
        print(f"  {set_name:40s} {text(scores(m, clips, range(len(clips))))}")
        for group in sorted({c["group"] for c in clips}):
            print(f"    {group:38s} {text(scores(m, clips, [i for i, c in enumerate(clips) if c['group'] == group]))}")
    sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", default=DESCRIPTIONS + LEARNED + RERANKINGS + FUSED)
    parser.add_argument("--matrix", default="build-bench/test/bench/described_matrix")
    parser.add_argument("--cache", type=Path, default=Path(tempfile.gettempdir()) / "deformseg-descriptions")
    args = parser.parse_args()
    sets = read_sets(args.cache)
    computed = {}  # each description's matrices per set, kept for the rows built on them

    def matrices_of(name):
        if name not in computed:
            computed[name] = [similarity_matrix(pool.map(described, [(name, c["path"]) for c in clips], chunksize=4),
                                                args.matrix) for _, clips in sets]
        return computed[name]

    with Pool(2) as pool:
        for name in args.names:
            if name in LEARNED:
                report(name, sets, learned_matrices(sets, pool, args.matrix, float(name[8:])))
            elif name in RERANKINGS:
                rerank = body_centred if name == "body-centred" else hubs
                report(name, sets, [rerank(m, clips) for m, (_, clips) in zip(matrices_of("default"), sets)])
            elif name.startswith("mean-"):
                parts = [matrices_of(part) for part in name[5:].split("+")]
                report(name, sets, [sum(ms) / len(ms) for ms in zip(*parts)])
            else:
                report(name, sets, matrices_of(name))


if __name__ == "__main__":
    main()
