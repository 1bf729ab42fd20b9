"""What the docs say of the values, checked: the histogram policy's values crowd near 1."""
import numpy as np

import deformseg
from conftest import REPOSITORY


def test_the_histogram_policy_says_its_values_crowd_near_1():
    doc = " ".join(deformseg.similarity.__doc__.split())
    assert "'histogram': per-frame histograms of the strain, no correspondence needed; its values crowd near 1" in doc
    assert "read the z-score or a rank, not the value" in doc


def test_the_histogram_figures_of_the_docs(characters):
    # The figures chapter 7 gives: the Knight's walk against a frozen copy of itself (its first
    # frame held) and against its death.
    chapter = " ".join((REPOSITORY / "doc" / "chapters" / "07_alignment_and_similarity.md").read_text().split())
    assert "scores 0.997 against a frozen copy of itself, its first frame held, and 0.996 against its" in chapter
    knight = characters / "Knight.glb"
    walk = deformseg.read_animation(knight, clip="Walking_A")
    death = deformseg.read_animation(knight, clip="Death_A")
    frozen = deformseg.Animation(walk.faces, np.repeat(walk.frames[:1], walk.num_frames, axis=0))
    histogram = {"policy": "histogram", "significance": 0}
    assert round(deformseg.similarity(walk, frozen, **histogram).value, 3) == 0.997
    assert round(deformseg.similarity(walk, death, **histogram).value, 3) == 0.996
