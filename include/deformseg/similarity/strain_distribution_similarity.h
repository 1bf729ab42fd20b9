/// @file similarity/strain_distribution_similarity.h
/// @brief `Strain_distribution_similarity`: two animations compared frame by frame through the
/// distribution of their triangles' strain, aligned in time; needs no correspondence between the
/// two meshes (beyond the thesis).
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/strain/histogram_distance.h>
#include <deformseg/similarity/similarity.h>
#include <deformseg/strain/strain_histograms.h>

#include <string>

namespace deformseg::similarity {

/// @brief Similarity policy (models `SimilarityPolicy`): each frame of an animation becomes the
/// area-weighted histogram of its triangles' strain (`strain_histograms`, previous-pose raw strain
/// by default), two animations' frames are compared by a histogram distance
/// (`histogram_distances`, in [0, 1]) and the two sequences are aligned by `alignment` with that
/// distance as the dissimilarity; `normalization` turns the score into the similarity.
///
/// It needs no correspondence between the meshes, and the same motion on another shape gives
/// alike histograms. It cannot see where on the mesh the strain lies: two motions that strain the
/// same amount of surface in the same way at the same times (one joint bending, then another,
/// or the same in the other order) look the same to it.
/// @tparam Alignment an `alignment::AlignmentPolicy` (default `alignment::Smith_waterman`).
/// @tparam Normalization how the score becomes a value in [0, 1] (default
/// `Best_score_normalization`).
/// @par Complexity `describe`: O(T F) (the strain); `compare`: O(Ta Tb B) for the distances plus
/// the alignment's O(Ta Tb).
template <alignment::AlignmentPolicy Alignment = alignment::Smith_waterman,
          class Normalization = Best_score_normalization>
struct Strain_distribution_similarity {
  /// @brief The strain and its histograms. Default: `Strain_histogram_options` (previous pose,
  /// raw maximal principal strain, 16 log-spaced bins from 0.05 to 1).
  strain::Strain_histogram_options histograms{};
  /// @brief How two frames' histograms are compared. Default: earth mover's distance.
  strain::Histogram_metric metric = strain::Histogram_metric::earth_movers;
  /// @brief How the two frame sequences are aligned. Default: Smith–Waterman, +1 / -1 / -1.
  Alignment alignment{};
  /// @brief How the score becomes the similarity. Default: `Best_score_normalization`.
  Normalization normalization{};

  /// @brief What is compared of one animation: its histograms, `T x (B + 2)`.
  using Description = strain::Strain_histograms;

  /// @brief The histograms of `animation`'s frames.
  /// @tparam Mesh a `DeformingMesh`.
  /// @throws invalid_input as `strain_histograms`.
  template <mesh::DeformingMesh Mesh>
  Description describe(const Mesh& animation) const {
    return strain::strain_histograms(animation, histograms);
  }

  /// @brief The similarity of two animations from their histograms: the alignment of their frame
  /// sequences under the histogram distance.
  /// @throws invalid_input when the histograms have different bin counts.
  Similarity compare(const Description& a, const Description& b) const {
    return internal::aligned_similarity(
        alignment, normalization, strain::histogram_distances(a, b, metric, histograms.histogram.threads),
        std::string("area-weighted histograms of each frame's strain, compared by ") +
            (metric == strain::Histogram_metric::earth_movers ? "earth mover's distance" : "total variation") +
            ", frames aligned in time");
  }
};

}  // namespace deformseg::similarity
