/// \page TemporalSegmentationPolicyConcept The TemporalSegmentationPolicy concept
///
/// How the frames of an animation are cut into temporal segments, given the within-segment
/// dissimilarities of its frame distance matrix. The C++20 concept
/// deformseg::temporal::TemporalSegmentationPolicy checks it at compile time.
///
/// A type `P` is a model when it is copyable and, for `const P& p` and a
/// `const deformseg::temporal::Segment_cost& cost`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `p(cost)` | `std::vector<deformseg::temporal::Frame_interval>` | intervals covering `[0, cost.num_frames() - 1]` without gap or overlap, in any order |
///
/// deformseg::temporal::segment_frames sorts the intervals, checks that they cover the frames exactly once
/// (throwing deformseg::invalid_input when not), and adds each segment's cost. The policy holds its
/// own parameters; thresholds are deformseg::temporal::Segmentation_threshold values, absolute or relative to
/// the mean frame distance.
///
/// \par Has models
/// deformseg::temporal::Optimal_partition (the default), deformseg::temporal::Binary_split,
/// deformseg::temporal::Thesis_greedy, deformseg::temporal::Barbic_pca; `examples/temporal_segmentation.cpp` adds one
/// of its own.
///
/// | policy | default threshold | fewer segments when the threshold grows |
/// |---|---|---|
/// | deformseg::temporal::Optimal_partition | penalty 0.03 of the one-segment cost | yes |
/// | deformseg::temporal::Binary_split | 0.5 x mean distance | yes |
/// | deformseg::temporal::Thesis_greedy | 0.2 x mean distance | not always |
/// | deformseg::temporal::Barbic_pca | none (3 standard deviations of the error's growth) | - |
