"""A small model of motion learned from the other groups' labels (issue 57), run by hand:

    apt-get install python3-torch    # this benchmark only
    cmake --build build-bench --target described_matrix
    PYTHONPATH=build/python /usr/bin/python3 test/bench/retrieval_model.py \\
        [--matrix build-bench/test/bench/described_matrix] [--cache DIR] [--hidden H ...] [--steps S] [--copies]

The sets, clips and scoring are retrieval_descriptions.py's. Each group (a rig of the characters,
a pack of the library, the cute fish) is left out in turn: a model is trained on the labelled
clips of every other group of the three sets, then maps the rows (today's signatures, 64 columns)
of every clip of the left-out group's set, and the group's queries are scored against that set
through the default's kernel and DTW (`described_matrix`). No label of a group teaches its own
model.

The model maps each row alone, x + B tanh(A x + a) (a hidden layer of H units, B zero at the start,
so that training starts from today's signatures), then scales the rows so that the mean squared
distance of random pairs stays. Training compares clips as DTW would without the order: the mean
over each clip's rows of the default's kernel to the other clip's nearest row, both ways. Each step
draws 32 anchors, each with 63 other clips of bodies not its own, among them up to 16 of its motion
(those of other groups first: a walk of another studio is what the default ranks too low), and
lowers the softmax's cross-entropy of finding a clip of its motion (temperature 0.05). Labels are
compared within a set only. With --copies (issue 57's "invariance taught by construction"), half
of each step's anchors are instead copies of clips of any group, the left-out one's too (no label is
read): each clip played 0.8x and 1.25x, and its motion scaled 0.75 and 1.25 from its first pose,
the four copies and the original one motion, each a body of its own. Seeds are fixed; the run is
the same from one time to the next.
"""
import argparse
import sys
import tempfile
from multiprocessing import Pool
from pathlib import Path

import numpy as np
import torch

sys.path.insert(0, str(Path(__file__).resolve().parent))
from retrieval_descriptions import (copies_of, described, describe, read_sets, scores,  # noqa: E402
                                    similarity_matrix, text)

SCALE = 1.77  # the default's kernel scale
ANCHORS, CANDIDATES, POSITIVES, ROWS, TEMPERATURE = 32, 63, 16, 24, 0.05


class RowModel(torch.nn.Module):
    def __init__(self, width, hidden):
        super().__init__()
        self.inner = torch.nn.Linear(width, hidden)
        self.outer = torch.nn.Linear(hidden, width, bias=False)
        torch.nn.init.zeros_(self.outer.weight)

    def forward(self, x):
        return x + self.outer(torch.tanh(self.inner(x)))


def kernel(a, b):
    """The default's kernel between every row of `a` (..., n, W) and of `b` (..., m, W)."""
    squared = (a * a).sum(-1, keepdim=True) + (b * b).sum(-1).unsqueeze(-2) - 2 * a @ b.transpose(-1, -2)
    return torch.exp(-squared.clamp(min=0) / (a.shape[-1] * SCALE ** 2))


def chamfer_similarity(anchors, candidates, anchor_mask, candidate_mask):
    """Per anchor (A, n, W) and candidate (A, C, m, W): the mean of each row's kernel to the other
    clip's nearest row, both ways (masked rows are padding)."""
    k = kernel(anchors.unsqueeze(1), candidates)  # (A, C, n, m)
    k_a = k.masked_fill(~candidate_mask[:, :, None, :], 0).amax(3)  # each anchor row's nearest
    k_b = k.masked_fill(~anchor_mask[:, None, :, None], 0).amax(2)
    forward = (k_a * anchor_mask[:, None]).sum(2) / anchor_mask.sum(1, keepdim=True)
    backward = (k_b * candidate_mask).sum(2) / candidate_mask.sum(2)
    return 0.5 * (forward + backward)


def padded(rows_list):
    """The clips' rows, at most ROWS of each (evenly spaced), padded, and their masks."""
    out = np.zeros((len(rows_list), ROWS, rows_list[0].shape[1]), np.float32)
    mask = np.zeros((len(rows_list), ROWS), bool)
    for i, r in enumerate(rows_list):
        if len(r) > ROWS:
            r = r[np.linspace(0, len(r) - 1, ROWS).astype(int)]
        out[i, :len(r)], mask[i, :len(r)] = r, True
    return torch.from_numpy(out), torch.from_numpy(mask)


def candidates_of(a, training, by_set, rng):
    """Anchor `a`'s candidates (clips of other bodies of its set): its motion's first, up to
    POSITIVES of them, other groups' before its own; then other motions' to CANDIDATES in all."""
    _, s, motion, body, group = training[a]
    indices, motions, bodies, groups = by_set[s]
    other_body, of_motion = bodies != str(body), motions == str(motion)
    same, different = np.flatnonzero(other_body & of_motion), indices[other_body & ~of_motion]
    if not len(same) or len(different) < CANDIDATES - POSITIVES:
        return None
    same = rng.permutation(same)
    same = indices[same[np.argsort(groups[same] == str(group), kind="stable")][:POSITIVES]]
    return same, rng.choice(different, CANDIDATES - len(same), replace=False)


