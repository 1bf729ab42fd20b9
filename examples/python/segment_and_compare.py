"""deformseg from Python, notebook style (each "# %%" a cell): reads a shared character, segments
one of its clips in time and in space, and compares its clips.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/segment_and_compare.py ../shared/data/characters/Fox.glb

The tests run it (CTest `python.example`); without the character it exits with status 77, which
CTest reports as skipped.
"""
# %% Read two clips of one character: a glTF file, a clip by name, sampled at 30 frames per second.
import pathlib
import sys

import numpy as np

import deformseg

character = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "../shared/data/characters/Fox.glb")
if not character.exists():
    print(f"{character} not found: run from the repository with ../shared/data beside it")
    sys.exit(77)

walk = deformseg.read_animation(character, clip="Walk")
run = deformseg.read_animation(f"{character}#Run")  # FILE#CLIP, as the tool takes it
print(walk)
print("repair:", {k: v for k, v in walk.repair.items() if v and k.startswith("welded")})
print("frames array:", walk.frames.shape, walk.frames.dtype, "(a read-only view, no copy)")

# %% Strain: a (T, F) float32 array, normalised into [0, 1], against frame 0.
strain = deformseg.strain(walk)
print("strain:", strain.shape, "most strained triangle at the last frame:", int(np.argmax(strain[-1])))

# %% Temporal segmentation: intervals of similar poses.
segments = deformseg.temporal_segmentation(walk)
print("temporal segments:", segments)

# %% Spatio-temporal segmentation: the evolving graph's key frames, R rigid, D<id> deformed.
graph = deformseg.evolving_graph(walk)
print(f"evolving graph: {graph.num_segments} segments, {len(graph)} key frames")
for key_frame in graph:
    labels = " ".join(node.label for node in key_frame.nodes)
    print(f"  frames {key_frame.first}-{key_frame.last}: {labels}, {len(key_frame.edges)} edges")

# %% How alike the clips move: the value in [0, 1], with a z-score against shuffled copies.
similarity = deformseg.similarity(walk, run)
print(f"walk vs run: {similarity.value:.3f} (z-score {similarity.z_score:.2f}, "
      f"{len(similarity.alignment)} aligned frame pairs)")
survey = deformseg.read_animation(character, clip="Survey")
matrix = deformseg.similarity_matrix([walk, run, survey])
print("similarity matrix (walk, run, survey):")
print(np.array2string(matrix, precision=3))

# %% Where the walk occurs in the survey clip, if at all.
best = deformseg.find_motion(walk, survey)[0]
print(f"walk found in survey frames {best.first}-{best.last}, value {best.value:.3f}")