def copies(path):
    """The default's rows of a clip's four copies (`copies_of`)."""
    z = np.load(path)
    faces = z["faces"]
    return [describe("default", copy, faces) for copy, _ in copies_of(z["positions"].astype(np.float64))]


def train(training, hidden, steps, seed):
    """A model trained on `training`: [(rows, set, motion, body, group)], labelled clips (set an
    index) or copies (set "copies", motion the clip, body the version), half the anchors each."""
    torch.manual_seed(seed)
    rng = np.random.default_rng(seed)
    model = RowModel(training[0][0].shape[1], hidden)
    optimiser = torch.optim.Adam(model.parameters(), lr=1e-3, weight_decay=1e-4)
    by_set = {}  # per set: its entries' indices, motions, bodies and groups
    for i, t in enumerate(training):
        by_set.setdefault(t[1], []).append(i)
    by_set = {s: (np.array(v), *(np.array([str(training[i][k]) for i in v]) for k in (2, 3, 4)))
              for s, v in by_set.items()}
    x, x_mask = padded([t[0] for t in training])
    pools = [np.array([i for i, t in enumerate(training) if (t[1] == "copies") == kind]) for kind in (False, True)]
    pools = [pool for pool in pools if len(pool)]
    for _ in range(steps):
        anchors, chosen, positive = [], [], []
        while len(anchors) < ANCHORS:
            a = int(rng.choice(pools[len(anchors) % len(pools)]))
            picked = candidates_of(a, training, by_set, rng)
            if picked is None or a in anchors:
                continue
            anchors.append(a)
            chosen.append(np.concatenate(picked))
            positive.append(np.arange(CANDIDATES) < len(picked[0]))
        chosen, positive = torch.from_numpy(np.array(chosen)), torch.from_numpy(np.array(positive))
        used = torch.unique(torch.cat([torch.tensor(anchors), chosen.flatten()]))
        y = torch.zeros_like(x)
        y[used] = model(x[used])
        s_ = chamfer_similarity(y[anchors], y[chosen], x_mask[anchors], x_mask[chosen]) / TEMPERATURE
        loss = (torch.logsumexp(s_, 1) - torch.logsumexp(s_.masked_fill(~positive, -1e9), 1)).mean()
        optimiser.zero_grad()
        loss.backward()
        optimiser.step()
    return model


def mapped(model, rows_list):
    """Every clip's rows through `model`, scaled so that the mean squared distance of random pairs
    of rows stays (the kernel's scale then means what it did)."""
    with torch.no_grad():
        out = [model(torch.from_numpy(r.astype(np.float32))).numpy() for r in rows_list]
    every = np.vstack(rows_list)
    pick = np.random.default_rng(0).choice(len(every), 4000)
    before = ((every[pick[:2000]] - every[pick[2000:]]) ** 2).sum(1).mean()
    every = np.vstack(out)
    after = ((every[pick[:2000]] - every[pick[2000:]]) ** 2).sum(1).mean()
    return [r * np.sqrt(before / after) for r in out]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--matrix", default="build-bench/test/bench/described_matrix")
    parser.add_argument("--cache", type=Path, default=Path(tempfile.gettempdir()) / "deformseg-descriptions")
    parser.add_argument("--hidden", type=int, nargs="+", default=[64])
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--copies", action="store_true", help="half the anchors copies of clips")
    args = parser.parse_args()
    torch.set_num_threads(2)
    sets = read_sets(args.cache)
    with Pool(2) as pool:
        rows = [pool.map(described, [("default", c["path"]) for c in clips], chunksize=4) for _, clips in sets]
        copied = [pool.map(copies, [c["path"] for c in clips], chunksize=4) for _, clips in sets] if args.copies else []
    labelled = [(rows[s][i], s, c["motion"], c["body"], c["group"])
                for s, (_, clips) in enumerate(sets) for i, c in enumerate(clips) if c["motion"] != "-"]
    versions = [(r, "copies", f"{s}/{i}", version, None) for s, of_set in enumerate(copied)
                for i, clip_copies in enumerate(of_set) for version, r in enumerate([rows[s][i]] + clip_copies)]
    for hidden in args.hidden:
        name = f"model-{hidden}" + ("-and-copies" if args.copies else "")
        print(f"{name}: queries NN mAP ROC-AUC")
        for s, (set_name, clips) in enumerate(sets):
            pooled = []
            for group in sorted({c["group"] for c in clips}):
                training = [t for t in labelled if not (t[1] == s and t[4] == group)] + versions
                model = train(training, hidden, args.steps, seed=0)
                m = similarity_matrix(mapped(model, rows[s]), args.matrix)
                queries = [i for i, c in enumerate(clips) if c["group"] == group]
                print(f"    {group:38s} {text(scores(m, clips, queries))}")
                sys.stdout.flush()
                pooled.append((m, queries))
            print(f"  {set_name:40s} {text(pooled_scores(pooled, clips))}")
            sys.stdout.flush()


def pooled_scores(pooled, clips):
    """The set's figures, each group's queries scored on its own fold's matrix, pooled as one."""
    m = np.zeros_like(pooled[0][0])
    for fold, queries in pooled:
        m[queries] = fold[queries]
    return scores(m, clips, range(len(clips)))


if __name__ == "__main__":
    main()
